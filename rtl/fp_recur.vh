// fp_recur.vh -- the register placement of the unrolled digit recurrences
// (fp_div, fp_sqrt): which of a core's places between datapath steps holds
// a pipeline register.  `include inside the module body after the
// parameter LATENCY and the localparams NBASE (base places, the output
// register's included) and NEXTRA (extra places) are defined.  Defines
// NPLACE = NBASE + NEXTRA, LC = min(LATENCY, NPLACE), DEPTH_O (the output
// register and the output delay stages of LATENCY > NPLACE, for
// fp_recur_out), regs_after and extra_reg; a LATENCY below 1 is an
// elaboration error.
//
// Base places: LB = min(LATENCY, NBASE).  With LB >= 2, one register
// right after the unpack (base place 0: the leading-zero count, the
// normalising shift and the special cases take about as long as several
// recurrence steps, so they get a stage of their own), and the other
// LB - 2 spread evenly over base places 1 .. NBASE - 2: place s holds one
// iff floor(s (LB - 1) / (NBASE - 1)) differs from
// floor((s - 1) (LB - 1) / (NBASE - 1)).  Their sum is LB - 1 (with the
// output register, LB).  LB = 1: no register but the output one.
//
// Extra places, k = 0 .. NEXTRA - 1, split the steps that are longer
// than a recurrence step (the unpack, the normalisation and rounding)
// once every base place holds its register: extra place k holds one iff
// LATENCY >= NBASE + 1 + k, so a LATENCY of NPLACE registers every place
// and each stage is at most one recurrence step long.

localparam integer NPLACE  = NBASE + NEXTRA;
localparam integer LC      = (LATENCY < NPLACE) ? LATENCY : NPLACE;
localparam integer LB      = (LATENCY < NBASE) ? LATENCY : NBASE;
localparam integer DEPTH_O = LATENCY - LC + 1;

generate
  if (LATENCY < 1) begin : g_bad_latency
    // Elaboration error on purpose: LATENCY must be at least 1.
    fp_recur_error_LATENCY_must_be_at_least_1 u_error ();
  end
endgenerate

// Registers after base step s (0 .. NBASE - 2).
function integer regs_after(input integer s);
  begin
    if (LB < 2)
      regs_after = 0;
    else if (s == 0)
      regs_after = 1;
    else
      regs_after = (s * (LB - 1)) / (NBASE - 1) - ((s - 1) * (LB - 1)) / (NBASE - 1);
  end
endfunction

// Registers at extra place k (0 .. NEXTRA - 1).
function integer extra_reg(input integer k);
  begin
    extra_reg = (LATENCY >= NBASE + 1 + k) ? 1 : 0;
  end
endfunction
