// ecp5_mult18x18d.v -- a simulation model of the part of Lattice's ECP5
// MULT18X18D (18 x 18-bit sysDSP multiplier) that fp_dsp_mul's ECP5 form
// uses (rtl/fp_dsp_mul.v, FP3_ECP5_DSP), for the post-synthesis check of
// that form (tests/test_dsp_mul.sh).  Written from the ECP5 sysDSP usage
// guide (Lattice TN1267): Yosys's own model of the block is a blackbox.
//
// Modelled: P = A * B (36 bits; A and B two's complement when SIGNEDA,
// SIGNEDB are high, else unsigned), operands from the A and B ports
// (SOURCEA = SOURCEB = 0); each of the input registers (REG_INPUTA_CLK,
// REG_INPUTB_CLK), the pipeline register (REG_PIPELINE_CLK, after the
// multiplier) and the output register (REG_OUTPUT_CLK) either "NONE"
// (bypassed) or "CLK0" (clocked by CLK0, enabled by CE0, cleared by RST0
// synchronously: every *_CE = "CE0", *_RST = "RST0", RESETMODE "SYNC").
// Registers start at zero.  SIGNEDP, the cascade outputs (SROA, SROB)
// and the registered operand outputs (ROA, ROB, ROC) are driven 0.
// Any other configuration stops the simulation with an error.
`default_nettype none
module MULT18X18D #(
  parameter REG_INPUTA_CLK   = "NONE",
  parameter REG_INPUTA_CE    = "CE0",
  parameter REG_INPUTA_RST   = "RST0",
  parameter REG_INPUTB_CLK   = "NONE",
  parameter REG_INPUTB_CE    = "CE0",
  parameter REG_INPUTB_RST   = "RST0",
  parameter REG_INPUTC_CLK   = "NONE",
  parameter REG_INPUTC_CE    = "CE0",
  parameter REG_INPUTC_RST   = "RST0",
  parameter REG_PIPELINE_CLK = "NONE",
  parameter REG_PIPELINE_CE  = "CE0",
  parameter REG_PIPELINE_RST = "RST0",
  parameter REG_OUTPUT_CLK   = "NONE",
  parameter REG_OUTPUT_CE    = "CE0",
  parameter REG_OUTPUT_RST   = "RST0",
  parameter CLK0_DIV         = "ENABLED",
  parameter CLK1_DIV         = "ENABLED",
  parameter CLK2_DIV         = "ENABLED",
  parameter CLK3_DIV         = "ENABLED",
  parameter HIGHSPEED_CLK    = "NONE",
  parameter GSR              = "ENABLED",
  parameter CAS_MATCH_REG    = "FALSE",
  parameter SOURCEB_MODE     = "B_SHIFT",
  parameter MULT_BYPASS      = "DISABLED",
  parameter RESETMODE        = "SYNC"
) (
  input  wire A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0,
  input  wire B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0,
  input  wire C17, C16, C15, C14, C13, C12, C11, C10, C9, C8, C7, C6, C5, C4, C3, C2, C1, C0,
  input  wire SIGNEDA, SIGNEDB, SOURCEA, SOURCEB,
  input  wire CLK0, CLK1, CLK2, CLK3,
  input  wire CE0, CE1, CE2, CE3,
  input  wire RST0, RST1, RST2, RST3,
  input  wire SRIA17, SRIA16, SRIA15, SRIA14, SRIA13, SRIA12, SRIA11, SRIA10, SRIA9,
  input  wire SRIA8, SRIA7, SRIA6, SRIA5, SRIA4, SRIA3, SRIA2, SRIA1, SRIA0,
  input  wire SRIB17, SRIB16, SRIB15, SRIB14, SRIB13, SRIB12, SRIB11, SRIB10, SRIB9,
  input  wire SRIB8, SRIB7, SRIB6, SRIB5, SRIB4, SRIB3, SRIB2, SRIB1, SRIB0,
  output wire SROA17, SROA16, SROA15, SROA14, SROA13, SROA12, SROA11, SROA10, SROA9,
  output wire SROA8, SROA7, SROA6, SROA5, SROA4, SROA3, SROA2, SROA1, SROA0,
  output wire SROB17, SROB16, SROB15, SROB14, SROB13, SROB12, SROB11, SROB10, SROB9,
  output wire SROB8, SROB7, SROB6, SROB5, SROB4, SROB3, SROB2, SROB1, SROB0,
  output wire ROA17, ROA16, ROA15, ROA14, ROA13, ROA12, ROA11, ROA10, ROA9,
  output wire ROA8, ROA7, ROA6, ROA5, ROA4, ROA3, ROA2, ROA1, ROA0,
  output wire ROB17, ROB16, ROB15, ROB14, ROB13, ROB12, ROB11, ROB10, ROB9,
  output wire ROB8, ROB7, ROB6, ROB5, ROB4, ROB3, ROB2, ROB1, ROB0,
  output wire ROC17, ROC16, ROC15, ROC14, ROC13, ROC12, ROC11, ROC10, ROC9,
  output wire ROC8, ROC7, ROC6, ROC5, ROC4, ROC3, ROC2, ROC1, ROC0,
  output wire P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24,
  output wire P23, P22, P21, P20, P19, P18, P17, P16, P15, P14, P13, P12,
  output wire P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0,
  output wire SIGNEDP
);
  // One register's clock setting: 0 "NONE", 1 "CLK0", 2 anything else.
  function integer clk_sel(input [8*4-1:0] s);
    begin
      if (s == "NONE")      clk_sel = 0;
      else if (s == "CLK0") clk_sel = 1;
      else                  clk_sel = 2;
    end
  endfunction
  localparam integer RA = clk_sel(REG_INPUTA_CLK);
  localparam integer RB = clk_sel(REG_INPUTB_CLK);
  localparam integer RP = clk_sel(REG_PIPELINE_CLK);
  localparam integer RO = clk_sel(REG_OUTPUT_CLK);
  initial begin
    if (RA == 2 || RB == 2 || RP == 2 || RO == 2 ||
        REG_INPUTA_CE != "CE0" || REG_INPUTB_CE != "CE0" ||
        REG_PIPELINE_CE != "CE0" || REG_OUTPUT_CE != "CE0" ||
        REG_INPUTA_RST != "RST0" || REG_INPUTB_RST != "RST0" ||
        REG_PIPELINE_RST != "RST0" || REG_OUTPUT_RST != "RST0" ||
        RESETMODE != "SYNC" || MULT_BYPASS != "DISABLED") begin
      $display("MULT18X18D model: configuration not modelled (REG_INPUTA_CLK %0s, REG_OUTPUT_CLK %0s)",
               REG_INPUTA_CLK, REG_OUTPUT_CLK);
      $finish;
    end
  end

  wire [17:0] a = {A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0};
  wire [17:0] b = {B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0};
  always @(*) begin
    if (SOURCEA !== 1'b0 || SOURCEB !== 1'b0) begin
      $display("MULT18X18D model: SOURCEA/SOURCEB (shift-chain operands) not modelled");
      $finish;
    end
  end

  // The operands (sign kept with them, as the block registers them).
  reg  [18:0] a_q = 19'd0, b_q = 19'd0;
  always @(posedge CLK0)
    if (RST0) begin
      a_q <= 19'd0;
      b_q <= 19'd0;
    end else if (CE0) begin
      a_q <= {SIGNEDA, a};
      b_q <= {SIGNEDB, b};
    end
  wire [18:0] a_m = RA ? a_q : {SIGNEDA, a};
  wire [18:0] b_m = RB ? b_q : {SIGNEDB, b};
  // Extended to 36 bits, each by its own sign rule, then multiplied: the
  // low 36 bits of the product of the extensions are the product.
  wire [35:0] a_x = {{18{a_m[18] & a_m[17]}}, a_m[17:0]};
  wire [35:0] b_x = {{18{b_m[18] & b_m[17]}}, b_m[17:0]};
  wire [35:0] prod = a_x * b_x;

  reg  [35:0] pipe_q = 36'd0, out_q = 36'd0;
  wire [35:0] pipe_m = RP ? pipe_q : prod;
  always @(posedge CLK0)
    if (RST0) begin
      pipe_q <= 36'd0;
      out_q  <= 36'd0;
    end else if (CE0) begin
      pipe_q <= prod;
      out_q  <= pipe_m;
    end
  wire [35:0] p = RO ? out_q : pipe_m;

  assign {P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24,
          P23, P22, P21, P20, P19, P18, P17, P16, P15, P14, P13, P12,
          P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0} = p;
  assign {SROA17, SROA16, SROA15, SROA14, SROA13, SROA12, SROA11, SROA10, SROA9,
          SROA8, SROA7, SROA6, SROA5, SROA4, SROA3, SROA2, SROA1, SROA0} = 18'd0;
  assign {SROB17, SROB16, SROB15, SROB14, SROB13, SROB12, SROB11, SROB10, SROB9,
          SROB8, SROB7, SROB6, SROB5, SROB4, SROB3, SROB2, SROB1, SROB0} = 18'd0;
  assign {ROA17, ROA16, ROA15, ROA14, ROA13, ROA12, ROA11, ROA10, ROA9,
          ROA8, ROA7, ROA6, ROA5, ROA4, ROA3, ROA2, ROA1, ROA0} = 18'd0;
  assign {ROB17, ROB16, ROB15, ROB14, ROB13, ROB12, ROB11, ROB10, ROB9,
          ROB8, ROB7, ROB6, ROB5, ROB4, ROB3, ROB2, ROB1, ROB0} = 18'd0;
  assign {ROC17, ROC16, ROC15, ROC14, ROC13, ROC12, ROC11, ROC10, ROC9,
          ROC8, ROC7, ROC6, ROC5, ROC4, ROC3, ROC2, ROC1, ROC0} = 18'd0;
  assign SIGNEDP = 1'b0;
  wire unused = &{1'b0, C17, C16, C15, C14, C13, C12, C11, C10, C9, C8, C7, C6, C5, C4, C3,
                  C2, C1, C0, CLK1, CLK2, CLK3, CE1, CE2, CE3, RST1, RST2, RST3};
endmodule
`default_nettype wire
