// fv_bresenham.v — formal-only (docs/FORMAL.md, proofs rephase and rephase_div): one step of the
// reference division state of DESIGN 4.5, (q, r) = divmod(d * tr, P), when the window travel tr
// moves by one count: tr + 1 adds d to r (a carry when r + d >= P: r - P, q + 1), tr - 1 takes d
// from r (a borrow when r < d: r + P, q - 1). No multiply: proof rephase_div shows, from (0, 0)
// at tr = 0, that (q, r) = divmod(d * tr, P) for every tr in [0, P]; proof rephase uses the same
// step as the reference of the RTL's Bresenham state. Inputs: r < P, d < P.
`timescale 1ns / 1ps
`default_nettype none

module fv_bresenham (
    input  wire [12:0]       i_per,   // P
    input  wire [12:0]       i_d,     // d in [0, P)
    input  wire [12:0]       i_q,
    input  wire [12:0]       i_r,     // r in [0, P)
    input  wire              i_up,    // tr + 1
    input  wire              i_dn,    // tr - 1 (when not i_up)
    output wire [12:0]       o_q,
    output wire [12:0]       o_r,
    output wire signed [1:0] o_dq     // q' - q
);
    wire [13:0] rup = {1'b0, i_r} + {1'b0, i_d};
    wire        cy  = rup >= {1'b0, i_per};
    wire        bw  = i_r < i_d;
    assign o_r  = i_up ? (cy ? rup[12:0] - i_per : rup[12:0]) :
                  i_dn ? (bw ? i_r + i_per - i_d : i_r - i_d) : i_r;
    assign o_dq = (i_up && cy) ? 2'sd1 : (!i_up && i_dn && bw) ? -2'sd1 : 2'sd0;
    assign o_q  = i_q + {{11{o_dq[1]}}, o_dq};
endmodule

`default_nettype wire
