# fp3_xc7.xdc -- clock constraint of fp3_top / fp3_axil for Vivado on
# 7-series: 150 MHz, the ECP5 target.  Inputs and outputs of the core are
# internal to a system (AXI interconnect on the same clock), so no I/O
# delays are given.
create_clock -name clk -period 6.667 [get_ports clk_i]
