// fv_pm_smul.v — formal harness of pulse_multiplier_smul, the re-base's serial multiplier
// (scripts/formal.sh proof pulse_multiplier_mul; docs/FORMAL.md).
//
// pulse_multiplier_smul is the same parameterised RTL that pulse_multiplier instantiates at
// WA = 32, WB = 38; this harness proves a narrow instance (WA, WB below) for every A and B. Its
// registers start in any state (no reset, no initial values), then the harness drives the
// schedule that proof pulse_multiplier_seq shows the parent drives (DESIGN §4.3, cnt = calls
// since the start): call 0 the start (i_clr), call C_DR0 = 1 i_load with A free, call
// C_MUL0 - 1 = 3 i_pre with B free and held from then on, calls C_MUL0 .. C_MUL0 + WA - 1 the WA
// steps with i_sign_nx in the second-last; from call C_MUL0 + WA on, o_p == A * B (signed, WA + WB
// bits), checked up to the end of the bounded run. The run starts from any state and the
// schedule overwrites every register of the multiplier before it is read, so the bounded check
// of this fixed-length computation covers every input at this width.
`timescale 1ns / 1ps
`default_nettype none

module fv_pm_smul #(
    parameter integer WA = 6,
    parameter integer WB = 7
) (
    input wire                 i_clk,
    input wire [WA-1:0]        i_a,
    input wire signed [WB-1:0] i_b
);
    localparam integer C_DR0 = 1, C_MUL0 = 4;
    localparam integer C_END = C_MUL0 + WA;   // first call after the last step

    reg [7:0] f_c;                             // call index
    initial f_c = 8'd0;
    reg signed [WA-1:0] f_a;
    reg signed [WB-1:0] f_b;

    wire [WA+WB-1:0] p;
    pulse_multiplier_smul #(.WA(WA), .WB(WB)) dut (
        .i_clk(i_clk), .i_rst(1'b0), .i_clr(f_c == 8'd0), .i_load(f_c == C_DR0), .i_a(i_a),
        .i_pre(f_c == C_MUL0 - 1), .i_step(f_c >= C_MUL0 && f_c < C_END),
        .i_sign_nx(f_c == C_END - 2), .i_b(i_b), .o_p(p));

    wire signed [WA+WB-1:0] f_prod = $signed(f_a) * $signed(f_b);

    always @* begin
        if (f_c > C_MUL0 - 1) assume(i_b == f_b);      // B held from the i_pre call on
        if (f_c >= C_END) assert(p == f_prod);
    end

    always @(posedge i_clk) begin
        if (f_c != 8'hff) f_c <= f_c + 8'd1;
        if (f_c == C_DR0) f_a <= i_a;
        if (f_c == C_MUL0 - 1) f_b <= i_b;
    end
endmodule

`default_nettype wire
