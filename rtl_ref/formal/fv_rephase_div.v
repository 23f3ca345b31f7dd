// fv_rephase_div.v — formal-only harness (docs/FORMAL.md, proof rephase_div), first half of the
// lemma that the reference step of fv_bresenham.v divides, for every legal P (8..4096, P % 8 ==
// 0), d in [0, P), r in [0, P), q in [0, P): the 13-bit Verilog step equals the step on integers
// (computed here 16 bits wide, where nothing can wrap), for a move up and a move down. The second
// half, fv_bresenham_int.smt2 (z3, integer arithmetic, every P), shows that the integer step
// keeps q * P + r = d * tr with 0 <= r < P and that this gives the facts F1..F4 proof rephase
// assumes. Combinational: no state.
`timescale 1ns / 1ps
`default_nettype none

module fv_rephase_div (
    input  wire [12:0] i_per,
    input  wire [12:0] i_d,
    input  wire [12:0] i_q,
    input  wire [12:0] i_r,
    input  wire        i_up,
    input  wire        i_dn
);
    wire [12:0]       q_n, r_n;
    wire signed [1:0] dq_n;
    fv_bresenham u_step (.i_per(i_per), .i_d(i_d), .i_q(i_q), .i_r(i_r), .i_up(i_up), .i_dn(i_dn),
                         .o_q(q_n), .o_r(r_n), .o_dq(dq_n));
    // the integer step, 16 bits wide
    wire [15:0] p = {3'd0, i_per}, d = {3'd0, i_d}, q = {3'd0, i_q}, r = {3'd0, i_r};
    wire [15:0] r_up = (r + d >= p) ? r + d - p : r + d;
    wire [15:0] q_up = (r + d >= p) ? q + 16'd1 : q;
    wire [15:0] r_dn = (r < d) ? r + p - d : r - d;
    wire [15:0] q_dn = (r < d) ? q - 16'd1 : q;
    always @* begin
        assume(i_per >= 13'd8 && i_per <= 13'd4096 && i_per[2:0] == 3'b000);
        assume(i_d < i_per && i_r < i_per && i_q < i_per);
        if (i_up) begin
            assert({3'd0, r_n} == r_up && {3'd0, q_n} == q_up);
        end else if (i_dn) begin
            assert({3'd0, r_n} == r_dn && (i_q == 13'd0 || {3'd0, q_n} == q_dn));
        end else begin
            assert(r_n == i_r && q_n == i_q);
        end
        assert($signed({{11{dq_n[1]}}, dq_n}) == $signed(q_n - i_q));
    end
endmodule

`default_nettype wire
