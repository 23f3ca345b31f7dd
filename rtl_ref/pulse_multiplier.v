// pulse_multiplier.v — raw laser counts to compensated output counts, by addition.
//
// Reference RTL of hls/pulse_multiplier.h (DESIGN §4.3, "Hardware form"). One rising clock edge =
// one call of pulse_multiplier::step(); o_comp / o_delta are registers holding the out_t of that
// call. Synchronous active-high reset = pulse_multiplier::reset() (all zero).
//
// V = N * R + OFF (Q.32 output counts) is kept as acc + T (mod 2^70):
//   stage 1  lo += +-R[31:0] (32-bit adder, carry registered), inc = +-R[36:32] (or the wrap
//            term), N += step;                       -- the only loop-carried adder besides hi
//   stage 2  hi += inc + c (38 bits), c2 = carry(lo + T[31:0])
//   stage 3  ci = hi + T_hi_d + c2   (= floor(V / 2^32) of the step three calls back)
//   stage 4  comp = ci, delta = ci - comp
// A ratio / offset change is seen by a registered 101-bit compare (pend); the next idle call
// starts a re-base: the target pair is loaded (steps from then on count at the new ratio) and the
// old one kept; from registers, in the calls after: N0 = N (call 1), dR = R' - R in two halves
// (calls 1, 2), S = T + OFF' (kept inverted) and X = ~(~S + OFF_old) = T + OFF' - OFF_old in
// 18-bit quarters (calls 1..4, 2..5), a
// serial shift-and-add multiplier P = N0 * dR (calls 4..35: 39-bit adder, addend registered a
// call ahead), T_new = X + P in quarters (calls 36..39), and T = T_new K_REBASE = 40 calls after
// the start.
// No multiplier and no adder wider than 39 bits anywhere. Latency: comp/delta of call t are
// those of the step of call t - 3.
// (The preset port of the C++ model is a testbench aid and is not part of this RTL.)
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module pulse_multiplier (
    input  wire                           i_clk,
    input  wire                           i_rst,         // synchronous, active high: pulse_multiplier::reset()
    input  wire signed [`LX_W_STEP-1:0]   i_step,        // raw count step from the decoder: -1, 0, +1
    input  wire [`LX_W_RATIO-1:0]         i_ratio,       // ratio in force R (Q5.32, unsigned)
    input  wire signed [`LX_W_OFFSET-1:0] i_comp_offset, // offset in force OFF (Q32.32 output counts)
    output wire signed [`LX_W_POS-1:0]    o_comp,        // floor(V / 2^32) of the step of three calls back
    output wire signed [`LX_W_DELTA-1:0]  o_delta        // comp' - comp
);

    // ---- widths (hls: pulse_multiplier_cfg) ---------------------------------------------------
    localparam integer W_RAW    = `LX_W_RAW;
    localparam integer R_FRAC   = `LX_R_FRAC;
    localparam integer W_RATIO  = `LX_W_RATIO;
    localparam integer R_INT    = W_RATIO - R_FRAC;      // 5
    localparam integer W_ACC    = `LX_W_ACC;
    localparam integer W_OFFSET = `LX_W_OFFSET;
    localparam integer W_HI     = W_ACC - R_FRAC;        // 38 (= W_POS)
    localparam integer W_DRATIO = W_RATIO + 1;           // 38
    localparam integer W_PP     = W_DRATIO + 1;          // 39
    localparam integer W_TQ     = 18;                    // quarters of the T additions
    localparam integer W_INC    = W_HI + 1;              // 39
    localparam integer K_REBASE = 40;
    localparam integer C_DR0    = 1, C_DR1 = 2;          // the two dR halves (N0 taken in C_DR0)
    localparam integer C_S0     = 1;                     // 1..4: S = T + OFF', by quarters
    localparam integer C_MUL0   = 4, MUL_STEPS = W_RAW;  // call 3 registers the first addend
    localparam integer C_ADD0   = C_MUL0 + MUL_STEPS;    // 36..39: T_new = X + P
    localparam integer C_X0     = C_S0 + 1;              // 2..5: X = ~(~S + OFF_old), a quarter behind
    localparam integer W_CNT    = 6;

    // ---- registers ----------------------------------------------------------------------------
    // stage 1
    reg signed [W_RAW-1:0]    n_q;
    reg                       nmax_q, nmin_q;  // n == 2^31 - 1, n == -2^31 (the wrap ends of N)
    reg        [W_RATIO-1:0]  r_use_q;     // target ratio (used by the steps)
    reg signed [W_OFFSET-1:0] off_tgt_q;   // target offset
    reg        [R_FRAC-1:0]   lo_q;
    reg                       c_q;
    reg signed [W_INC-1:0]    inc_q;
    reg signed [W_INC-1:0]    wrap_pos_q;  // R_int - R of the target ratio (~R_int + R is its inversion)
    // stages 2..4
    reg signed [W_HI-1:0]     hi_q;
    reg                       c2_q;
    reg signed [W_HI-1:0]     ci_q;
    reg signed [W_HI-1:0]     comp_q;
    reg signed [W_HI:0]       delta_q;
    // base T and the delayed high half
    reg        [R_FRAC-1:0]   t_lo_q;
    reg signed [W_HI-1:0]     t_hi_q, t_hi_d_q;
    // re-base sequencer
    reg                       busy_q, pend_q;
    reg        [W_CNT-1:0]    cnt_q;
    reg                       f_dr0_q, f_dr1_q, f_pre0_q, f_mul_q, f_mul_pre_q;  // cnt decoded
    reg        [3:0]          f_x_q, f_y_q;   // quarter of X = T + OFF' - OFF_old / of T_new = X + P
    reg                       f_last_q;
    reg signed [W_DRATIO-1:0] dr_q;
    reg        [W_RATIO-1:0]  r_old_q;     // the target ratio before the start
    reg                       drc_q;       // carry of the low dR half
    reg signed [W_OFFSET-1:0] off_old_q;
    reg        [W_ACC-1:0]    ns_q;        // ~S, S = T + OFF' (OFF' sign-extended)
    reg        [2:0]          sc_q;        // carry out of each quarter of S
    reg        [3:0]          f_s_q;       // quarter of S
    reg        [W_ACC-1:0]    x_q, y_q;
    reg        [2:0]          xc_q, yc_q;  // carry out of each quarter, its own flip-flop

    // 39-bit sum a + b + cin as carry-select (two 20/19-bit chains in parallel and a mux): used
    // where a 39-bit result feeds more logic in the same call
    function [38:0] add39_cs;
        input [38:0] a, b;
        input        cin;
        reg   [20:0] lo;
        reg   [18:0] h0, h1;
        begin
            lo = {1'b0, a[19:0]} + {1'b0, b[19:0]} + {20'd0, cin};
            h0 = a[38:20] + b[38:20];
            h1 = a[38:20] + b[38:20] + 19'd1;
            add39_cs = {lo[20] ? h1 : h0, lo[19:0]};
        end
    endfunction

    // ---- stage 1: the step at the target ratio before this call ----------------------------------
    wire step_pos = !i_step[1] && i_step[0];
    wire step_neg = i_step[1];
    // N + step (wraps): one 32-bit chain from the register
    wire signed [W_RAW-1:0] n_next = n_q + {{(W_RAW-2){i_step[1]}}, i_step};
    // N wraps when it steps past an end: the end flags are registers (nmax, nmin), so the wrap is
    // one LUT from the step. Their next values are equalities of n_q with the constants that the
    // step of this call takes to an end (n + step, the step -2 included), selected by the step.
    localparam signed [W_RAW-1:0] N_MAX = {1'b0, {(W_RAW-1){1'b1}}};
    localparam signed [W_RAW-1:0] N_MIN = {1'b1, {(W_RAW-1){1'b0}}};
    wire                    n_wrap = (step_pos && nmax_q) || (step_neg && nmin_q);
    wire                    e_maxm1 = n_q == N_MAX - 1, e_max = n_q == N_MAX, e_min = n_q == N_MIN;
    wire                    e_minp1 = n_q == N_MIN + 1, e_minp2 = n_q == N_MIN + 2;
    wire                    nmax_d = step_pos ? e_maxm1 : !step_neg ? e_max : i_step[0] ? e_min : e_minp1;
    wire                    nmin_d = step_pos ? e_max : !step_neg ? e_min : i_step[0] ? e_minp1 : e_minp2;
    wire [R_FRAC-1:0] r_frac = r_use_q[R_FRAC-1:0];
    wire [R_FRAC-1:0] lo_add = step_pos ? r_frac : step_neg ? ~r_frac : {R_FRAC{1'b0}};
    // 32-bit fraction adder as carry-select: the low half, and the high half for both carries
    wire [16:0]       lo_sum_l  = {1'b0, lo_q[15:0]} + {1'b0, lo_add[15:0]} + {16'd0, step_neg};
    wire [16:0]       lo_sum_h0 = {1'b0, lo_q[31:16]} + {1'b0, lo_add[31:16]};
    wire [16:0]       lo_sum_h1 = {1'b0, lo_q[31:16]} + {1'b0, lo_add[31:16]} + 17'd1;
    wire [R_FRAC:0]   lo_sum = {lo_sum_l[16] ? lo_sum_h1 : lo_sum_h0, lo_sum_l[15:0]};
    // increment of the integer part: R_int, -R_int - 1 = ~R_int, and with a wrap of N the two
    // values precomputed when the ratio was loaded (R_int - R, ~R_int + R): a mux, no adder
    wire signed [W_INC-1:0] r_int_x = $signed({{(W_INC-R_INT){1'b0}}, r_use_q[W_RATIO-1:R_FRAC]});
    wire signed [W_INC-1:0] inc_d = step_pos ? (n_wrap ? wrap_pos_q : r_int_x) :
                                    step_neg ? (n_wrap ? ~wrap_pos_q : ~r_int_x) : {W_INC{1'b0}};
    wire signed [W_INC-1:0] in_int_x = $signed({{(W_INC-R_INT){1'b0}}, i_ratio[W_RATIO-1:R_FRAC]});
    wire signed [W_INC-1:0] in_all_x = $signed({{(W_INC-W_RATIO){1'b0}}, i_ratio});

    // ---- stages 2..4 ----------------------------------------------------------------------------
    // (every adder below is split: carry-select halves of at most 20 bits)
    wire [38:0]            hi_sum = add39_cs({inc_q[W_HI-1], inc_q[W_HI-1:0]}, {hi_q[W_HI-1], hi_q}, c_q);
    wire signed [W_HI-1:0] hi_d = hi_sum[W_HI-1:0];
    wire [16:0]            c2_l  = {1'b0, lo_q[15:0]} + {1'b0, t_lo_q[15:0]};
    wire [16:0]            c2_h0 = {1'b0, lo_q[31:16]} + {1'b0, t_lo_q[31:16]};
    wire [16:0]            c2_h1 = {1'b0, lo_q[31:16]} + {1'b0, t_lo_q[31:16]} + 17'd1;
    wire                   c2_d  = c2_l[16] ? c2_h1[16] : c2_h0[16];   // carry of lo + T[31:0]
    wire [38:0]            ci_sum = add39_cs({hi_q[W_HI-1], hi_q}, {t_hi_d_q[W_HI-1], t_hi_d_q}, c2_q);
    wire signed [W_HI-1:0] ci_d = ci_sum[W_HI-1:0];
    wire signed [W_HI:0]   delta_d = add39_cs({ci_q[W_HI-1], ci_q}, ~{comp_q[W_HI-1], comp_q}, 1'b1);

    // ---- re-base sequencer ----------------------------------------------------------------------
    // Control: cnt (calls since the start) and its decoded values are registers computed from
    // the next count, so every mux select below comes straight from a flip-flop.
    wire last  = f_last_q;                                  // cnt == K_REBASE: T applied
    wire start = (!busy_q || last) && pend_q;
    // the pair in force differs from the target pair: a 101-bit equality as 51 bit-pair equalities
    // (one LUT each), ANDed on three 17-long carry chains (the carry of E + E[0] is the AND of E's
    // bits: no LUT tree behind the pair LUTs)
    localparam integer W_CMP = W_RATIO + W_OFFSET;      // 101
    localparam integer N_EQ  = 51;                      // bit pairs (the last one padded)
    wire [2*N_EQ-1:0] cmp_a = {{(2*N_EQ-W_CMP){1'b0}}, i_ratio, i_comp_offset};
    wire [2*N_EQ-1:0] cmp_b = {{(2*N_EQ-W_CMP){1'b0}}, r_use_q, off_tgt_q};
    wire [N_EQ-1:0]   eq2;
    genvar gq;
    generate
        for (gq = 0; gq < N_EQ; gq = gq + 1) begin : g_eq2
            assign eq2[gq] = cmp_a[2*gq+1:2*gq] == cmp_b[2*gq+1:2*gq];
        end
    endgenerate
    wire [17:0] eq_c0 = {1'b0, eq2[16:0]}  + {17'd0, eq2[0]};
    wire [17:0] eq_c1 = {1'b0, eq2[33:17]} + {17'd0, eq2[17]};
    wire [17:0] eq_c2 = {1'b0, eq2[50:34]} + {17'd0, eq2[34]};
    wire pend_d = !start && !(eq_c0[17] && eq_c1[17] && eq_c2[17]);
    wire             busy_d = start || (busy_q && !last);
    // C_MUL0 <= cnt_d < C_MUL0 + MUL_STEPS (4 <= cnt_d < 36, 6-bit cnt_d) as bit logic: a compare
    // with a constant is mapped to a carry chain with an inverter per bit on the iCE40
    wire             mul_rng = (cnt_d[5:2] != 4'd0) && (!cnt_d[5] || cnt_d[4:2] == 3'd0);
    generate
        if (C_MUL0 != 4 || MUL_STEPS != 32 || W_CNT != 6) begin : g_bad_mul_rng
            pulse_multiplier_mul_rng_is_written_for_4_to_35 u_param_error ();
        end
    endgenerate
    wire [W_CNT-1:0] cnt_d  = start ? {{(W_CNT-1){1'b0}}, 1'b1} : (busy_q && !last) ? cnt_q + 1'b1 : {W_CNT{1'b0}};
    // dR = R_tgt - R_old (38 bits) from registers, in two halves (calls C_DR0, C_DR1), each
    // one plain chain with a registered carry
    localparam integer W_DRL = 20;
    wire [W_DRL:0]            dr_lo = {1'b0, r_use_q[W_DRL-1:0]} + {1'b0, ~r_old_q[W_DRL-1:0]} + 1'b1;
    wire [W_DRATIO-W_DRL-1:0] dr_hi = {1'b0, r_use_q[W_RATIO-1:W_DRL]} + ~{1'b0, r_old_q[W_RATIO-1:W_DRL]} +
                                      {{(W_DRATIO-W_DRL-1){1'b0}}, drc_q};
    // P = N0 * dR: the serial multiplier (module pulse_multiplier_smul below), driven by the
    // decoded flags: P cleared by a start, N0 loaded in call C_DR0, the addend of step 0 in call
    // C_MUL0 - 1, the steps in calls C_MUL0 .. C_MUL0 + 31 (the last one subtracts)
    wire [W_ACC-1:0] p_x;
    pulse_multiplier_smul #(.WA(W_RAW), .WB(W_DRATIO)) u_smul (
        .i_clk(i_clk), .i_rst(i_rst), .i_clr(start), .i_load(busy_q && f_dr0_q), .i_a(n_q),
        .i_pre(busy_q && f_pre0_q), .i_step(busy_q && f_mul_q), .i_sign_nx(f_mul_pre_q), .i_b(dr_q),
        .o_p(p_x));
    // X = T + OFF' - OFF_old (OFF' and OFF_old sign-extended to 70 bits) without an inverted
    // operand in front of a carry chain (which costs one LUT per bit on the iCE40: the carry
    // logic needs the inverted bit as a net), by ~a = -a - 1: S = T + OFF' (calls 1..4), stored
    // inverted (the sum LUTs invert for free), then X = ~(~S + OFF_old) (calls 2..5), each one
    // 18-bit quarter per call with a registered carry, the S quarter a call ahead of the X quarter
    // that reads it; then T_new = X + P (calls 36..39). Every quarter is its own adder with its
    // operands straight from flip-flops.
    wire [W_ACC-1:0] t_x       = {t_hi_q, t_lo_q};
    wire [W_ACC-1:0] off_new_x = {{(W_ACC-W_OFFSET){off_tgt_q[W_OFFSET-1]}}, off_tgt_q};
    wire [W_ACC-1:0] off_old_x = {{(W_ACC-W_OFFSET){off_old_q[W_OFFSET-1]}}, off_old_q};
    wire [W_TQ:0]    ss0 = {1'b0, t_x[17:0]}  + {1'b0, off_new_x[17:0]};
    wire [W_TQ:0]    ss1 = {1'b0, t_x[35:18]} + {1'b0, off_new_x[35:18]} + {{W_TQ{1'b0}}, sc_q[0]};
    wire [W_TQ:0]    ss2 = {1'b0, t_x[53:36]} + {1'b0, off_new_x[53:36]} + {{W_TQ{1'b0}}, sc_q[1]};
    wire [15:0]      ss3 = t_x[69:54] + off_new_x[69:54] + {15'd0, sc_q[2]};
    wire [W_TQ:0]    xs0 = {1'b0, ns_q[17:0]}  + {1'b0, off_old_x[17:0]};
    wire [W_TQ:0]    xs1 = {1'b0, ns_q[35:18]} + {1'b0, off_old_x[35:18]} + {{W_TQ{1'b0}}, xc_q[0]};
    wire [W_TQ:0]    xs2 = {1'b0, ns_q[53:36]} + {1'b0, off_old_x[53:36]} + {{W_TQ{1'b0}}, xc_q[1]};
    wire [15:0]      xs3 = ns_q[69:54] + off_old_x[69:54] + {15'd0, xc_q[2]};
    wire [W_TQ:0]    ys0 = {1'b0, x_q[17:0]}  + {1'b0, p_x[17:0]};
    wire [W_TQ:0]    ys1 = {1'b0, x_q[35:18]} + {1'b0, p_x[35:18]} + {{W_TQ{1'b0}}, yc_q[0]};
    wire [W_TQ:0]    ys2 = {1'b0, x_q[53:36]} + {1'b0, p_x[53:36]} + {{W_TQ{1'b0}}, yc_q[1]};
    wire [15:0]      ys3 = x_q[69:54] + p_x[69:54] + {15'd0, yc_q[2]};

    always @(posedge i_clk) begin
        if (i_rst) begin
            n_q <= 0; nmax_q <= 1'b0; nmin_q <= 1'b0; r_use_q <= 0; off_tgt_q <= 0; lo_q <= 0; c_q <= 1'b0; inc_q <= 0;
            wrap_pos_q <= 0;  // the value for R = 0
            hi_q <= 0; c2_q <= 1'b0; ci_q <= 0; comp_q <= 0; delta_q <= 0;
            t_lo_q <= 0; t_hi_q <= 0; t_hi_d_q <= 0;
            busy_q <= 1'b0; pend_q <= 1'b0; cnt_q <= 0;
            f_dr0_q <= 1'b0; f_dr1_q <= 1'b0; f_mul_q <= 1'b0; f_mul_pre_q <= 1'b0; f_pre0_q <= 1'b0;
            f_x_q <= 4'd0; f_y_q <= 4'd0; f_last_q <= 1'b0; dr_q <= 0; r_old_q <= 0; drc_q <= 1'b0;
            off_old_q <= 0; ns_q <= 0; sc_q <= 3'd0; f_s_q <= 4'd0;
            x_q <= 0; y_q <= 0; xc_q <= 3'd0; yc_q <= 3'd0;
        end else begin
            // stage 4, 3, 2
            comp_q   <= ci_q;
            delta_q  <= delta_d;
            ci_q     <= ci_d;
            hi_q     <= hi_d;
            c2_q     <= c2_d;
            t_hi_d_q <= t_hi_q;
            // stage 1
            n_q   <= n_next;
            nmax_q <= nmax_d;
            nmin_q <= nmin_d;
            lo_q  <= lo_sum[R_FRAC-1:0];
            c_q   <= lo_sum[R_FRAC];   // 0 without a step: lo + 0 never carries
            inc_q <= inc_d;
            // running re-base
            if (busy_q) begin
                if (f_s_q[0]) begin ns_q[17:0]  <= ~ss0[W_TQ-1:0]; sc_q[0] <= ss0[W_TQ]; end
                if (f_s_q[1]) begin ns_q[35:18] <= ~ss1[W_TQ-1:0]; sc_q[1] <= ss1[W_TQ]; end
                if (f_s_q[2]) begin ns_q[53:36] <= ~ss2[W_TQ-1:0]; sc_q[2] <= ss2[W_TQ]; end
                if (f_s_q[3])       ns_q[69:54] <= ~ss3;
                if (f_dr0_q) begin  // the call after the start (N0 = N(s) is the register N now)
                    dr_q[W_DRL-1:0] <= dr_lo[W_DRL-1:0];
                    drc_q           <= dr_lo[W_DRL];
                end
                if (f_dr1_q) dr_q[W_DRATIO-1:W_DRL] <= dr_hi;
                if (f_x_q[0]) begin x_q[17:0]  <= ~xs0[W_TQ-1:0]; xc_q[0] <= xs0[W_TQ]; end
                if (f_x_q[1]) begin x_q[35:18] <= ~xs1[W_TQ-1:0]; xc_q[1] <= xs1[W_TQ]; end
                if (f_x_q[2]) begin x_q[53:36] <= ~xs2[W_TQ-1:0]; xc_q[2] <= xs2[W_TQ]; end
                if (f_x_q[3])       x_q[69:54] <= ~xs3;
                if (f_y_q[0]) begin y_q[17:0]  <= ys0[W_TQ-1:0]; yc_q[0] <= ys0[W_TQ]; end
                if (f_y_q[1]) begin y_q[35:18] <= ys1[W_TQ-1:0]; yc_q[1] <= ys1[W_TQ]; end
                if (f_y_q[2]) begin y_q[53:36] <= ys2[W_TQ-1:0]; yc_q[2] <= ys2[W_TQ]; end
                if (f_y_q[3])       y_q[69:54] <= ys3;
                if (last) begin
                    t_lo_q <= y_q[R_FRAC-1:0];
                    t_hi_q <= y_q[W_ACC-1:R_FRAC];
                end
            end
            busy_q       <= busy_d;
            cnt_q        <= cnt_d;
            f_dr0_q      <= busy_d && cnt_d == C_DR0;
            f_dr1_q      <= busy_d && cnt_d == C_DR1;
            f_s_q[0]     <= busy_d && cnt_d == C_S0;
            f_s_q[1]     <= busy_d && cnt_d == C_S0 + 1;
            f_s_q[2]     <= busy_d && cnt_d == C_S0 + 2;
            f_s_q[3]     <= busy_d && cnt_d == C_S0 + 3;
            f_pre0_q     <= busy_d && cnt_d == C_MUL0 - 1;
            f_mul_q      <= busy_d && mul_rng;
            f_mul_pre_q  <= busy_d && cnt_d == C_MUL0 + MUL_STEPS - 2;  // next step is the sign bit
            f_x_q[0]     <= busy_d && cnt_d == C_X0;
            f_x_q[1]     <= busy_d && cnt_d == C_X0 + 1;
            f_x_q[2]     <= busy_d && cnt_d == C_X0 + 2;
            f_x_q[3]     <= busy_d && cnt_d == C_X0 + 3;
            f_y_q[0]     <= busy_d && cnt_d == C_ADD0;
            f_y_q[1]     <= busy_d && cnt_d == C_ADD0 + 1;
            f_y_q[2]     <= busy_d && cnt_d == C_ADD0 + 2;
            f_y_q[3]     <= busy_d && cnt_d == C_ADD0 + 3;
            f_last_q     <= busy_d && cnt_d == K_REBASE;
            // start (after the running one: a start in its last call reloads the sequencer)
            if (start) begin
                r_old_q   <= r_use_q;
                off_old_q <= off_tgt_q;
                r_use_q   <= i_ratio;
                // R_int - R = ~(R + ~R_int): only the 5 bits of R_int are inverted in front of
                // the chains (an inverted operand costs a LUT per bit), the result's inversion
                // is the output LUTs'
                wrap_pos_q <= ~add39_cs(in_all_x, ~in_int_x, 1'b0);
                off_tgt_q <= i_comp_offset;
            end
            pend_q <= pend_d;
        end
    end

    assign o_comp  = comp_q;
    assign o_delta = delta_q;

`ifdef FORMAL
    // ---- formal properties (read_verilog -formal; see docs/FORMAL.md) --------------------------
    // Proof `pulse_multiplier` (k-induction, every state after a reset, every input sequence): the
    //    step accumulator and the output pipeline. A reference accumulator f_acc (one plain 70-bit
    //    adder) adds s * R_use per call (and the wrap term -s * R_use * 2^32 when N wraps); the
    //    split acc = {hi + inc + c, lo} equals it, and comp(t) = floor((acc + T) / 2^32) of the
    //    state three calls back (mod 2^38), delta = its difference, T the base register. The
    //    re-base timing follows the Definition of DESIGN §4.3 (reference pend / start / target
    //    pair), and T changes only in the apply call (K_REBASE calls after a start).
    reg               f_init;
    reg signed [W_RAW-1:0] f_n;
    reg [W_ACC-1:0]   f_acc, f_acc1, f_t1;   // acc after the last edge; acc, T one edge earlier
    reg [W_HI-1:0]    f_ca, f_cb, f_cc;      // comp_int of two, three, four calls back
    reg               f_pend;
    reg [6:0]         f_age;                 // calls since the last start (127: none / long ago)
    reg [W_RATIO-1:0] f_rt;
    reg signed [W_OFFSET-1:0] f_ot;
    reg [W_ACC-1:0]   f_tp;                  // T before the last edge
    reg               f_start_p;             // the last edge was a start
    initial f_init = 1'b0;

    wire [W_ACC-1:0] f_t    = {t_hi_q, t_lo_q};
    wire [W_ACC-1:0] f_rx   = {{(W_ACC-W_RATIO){1'b0}}, r_use_q};
    wire             f_wrap = (step_pos && f_n == {1'b0, {(W_RAW-1){1'b1}}}) ||
                              (step_neg && f_n == {1'b1, {(W_RAW-1){1'b0}}});
    wire [W_ACC-1:0] f_add  = step_pos ? (f_wrap ? f_rx - (f_rx << 32) : f_rx) :
                              step_neg ? (f_wrap ? (f_rx << 32) - f_rx : -f_rx) : {W_ACC{1'b0}};
    wire [W_HI-1:0]  f_acch = hi_q + inc_q[W_HI-1:0] + {{(W_HI-1){1'b0}}, c_q};
    wire [W_ACC-1:0] f_v1   = f_acc1 + f_t1;
    wire [W_ACC:0]   f_c2s  = {1'b0, f_acc1[31:0]} + {1'b0, f_t1[31:0]};
    wire             f_idle  = f_age >= K_REBASE - 1;    // no re-base in progress before this call
    wire             f_start = f_idle && f_pend;
    wire [W_RATIO-1:0] f_rt_n = f_start ? i_ratio : f_rt;
    wire signed [W_OFFSET-1:0] f_ot_n = f_start ? i_comp_offset : f_ot;

`ifdef FORMAL_REBASE
    // re-base proofs (-DFORMAL_REBASE: the sequencer's additions and the multiplier's operands
    // and schedule; the multiplier itself is proven on its own, proof pulse_multiplier_mul):
    // references captured at each start (N0, R_old, OFF_old); the target pair in force is R', OFF'
    // (r_use_q / off_tgt_q, proven equal to the Definition's target above)
    reg signed [W_RAW-1:0]    f_bn0;
    reg [W_RATIO-1:0]         f_bro;
    reg signed [W_OFFSET-1:0] f_boo;
    reg [W_ACC-1:0]           f_yp;       // y_q before the last edge
    reg                       f_app_p;    // the last edge applied T
    wire signed [W_DRATIO-1:0] f_bdr = $signed({1'b0, r_use_q}) - $signed({1'b0, f_bro});
    wire signed [W_OFFSET:0]   f_bdo = $signed({off_tgt_q[W_OFFSET-1], off_tgt_q}) -
                                       $signed({f_boo[W_OFFSET-1], f_boo});
    wire [W_ACC-1:0] f_bdoff = {{(W_ACC-W_OFFSET-1){f_bdo[W_OFFSET]}}, f_bdo};
    wire [W_ACC-1:0] f_xs  = f_t + f_bdoff;                   // X = T + OFF' - OFF_old
    wire [W_ACC-1:0] f_ys  = f_xs + f_px;
    // S = T + OFF' and the carries out of its low 18, 36, 54 bits
    wire [W_ACC-1:0] f_ss  = f_t + off_new_x;
    wire [18:0]      f_sc0 = {1'b0, f_t[17:0]} + {1'b0, off_new_x[17:0]};
    wire [36:0]      f_sc1 = {1'b0, f_t[35:0]} + {1'b0, off_new_x[35:0]};
    wire [54:0]      f_sc2 = {1'b0, f_t[53:0]} + {1'b0, off_new_x[53:0]};
    wire [W_ACC-1:0] f_ns  = ~f_ss;
    // ~(~S + OFF_old) is X (~a = -a - 1), and the carries of ~S + OFF_old
    wire [W_ACC-1:0] f_xalt = ~(f_ns + off_old_x);
    wire [18:0]      f_xc0 = {1'b0, f_ns[17:0]} + {1'b0, off_old_x[17:0]};
    wire [36:0]      f_xc1 = {1'b0, f_ns[35:0]} + {1'b0, off_old_x[35:0]};
    wire [54:0]      f_xc2 = {1'b0, f_ns[53:0]} + {1'b0, off_old_x[53:0]};
    wire [W_ACC-1:0] f_px  = p_x;
    always @(posedge i_clk) begin
        if (f_start && !i_rst) begin
            f_bn0 <= f_n + {{(W_RAW-2){i_step[1]}}, i_step};
            f_bro <= f_rt;
            f_boo <= f_ot;
        end
        f_yp    <= y_q;
        f_app_p <= !i_rst && busy_q && f_last_q;
    end
`endif
    always @(posedge i_clk) begin
        if (i_rst) begin
            f_init <= 1'b1;
            f_n <= 0; f_acc <= 0; f_acc1 <= 0; f_t1 <= 0; f_ca <= 0; f_cb <= 0; f_cc <= 0;
            f_pend <= 1'b0; f_age <= 7'd127; f_rt <= 0; f_ot <= 0;
        end else begin
            f_n    <= f_n + {{(W_RAW-2){i_step[1]}}, i_step};
            f_acc  <= f_acc + f_add;
            f_acc1 <= f_acc;
            f_t1   <= f_t;
            f_ca   <= f_v1[W_ACC-1:R_FRAC];
            f_cb   <= f_ca;
            f_cc   <= f_cb;
            f_pend <= !f_start && (i_ratio != f_rt_n || i_comp_offset != f_ot_n);
            f_age  <= f_start ? 7'd0 : (f_age == 7'd127 ? f_age : f_age + 7'd1);
            f_rt   <= f_rt_n;
            f_ot   <= f_ot_n;
        end
        f_tp      <= i_rst ? {W_ACC{1'b0}} : f_t;
        f_start_p <= !i_rst && f_start;
    end

    always @* begin
        assume(i_step != -2'sd2);      // the step is -1, 0 or +1
        if (f_init) begin
            assert(n_q == f_n);
            assert(nmax_q == (n_q == N_MAX) && nmin_q == (n_q == N_MIN));
            // the split accumulator {hi + inc + c, lo} is the reference accumulator
            assert({f_acch, lo_q} == f_acc);
            // stage 2 and 3 hold the parts of acc + T of one and two calls back
            assert(hi_q == f_acc1[W_ACC-1:R_FRAC]);
            assert(c2_q == f_c2s[R_FRAC]);
            assert(t_hi_d_q == f_t1[W_ACC-1:R_FRAC]);
            assert(ci_q == f_ca);
            // outputs: comp = floor((acc + T) / 2^32) of three calls back, delta its difference
            assert(comp_q == f_cb);
            assert(delta_q == $signed({f_cb[W_HI-1], f_cb}) - $signed({f_cc[W_HI-1], f_cc}));
            // re-base timing (Definition, DESIGN §4.3): pend, start, target pair, apply call
            assert(pend_q == f_pend);
            assert(r_use_q == f_rt);
            assert(off_tgt_q == f_ot);
            assert(busy_q == (f_age < K_REBASE));
            if (busy_q) assert(cnt_q == f_age[W_CNT-1:0] + 1'b1);
            assert(f_last_q == (f_age == K_REBASE - 1));
            if (f_t != f_tp && !f_start_p) assert(f_age == 7'd0 || f_age == K_REBASE);
            if (f_start_p) assert(f_age == 7'd0);
            // helper invariants: the precomputed wrap increments and the decoded count
            assert(wrap_pos_q == $signed({{(W_INC-R_INT){1'b0}}, r_use_q[W_RATIO-1:R_FRAC]}) -
                                 $signed({{(W_INC-W_RATIO){1'b0}}, r_use_q}));
        end
`ifdef FORMAL_REBASE
        if (f_init) begin
            // decoded control flags (helper invariants)
            if (!busy_q) assert(cnt_q == {W_CNT{1'b0}});
            assert(f_dr0_q == (busy_q && cnt_q == C_DR0) && f_pre0_q == (busy_q && cnt_q == C_MUL0 - 1));
            assert(f_dr1_q == (busy_q && cnt_q == C_DR1));
            assert(f_s_q == {busy_q && cnt_q == C_S0 + 3, busy_q && cnt_q == C_S0 + 2,
                             busy_q && cnt_q == C_S0 + 1, busy_q && cnt_q == C_S0});
            assert(f_mul_q == (busy_q && cnt_q >= C_MUL0 && cnt_q < C_MUL0 + MUL_STEPS));
            assert(f_mul_pre_q == (busy_q && cnt_q == C_MUL0 + MUL_STEPS - 2));
            assert(f_x_q == {busy_q && cnt_q == C_X0 + 3, busy_q && cnt_q == C_X0 + 2,
                             busy_q && cnt_q == C_X0 + 1, busy_q && cnt_q == C_X0});
            assert(f_y_q == {busy_q && cnt_q == C_ADD0 + 3, busy_q && cnt_q == C_ADD0 + 2,
                             busy_q && cnt_q == C_ADD0 + 1, busy_q && cnt_q == C_ADD0});
            if (f_app_p) assert(f_t == f_yp);    // the apply call loads T_new
            if (busy_q) begin
                assert(r_old_q == f_bro);
                // dR = R' - R_old in two halves
                if (cnt_q >= 2) assert(dr_q[W_DRL-1:0] == f_bdr[W_DRL-1:0] && drc_q == dr_lo[W_DRL]);
                if (cnt_q >= 3) assert(dr_q == f_bdr);
                assert(off_old_q == f_boo);
                // S = T + OFF' (kept inverted), one quarter per call; ~(~S + OFF_old) = X
                assert(f_xalt == f_xs);
                if (cnt_q >= C_S0 + 1) assert(ns_q[17:0] == f_ns[17:0] && sc_q[0] == f_sc0[18]);
                if (cnt_q >= C_S0 + 2) assert(ns_q[35:0] == f_ns[35:0] && sc_q[1] == f_sc1[36]);
                if (cnt_q >= C_S0 + 3) assert(ns_q[53:0] == f_ns[53:0] && sc_q[2] == f_sc2[54]);
                if (cnt_q >= C_S0 + 4) assert(ns_q == f_ns);
                // X = T + OFF' - OFF_old, one quarter per call
                if (cnt_q >= C_X0 + 1) assert(x_q[17:0] == f_xs[17:0] && xc_q[0] == f_xc0[18]);
                if (cnt_q >= C_X0 + 2) assert(x_q[35:0] == f_xs[35:0] && xc_q[1] == f_xc1[36]);
                if (cnt_q >= C_X0 + 3) assert(x_q[53:0] == f_xs[53:0] && xc_q[2] == f_xc2[54]);
                if (cnt_q >= C_X0 + 4) assert(x_q == f_xs);
                // the multiplier's operands: N0 = N(s) in the call that loads it, dR held from
                // the call of the first addend (C_MUL0 - 1) on (above: dr_q == dR from call 3)
                if (cnt_q == C_DR0) assert(n_q == f_bn0);
                // T_new = X + P, one quarter per call
                if (cnt_q >= C_ADD0 + 1) assert(y_q[17:0] == f_ys[17:0] && yc_q[0] == (({1'b0, x_q[17:0]} + {1'b0, f_px[17:0]}) >> 18));
                if (cnt_q >= C_ADD0 + 2) assert(y_q[35:0] == f_ys[35:0] && yc_q[1] == (({1'b0, x_q[35:0]} + {1'b0, f_px[35:0]}) >> 36));
                if (cnt_q >= C_ADD0 + 3) assert(y_q[53:0] == f_ys[53:0] && yc_q[2] == (({1'b0, x_q[53:0]} + {1'b0, f_px[53:0]}) >> 54));
                // the re-base step: the T applied in the next call (cnt = K_REBASE) is
                // T + (OFF' - OFF_old) + P  (mod 2^70), P = N0 * dR (proof pulse_multiplier_mul)
                if (cnt_q >= C_ADD0 + 4) assert(y_q == f_t + f_bdoff + f_px);
            end
        end
`endif
    end
`endif

endmodule

// pulse_multiplier_smul — the re-base's serial signed multiplier, P = A * B (A: WA bits, B: WB
// bits, both signed; P: WA + WB bits), one bit of A per step, LSB first (DESIGN §4.3, "Hardware
// form"). Parameterised so that a narrow instance of this same RTL can be proven (proof
// pulse_multiplier_mul, rtl_ref/formal/fv_pm_smul.v); pulse_multiplier uses WA = 32, WB = 38.
// Schedule (the caller's): i_clr (P = 0; in or before the i_load call), i_load (A = i_a), i_pre
// (the addend of step 0 registered from bit 0 of A and i_b), then WA calls with i_step, i_sign_nx
// in the second-last of them (the last step is the sign bit of A: it subtracts B); i_b held from
// i_pre to the last step. After the last step o_p = A * B, held until the next i_clr.
// Per step: {pp, pl} += addend * 2^WA then shifts right by one (pp: WB + 1 bits, arithmetic;
// pl: WA bits, the product's low bits arriving at the top); the addend of the next step (0, B or
// ~B with a carry-in of 1) is registered a call ahead, so the (WB + 1)-bit adder has flip-flop
// operands only.
module pulse_multiplier_smul #(
    parameter integer WA = 32,              // A (N0), one bit per step
    parameter integer WB = 38               // B (dR)
) (
    input  wire                 i_clk,
    input  wire                 i_rst,      // synchronous, active high: everything 0
    input  wire                 i_clr,      // P = 0
    input  wire                 i_load,     // A = i_a
    input  wire [WA-1:0]        i_a,
    input  wire                 i_pre,      // register the addend of step 0
    input  wire                 i_step,     // one multiply step
    input  wire                 i_sign_nx,  // (with i_step) the next step is the last one
    input  wire signed [WB-1:0] i_b,
    output wire [WA+WB-1:0]     o_p         // {pp, pl}
);
    localparam integer W_PP = WB + 1;
    generate
        if (WA < 3 || WB < 2) begin : g_bad_width
            pulse_multiplier_smul_PARAMETER_WA_must_be_at_least_3_WB_at_least_2 u_param_error ();
        end
    endgenerate

    reg        [WA-1:0]   a_q;       // shifts right, one bit per step
    reg        [W_PP-1:0] addend_q;  // addend of the next step
    reg                   cin_q;
    reg signed [W_PP-1:0] pp_q;
    reg        [WA-1:0]   pl_q;

    wire signed [W_PP-1:0] b_x         = {i_b[WB-1], i_b};
    wire        [W_PP-1:0] addend_next = !a_q[1] ? {W_PP{1'b0}} : i_sign_nx ? ~b_x : b_x;
    wire signed [W_PP-1:0] pp_sum      = pp_q + addend_q + {{(W_PP-1){1'b0}}, cin_q};

    always @(posedge i_clk) begin
        if (i_rst) begin
            a_q <= {WA{1'b0}}; addend_q <= {W_PP{1'b0}}; cin_q <= 1'b0; pp_q <= {W_PP{1'b0}}; pl_q <= {WA{1'b0}};
        end else begin
            if (i_load) a_q <= i_a;
            if (i_pre) begin                 // step 0: bit 0 of A is never the sign bit
                addend_q <= a_q[0] ? b_x : {W_PP{1'b0}};
                cin_q    <= 1'b0;
            end
            if (i_step) begin
                addend_q <= addend_next;
                cin_q    <= a_q[1] & i_sign_nx;
                pp_q     <= pp_sum >>> 1;
                pl_q     <= {pp_sum[0], pl_q[WA-1:1]};
                a_q      <= a_q >> 1;
            end
            if (i_clr) begin
                pp_q <= {W_PP{1'b0}};
                pl_q <= {WA{1'b0}};
            end
        end
    end

    assign o_p = {pp_q[WB-1:0], pl_q};
endmodule

`default_nettype wire
