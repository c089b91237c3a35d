// fp_recur.vh -- the register placement of the unrolled digit recurrences
// (fp_div, fp_sqrt): which of a core's places between datapath steps holds
// a pipeline register.  `include inside the module body after the
// localparams LC (= min(LATENCY, NPLACE)) and NPLACE (places for a
// register, the output register's included) are defined.
//
// With LC >= 2, one register right after the unpack step (place 0: the
// leading-zero count, the normalising shift and the special cases take
// about as long as several recurrence steps, so they get a stage of their
// own), and the other LC - 2 spread evenly over places 1 .. NPLACE - 2:
// place s holds one iff floor(s (LC - 1) / (NPLACE - 1)) differs from
// floor((s - 1) (LC - 1) / (NPLACE - 1)).  Their sum is LC - 1 (with the
// output register, LC).  LC = 1: no register but the output one.

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
