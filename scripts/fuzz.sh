#!/usr/bin/env bash
# fuzz.sh -- run libFuzzer harnesses for a fixed time each (make fuzz,
# tests/test_fuzz.sh).
#
#   bash scripts/fuzz.sh SECONDS BINDIR NAME...
#   bash scripts/fuzz.sh --seeds NAME     the seed files of harness NAME
#
# The seeds of a harness are fuzz/regress/NAME/ (inputs that once failed),
# fuzz/corpus/NAME/ (inputs written for the harness) and the project's own
# files of that kind (programs/*.s, scenes/*.scene, models/*.fp3m), read
# where they are rather than copied.  Each harness BINDIR/fuzz_NAME starts
# from a working copy of its seeds, WORK/corpus/NAME (kept between runs so
# that a longer campaign resumes; WORK is $FUZZ_WORK, default BINDIR), and
# runs SECONDS.  One line per harness: "fuzz NAME: N executions in S s (E
# exec/s), corpus K inputs, 0 crashes", from libFuzzer's final statistics.
# A crash, leak, timeout or sanitizer report ends that harness: the script
# prints the reproducer's path (WORK/crashes/NAME/...) and the command
# that replays it, goes on with the other harnesses, and exits 1.
# libFuzzer's log of each run is WORK/logs/NAME.log.  The harnesses run
# one after another, or all at once with FUZZ_PARALLEL=1 (one process
# each: a campaign of N harnesses takes SECONDS, not N x SECONDS, of wall
# time; the lines are printed when all have ended).
set -u
here=$(cd "$(dirname "$0")/.." && pwd)

# The seed files of harness $1, one per line.
seeds() {
  local dirs=("$here/fuzz/regress/$1" "$here/fuzz/corpus/$1")
  case $1 in
    asm) dirs+=("$here/programs") ;;
    scene) dirs+=("$here/scenes") ;;
    model) dirs+=("$here/models") ;;
  esac
  local d
  for d in "${dirs[@]}"; do
    [ -d "$d" ] || continue
    case $1:$d in
      asm:*/programs) find "$d" -maxdepth 1 -type f -name '*.s' ;;
      scene:*/scenes) find "$d" -maxdepth 1 -type f -name '*.scene' ;;
      model:*/models) find "$d" -maxdepth 1 -type f -name '*.fp3m' ;;
      *) find "$d" -maxdepth 1 -type f ! -name '.*' ;;
    esac
  done | sort
}

if [ "${1:-}" = --seeds ] && [ $# -eq 2 ]; then
  seeds "$2"
  exit 0
fi
if [ $# -lt 3 ]; then
  echo "usage: fuzz.sh SECONDS BINDIR NAME... | fuzz.sh --seeds NAME" >&2
  exit 2
fi
secs=$1 bindir=$2
workdir=${FUZZ_WORK:-$bindir}
shift 2
# Fuzz harness $1: one summary line (and the report of a failure) on
# stdout; status 1 if it failed.
fuzz_one() {
  local name=$1
  local bin=$bindir/fuzz_$name work=$workdir/corpus/$name crashes=$workdir/crashes/$name
  local log=$workdir/logs/$name.log
  mkdir -p "$work" "$crashes" "$(dirname "$log")"
  if [ ! -x "$bin" ]; then
    echo "fuzz $name: no harness $bin (make fuzz-build)"
    return 1
  fi
  # each seed under its folder's name, so that two folders' files never clash
  local f d
  while IFS= read -r f; do
    d=${f%/*}
    cp -n "$f" "$work/${d##*/}-${f##*/}"
  done < <(seeds "$name")
  # -close_fd_mask=3: the parsers' own messages (stdout, stderr) are
  # silenced; libFuzzer and the sanitizers keep a copy of stderr for their
  # reports.  -timeout: an input that takes 10 s is a hang.
  "$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$crashes/" "$work" >"$log" 2>&1
  local rc=$?
  local execs rate units repro
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  units=$(find "$work" -maxdepth 1 -type f | wc -l)
  repro=$(sed -n "s/.*Test unit written to \(.*\)$/\1/p" "$log" | tail -1)
  if [ "$rc" -eq 0 ] && [ -z "$repro" ]; then
    echo "fuzz $name: ${execs:-?} executions in $secs s (${rate:-?} exec/s), corpus $units inputs, 0 crashes"
    return 0
  fi
  echo "fuzz $name: FAILED after ${execs:-?} executions (${rate:-?} exec/s), exit status $rc"
  grep -m3 -E '^==[0-9]+==ERROR|runtime error:|^SUMMARY:|ERROR: libFuzzer' "$log" | sed 's/^/  /'
  if [ -n "$repro" ]; then
    echo "  reproducer: $repro"
    echo "  replay: $bin $repro"
  fi
  echo "  log: $log"
  return 1
}

failed=0
if [ "${FUZZ_PARALLEL:-0}" = 1 ]; then
  # all harnesses at once, each its own process; the lines in the order given
  mkdir -p "$workdir/logs"
  pids=()
  for name in "$@"; do
    fuzz_one "$name" >"$workdir/logs/$name.summary" &
    pids+=($!)
  done
  i=0
  for name in "$@"; do
    wait "${pids[$i]}" || failed=1
    cat "$workdir/logs/$name.summary"
    i=$((i + 1))
  done
else
  for name in "$@"; do
    fuzz_one "$name" || failed=1
  done
fi
exit $failed
