// pulse_multiplier.v — raw laser counts to compensated output counts.
//
// Reference RTL of hls/pulse_multiplier.h (DESIGN §4.3). One rising clock edge = one call of
// pulse_multiplier::step(); o_comp / o_delta are registers holding the out_t of that call.
// Synchronous active-high reset = pulse_multiplier::reset() (all zero).
//
// After every call comp = floor((N * R + OFF) / 2^32) for the register values N, R after the call
// and the comp_offset input OFF (Q32.32 output counts, signed). The accumulator holds N*R exactly
// and is updated with one multiply and one add per call:
//     acc' = acc + N * (R' - R) + step * R'  [- sign(step) * (R' << 32) when N wraps]  (= N' * R')
// and the offset is added after it (comp' = (acc' + OFF) >> 32; one adder, no state).
// Widths: N 32 signed, R 37 unsigned (Q5.32), R'-R 38 signed, acc 70 signed, OFF 64 signed,
// comp 38 signed, delta 39 signed. Latency: 1 call.
// (The preset port of the C++ model is a testbench aid and is not part of this RTL.)
`timescale 1ns / 1ps
`default_nettype none

module pulse_multiplier (
    input  wire               i_clk,
    input  wire               i_rst,    // synchronous, active high: pulse_multiplier::reset()
    input  wire signed [1:0]  i_step,   // raw count step from the decoder: -1, 0, +1
    input  wire [36:0]        i_ratio,  // ratio register R' (Q5.32, unsigned)
    input  wire signed [63:0] i_comp_offset,  // offset register OFF (Q32.32 output counts)
    output wire signed [37:0] o_comp,   // floor((N' * R' + OFF) / 2^32)
    output wire signed [38:0] o_delta   // comp' - comp
);

    // ---- fixed widths (hls: pulse_multiplier_cfg, axis_widths) -------------------------------
    localparam integer W_RAW    = 32;                    // raw count N, signed, wraps
    localparam integer R_FRAC   = 32;                    // ratio fraction bits
    localparam integer W_RATIO  = 37;                    // R_INT + R_FRAC, unsigned
    localparam integer W_DRATIO = W_RATIO + 1;           // R' - R, signed
    localparam integer W_ACC    = W_RAW + W_RATIO + 1;   // 70, exact N*R, signed (and N*R + OFF)
    localparam integer W_OFFSET = 64;                    // comp offset, Q32.32, signed
    localparam integer W_POS    = W_ACC - R_FRAC;        // 38
    localparam integer W_DELTA  = W_POS + 1;             // 39

    // ---- registers ---------------------------------------------------------------------------
    reg signed [W_RAW-1:0]   n_q;
    reg        [W_RATIO-1:0] r_q;
    reg signed [W_ACC-1:0]   acc_q;
    reg signed [W_POS-1:0]   comp_q;
    reg signed [W_DELTA-1:0] delta_q;

    // ---- next state --------------------------------------------------------------------------
    wire signed [W_RAW:0]    n_sum  = {n_q[W_RAW-1], n_q} + {{(W_RAW-1){i_step[1]}}, i_step};
    wire signed [W_RAW-1:0]  n_next = n_sum[W_RAW-1:0];          // wraps at W_RAW bits
    wire                     n_wrap = n_sum[W_RAW] != n_sum[W_RAW-1];
    wire signed [W_DRATIO-1:0] dr   = $signed({1'b0, i_ratio}) - $signed({1'b0, r_q});
    // the one multiplier: re-base the accumulator to the new ratio (exact in W_ACC bits)
    wire signed [W_ACC-1:0]  prod   = n_q * dr;
    wire signed [W_ACC-1:0]  ratio_x = $signed({{(W_ACC-W_RATIO){1'b0}}, i_ratio});
    // R' << W_RAW in W_ACC bits (the wrap term is a shift, not a multiply)
    wire signed [W_ACC-1:0]  wrap_term = $signed({1'b0, i_ratio, {W_RAW{1'b0}}});

    wire                     step_pos = !i_step[1] && i_step[0];   // step > 0
    wire                     step_neg = i_step[1];                 // step < 0

    reg signed [W_ACC-1:0]   acc_d;
    always @* begin
        acc_d = acc_q + prod;
        if (step_pos) acc_d = acc_d + ratio_x;
        if (step_neg) acc_d = acc_d - ratio_x;
        // raw counter wrapped: N' = N + step -/+ 2^W_RAW, so subtract/add R' << W_RAW
        if (n_wrap) acc_d = step_pos ? acc_d - wrap_term : acc_d + wrap_term;
    end

    // N*R + OFF: |N*R| < 2^68, |OFF| <= 2^63, fits W_ACC
    wire signed [W_ACC-1:0]   sum_d   = acc_d + {{(W_ACC-W_OFFSET){i_comp_offset[W_OFFSET-1]}}, i_comp_offset};
    wire signed [W_POS-1:0]   comp_d  = sum_d[W_ACC-1:R_FRAC];   // floor: arithmetic shift
    wire signed [W_DELTA-1:0] delta_d = {comp_d[W_POS-1], comp_d} - {comp_q[W_POS-1], comp_q};

    always @(posedge i_clk) begin
        if (i_rst) begin
            n_q     <= {W_RAW{1'b0}};
            r_q     <= {W_RATIO{1'b0}};
            acc_q   <= {W_ACC{1'b0}};
            comp_q  <= {W_POS{1'b0}};
            delta_q <= {W_DELTA{1'b0}};
        end else begin
            n_q     <= n_next;
            r_q     <= i_ratio;
            acc_q   <= acc_d;
            comp_q  <= comp_d;
            delta_q <= delta_d;
        end
    end

    assign o_comp  = comp_q;
    assign o_delta = delta_q;

endmodule

`default_nettype wire
