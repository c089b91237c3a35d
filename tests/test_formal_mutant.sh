#!/usr/bin/env bash
# test_formal_mutant.sh -- the proofs can fail.  Nine broken copies, each of
# which must FAIL its property set, and scripts/formal.sh must name the
# counterexample trace (an existing VCD) and the failing assertion's
# file:line in the repository:
#   rr_arbiter.sby:mutant  rtl/fp3_rr_arbiter.v with FP3_MUTANT_RR_STUCK
#                          (the round-robin position never moves, so a
#                          context behind others that keep requesting
#                          starves): the fairness or one-hot assertion
#   rr_arbiter.sby:mutant_issue  rtl/fp3_sched_issue.v with
#                          FP3_MUTANT_ISSUE_POS_LATE (PICK_STAGES = 2: the
#                          position moves with the grant, a cycle after the
#                          decision, so a waiting context is passed over for
#                          up to 2 NUM_CONTEXTS - 3 cycles): the fairness
#                          assertion (formal/fp3_fair_wait.v)
#   sched.sby:mutant       rtl/fp3_wb_tag.v with FP3_MUTANT_ANNOUNCE_EARLY
#                          (the tag lines one stage short: every
#                          write-back announced a cycle early, so the
#                          scoreboard frees a register, and the scheduler
#                          may issue its consumer, before the value
#                          exists): an assertion of formal/fp3_sched_check.v
#                          (the busy flag's, the write-back's or RAW)
#   sched.sby:mutant_div   rtl/fp3_top.v with FP3_MUTANT_DIV_TAG_SHORT (the
#                          div/sqrt unit's tag line alone a stage short):
#                          the busy flag's or the div write-back's
#                          assertion of formal/fp3_sched_check.v
#   sched.sby:mutant_flags rtl/fp3_simd.v with FP3_MUTANT_FLAGS_UNSTAGED (the
#                          host's FLAGS read without the staged cycle, so
#                          a write-back of the last cycle is missing):
#                          flags_staged_exact in rtl/fp3_simd.v
#   sched.sby:mutant_wb1   rtl/fp3_top.v with FP3_MUTANT_MOV_SHORT (one
#                          write-back port, the move path a cycle shorter
#                          than the add/sub core: a move and an add issued
#                          a cycle apart meet at the port): wb_one_port,
#                          in2_one_port or clr_one_port in rtl/fp3_regfile.v
#   uartbone.sby:mutant_len      rtl/fp3_uartbone.v with FP3_MUTANT_UARTBONE_LEN
#                          (a read frame ends a word short): rd_len_exact
#   uartbone.sby:mutant_timeout  ... FP3_MUTANT_UARTBONE_TIMEOUT (an
#                          unfinished frame dropped a cycle early):
#                          drop_not_early
#   uartbone.sby:mutant_wvalid   ... FP3_MUTANT_UARTBONE_WVALID (WVALID
#                          falls with AWREADY instead of WREADY: a data
#                          transfer lost or sent twice): m_w_held or
#                          wr_aw_w_once
set -u
cd "$(dirname "$0")/.."
out=${FORMAL_OUT:-build/formal}/mutant
fail() { echo "test_formal_mutant: $*"; exit 1; }

# check TASK REGEX: TASK must fail with a trace and an assertion matching REGEX
check() {
  local log rc vcd
  log=$(mktemp)
  bash scripts/formal.sh "$out" --expect-fail "$1" | tee "$log"
  rc=${PIPESTATUS[0]}
  [ "$rc" -eq 0 ] || { rm -f "$log"; fail "$1: the mutant's proof did not fail"; }
  grep -q '^formal: FAIL' "$log" || { rm -f "$log"; fail "$1: no FAIL verdict"; }
  vcd=$(sed -n 's/^ *trace: \(.*\.vcd\)$/\1/p' "$log" | head -1)
  [ -n "$vcd" ] || { rm -f "$log"; fail "$1: no counterexample trace named"; }
  [ -s "$vcd" ] || { rm -f "$log"; fail "$1: the trace $vcd does not exist"; }
  grep -Eq 'failed assertion: [^ ]+ at (rtl|formal)/[a-z0-9_]+\.v:[0-9]+$' "$log" ||
    { rm -f "$log"; fail "$1: no failing assertion with file:line"; }
  grep -Eq "$2" "$log" || { rm -f "$log"; fail "$1: not the expected assertion"; }
  rm -f "$log"
  echo "test_formal_mutant: $1 fails its proof, trace $vcd"
}

check formal/rr_arbiter.sby:mutant 'f_served_within_bound|rr_taken_onehot'
check formal/rr_arbiter.sby:mutant_issue 'f_served_within_bound at formal/fp3_fair_wait\.v:[0-9]+$'
check formal/sched.sby:mutant 'at formal/fp3_sched_check\.v:[0-9]+$'
check formal/sched.sby:mutant_div 'at formal/fp3_sched_check\.v:[0-9]+$'
check formal/sched.sby:mutant_flags 'flags_staged_exact at rtl/fp3_simd\.v:[0-9]+$'
check formal/sched.sby:mutant_wb1 '(wb|in2|clr)_one_port at rtl/fp3_regfile\.v:[0-9]+$'
check formal/uartbone.sby:mutant_len 'rd_len_exact at rtl/fp3_uartbone\.v:[0-9]+$'
check formal/uartbone.sby:mutant_timeout 'drop_not_early at rtl/fp3_uartbone\.v:[0-9]+$'
check formal/uartbone.sby:mutant_wvalid '(m_w_held|wr_aw_w_once) at rtl/fp3_uartbone\.v:[0-9]+$'
