# fp3_ice40.py -- clock constraint for nextpnr-ice40 (--pre-pack): the FP
# cores on an iCE40 HX8K (the processor does not fit any iCE40, see docs/fpga.md).
ctx.addClock("clk_i", 75)
