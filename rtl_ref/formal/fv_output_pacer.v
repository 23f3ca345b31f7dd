// fv_output_pacer.v — formal harness of output_pacer (scripts/formal.sh; docs/FORMAL.md).
//
// The pacing and alarm properties are in rtl_ref/output_pacer.v under `ifdef FORMAL. This harness
// checks conservation: it sums the inputs (delta + add) since reset and asserts, at every call,
//     backlog + paced == sum of the inputs up to two calls earlier   (exact, 42-bit integers;
//                                                                      the taps are 2 calls late)
// under the assumption that the input sum stays within +-2^35 (the widths then cannot wrap;
// a real axis stays far inside: 2^35 counts). Reset in the first call, none later.
// The pacer's formal-only ports f_o_c0..2 (B + P of this and the two previous calls) and f_o_p
// (P) carry the induction: B + P equals the input sum at every call.
`timescale 1ns / 1ps
`default_nettype none

module fv_output_pacer (
    input wire               i_clk,
    input wire               i_rst,
    input wire signed [38:0] i_delta,
    input wire signed [17:0] i_add,
    input wire [15:0]        i_pace_m,
    input wire [31:0]        i_thr,
    input wire               i_clear,
    input wire               i_wide
);
    localparam integer W = 42;
    localparam signed [W-1:0] LIM = 42'sd34359738368;   // 2^35

    wire signed [1:0]  pstep;
    wire signed [37:0] paced;
    wire signed [39:0] backlog;
    wire ovs, ovs_st;
    wire signed [W-1:0] c0, c1, c2, pc;
    wire dut_init;

    output_pacer dut (
        .i_clk(i_clk), .i_rst(i_rst), .i_delta(i_delta), .i_add(i_add), .i_pace_m(i_pace_m), .i_thr(i_thr),
        .i_clear(i_clear), .i_wide(i_wide), .o_pstep(pstep), .o_pstep_nx(), .o_slot(), .o_slot_nx(), .o_paced(paced), .o_backlog(backlog), .o_ovs(ovs),
        .o_ovs_st(ovs_st), .f_o_c0(c0), .f_o_c1(c1), .f_o_c2(c2), .f_o_p(pc), .f_o_init(dut_init));

    reg f_started;
    reg signed [W-1:0] f_sum;                 // sum of the deltas since reset
    reg signed [W-1:0] f_sum1, f_sum2;        // ... up to one / two calls earlier
    initial f_started = 1'b0;

    wire signed [W-1:0] delta_x   = {{(W-39){i_delta[38]}}, i_delta} + {{(W-18){i_add[17]}}, i_add};
    wire signed [W-1:0] sum_next  = f_sum + delta_x;
    wire signed [W-1:0] backlog_x = {{(W-40){backlog[39]}}, backlog};
    wire signed [W-1:0] paced_x   = {{(W-38){paced[37]}}, paced};

    always @* begin
        if (!f_started) assume(i_rst);
        else assume(!i_rst);
        // the input sum stays within +-2^35 (bounds the widths; see the header)
        assume(sum_next <= LIM && sum_next >= -LIM);
        assume(delta_x <= LIM && delta_x >= -LIM);
    end

    always @(posedge i_clk) begin
        f_started <= 1'b1;
        if (i_rst) begin
            f_sum  <= {W{1'b0}};
            f_sum1 <= {W{1'b0}};
            f_sum2 <= {W{1'b0}};
        end else begin
            f_sum  <= sum_next;
            f_sum1 <= f_sum;
            f_sum2 <= f_sum1;
        end
    end

    always @* begin
        if (f_started) begin
            // conservation of the state: B + P is the input sum at every call
            assert(c0 == f_sum);
`ifdef FV_TAPS
            // the same for the taps (B + P two calls earlier): slow (minutes); the block's own
            // proof shows the taps equal B and P of two calls earlier, which with c0 gives it
            assert(c1 == f_sum1);
            assert(c2 == f_sum2);
            assert(backlog_x + paced_x == f_sum2);
`endif
            // helper invariants (induction): the input bound, the paced position never runs
            // past it by more than one count
            assert(dut_init);
            assert(f_sum <= LIM && f_sum >= -LIM);
            assert(f_sum1 <= LIM && f_sum1 >= -LIM);
            assert(f_sum2 <= LIM && f_sum2 >= -LIM);
            assert(pc <= LIM + 1 && pc >= -LIM - 1);
        end
    end
endmodule

`default_nettype wire
