// fv_quad_decoder.v — formal harness of quad_decoder (scripts/formal.sh; docs/FORMAL.md).
//
// The properties of the decoder itself are in rtl_ref/quad_decoder.v under `ifdef FORMAL.
// This harness adds an end-to-end check from the pins: reset in the first call, then legal pins
// only (filter length N = 2 as a constant, laser error line low, at most one of A/B changing per
// call, each level held at least N calls, no change in the 4 calls after reset while the filters
// prime). A tiny reference counter counts the quadrature sequence on the pins; the decoder's raw
// count must equal it delayed by the pipeline latency (N + 1 filter calls + the output register).
`timescale 1ns / 1ps
`default_nettype none

module fv_quad_decoder (
    input wire i_clk,
    input wire i_rst,
    input wire i_a,
    input wire i_b,
    input wire i_clear,
    input wire [15:0] i_min_spacing
);
    localparam integer N   = 2;        // glitch filter length used by this harness
    // pin -> raw count: N + 1 calls (f_ref_d3)

    wire signed [1:0]  step;
    wire signed [31:0] raw;
    wire illegal, ovs, illegal_st, ovs_st, lerr, lerr_alarm, glitch_st;
    wire [7:0] err_cnt;

    quad_decoder dut (
        .i_clk(i_clk), .i_rst(i_rst), .i_a(i_a), .i_b(i_b), .i_lerr(1'b0),
        .i_glitch_n(N[7:0]), .i_min_spacing(i_min_spacing), .i_clear(i_clear),
        .o_step(step), .o_raw_count(raw), .o_illegal(illegal), .o_ovs(ovs), .o_err_cnt(err_cnt),
        .o_illegal_st(illegal_st), .o_ovs_st(ovs_st), .o_lerr(lerr), .o_lerr_alarm(lerr_alarm),
        .o_glitch_st(glitch_st));

    reg        f_started;
    reg [3:0]  f_age;               // calls since reset, saturating
    reg        f_pa, f_pb;          // pin levels of the previous call
    reg [3:0]  f_hold_a, f_hold_b;  // calls each pin has held its level, saturating
    reg signed [31:0] f_ref;        // quadrature count of the pins
    reg signed [31:0] f_ref_d1, f_ref_d2, f_ref_d3;   // f_ref delayed by 1..LAT calls
    initial f_started = 1'b0;

    // quadrature index of the pins: 00 -> 0, 10 -> 1, 11 -> 2, 01 -> 3 (A leads B: forward)
    wire [1:0] idx_now  = {i_b, i_a ^ i_b};
    wire [1:0] idx_prev = {f_pb, f_pa ^ f_pb};
    wire [1:0] move     = idx_now - idx_prev;

    always @* begin
        if (!f_started) assume(i_rst);
        else assume(!i_rst);
        if (f_started && f_age < 4'd4) assume(i_a == f_pa && i_b == f_pb);
        if (f_started) begin
            assume(!(i_a != f_pa && i_b != f_pb));          // one line at a time
            if (i_a != f_pa) assume(f_hold_a >= N);
            if (i_b != f_pb) assume(f_hold_b >= N);
        end
    end

    always @(posedge i_clk) begin
        f_started <= 1'b1;
        f_pa <= i_a;
        f_pb <= i_b;
        f_hold_a <= (i_a != f_pa || !f_started) ? 4'd1 : (f_hold_a == 4'hf ? 4'hf : f_hold_a + 4'd1);
        f_hold_b <= (i_b != f_pb || !f_started) ? 4'd1 : (f_hold_b == 4'hf ? 4'hf : f_hold_b + 4'd1);
        if (i_rst) begin
            f_age <= 4'd0;
            f_ref <= 32'sd0;
            f_ref_d1 <= 32'sd0; f_ref_d2 <= 32'sd0; f_ref_d3 <= 32'sd0;
        end else begin
            f_age <= (f_age == 4'hf) ? 4'hf : f_age + 4'd1;
            if (f_age >= 4'd4 && move == 2'd1) f_ref <= f_ref + 32'sd1;
            if (f_age >= 4'd4 && move == 2'd3) f_ref <= f_ref - 32'sd1;
            f_ref_d1 <= f_ref;
            f_ref_d2 <= f_ref_d1;
            f_ref_d3 <= f_ref_d2;
        end
    end

    always @* begin
        if (f_started && !i_rst && f_age >= 4'd1) begin
            assert(raw == f_ref_d3);           // every pin count arrives, none extra
            assert(!illegal && !illegal_st && err_cnt == 8'd0 && !lerr && !glitch_st);
        end
    end
endmodule

`default_nettype wire
