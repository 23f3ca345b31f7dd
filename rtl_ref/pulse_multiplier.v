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
// starts a re-base: the target pair is loaded (steps from then on count at the new ratio),
// N0 = N' and dR = R' - R are snapshot, a serial shift-and-add multiplier forms P = N0 * dR over
// 32 calls (39-bit adder, addend registered a call ahead), dOFF = OFF' - OFF in two 33-bit
// halves, X = T + dOFF and T_new = X + P in 18-bit quarters, and T = T_new K_REBASE = 40 calls
// after the start.
// No multiplier and no adder wider than 39 bits anywhere. Latency: comp/delta of call t are
// those of the step of call t - 3.
// (The preset port of the C++ model is a testbench aid and is not part of this RTL.)
`timescale 1ns / 1ps
`default_nettype none

module pulse_multiplier (
    input  wire               i_clk,
    input  wire               i_rst,    // synchronous, active high: pulse_multiplier::reset()
    input  wire signed [1:0]  i_step,   // raw count step from the decoder: -1, 0, +1
    input  wire [36:0]        i_ratio,  // ratio in force R (Q5.32, unsigned)
    input  wire signed [63:0] i_comp_offset,  // offset in force OFF (Q32.32 output counts)
    output wire signed [37:0] o_comp,   // floor(V / 2^32) of the step of three calls back
    output wire signed [38:0] o_delta   // comp' - comp
);

    // ---- widths (hls: pulse_multiplier_cfg) ---------------------------------------------------
    localparam integer W_RAW    = 32;
    localparam integer R_FRAC   = 32;
    localparam integer W_RATIO  = 37;
    localparam integer R_INT    = W_RATIO - R_FRAC;      // 5
    localparam integer W_ACC    = 70;
    localparam integer W_OFFSET = 64;
    localparam integer W_HI     = W_ACC - R_FRAC;        // 38 (= W_POS)
    localparam integer W_DRATIO = W_RATIO + 1;           // 38
    localparam integer W_PP     = W_DRATIO + 1;          // 39
    localparam integer W_DOFF_H = 33;                    // halves of the 65-bit dOFF
    localparam integer W_TQ     = 18;                    // quarters of the T additions
    localparam integer W_INC    = W_HI + 1;              // 39
    localparam integer K_REBASE = 40;
    localparam integer C_DOFF0  = 1, C_DOFF1 = 2;
    localparam integer C_MUL0   = 2, MUL_STEPS = W_RAW;  // call 1 registers the first addend
    localparam integer C_ADD0   = C_MUL0 + MUL_STEPS;    // 34..37: T_new = X + P
    localparam integer C_X0     = C_DOFF1 + 1;           // 3..6: X = T + dOFF
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
    reg signed [W_INC-1:0]    wrap_pos_q, wrap_neg_q;  // R_int - R and ~R_int + R of the target ratio
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
    reg                       f_doff0_q, f_doff1_q, f_pre0_q, f_mul_q, f_mul_pre_q;  // cnt decoded
    reg        [W_PP-1:0]     addend_q;    // addend of the next multiply step
    reg                       cin_q;
    reg        [3:0]          f_x_q, f_y_q;   // quarter of X = T + dOFF / of T_new = X + P
    reg                       f_last_q;
    reg        [W_RAW-1:0]    n0_q;        // shifts right, one bit per multiply call
    reg signed [W_DRATIO-1:0] dr_q;
    reg signed [W_PP-1:0]     pp_q;
    reg        [R_FRAC-1:0]   pl_q;
    reg signed [W_OFFSET-1:0] off_old_q;
    reg        [W_DOFF_H-1:0] doff_lo_q, doff_hi_q;
    reg                       dcy_q;
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
    // N + step (wraps), carry-select over two 16-bit halves
    wire [16:0]             n_sum_l  = {1'b0, n_q[15:0]} + {1'b0, {14{i_step[1]}}, i_step};
    wire [15:0]             n_sum_h0 = n_q[31:16] + {16{i_step[1]}};          // + sign extension
    wire [15:0]             n_sum_h1 = n_q[31:16] + {16{i_step[1]}} + 16'd1;
    wire signed [W_RAW-1:0] n_next = {n_sum_l[16] ? n_sum_h1 : n_sum_h0, n_sum_l[15:0]};
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
                                    step_neg ? (n_wrap ? wrap_neg_q : ~r_int_x) : {W_INC{1'b0}};
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
    wire pend_d = !start && ((i_ratio != r_use_q) || (i_comp_offset != off_tgt_q));
    wire             busy_d = start || (busy_q && !last);
    wire [W_CNT-1:0] cnt_d  = start ? {{(W_CNT-1){1'b0}}, 1'b1} : (busy_q && !last) ? cnt_q + 1'b1 : {W_CNT{1'b0}};
    wire mul_on = f_mul_q;
    // The addend of multiply step i (bit i of N0 times dR; the sign bit subtracts: + ~dR + 1) is
    // registered one call ahead (addend_q, cin_q), so the 39-bit adder has flip-flop operands.
    wire signed [W_PP-1:0] dr_x = {dr_q[W_DRATIO-1], dr_q};
    wire [38:0] dr_sum = add39_cs({2'b00, i_ratio}, ~{2'b00, r_use_q}, 1'b1);  // R_in - R_tgt
    wire signed [W_DRATIO-1:0] dr_d = dr_sum[W_DRATIO-1:0];
    wire        [W_PP-1:0] addend_next = !n0_q[1] ? {W_PP{1'b0}} : f_mul_pre_q ? ~dr_x : dr_x;
    wire signed [W_PP-1:0] pp_sum = pp_q + addend_q + {{(W_PP-1){1'b0}}, cin_q};
    // dOFF = OFF_tgt - OFF_old (65 bits as 66) in two halves
    wire [69:0] off_new_x = {{6{off_tgt_q[W_OFFSET-1]}}, off_tgt_q};
    wire [69:0] off_old_x = {{6{off_old_q[W_OFFSET-1]}}, off_old_q};
    wire [38:0] doff0_x = add39_cs({6'd0, off_new_x[W_DOFF_H-1:0]}, {6'd0, ~off_old_x[W_DOFF_H-1:0]}, 1'b1);
    wire [38:0] doff1_x = add39_cs({6'd0, off_new_x[2*W_DOFF_H-1:W_DOFF_H]}, {6'd0, ~off_old_x[2*W_DOFF_H-1:W_DOFF_H]}, dcy_q);
    wire [W_DOFF_H:0]   doff0_sum = doff0_x[W_DOFF_H:0];
    wire [W_DOFF_H-1:0] doff1_sum = doff1_x[W_DOFF_H-1:0];
    // X = T + dOFF (calls 3..6), then T_new = X + P (calls 34..37): one 18-bit quarter per call,
    // each quarter its own adder (operands straight from flip-flops), carry registered
    wire [W_ACC-1:0] t_x = {t_hi_q, t_lo_q};
    wire [W_ACC-1:0] p_x = {pp_q[W_HI-1:0], pl_q};
    wire [W_ACC-1:0] d_x = {{(W_ACC-2*W_DOFF_H){doff_hi_q[W_DOFF_H-1]}}, doff_hi_q, doff_lo_q};
    wire [W_TQ:0]    xs0 = {1'b0, t_x[17:0]}  + {1'b0, d_x[17:0]};
    wire [W_TQ:0]    xs1 = {1'b0, t_x[35:18]} + {1'b0, d_x[35:18]} + {{W_TQ{1'b0}}, xc_q[0]};
    wire [W_TQ:0]    xs2 = {1'b0, t_x[53:36]} + {1'b0, d_x[53:36]} + {{W_TQ{1'b0}}, xc_q[1]};
    wire [15:0]      xs3 = t_x[69:54] + d_x[69:54] + {15'd0, xc_q[2]};
    wire [W_TQ:0]    ys0 = {1'b0, x_q[17:0]}  + {1'b0, p_x[17:0]};
    wire [W_TQ:0]    ys1 = {1'b0, x_q[35:18]} + {1'b0, p_x[35:18]} + {{W_TQ{1'b0}}, yc_q[0]};
    wire [W_TQ:0]    ys2 = {1'b0, x_q[53:36]} + {1'b0, p_x[53:36]} + {{W_TQ{1'b0}}, yc_q[1]};
    wire [15:0]      ys3 = x_q[69:54] + p_x[69:54] + {15'd0, yc_q[2]};

    always @(posedge i_clk) begin
        if (i_rst) begin
            n_q <= 0; nmax_q <= 1'b0; nmin_q <= 1'b0; r_use_q <= 0; off_tgt_q <= 0; lo_q <= 0; c_q <= 1'b0; inc_q <= 0;
            wrap_pos_q <= 0; wrap_neg_q <= {W_INC{1'b1}};  // the values for R = 0
            hi_q <= 0; c2_q <= 1'b0; ci_q <= 0; comp_q <= 0; delta_q <= 0;
            t_lo_q <= 0; t_hi_q <= 0; t_hi_d_q <= 0;
            busy_q <= 1'b0; pend_q <= 1'b0; cnt_q <= 0;
            f_doff0_q <= 1'b0; f_doff1_q <= 1'b0; f_mul_q <= 1'b0; f_mul_pre_q <= 1'b0; f_pre0_q <= 1'b0;
            addend_q <= 0; cin_q <= 1'b0;
            f_x_q <= 4'd0; f_y_q <= 4'd0; f_last_q <= 1'b0; n0_q <= 0; dr_q <= 0; pp_q <= 0; pl_q <= 0;
            off_old_q <= 0; doff_lo_q <= 0; doff_hi_q <= 0; dcy_q <= 1'b0;
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
                if (f_doff0_q) begin
                    doff_lo_q <= doff0_sum[W_DOFF_H-1:0];
                    dcy_q     <= doff0_sum[W_DOFF_H];
                end
                if (f_doff1_q) doff_hi_q <= doff1_sum;
                if (f_pre0_q) begin  // addend of step 0 (bit 0 of N0 is never the sign bit)
                    addend_q <= n0_q[0] ? dr_x : {W_PP{1'b0}};
                    cin_q    <= 1'b0;
                end
                if (mul_on) begin
                    addend_q <= addend_next;
                    cin_q    <= n0_q[1] & f_mul_pre_q;
                    pp_q <= pp_sum >>> 1;
                    pl_q <= {pp_sum[0], pl_q[R_FRAC-1:1]};
                    n0_q <= n0_q >> 1;
                end
                if (f_x_q[0]) begin x_q[17:0]  <= xs0[W_TQ-1:0]; xc_q[0] <= xs0[W_TQ]; end
                if (f_x_q[1]) begin x_q[35:18] <= xs1[W_TQ-1:0]; xc_q[1] <= xs1[W_TQ]; end
                if (f_x_q[2]) begin x_q[53:36] <= xs2[W_TQ-1:0]; xc_q[2] <= xs2[W_TQ]; end
                if (f_x_q[3])       x_q[69:54] <= xs3;
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
            f_doff0_q    <= busy_d && cnt_d == C_DOFF0;
            f_doff1_q    <= busy_d && cnt_d == C_DOFF1;
            f_pre0_q     <= busy_d && cnt_d == C_MUL0 - 1;
            f_mul_q      <= busy_d && cnt_d >= C_MUL0 && cnt_d < C_MUL0 + MUL_STEPS;
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
                n0_q      <= n_next;
                dr_q      <= dr_d;
                off_old_q <= off_tgt_q;
                pp_q      <= 0;
                pl_q      <= 0;
                r_use_q   <= i_ratio;
                wrap_pos_q <= add39_cs(in_int_x, ~in_all_x, 1'b1);   // R_int - R
                wrap_neg_q <= add39_cs(~in_int_x, in_all_x, 1'b0);   // ~R_int + R
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
    localparam integer F_NB = 8;   // N0 width of the multiplier proof

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
    wire [7:0]       f_n_nb = f_n[7:0] + {{6{i_step[1]}}, i_step};   // N after the step, low 8 bits
    wire signed [W_OFFSET-1:0] f_ot_n = f_start ? i_comp_offset : f_ot;

`ifdef FORMAL_REBASE
    // re-base proofs (-DFORMAL_REBASE: the sequencer's additions; with -DFORMAL_MUL as well: the
    // serial multiplier): references captured at each start (N0, R_old, OFF_old); the target pair
    // in force is R', OFF' (r_use_q / off_tgt_q, proven equal to the Definition's target above)
    reg signed [W_RAW-1:0]    f_bn0;
    reg [W_RATIO-1:0]         f_bro;
    reg signed [W_OFFSET-1:0] f_boo;
    reg [W_ACC-1:0]           f_yp;       // y_q before the last edge
    reg                       f_app_p;    // the last edge applied T
    wire signed [W_DRATIO-1:0] f_bdr = $signed({1'b0, r_use_q}) - $signed({1'b0, f_bro});
    wire signed [W_OFFSET:0]   f_bdo = $signed({off_tgt_q[W_OFFSET-1], off_tgt_q}) -
                                       $signed({f_boo[W_OFFSET-1], f_boo});
    wire [W_ACC-1:0] f_bdoff = {{(W_ACC-W_OFFSET-1){f_bdo[W_OFFSET]}}, f_bdo};
`ifdef FORMAL_MUL
    wire [71:0]      f_dr72  = {{(72-W_DRATIO){f_bdr[W_DRATIO-1]}}, f_bdr};
    wire             f_neg   = f_bn0[W_RAW-1];
    wire [71:0]      f_z     = {{(72-W_PP-R_FRAC){pp_q[W_PP-1]}}, pp_q, pl_q};
    // multiply steps done after this count: 0 up to cnt 2, cnt - 2, 32 from cnt 34
    wire [5:0]       f_i     = !busy_q ? 6'd0 : (cnt_q <= 2) ? 6'd0 : (cnt_q >= 34) ? 6'd32 : cnt_q - 6'd2;
    // L_j = sum over k < j of bit k of N0 times dR * 2^k (j <= F_NB-1), incrementally;
    // P = N0 * dR = L_(F_NB-1) - sign * dR * 2^(F_NB-1). After i multiply steps {pp, pl} is
    //   L_i * 2^(32-i)                          for i <= F_NB-1,
    //   P * 2^(32-i) + sign * dR * 2^32          for F_NB-1 < i < 32 (the sign bits added so far),
    //   P                                       for i = 32 (the sign bit subtracted).
    reg  [72*F_NB-1:0] f_lv;
    reg  [71:0]      f_zexp;
    integer          f_j;
    always @* begin
        f_lv[71:0] = 72'd0;
        for (f_j = 1; f_j < F_NB; f_j = f_j + 1)
            f_lv[f_j*72 +: 72] = f_lv[(f_j-1)*72 +: 72] + (f_bn0[f_j-1] ? (f_dr72 << (f_j - 1)) : 72'd0);
    end
    wire [71:0]      f_pall = f_lv[(F_NB-1)*72 +: 72] - (f_neg ? (f_dr72 << (F_NB - 1)) : 72'd0);
    always @* begin
        f_zexp = f_pall;
        for (f_j = 0; f_j < 32; f_j = f_j + 1)
            if (f_i == f_j) f_zexp = (f_j < F_NB) ? (f_lv[((f_j < F_NB) ? f_j : 0)*72 +: 72] << (32 - f_j))
                                                  : (f_pall << (32 - f_j));
    end
    wire             f_mul_ok = f_z == f_zexp + ((f_neg && f_i >= F_NB && f_i < 32) ? (f_dr72 << 32) : 72'd0);
    wire [W_ACC-1:0] f_bprod = f_pall[W_ACC-1:0];            // N0 * dR
`endif
    wire [W_ACC-1:0] f_xs  = f_t + f_bdoff;                   // X = T + dOFF
    wire [W_ACC-1:0] f_ys  = f_xs + f_px;
    // carries out of the low 18, 36, 54 bits of T + dOFF
    wire [18:0]      f_xc0 = {1'b0, f_t[17:0]} + {1'b0, f_bdoff[17:0]};
    wire [36:0]      f_xc1 = {1'b0, f_t[35:0]} + {1'b0, f_bdoff[35:0]};
    wire [54:0]      f_xc2 = {1'b0, f_t[53:0]} + {1'b0, f_bdoff[53:0]};
    wire [33:0]      f_dl  = {1'b0, off_new_x[32:0]} + {1'b0, ~off_old_x[32:0]} + 34'd1;
    wire [W_ACC-1:0] f_px  = {pp_q[W_HI-1:0], pl_q};
    wire [W_PP-1:0]  f_drx = {dr_q[W_DRATIO-1], dr_q};
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
            assert(wrap_neg_q == ~$signed({{(W_INC-R_INT){1'b0}}, r_use_q[W_RATIO-1:R_FRAC]}) +
                                 $signed({{(W_INC-W_RATIO){1'b0}}, r_use_q}));
        end
`ifdef FORMAL_REBASE
`ifdef FORMAL_MUL
        // every start has N0 (N after its step) in F_NB bits: |N0| < 2^(F_NB-1)
        if (f_start && !i_rst) assume((f_n + {{(W_RAW-2){i_step[1]}}, i_step}) ==
                                      {{(W_RAW-F_NB){f_n_nb[F_NB-1]}}, f_n_nb[F_NB-1:0]});
`endif
        if (f_init) begin
            // decoded control flags (helper invariants)
            if (!busy_q) assert(cnt_q == {W_CNT{1'b0}});
            assert(f_doff0_q == (busy_q && cnt_q == C_DOFF0) && f_pre0_q == (busy_q && cnt_q == C_MUL0 - 1));
            assert(f_doff1_q == (busy_q && cnt_q == C_DOFF1));
            assert(f_mul_q == (busy_q && cnt_q >= C_MUL0 && cnt_q < C_MUL0 + MUL_STEPS));
            assert(f_mul_pre_q == (busy_q && cnt_q == C_MUL0 + MUL_STEPS - 2));
            assert(f_x_q == {busy_q && cnt_q == C_X0 + 3, busy_q && cnt_q == C_X0 + 2,
                             busy_q && cnt_q == C_X0 + 1, busy_q && cnt_q == C_X0});
            assert(f_y_q == {busy_q && cnt_q == C_ADD0 + 3, busy_q && cnt_q == C_ADD0 + 2,
                             busy_q && cnt_q == C_ADD0 + 1, busy_q && cnt_q == C_ADD0});
            if (f_app_p) assert(f_t == f_yp);    // the apply call loads T_new
            if (busy_q) begin
                assert(dr_q == f_bdr);           // dR = R' - R_old
                assert(off_old_q == f_boo);
                // dOFF = OFF' - OFF_old in two halves
                if (cnt_q >= 2) assert(doff_lo_q == f_dl[32:0] && dcy_q == f_dl[33]);
                if (cnt_q >= 3) assert({{(W_ACC-2*W_DOFF_H){doff_hi_q[W_DOFF_H-1]}}, doff_hi_q, doff_lo_q} == f_bdoff);
                // X = T + dOFF, one quarter per call
                if (cnt_q >= 4) assert(x_q[17:0] == f_xs[17:0] && xc_q[0] == f_xc0[18]);
                if (cnt_q >= 5) assert(x_q[35:0] == f_xs[35:0] && xc_q[1] == f_xc1[36]);
                if (cnt_q >= 6) assert(x_q[53:0] == f_xs[53:0] && xc_q[2] == f_xc2[54]);
                if (cnt_q >= 7) assert(x_q == f_xs);
`ifdef FORMAL_MUL
                // the serial multiplier: after i steps {pp, pl} is the sum of the first i
                // partial products (closed form above), N0 shifted right by i, the addend of
                // step i registered; after the 32 steps {pp, pl} = N0 * dR
                assert(f_bn0 == {{(W_RAW-F_NB){f_bn0[F_NB-1]}}, f_bn0[F_NB-1:0]});
                assert(f_mul_ok);
                assert(n0_q == ($unsigned(f_bn0) >> f_i));
                if (cnt_q >= 34) assert(f_px == f_bprod);
                if (cnt_q >= 2 && cnt_q <= 33)
                    assert(addend_q == (!n0_q[0] ? {W_PP{1'b0}} : (f_i == 6'd31) ? ~f_drx : f_drx) &&
                           cin_q == (n0_q[0] && f_i == 6'd31));
`else
                // T_new = X + P, one quarter per call
                if (cnt_q >= 35) assert(y_q[17:0] == f_ys[17:0] && yc_q[0] == (({1'b0, x_q[17:0]} + {1'b0, f_px[17:0]}) >> 18));
                if (cnt_q >= 36) assert(y_q[35:0] == f_ys[35:0] && yc_q[1] == (({1'b0, x_q[35:0]} + {1'b0, f_px[35:0]}) >> 36));
                if (cnt_q >= 37) assert(y_q[53:0] == f_ys[53:0] && yc_q[2] == (({1'b0, x_q[53:0]} + {1'b0, f_px[53:0]}) >> 54));
                // the re-base step: the T applied in the next call (cnt = K_REBASE) is
                // T + (OFF' - OFF_old) + {pp, pl}  (mod 2^70), {pp, pl} = N0 * dR by FORMAL_MUL
                if (cnt_q >= 38) assert(y_q == f_t + f_bdoff + f_px);
`endif
            end
        end
`endif
    end
`endif

endmodule

`default_nettype wire
