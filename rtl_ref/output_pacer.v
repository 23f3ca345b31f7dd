// output_pacer.v — rate limiter for the compensated count stream.
//
// Reference RTL of hls/output_pacer.h (DESIGN §4.4). One rising clock edge = one call of
// output_pacer::step(); every output is a register holding the out_t of that call.
// Synchronous active-high reset = output_pacer::reset() (all zero).
//
//   emit     = (timer == 0 && g_prev == 0 && h == 0 && B != 0) ? sgn(B) : 0  (registers before the edge)
//   slot     = timer == 0 && g_prev == 0 && h == 1   (the slot owed to a count emitted while wide)
//   B'       = B + delta + add - emit   (add: the error-map delta, a second addend, so that no
//              adder precedes the pacer in the top: the sum is formed in the carry-save layer)
//   timer'   = (emit != 0 || slot) ? M - 1 : max(timer - 1, 0);  e_prev' = emit;
//              g_prev' = emit != 0 || slot;  h' = emit != 0 ? wide : (slot ? 0 : h)
//              (the register holds timer + 1: an event loads M, no decrement of M before it)
//   taps: paced = P(t-2), backlog = B(t-2); ovs = |B(t-4)| > thr(t-1) (pulse); ovs_st cleared by
//   clear, set by ovs (event wins)
// Hardware form (no carry chain over 23 bits): X = B + e_prev = (hi + cq) * 2^20 + lo with a
// registered carry cq in -1 .. +2; sign and zero of X from equality trees on hi and lo (no chain);
// the lower half's four operands (lo, delta_lo, add, -e_prev) through two carry-save layers, the
// upper half's three (hi, delta_hi, cq) through one; the taps in two register stages off the loop.
// Latency: delta in at call t, the first count leaves at call t+1; taps 2 calls, ovs 4 calls.
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module output_pacer (
    input  wire                            i_clk,
    input  wire                            i_rst,      // synchronous, active high: output_pacer::reset()
    input  wire signed [`LX_W_DELTA-1:0]   i_delta,    // comp(t) - comp(t-1) from the multiplier
    input  wire signed [`LX_OP_W_ADD-1:0]  i_add,      // second addend: the error-map delta (same call)
    input  wire [`LX_OP_W_PACE-1:0]        i_pace_m,   // M: at least max(M, 2) calls between two emitted counts
    input  wire [`LX_OP_W_THR-1:0]         i_thr,      // backlog alarm threshold
    input  wire                            i_clear,    // register pulse: clears ovs_st (unless ovs)
    input  wire                            i_wide,     // rephase is in its window: a count owes a slot
    output wire signed [`LX_W_STEP-1:0]    o_pstep,    // emitted count: -1, 0, +1
    output wire signed [`LX_W_STEP-1:0]    o_pstep_nx, // look-ahead: the o_pstep of the next call (emit, 0 in a
                                                       // reset call), for rephase's registered decode (DESIGN 4.4)
    output wire                            o_slot,     // the slot owed to the count before it (rephase's extra count)
    output wire                            o_slot_nx,  // look-ahead: the o_slot of the next call (0 in a reset call)
    output wire signed [`LX_W_POS-1:0]     o_paced,    // paced position P(t-2) (tap)
    output wire signed [`LX_W_BACKLOG-1:0] o_backlog,  // counts still to emit, B(t-2) (tap)
    output wire                            o_ovs,      // pulse: |B(t-4)| > thr(t-1)
    output wire                            o_ovs_st    // sticky
`ifdef FORMAL
    ,
    output wire signed [41:0] f_o_c0,    // formal only: B + P of this call (B(t) + P(t))
    output wire signed [41:0] f_o_c1,    //   of the previous call
    output wire signed [41:0] f_o_c2,    //   of two calls earlier
    output wire signed [41:0] f_o_p,     //   P(t)
    output wire               f_o_init   //   reset seen
`endif
);

    // ---- fixed widths (hls: output_pacer_cfg, axis_widths) -----------------------------------
    localparam integer W_PACE    = `LX_OP_W_PACE;  // M register
    localparam integer W_THR     = `LX_OP_W_THR;   // backlog alarm threshold
    localparam integer W_POS     = `LX_W_POS;      // paced position
    localparam integer W_DELTA   = `LX_W_DELTA;    // input delta
    localparam integer W_ADD     = `LX_OP_W_ADD;   // second addend (error-map delta), inside the lower half
    localparam integer W_BACKLOG = `LX_W_BACKLOG;  // backlog, signed
    localparam integer L         = W_BACKLOG / 2;  // 20: backlog split point
    localparam integer W_HI      = W_BACKLOG - L;  // 20
    localparam integer LP        = W_POS / 2;      // 19: paced split point
    localparam integer W_PHI     = W_POS - LP;     // 19
    localparam integer W_THI     = W_THR - L;      // 12
    localparam integer W_T       = L + 3;          // lo + delta_lo + add - e_prev
    localparam integer W_CQ      = W_T - L;        // 3: backlog carry -1 .. +2

    // ---- registers ---------------------------------------------------------------------------
    reg        [L-1:0]     lo_q;       // X = (hi + cq) * 2^L + lo
    reg signed [W_HI-1:0]  hi_q;
    reg signed [W_CQ-1:0]  cq_q;
    reg signed [1:0]       e_prev_q;   // emitted count of the previous call (= o_pstep)
    reg        [W_PACE-1:0] tm_q;       // timer + 1 (mod 2^16: 0 stands for 65536)
    reg signed [W_HI-1:0]  a_hi_q;     // backlog tap, stage A: B(t-1) halves and carry
    reg        [L-1:0]     a_lo_q;
    reg signed [1:0]       a_cy_q;
    reg signed [W_HI-1:0]  b_hi_q;     // backlog tap, stage B: B(t-2)
    reg        [L-1:0]     b_lo_q;
    reg        [LP-1:0]    p_lo_q;     // paced tap: split counter, lower half delayed one call
    reg        [LP-1:0]    p_lo_d_q;
    reg signed [W_PHI-1:0] p_hi_q;
    reg signed [1:0]       p_cy_q;
    reg                    ovs_q;
    reg                    ovs_st_q;

    // ---- emit decision: sign and zero of X, equality trees (no carry chain) ------------------
    // The first level of the trees is registered with the halves: 4-bit pieces of hi' and lo'
    // all zero / all one (and the lowest piece of hi' == 1), and timer' == 0.
    localparam integer NH = W_HI / 4;               // 5 pieces of hi
    localparam integer NL = L / 4;                  // 5 pieces of lo
    reg [NH-1:0]  hz_q, ho_q;                      // piece of hi all 0 / all 1
    reg           h1_q;                            // hi[3:0] == 1
    reg           he_q;                            // hi[3:0] == 0xe (hi == -2 with ho_q)
    reg [NL-1:0]  lz_q;                            // piece of lo all 0
    reg           tz_q;                            // timer == 0, g_prev == 0, h == 0: a count may leave (tz_d)
    reg           sl_q;                            // timer == 0, g_prev == 0, h == 1: the slot (sl_d)
    reg           h_q;                             // a slot is owed (a count was emitted while wide)
    reg           so_q;                            // o_slot: the slot of this call
    wire hi_neg  = hi_q[W_HI-1];
    wire hi_z    = &hz_q;
    wire hi_m1   = &ho_q;
    wire hi_p1   = h1_q && (&hz_q[NH-1:1]);
    wire hi_m2   = he_q && (&ho_q[NH-1:1]);
    wire cq_neg  = cq_q[W_CQ-1];                   // cq: 111 (-1), 000, 001, 010 (+2)
    wire cq_one  = cq_q[0] && !cq_neg;
    wire cq_two  = cq_q[1] && !cq_neg;
    // hi + cq == 0 and hi + cq < 0
    wire h_zero  = cq_neg ? hi_p1 : cq_two ? hi_m2 : cq_one ? hi_m1 : hi_z;
    wire h_neg   = cq_neg ? (hi_neg || hi_z) : cq_two ? (hi_neg && !hi_m1 && !hi_m2)
                 : cq_one ? (hi_neg && !hi_m1) : hi_neg;
    wire x_nz    = !(h_zero && (&lz_q));
    wire emit_nz = tz_q && x_nz;
    wire signed [1:0] emit = emit_nz ? (h_neg ? -2'sd1 : 2'sd1) : 2'sd0;

    // ---- X' = X + delta + add - e_prev: carry-save layers, then one chain per half ----------
    // lower half: lo + delta[L-1:0] + add - e_prev in W_T bits
    // (-2^(W_ADD-1) - 1 .. 2^(L+1) + 2^(W_ADD-1) - 2, so the carry to the upper half is -1 .. +2)
    wire [W_T-1:0] t_a  = {3'b000, lo_q};
    wire [W_T-1:0] t_b  = {3'b000, i_delta[L-1:0]};
    wire [W_T-1:0] t_m  = {{(W_T-W_ADD){i_add[W_ADD-1]}}, i_add};           // add, sign-extended
    reg            e_pos_q;                                                  // e_prev == +1
    wire [W_T-1:0] t_n  = {{(W_T-1){e_pos_q}}, e_prev_q[0]};                // -e_prev
    // first layer: lo + delta_lo + add; second layer: + (-e_prev)
    wire [W_T-1:0] t_s1 = t_a ^ t_b ^ t_m;
    wire [W_T-1:0] t_k1 = {((t_a[W_T-2:0] & t_b[W_T-2:0]) | (t_a[W_T-2:0] & t_m[W_T-2:0]) |
                            (t_b[W_T-2:0] & t_m[W_T-2:0])), 1'b0};
    wire [W_T-1:0] t_s  = t_s1 ^ t_k1 ^ t_n;
    wire [W_T-1:0] t_k  = {((t_s1[W_T-2:0] & t_k1[W_T-2:0]) | (t_s1[W_T-2:0] & t_n[W_T-2:0]) |
                            (t_k1[W_T-2:0] & t_n[W_T-2:0])), 1'b0};
`ifndef FORMAL_SUM
    wire [W_T-1:0] t_sum = t_s + t_k;
`else
    // conservation proof only: the plain sum (the block's own proof shows the two are equal)
    wire [W_T-1:0] t_sum = t_a + t_b + t_m + t_n;
`endif
    // upper half: hi + (delta >> L) + cq (mod 2^W_HI)
    wire [W_HI-1:0] h_a = hi_q;
    wire [W_HI-1:0] h_b = {{(W_HI-(W_DELTA-L)){i_delta[W_DELTA-1]}}, i_delta[W_DELTA-1:L]};
    wire [W_HI-1:0] h_n = {{(W_HI-W_CQ){cq_q[W_CQ-1]}}, cq_q};                 // cq, sign-extended
    wire [W_HI-1:0] h_s = h_a ^ h_b ^ h_n;
    wire [W_HI-1:0] h_k = {((h_a[W_HI-2:0] & h_b[W_HI-2:0]) | (h_a[W_HI-2:0] & h_n[W_HI-2:0]) |
                            (h_b[W_HI-2:0] & h_n[W_HI-2:0])), 1'b0};
`ifndef FORMAL_SUM
    wire [W_HI-1:0] h_sum = h_s + h_k;
`else
    wire [W_HI-1:0] h_sum = h_a + h_b + h_n;
`endif

    // ---- timer -------------------------------------------------------------------------------
    // Kept as tm = timer + 1 (mod 2^16, 0 standing for 65536), so an event loads M itself
    // (M = 0: 65536, timer 65535) and no decrement of M precedes the register:
    // tm' = event ? M : max(tm - 1, 1); timer == 0 is tm == 1.
    // tz' = (timer' == 0 && g_prev' == 0 && !h'), sl' = (timer' == 0 && g_prev' == 0 && h'):
    // after an event g_prev' = 1, so both 0 (whatever M loads the timer); otherwise g_prev' = 0,
    // h' = h and timer' = max(timer - 1, 0) is 0 iff timer <= 1, i.e. tm is 1 or 2. So the
    // decision needs no test of g_prev (it only mattered for the illegal M = 1), and i_wide
    // reaches only h. A count needs !h and a slot needs h, so tz' and h' read emit only where
    // h = 0 and sl' not at all (no enable on h: the emit decision meets h as a data input).
    wire              ev   = emit_nz || sl_q;
    wire              tm12 = (tm_q[W_PACE-1:2] == {(W_PACE-2){1'b0}}) && (tm_q[1] ^ tm_q[0]);
    wire              tz_d = !h_q && !emit_nz && tm12;           // = !ev && tm12 && !h
    wire              sl_d = h_q && !sl_q && tm12;               // = !ev && tm12 && h
    wire              h_d  = h_q ? !sl_q : (emit_nz && i_wide);  // = emit ? wide : slot ? 0 : h
    wire [W_PACE-1:0] tm_d = ev ? i_pace_m
                           : (tm_q != {{(W_PACE-1){1'b0}}, 1'b1}) ? tm_q - {{(W_PACE-1){1'b0}}, 1'b1}
                           : {{(W_PACE-1){1'b0}}, 1'b1};

    // ---- taps (off the loop) -----------------------------------------------------------------
    wire signed [W_HI-1:0] a_hi_d = hi_q + {{(W_HI-W_CQ){cq_q[W_CQ-1]}}, cq_q};
    wire [L+1:0]           al     = {2'b00, lo_q} - {{L{e_prev_q[1]}}, e_prev_q};
    wire signed [W_HI-1:0] b_hi_d = a_hi_q + {{(W_HI-2){a_cy_q[1]}}, a_cy_q};
    wire [LP+1:0]          ps     = {2'b00, p_lo_q} + {{LP{e_prev_q[1]}}, e_prev_q};
    wire signed [W_PHI-1:0] p_hi_d = p_hi_q + {{(W_PHI-2){p_cy_q[1]}}, p_cy_q};

    // ---- ovs: |B(t-3)| > thr on the stage-B tap, split compares ------------------------------
    // B = bh * 2^L + bl, thr = th * 2^L + tl (th: 12 bits). B > thr: bh > th, or bh == th and
    // bl > tl. B < -thr: bh + th + carry(bl + tl) < 0. Every compare is split into pieces of at
    // most 12 bits (no chain over 13 bits): bh against th through its upper 8 bits (all 0 / all 1)
    // and a 12-bit compare or carry; bl against tl in two 10-bit halves.
    localparam integer LH = L / 2;                  // 10
    wire [W_THI-1:0]  t_hi   = i_thr[W_THR-1:L];
    wire [L-1:0]      t_lo   = i_thr[L-1:0];
    wire [W_THI-1:0]  bh_low = b_hi_q[W_THI-1:0];
    wire              bh_neg = b_hi_q[W_HI-1];
    wire              bh_top0 = b_hi_q[W_HI-1:W_THI] == {(W_HI-W_THI){1'b0}};
    wire              bh_top1 = b_hi_q[W_HI-1:W_THI] == {(W_HI-W_THI){1'b1}};
    wire              gt_hi  = !bh_neg && (!bh_top0 || (bh_low > t_hi));       // bh > th
    wire              eq_hi  = bh_top0 && (bh_low == t_hi);                    // bh == th
    wire [W_THI:0]    sh0    = {1'b0, bh_low} + {1'b0, t_hi};
    wire [W_THI:0]    sh1    = {1'b0, bh_low} + {1'b0, t_hi} + {{W_THI{1'b0}}, 1'b1};
    wire              neg0   = bh_neg && (!bh_top1 || !sh0[W_THI]);            // bh + th < 0
    wire              neg1   = bh_neg && (!bh_top1 || !sh1[W_THI]);            // bh + th + 1 < 0
    wire [LH-1:0]     bl_h   = b_lo_q[L-1:LH];
    wire [LH-1:0]     bl_l   = b_lo_q[LH-1:0];
    wire [LH-1:0]     tl_h   = t_lo[L-1:LH];
    wire [LH-1:0]     tl_l   = t_lo[LH-1:0];
    wire              gt_lh  = bl_h > tl_h;
    wire              eq_lh  = bl_h == tl_h;
    wire              gt_ll  = bl_l > tl_l;                                    // bl > tl: lh, or eq and ll
    wire [LH:0]       cl     = {1'b0, bl_l} + {1'b0, tl_l};
    wire [LH:0]       cu0    = {1'b0, bl_h} + {1'b0, tl_h};
    wire [LH:0]       cu1    = {1'b0, bl_h} + {1'b0, tl_h} + {{LH{1'b0}}, 1'b1};
    // first stage (registered): every piece is one chain or one tree; the second stage combines
    // them: B > thr = gt_hi | eq_hi & (gt_lh | eq_lh & gt_ll); carry(bl + tl) = cl ? cu1 : cu0
    // selects neg1 / neg0
    reg               o_gt_hi_q, o_eq_hi_q, o_gt_lh_q, o_eq_lh_q, o_gt_ll_q;
    reg               o_neg0_q, o_neg1_q, o_cl_q, o_cu0_q, o_cu1_q;
    wire              o_gt   = o_gt_hi_q || (o_eq_hi_q && (o_gt_lh_q || (o_eq_lh_q && o_gt_ll_q)));
    wire              o_cs   = o_cl_q ? o_cu1_q : o_cu0_q;
    wire              ovs_d  = o_gt || (o_cs ? o_neg1_q : o_neg0_q);              // second stage
    wire                   ovs_st_d = ovs_d || (ovs_st_q && !i_clear);

    // the registered first level of the trees, from the new halves
    wire [NH-1:0] hz_d = {h_sum[19:16] == 4'h0, h_sum[15:12] == 4'h0, h_sum[11:8] == 4'h0,
                          h_sum[7:4] == 4'h0, h_sum[3:0] == 4'h0};
    wire [NH-1:0] ho_d = {h_sum[19:16] == 4'hf, h_sum[15:12] == 4'hf, h_sum[11:8] == 4'hf,
                          h_sum[7:4] == 4'hf, h_sum[3:0] == 4'hf};
    wire [NL-1:0] lz_d = {t_sum[19:16] == 4'h0, t_sum[15:12] == 4'h0, t_sum[11:8] == 4'h0,
                          t_sum[7:4] == 4'h0, t_sum[3:0] == 4'h0};

    always @(posedge i_clk) begin
        if (i_rst) begin
            hz_q     <= {NH{1'b1}};
            ho_q     <= {NH{1'b0}};
            h1_q     <= 1'b0;
            he_q     <= 1'b0;
            lz_q     <= {NL{1'b1}};
            tz_q     <= 1'b1;
            sl_q     <= 1'b0;
            h_q      <= 1'b0;
            so_q     <= 1'b0;
            e_pos_q  <= 1'b0;
            lo_q     <= {L{1'b0}};
            hi_q     <= {W_HI{1'b0}};
            cq_q     <= {W_CQ{1'b0}};
            e_prev_q <= 2'sd0;
            tm_q     <= {{(W_PACE-1){1'b0}}, 1'b1};
            a_hi_q   <= {W_HI{1'b0}};
            a_lo_q   <= {L{1'b0}};
            a_cy_q   <= 2'sd0;
            b_hi_q   <= {W_HI{1'b0}};
            b_lo_q   <= {L{1'b0}};
            p_lo_q   <= {LP{1'b0}};
            p_lo_d_q <= {LP{1'b0}};
            p_hi_q   <= {W_PHI{1'b0}};
            p_cy_q   <= 2'sd0;
            o_gt_hi_q <= 1'b0;
            o_eq_hi_q <= 1'b0;
            o_gt_lh_q <= 1'b0;
            o_eq_lh_q <= 1'b0;
            o_gt_ll_q <= 1'b0;
            o_neg0_q  <= 1'b0;
            o_neg1_q  <= 1'b0;
            o_cl_q    <= 1'b0;
            o_cu0_q   <= 1'b0;
            o_cu1_q   <= 1'b0;
            ovs_q    <= 1'b0;
            ovs_st_q <= 1'b0;
        end else begin
            o_gt_hi_q <= gt_hi;
            o_eq_hi_q <= eq_hi;
            o_gt_lh_q <= gt_lh;
            o_eq_lh_q <= eq_lh;
            o_gt_ll_q <= gt_ll;
            o_neg0_q  <= neg0;
            o_neg1_q  <= neg1;
            o_cl_q    <= cl[LH];
            o_cu0_q   <= cu0[LH];
            o_cu1_q   <= cu1[LH];
            hz_q     <= hz_d;
            ho_q     <= ho_d;
            h1_q     <= h_sum[3:0] == 4'h1;
            he_q     <= h_sum[3:0] == 4'he;
            lz_q     <= lz_d;
            tz_q     <= tz_d;
            sl_q     <= sl_d;
            h_q      <= h_d;
            so_q     <= sl_q;
            e_pos_q  <= emit_nz && !h_neg;
            lo_q     <= t_sum[L-1:0];
            cq_q     <= t_sum[W_T-1:L];
            hi_q     <= h_sum;
            e_prev_q <= emit;
            tm_q     <= tm_d;
            a_hi_q   <= a_hi_d;
            a_lo_q   <= al[L-1:0];
            a_cy_q   <= al[L+1:L];
            b_hi_q   <= b_hi_d;
            b_lo_q   <= a_lo_q;
            p_lo_d_q <= p_lo_q;
            p_lo_q   <= ps[LP-1:0];
            p_cy_q   <= ps[LP+1:LP];
            p_hi_q   <= p_hi_d;
            ovs_q    <= ovs_d;
            ovs_st_q <= ovs_st_d;
        end
    end

    assign o_pstep   = e_prev_q;
    assign o_pstep_nx = i_rst ? 2'sd0 : emit;
    assign o_slot    = so_q;
    assign o_slot_nx = !i_rst && sl_q;
    assign o_paced   = {p_hi_q, p_lo_d_q};
    assign o_backlog = {b_hi_q, b_lo_q};
    assign o_ovs     = ovs_q;
    assign o_ovs_st  = ovs_st_q;

`ifdef FORMAL
    // ---- formal properties (read_verilog -formal; see docs/FORMAL.md) --------------------------
    // Checked after the first reset. The f_* registers record what the pacer saw in each call.
    // Conservation (backlog + paced = sum of the deltas two calls earlier) is checked in the
    // harness rtl_ref/formal/fv_output_pacer.v, which tracks the input sum; the f_o_* ports give
    // it B + P of the present and the two previous calls (formal-only ports).
    localparam integer FW = 42;
    reg                   f_init, f_rst_p, f_clear_p, f_ovs_st_p;
    reg [W_THR-1:0]       f_thr_p;
    reg [W_PACE:0]        f_m;      // M in force at the last event (0 read as 2^16)
    reg [W_PACE+1:0]      f_since;  // calls since the last event (count or slot), saturating
    reg                   f_g1;     // the previous call had an event
    reg                   f_owe;    // the text's h: a slot is owed
    reg                   f_snx;    // o_slot_nx of the previous call
    reg [W_BACKLOG:0]     f_bmag_p, f_bmag_p2; // |backlog tap| before the last / last but one edge
    reg [W_THR-1:0]       f_thr_p2;
    reg                   f_rst_p2;
    reg signed [FW-1:0]   f_pc, f_b1, f_pc1, f_b2, f_pc2;   // P(t); B, P of calls t-1, t-2
    reg signed [1:0]      f_e1;     // emitted count of the previous call
    reg signed [1:0]      f_nx;     // o_pstep_nx of the previous call
    initial f_init = 1'b0;

    localparam [W_PACE+1:0] F_SINCE_MAX = {(W_PACE+2){1'b1}};
    wire [W_PACE:0] f_m_now = (i_pace_m == {W_PACE{1'b0}}) ? {1'b1, {W_PACE{1'b0}}}
                                                            : {1'b0, i_pace_m};
    // X = (hi + cq) * 2^L + lo and B = X - e_prev, computed arithmetically (independent of the trees)
    wire signed [FW-L-1:0] f_h = $signed({{(FW-L-W_HI){hi_q[W_HI-1]}}, hi_q}) +
                                 $signed({{(FW-L-W_CQ){cq_q[W_CQ-1]}}, cq_q});
    wire signed [FW-1:0] f_x = {f_h, lo_q};
    wire signed [FW-1:0] f_bnow = f_x - $signed({{(FW-2){e_prev_q[1]}}, e_prev_q});
    wire signed [FW-1:0] f_btap = $signed({{(FW-W_BACKLOG){b_hi_q[W_HI-1]}}, b_hi_q, b_lo_q});
    wire [W_HI-1:0]      f_ah   = a_hi_q + {{(W_HI-2){a_cy_q[1]}}, a_cy_q};
    wire [W_BACKLOG-1:0] f_atap = {f_ah, a_lo_q};     // modulo 2^W_BACKLOG
    wire signed [FW-1:0] f_ptap = $signed({{(FW-W_POS){p_hi_q[W_PHI-1]}}, p_hi_q, p_lo_d_q});
    wire [W_PHI-1:0]     f_ph   = p_hi_q + {{(W_PHI-2){p_cy_q[1]}}, p_cy_q};
    wire [W_POS-1:0]     f_pint = {f_ph, p_lo_q};     // modulo 2^W_POS
    wire [W_BACKLOG:0] f_bmag = f_btap[FW-1] ? -f_btap[W_BACKLOG:0] : f_btap[W_BACKLOG:0];
    // the timer the register tm stands for (timer == 0 is tm == 1), and the timer of the gap left
    wire               f_tz    = tm_q == {{(W_PACE-1){1'b0}}, 1'b1};
    wire [W_PACE:0]    f_timer = (f_since >= {1'b0, f_m}) ? {(W_PACE+1){1'b0}} : (f_m - f_since[W_PACE:0]);
    assign f_o_c0 = f_bnow + f_pc;
    assign f_o_c1 = f_b1 + f_pc1;
    assign f_o_c2 = f_b2 + f_pc2;
    assign f_o_p  = f_pc;
    assign f_o_init = f_init;

    always @(posedge i_clk) begin
        if (i_rst) f_init <= 1'b1;
        f_nx       <= o_pstep_nx;
        f_snx      <= o_slot_nx;
        f_rst_p    <= i_rst;
        f_clear_p  <= i_clear;
        f_ovs_st_p <= ovs_st_q;
        f_thr_p    <= i_thr;
        f_bmag_p   <= f_bmag;
        f_bmag_p2  <= f_bmag_p;
        f_thr_p2   <= f_thr_p;
        f_rst_p2   <= f_rst_p;
        if (i_rst) begin
            f_since <= F_SINCE_MAX;
            f_m     <= {(W_PACE+1){1'b0}};
            f_pc    <= {FW{1'b0}};
            f_b1    <= {FW{1'b0}};
            f_pc1   <= {FW{1'b0}};
            f_b2    <= {FW{1'b0}};
            f_pc2   <= {FW{1'b0}};
            f_e1    <= 2'sd0;
            f_g1    <= 1'b0;
            f_owe   <= 1'b0;
        end else begin
            f_g1    <= ev;
            f_owe   <= emit_nz ? i_wide : (sl_q ? 1'b0 : f_owe);
            if (ev) begin
                f_since <= {{(W_PACE+1){1'b0}}, 1'b1};
                f_m     <= f_m_now;
            end else if (f_since != F_SINCE_MAX) begin
                f_since <= f_since + 1'b1;
            end
            f_pc  <= f_pc + $signed({{(FW-2){emit[1]}}, emit});
            f_b1  <= f_bnow;
            f_pc1 <= f_pc;
            f_b2  <= f_b1;
            f_pc2 <= f_pc1;
            f_e1  <= e_prev_q;
        end
    end

    always @* begin
`ifndef FORMAL_SUM
        // (the conservation proof, -DFORMAL_SUM, leaves out what it does not need; the
        // block's own proof checks all of it)
        if (f_init && !f_rst_p) begin
            // alarm exactly when |backlog of four calls earlier| > threshold of the previous call
            if (!f_rst_p2) assert(ovs_q == (f_bmag_p2 > {{(W_BACKLOG-W_THR+1){1'b0}}, f_thr_p2}));
            // helper invariant (induction): the first stage holds that result for either carry
            assert(ovs_d == (f_bmag_p > {{(W_BACKLOG-W_THR+1){1'b0}}, f_thr_p}));
            assert(ovs_st_q == (ovs_q || (f_ovs_st_p && !f_clear_p)));
        end
        if (f_init) begin
            // the trees give the zero test and the sign of X
            assert(x_nz == (f_x != {FW{1'b0}}));
            if (x_nz) assert(h_neg == f_x[FW-1]);
            // at most one event (count or slot) per max(M, 2) calls: an event comes only M or
            // more calls after the previous one (M as set at the previous event), never in two
            // consecutive calls
            if (ev) assert(f_since >= {1'b0, f_m});
            if (ev) assert(f_since >= 2);
            // a count emitted while wide is followed by its slot before the next count, and a
            // slot comes only when owed (so rephase's extra count has a paced call of its own)
            assert(h_q == f_owe);
            if (emit_nz) assert(!f_owe);
            if (sl_q) assert(f_owe);
            assert(!(emit_nz && sl_q));
            // the count has the sign of the backlog, and an event comes whenever it may
            if (emit_nz) assert(emit == (f_bnow[FW-1] ? -2'sd1 : 2'sd1) && f_bnow != 0);
            if (f_tz && !f_g1 && !f_owe && f_bnow != 0) assert(emit_nz);
            if (f_tz && !f_g1 && f_owe) assert(sl_q);
            // helper invariant (induction): the timer (tm - 1) is what is left of the gap
            assert(!f_timer[W_PACE] && tm_q == f_timer[W_PACE-1:0] + 1'b1);
            if (!f_rst_p) assert(!f_g1 || f_since == {{(W_PACE+1){1'b0}}, 1'b1});
            if (e_prev_q != 2'sd0) assert(f_g1);
        end
`endif
        if (f_init) begin
            assert(o_pstep == f_nx);   // the look-ahead is the next call's pstep
            assert(o_slot == f_snx);   // and the next call's slot
            if (emit_nz) assert(emit == (f_bnow[FW-1] ? -2'sd1 : 2'sd1) && f_bnow != 0);
            // the carry-save sums equal the plain sums (the conservation proof uses the plain ones)
            assert(t_sum == t_a + t_b + t_m + t_n);
            assert(h_sum == h_a + h_b + h_n);
            // the registered first level of the trees matches the halves (helper invariant)
            assert(hz_q == {hi_q[19:16] == 4'h0, hi_q[15:12] == 4'h0, hi_q[11:8] == 4'h0,
                            hi_q[7:4] == 4'h0, hi_q[3:0] == 4'h0});
            assert(ho_q == {hi_q[19:16] == 4'hf, hi_q[15:12] == 4'hf, hi_q[11:8] == 4'hf,
                            hi_q[7:4] == 4'hf, hi_q[3:0] == 4'hf});
            assert(h1_q == (hi_q[3:0] == 4'h1));
            assert(he_q == (hi_q[3:0] == 4'he));
            assert(lz_q == {lo_q[19:16] == 4'h0, lo_q[15:12] == 4'h0, lo_q[11:8] == 4'h0,
                            lo_q[7:4] == 4'h0, lo_q[3:0] == 4'h0});
            assert(tz_q == (f_tz && !f_g1 && !h_q));
            assert(sl_q == (f_tz && !f_g1 && h_q));
            assert(e_pos_q == (e_prev_q == 2'sd1));
            // counts and tap carries are -1, 0 or +1, the backlog carry -1 .. +2 (helper invariant)
            assert(e_prev_q != -2'sd2 && a_cy_q != -2'sd2 && p_cy_q != -2'sd2 && f_e1 != -2'sd2);
            assert(cq_q == 3'b111 || cq_q == 3'b000 || cq_q == 3'b001 || cq_q == 3'b010);
`ifndef FORMAL_SUM
            // the taps: stage A holds B(t-1), stage B B(t-2); paced P(t-2); the paced counter
            // P(t-1) (modulo the register widths: the halves wrap like the whole would)
            assert(f_atap == f_b1[W_BACKLOG-1:0]);
            assert(f_btap[W_BACKLOG-1:0] == f_b2[W_BACKLOG-1:0]);
            assert(f_ptap[W_POS-1:0] == f_pc2[W_POS-1:0]);
            assert(f_pint == f_pc1[W_POS-1:0]);
            assert(f_pc1 == f_pc - $signed({{(FW-2){e_prev_q[1]}}, e_prev_q}));
            assert(f_pc2 == f_pc1 - $signed({{(FW-2){f_e1[1]}}, f_e1}));
`endif
        end
    end
`endif

endmodule

`default_nettype wire
