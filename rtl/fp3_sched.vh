// fp3_sched.vh -- what the scheduler's modules (fp3_scheduler and its
// fp3_sched_* parts) share: the formats of a queue entry's decoded bits
// and of an instruction's issue fields, and the one-hot helpers.
// `include inside a module body, after NC (= NUM_CONTEXTS), CW and IW are
// defined.  Each module uses a few of these, never all of them, so the
// unused-parameter lint is waived for this header only.
/* verilator lint_off UNUSEDPARAM */

// A word's decoded bits as stored beside it in the instruction memory
// (SCH_SW bits, decided as the host writes it: fp3_sched_fetch):
//   {sop[2:0], illegal, use_rb, use_ra, use_rd, unit[2:0], sub, li, endi, beq, halt}
// and as kept in its queue entry (SCH_DW bits: illegal inverted, ovf
// appended as the word joins its queue):
//   {sop[2:0], legal, use_rb, use_ra, use_rd, unit[2:0], sub, li, endi, beq, halt, ovf}
// (ovf: the word would run off the end of the memory; sop: the sign group
// on the move path, {abs/neg/min/max, fp_sign's op: 0 abs, 1 neg, 2 min,
// 3 max}; sub: on the add/sub core a sub, on the div/sqrt unit a sqrt).
// A zero word's stored bits are zero: the nop, legal.
localparam integer SCH_DW = 16;
localparam integer SCH_SW = SCH_DW - 1;

// An instruction's issue fields (SCH_FW bits), per queue slot and as
// picked (fp3_sched_queue -> fp3_sched_issue):
//   {sop[2:0], ra, rb, rd (IW bits each), unit[2:0], sub, li, immediate[31:0], endi, beq}
localparam integer SCH_FW = 3 + 3 * IW + 3 + 1 + 1 + 32 + 1 + 1;
// ... the immediate's bits in a field word
localparam [SCH_FW-1:0] SCH_IMM_BITS = {{(SCH_FW-34){1'b0}}, {32{1'b1}}, 2'b00};

/* verilator lint_on UNUSEDPARAM */

// Index of a one-hot x (the OR of the set bits' indices: 0 if none).
function [CW-1:0] sch_encode;
  input [NC-1:0] x;
  integer p;
  begin
    sch_encode = {CW{1'b0}};
    for (p = 0; p < NC; p = p + 1) if (x[p]) sch_encode = sch_encode | p[CW-1:0];
  end
endfunction

// One-hot of x over NC bits (none unless valid).
function [NC-1:0] sch_onehot;
  input          valid;
  input [CW-1:0] x;
  integer p;
  begin
    for (p = 0; p < NC; p = p + 1) sch_onehot[p] = valid && x == p[CW-1:0];
  end
endfunction
