// fp_recur.vh -- the register placement of the unrolled digit recurrences
// (fp_div, fp_sqrt): which of a core's places between datapath steps holds
// a pipeline register.  `include inside the module body after the
// parameter LATENCY and the localparam NPLACE (places for a register, the
// output register's included) are defined.  Defines LC = min(LATENCY,
// NPLACE), DEPTH_O (the output register and the output delay stages of
// LATENCY > NPLACE, for fp_recur_out) and regs_after; a LATENCY below 1
// is an elaboration error.
//
// With LC >= 2, one register right after the unpack step (place 0: the
// leading-zero count, the normalising shift and the special cases take
// about as long as several recurrence steps, so they get a stage of their
// own), and the other LC - 2 spread evenly over places 1 .. NPLACE - 2:
// place s holds one iff floor(s (LC - 1) / (NPLACE - 1)) differs from
// floor((s - 1) (LC - 1) / (NPLACE - 1)).  Their sum is LC - 1 (with the
// output register, LC).  LC = 1: no register but the output one.

localparam integer LC      = (LATENCY < NPLACE) ? LATENCY : NPLACE;
localparam integer DEPTH_O = LATENCY - LC + 1;

generate
  if (LATENCY < 1) begin : g_bad_latency
    // Elaboration error on purpose: LATENCY must be at least 1.
    fp_recur_error_LATENCY_must_be_at_least_1 u_error ();
  end
endgenerate

// Registers after step s (0 .. NPLACE - 2).
function integer regs_after(input integer s);
  begin
    if (LC < 2)
      regs_after = 0;
    else if (s == 0)
      regs_after = 1;
    else
      regs_after = (s * (LC - 1)) / (NPLACE - 1) - ((s - 1) * (LC - 1)) / (NPLACE - 1);
  end
endfunction
