// rephase.v — referencing state machine: stage 1/2/3, points A, B, Z, C, phase adjustment d.
//
// Reference RTL of hls/rephase.h (DESIGN §4.5, "Hardware form"). One rising clock edge = one call
// of rephase::step(); the outputs after edge t are the out_t of call t (all registers).
// Synchronous active-high reset = rephase::reset() (stage 1, forward, everything else 0).
//
// Per call, in the order of the C++ model:
//   1. taps: paced' = paced + pstep; direction of the last real count.
//   2. the extra count dq of this call from registers: a forward count carries when t >= 0, a
//      backward count inside the window borrows when v < 0 (Bresenham state num, t = num + d - P,
//      v = num - d; k = d - P).
//   3. phase w = (ph_out + P/8) mod P of the output position moves by ostep (-1..1), with the
//      flags w == P - 1, w == 0, w >= P/2.
//   4. stage machine: unhome/rehome -> stage 1; stage 1: rising switch edge (and !unhome) ->
//      stage 2, A = paced', d from w (P - w forward, w -/+ P/2 backward); stage 2: (num, t, v)
//      step, tr < 0 -> stage 1, tr == P (flagged a call ahead: at_last) -> stage 3, B = bs (A +
//      dir*P, formed in the calls before), C = B + dir*mark_len, Z = B + dir*P/4.
//   5. ostep = pstep, or else in the pacer's slot sgn(lag) (lag = adj_tgt - adj: the pending extra
//      count, 2 bits; 0 after a call with unhome or rehome: the leave drops it).
//   6. mark = stage' == 3 && u' in [0, L], u = dir*(paced - B) counted from homing on (L =
//      mark_len at homing; the test is made on u before the count, for each count direction).
//   7. index = mark && w == P/4 of the call before (a register of registers: one count wide at
//      the home point Z, latency one call more than mark; DESIGN 4.5 step 5).
// Every path is one carry chain from registers plus a few LUT levels: 38 bits only for the
// counters adj and u, whose steps are registers of their own (as_q, us_q, from the look-ahead);
// A + dir*P in two parts over two calls (13 + 25 bits), C and Z as 13-bit adds and a select;
// at most 19 bits for the split position counters (paced by the late pstep, out_pos by a
// registered step) and 14 bits (Bresenham, tr, w, d) elsewhere; no 38-bit compare, no adder in
// series with another, and the late pstep enters no chain but paced's low half.
// Widths: positions 38 signed, d/num/w 12 unsigned, t/v/k/tr 14 signed, lag 2 signed, stage 2.
// Latency: 1 call (pstep, slot in, ostep/out_pos/mark out); extra counts in the slot.
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module rephase (
    input  wire                         i_clk,
    input  wire                         i_rst,       // synchronous, active high: rephase::reset()
    input  wire signed [`LX_W_STEP-1:0] i_pstep,     // paced count from the pacer: -1, 0, +1
    // look-ahead: the i_pstep of the next call, in every call (reset calls included); the pacer's
    // o_pstep_nx. The count's direction relative to the homing direction (s_pos / s_neg) is
    // registered from it, so its decode and fan-out are off the path from the pacer (DESIGN 4.5)
    input  wire signed [`LX_W_STEP-1:0] i_pstep_nx,
    input  wire                         i_slot,      // the pacer's slot: the call for a pending extra count
    // look-ahead: the i_slot of the next call (the pacer's o_slot_nx); the block reads its
    // registered copy (sl_q), i_slot is used only by the formal properties
    input  wire                         i_slot_nx,
    input  wire                         i_sw,        // debounced reference switch level
    input  wire                         i_sw_valid,  // its input_filter valid flag
    input  wire                         i_rehome,    // register pulse: back to stage 1
    input  wire                         i_unhome,    // laser error level: back to stage 1, no homing
    // look-ahead: i_unhome and i_rehome of the next call, in every call (reset calls included);
    // the decoder's o_lerr_nx and the top's presented rehome. The block reads registered copies
    // (un_q, re_q) in place of i_unhome / i_rehome, so the decoder's register does not drive
    // the enables here across the chip (DESIGN 4.5); i_unhome / i_rehome are then used only by
    // the formal properties
    input  wire                         i_unhome_nx,
    input  wire                         i_rehome_nx,
    input  wire [`LX_W_P-1:0]           i_period,    // P (8..4096, multiple of 8)
    // P - 1 and P - 2 as 14-bit signed values ({1'b0, P} - 1, - 2), formed by the caller from the
    // same period value (the top: in its register stage, beside the period register), so no
    // decrement of P sits in front of the travel and phase-wrap equalities. They must equal
    // those of i_period in every call (the testbench forms them from the period column).
    input  wire signed [`LX_W_P:0]      i_period_m1,
    input  wire signed [`LX_W_P:0]      i_period_m2,
    input  wire [`LX_W_P-1:0]           i_mark_len,  // C - B in counts (P/4..P)
    // ~mark_len, formed by the caller from the same value (the top: the configuration check's
    // inverted operand, registered beside r_mark_len), so the mark compares of u with L and L + 1
    // are carry chains without an inverted operand (one LUT per bit on the iCE40). It must equal
    // ~i_mark_len in every call (the testbench forms it from the mark_len column).
    input  wire [`LX_W_P-1:0]           i_mark_len_n,
    output wire signed [`LX_W_STEP-1:0] o_ostep,     // output count: -1, 0, +1
    output wire signed [`LX_W_POS-1:0]  o_out_pos,   // paced + adj
    output wire                         o_mark,      // reference mark
    output wire                         o_index,     // index: mark && w == P/4 of the call before
    output wire [`LX_W_STAGE-1:0]       o_stage,     // 1, 2, 3
    output wire signed [`LX_W_POS-1:0]  o_a,         // point A
    output wire [`LX_W_PH-1:0]          o_d,         // phase advance d in [0, P)
    output wire signed [`LX_W_POS-1:0]  o_b,         // point B
    output wire signed [`LX_W_POS-1:0]  o_c,         // point C (end of mark)
    output wire signed [`LX_W_POS-1:0]  o_z,         // point Z = B + dir * P/4
    output wire signed [`LX_W_POS-1:0]  o_adj,       // applied adjustment
    output wire                         o_homed      // stage == 3
);

    // ---- fixed widths (hls: rephase_cfg, axis_widths) ----------------------------------------
    localparam integer W_POS = `LX_W_POS;  // positions
    localparam integer W_P   = `LX_W_P;    // period and mark_len registers, L
    localparam integer W_PH  = `LX_W_PH;   // d, num, w: 0..P-1
    localparam integer W_TR  = W_P + 1;    // travel beyond A, signed
    localparam integer W_BR  = W_P + 1;    // Bresenham t, v, k, signed
    localparam integer W_LAG = 2;          // adj_tgt - adj, signed: -1..1 (counts >= 2 calls apart)
    localparam integer W_X   = W_P + 1;    // w moves and wraps
    localparam integer W_LO  = W_POS / 2;  // low half of a position counter (pos_step)
    localparam integer W_CZ  = W_P;        // low part of B = A + dir*P, C = B + dir*mark_len, Z

    // the referencing stages (DESIGN 4.5), the values of stage_q and o_stage. The stage machine
    // below is an if-chain on stage_q with "hold" as the last branch (the 0 encoding is never
    // reached and holds). The same machine as `case (stage_q)` with a `default` hold, measured
    // (HX8K, seed 1): the top 104.4 MHz instead of 108.4, and nextpnr's router did not converge for
    // the block alone within 15 minutes; so the chain stays (hls/rephase.h: switch with default).
    localparam [1:0] ST_UNHOMED = 2'd1;  // stage 1: un-homed, waiting for the switch edge (A)
    localparam [1:0] ST_WINDOW  = 2'd2;  // stage 2: from A towards B, d paid out over P counts
    localparam [1:0] ST_HOMED   = 2'd3;  // stage 3: homed, phase locked, mark on [B, C]

    // ---- registers ---------------------------------------------------------------------------
    reg [1:0]              stage_q, stage_d;
    reg signed [W_POS-1:0] paced_q, paced_d, out_pos_q, out_pos_d, adj_q, adj_d;
    reg                    fwd_last_q, fwd_last_d, sw_prev_q, sw_seen_q;
    reg signed [W_POS-1:0] a_q, a_d, bs_q, bs_d;
    reg                    bs_c_q;             // carry of bs's low half (previous call)
    reg [W_POS-W_CZ-1:0]   bs_pm_q;            // bs's high part (above W_CZ) + dir
    reg                    fwd_q, fwd_d;
    reg [W_PH-1:0]         d_q, d_d;
    reg [W_PH-1:0]         wa_q, wa_d;         // w at A
    reg [1:0]              dm_q, dm_d;         // the form of d at A (see d_new)
    reg                    dnew_q, dnew_d;     // A was in the previous call: d not yet loaded
    reg signed [W_BR-1:0]  k_q, k_d;
    reg signed [W_TR-1:0]  tr_q, tr_d;
    reg                    tr_pos_q, tr_pos_d; // tr > 0, registered beside tr
    reg                    at_last_q, at_last_d, fresh_q, fresh_d;
    reg                    first_q, first_d;   // the first count after A was in the previous
                                               // call: this call loads num = d, t = 2d - P
    reg [W_PH-1:0]         num_q, num_d;
    reg signed [W_BR-1:0]  t_q, v_q;
    reg signed [W_LAG-1:0] lag_q, lag_d;
    reg [W_PH-1:0]         w_q, w_d;
    reg                    t1_q, z0_q, w_init_q;  // w == P - 1, w == 0
    reg                    h_q;                // w >= P/2
    reg signed [W_POS-1:0] u_q, u_d;
    reg [W_P-1:0]          nlen_q, nlen_d;      // ~L (L = mark_len at homing)
    reg [W_P:0]            nlen1_q, nlen1_d;    // ~(L + 1) in W_P + 1 bits
    reg signed [W_POS-1:0] b_q, b_d, c_q, c_d, z_q, z_d;
    reg signed [1:0]       ostep_q, ostep_d;
    reg                    mark_q, mark_d;
    reg                    idx_q;              // index: mark_q && w_q == P/4 (the call before)
    reg                    mp_q, mn_q;         // u + 1 / u - 1 in [0, L], of the previous call
    reg                    sp_q, sn_q;         // s_pos / s_neg of this call, from i_pstep_nx
    reg                    pp_q, pn_q;         // pstep > 0 / < 0 in this call, from i_pstep_nx
    (* keep *) reg [1:0]   us_q;               // {s_neg, s_pos || s_neg}: the step of u
    (* keep *) reg [1:0]   as_q;               // the step of adj: sgn(lag) when pstep == 0
    reg                    op_one_q, op_zero_q; // out_pos's low half is all ones / zero
    reg                    pa_ones_q, pa_zero_q, pa_one_q; // paced's low half is all ones / 0 / 1
    (* keep *) reg         bw_c_q, bw_z_q;     // !fwd_q, copies for the C and Z adds
    (* keep *) reg         bw_b_q;             // !fwd_q, the copy for A + dir*P (bs)
    reg                    un_q, re_q;         // unhome / rehome of this call, from the look-ahead
    reg                    sl_q;               // slot of this call, from the look-ahead
    reg                    osu_q, osd_q;       // ostep of this call is +1 / -1, from the look-ahead
    (* keep *) reg         osd_w_q;            // osd_q, the copy for w's step chain (x_s)
    reg                    hom_q;              // this call is the homing count (from the look-ahead)

    // ---- position counters: x + s, s in -2..1 (a 2-bit step), as two halves --------------------
    // The low half adds s (a W_LO-bit chain); the high half takes hi + 1 / hi - 1 (chains of the
    // register alone, in parallel) when the low half wraps, which equalities of the register's low
    // half tell (all ones and s = +1; below |s| and s < 0): the late step never enters a 38-bit
    // chain, only the low chain and the last select. Equal to x + s (mod 2^W_POS) for every s.
    function signed [W_POS-1:0] pos_step;
        input signed [W_POS-1:0] x;
        input signed [1:0]       st;
        reg [W_LO-1:0]           lo;
        reg [W_POS-W_LO-1:0]     hi;
        reg                      up_w, dn_w;
        begin
            lo   = x[W_LO-1:0] + {{(W_LO-2){st[1]}}, st};
            up_w = st == 2'sd1 && x[W_LO-1:0] == {W_LO{1'b1}};
            dn_w = st[1] && (st[0] ? x[W_LO-1:0] == {W_LO{1'b0}} : x[W_LO-1:1] == {(W_LO-1){1'b0}});
            hi   = up_w ? x[W_POS-1:W_LO] + 1'b1 : dn_w ? x[W_POS-1:W_LO] - 1'b1 : x[W_POS-1:W_LO];
            pos_step = {hi, lo};
        end
    endfunction

    // ---- constants of P and the registers' extensions ----------------------------------------
    wire [W_PH-1:0]         p8       = i_period[W_P-1:3];                            // P/8
    wire [W_PH-1:0]         p2       = i_period[W_P-1:1];                            // P/2
    wire signed [W_X-1:0]   px       = $signed({1'b0, i_period});
    wire signed [W_POS-1:0] period_x = $signed({{(W_POS-W_P){1'b0}}, i_period});
    wire signed [W_POS-1:0] mark_len_x = $signed({{(W_POS-W_P){1'b0}}, i_mark_len});
    wire signed [W_POS-1:0] p4_x     = $signed({{(W_POS-W_PH-1){1'b0}}, p8, 1'b0}); // 2 * P/8
    // the sign of pstep (pp_q: > 0, pn_q: < 0), registered in the previous call from i_pstep_nx:
    // only the paced counter reads the late pstep itself
    wire                    pz       = !pp_q && !pn_q;
    wire                    pfwd     = !pn_q;           // pstep > 0 when pstep != 0
    wire                    rise     = i_sw && !sw_prev_q && sw_seen_q;
    wire                    leave    = (un_q || re_q) && stage_q != ST_UNHOMED;
    wire                    in2      = stage_q == ST_WINDOW && !leave;
    wire                    in3      = stage_q == ST_HOMED && !leave;
    wire                    cap      = stage_q == ST_UNHOMED && rise && !un_q;
    // step in the homing direction: s_pos = pstep != 0 && (pstep > 0) == fwd, s_neg likewise,
    // registered in the previous call from i_pstep_nx and the next fwd (sp_q, sn_q)
    wire                    s_pos    = sp_q;
    wire                    s_neg    = sn_q;
    wire                    tr_pos   = tr_pos_q;     // tr > 0 (a register, see tr_pos_d)

    // 2. the extra count of this call (registers only)
    wire fr    = fresh_q || first_q;   // (num, t) not yet valid: a forward count is a first count
    wire dq_up = in2 && s_pos && !fr && !t_q[W_BR-1];
    wire dq_dn = in2 && s_neg && tr_pos && v_q[W_BR-1];
    wire dq_nz = dq_up || dq_dn;     // an extra count rides on this real count (the definition;
                                     // step 5 uses its forms per pstep value, dq_p / dq_m)
    // dadj = dir * dq = pstep * |dq| (dq has the sign of s = dir * pstep)

    // 3. w = (ph_out + P/8) mod P moves by ostep (-1..1): candidates from registers, the wrap
    //    taken from the registered flags t1 (w == P - 1) and z0 (w == 0); the flags of the next
    //    value come from equalities of w with P - 2, P, 1 and all ones (beside the candidates)
    // sgn(lag) of the 2-bit lag: -2 (a wrap, only with a broken precondition) has the sign -1
    wire signed [1:0]     lsgn    = {lag_q[1], lag_q[1] | lag_q[0]};
    // the output step: the sign of pstep, or else in a slot without unhome / rehome sgn(lag); its
    // two decodes (+1, -1) are registered in the previous call from the look-ahead i_pstep_nx,
    // i_slot_nx, i_unhome_nx, i_rehome_nx and the next lag (osu_q, osd_q), so neither the move of
    // w nor the output counter waits for the late pstep
    wire                  eup  = osu_q;
    wire                  edn  = osd_q;
    wire signed [1:0]     ostep_n = {edn, eup || edn};
    wire [W_PH-1:0]       w0   = w_init_q ? w_q : p8;                          // ph = 0 after reset
    // the flags after reset are those of w = P/8 for every legal P (>= 8): 0 (their reset values)
    wire                  t1   = t1_q;
    wire                  z0   = z0_q;
    wire signed [W_X-1:0] w0x  = $signed({{(W_X-W_PH){1'b0}}, w0});
    // one chain w0 +/- 1 (the step from osd_w_q, a copy of osd_q kept beside the chain); the
    // wrap and move selects are formed from registers beside it, so one select level follows
    // the chain
    wire [W_PH-1:0]       x_s  = w0 + {{(W_PH-1){osd_w_q}}, 1'b1};
    wire signed [W_X-1:0] p_m1 = i_period_m1;     // px - 1
    wire signed [W_X-1:0] p_m2 = i_period_m2;     // px - 2
    wire                  w_wr = (eup && t1) || (edn && z0);             // wrap: 0 up, P - 1 down
    wire                  w_mv = eup || edn;
    wire [W_PH-1:0]       w_wv = eup ? {W_PH{1'b0}} : p_m1[W_PH-1:0];
    wire [W_PH-1:0] w_n  = w_wr ? w_wv : w_mv ? x_s : w0;
    wire            t1_n = eup ? (t1 ? (px == 1) : (w0x == p_m2)) :
                           edn ? (z0 ? 1'b1 : (w0x == px)) : t1;
    wire            z0_n = eup ? (t1 ? 1'b1 : (w0 == {W_PH{1'b1}})) :
                           edn ? (z0 ? (p_m1[W_PH-1:0] == {W_PH{1'b0}}) : (w0 == {{(W_PH-1){1'b0}}, 1'b1})) : z0;

    // the flag h = (w >= P/2) beside t1 and z0 (for the form of d at A): it rises on a step up
    // from P/2 - 1 (= (P - 2)/2, bits of i_period_m2), falls on a step down from P/2, is 0 after
    // the wrap up to 0 and 1 after the wrap down to P - 1 (0 after reset: P/8 < P/2)
    wire [W_PH-1:0] p2m1 = i_period_m2[W_PH:1];                                  // P/2 - 1
    wire            h    = h_q;
    wire            h_n  = eup ? (t1 ? 1'b0 : (h || w0 == p2m1)) :
                           edn ? (z0 ? 1'b1 : (h && w0 != p2)) : h;

    // d from the phase at A (wA, registered at A): P - wA forward, (wA - P/2) mod P backward. It
    // is one 12-bit add X + Y + ci in the call after A (dnew), loaded into d there; the output o_d
    // shows it from A on. Which of the four forms applies is the 2-bit mode dm registered at A
    // from the direction and the phase flags (dm[1]: backward; dm[0]: wA == 0 forward, wA >= P/2
    // backward): 00 P + ~wA + 1, 01 0, 10 wA + P/2, 11 wA + ~(P/2) + 1. So the operands are one
    // LUT each from registers and no compare or select follows the add.
    wire [W_PH-1:0]       dx_op  = dm_q[1] ? wa_q : (dm_q[0] ? {W_PH{1'b0}} : ~wa_q);
    wire [W_PH-1:0]       dy_op  = dm_q[1] ? (dm_q[0] ? ~p2 : p2) :
                                   (dm_q[0] ? {W_PH{1'b0}} : i_period[W_PH-1:0]);
    wire                  d_ci   = dm_q[1] ~^ dm_q[0];
    wire [W_PH-1:0]       d_new  = dx_op + dy_op + {{(W_PH-1){1'b0}}, d_ci};
    wire [W_PH-1:0]       d_cur  = dnew_q ? d_new : d_q;

    // Bresenham candidates (one 14-bit add of registers each)
    wire signed [W_BR-1:0] px_br  = $signed({1'b0, i_period});
    wire signed [W_BR-1:0] d_br   = $signed({{(W_BR-W_PH){1'b0}}, d_q});
    // 2d - P, loaded into t in the call after the first count after A (num' = d there)
    wire signed [W_BR-1:0] t_ld   = (d_br <<< 1) - px_br;
    wire signed [W_BR-1:0] num_br = $signed({{(W_BR-W_PH){1'b0}}, num_q});
    wire signed [W_BR-1:0] t_rc   = num_br + k_q;     // t = num + d - P
    wire signed [W_BR-1:0] v_rc   = num_br - d_br;    // v = num - d
    wire signed [W_BR-1:0] v_pp   = v_q + px_br;
    wire [W_PH-1:0]        num_pd = num_q + d_q;

    // homing: the count that makes tr == P (in2 && s_pos && at_last, at_last: tr == P - 1 after
    // the previous call), a register formed in the previous call from the next stage, at_last and
    // the look-ahead inputs, so the load enable of B, C, Z, L and the selects behind it start at a
    // flip-flop
    wire homing = hom_q;
    wire signed [W_TR-1:0] tr_s = tr_q + (s_pos ? 1 : 0) - (s_neg ? 1 : 0);
    // A + dir*P for B (formed every call from registers; used at homing, >= 2P calls after A),
    // as x + dir*y = x + (y ^ bwd) + bwd (the inversion is a LUT in front of the chain, the
    // carry-in the chain's own), in two parts: the low W_CZ bits in one call, the high part
    // with the low part's carry of the previous call (bs_c), so bs is exact from the second call
    // after A on. The homing call forms C = B + dir*mark_len and Z = B + dir*P/4 as a W_CZ-bit
    // add and a select of the high part: bs's, or bs's + dir (bs_pm, a register formed from
    // bs in the calls before: exact from the third call after A), by the low part's carry
    // (forward) or its absence (backward)
    wire                    bwd_x  = bw_b_q;   // !fwd_q (a register: no inverter in front of the chain)
    wire [W_CZ:0]           bs_lo  = {1'b0, a_q[W_CZ-1:0]} +
                                     {1'b0, period_x[W_CZ-1:0] ^ {W_CZ{bwd_x}}} + {{W_CZ{1'b0}}, bwd_x};
    wire [W_POS-W_CZ-1:0]   bs_hi  = a_q[W_POS-1:W_CZ] + {(W_POS-W_CZ){bwd_x}} +
                                     {{(W_POS-W_CZ-1){1'b0}}, bs_c_q};
    wire [W_POS-W_CZ-1:0]   bs_pm_n = bs_q[W_POS-1:W_CZ] + {{(W_POS-W_CZ-1){bwd_x}}, 1'b1};
    function signed [W_POS-1:0] b_add;       // bs + dir*y (y < 2^W_CZ) at homing
        input signed [W_POS-1:0] b;
        input [W_POS-W_CZ-1:0]   b_pm;       // b's high part + dir
        input [W_CZ-1:0]         y;
        input                    bw;
        reg [W_CZ:0]             lo;
        begin
            lo    = {1'b0, b[W_CZ-1:0]} + {1'b0, y ^ {W_CZ{bw}}} + {{W_CZ{1'b0}}, bw};
            b_add = {(lo[W_CZ] ^ bw) ? b_pm : b[W_POS-1:W_CZ], lo[W_CZ-1:0]};
        end
    endfunction
    wire signed [W_POS-1:0] c_hom  = b_add(bs_q, bs_pm_q, mark_len_x[W_CZ-1:0], bw_c_q);
    wire signed [W_POS-1:0] z_hom  = b_add(bs_q, bs_pm_q, p4_x[W_CZ-1:0], bw_z_q);
    wire signed [W_POS-1:0] bs_nx  = {bs_hi, bs_lo[W_CZ-1:0]};
    // out_pos moves by ostep (osu_q / osd_q) in two halves like pos_step, but the low half's wrap
    // tests are registers (op_one_q: low half all ones, op_zero_q: low half zero), formed in the
    // call before from equalities of the register and its step, so the high half's enable is one
    // LUT of registers
    wire [W_LO-1:0]         op_lo  = out_pos_q[W_LO-1:0] + {{(W_LO-1){osd_q}}, osu_q || osd_q};
    wire [W_POS-W_LO-1:0]   op_hi  = out_pos_q[W_POS-1:W_LO];
    wire signed [W_POS-1:0] op_nx  = {(osu_q && op_one_q) ? op_hi + 1'b1 :
                                      (osd_q && op_zero_q) ? op_hi - 1'b1 : op_hi, op_lo};
    wire                    op_h1  = out_pos_q[W_LO-1:1] == {(W_LO-1){1'b1}};
    wire                    op_h0  = out_pos_q[W_LO-1:1] == {(W_LO-1){1'b0}};
    wire                    op_b0  = out_pos_q[0];
    // the next low half is all ones: ...10 and +1, all ones and 0, zero and -1; zero: all ones
    // and +1, zero and 0, ...01 and -1
    wire op_one_n  = osu_q ? (op_h1 && !op_b0) : osd_q ? (op_h0 && !op_b0) : (op_h1 && op_b0);
    wire op_zero_n = osu_q ? (op_h1 && op_b0) : osd_q ? (op_h0 && op_b0) : (op_h0 && !op_b0);
    // the paced counter adds the late pstep itself (s in -2..1), as pos_step does, but the low
    // half's wrap tests are registers (pa_ones_q: all ones, pa_zero_q: 0, pa_one_q: 1), formed
    // in the call before from equalities of the register and the step of that call, so the late
    // step meets them in one LUT in front of the high half's select: up at all ones with +1,
    // down at 0 with -1 or -2, and at 1 with -2. Equal to pos_step(paced, pstep) for every s.
    wire [W_LO-1:0]         pa_lo  = paced_q[W_LO-1:0] + {{(W_LO-2){i_pstep[1]}}, i_pstep};
    wire [W_POS-W_LO-1:0]   pa_hi  = paced_q[W_POS-1:W_LO];
    wire                    pa_up  = i_pstep == 2'sd1 && pa_ones_q;
    wire                    pa_dn  = i_pstep[1] && (pa_zero_q || (!i_pstep[0] && pa_one_q));
    wire signed [W_POS-1:0] paced_nx = {pa_up ? pa_hi + 1'b1 : pa_dn ? pa_hi - 1'b1 : pa_hi, pa_lo};
    // equalities of the low half: bits [W_LO-1:2] all ones / zero, then the two low bits
    wire                    pa_h1  = paced_q[W_LO-1:2] == {(W_LO-2){1'b1}};
    wire                    pa_h0  = paced_q[W_LO-1:2] == {(W_LO-2){1'b0}};
    wire [1:0]              pa_b   = paced_q[1:0];
    // the next low half (low + s) is all ones: low = ones - s; zero: low = -s; one: low = 1 - s
    reg                     pa_ones_n, pa_zero_n, pa_one_n;
    always @* begin
        case (i_pstep)
            2'sd0:   begin pa_ones_n = pa_h1 && pa_b == 2'd3; pa_zero_n = pa_h0 && pa_b == 2'd0; pa_one_n = pa_h0 && pa_b == 2'd1; end
            2'sd1:   begin pa_ones_n = pa_h1 && pa_b == 2'd2; pa_zero_n = pa_h1 && pa_b == 2'd3; pa_one_n = pa_h0 && pa_b == 2'd0; end
            -2'sd1:  begin pa_ones_n = pa_h0 && pa_b == 2'd0; pa_zero_n = pa_h0 && pa_b == 2'd1; pa_one_n = pa_h0 && pa_b == 2'd2; end
            default: begin pa_ones_n = pa_h0 && pa_b == 2'd1; pa_zero_n = pa_h0 && pa_b == 2'd2; pa_one_n = pa_h0 && pa_b == 2'd3; end
        endcase
    end
    // the steps of adj and u from their own registers (sign-extended)
    wire signed [W_POS-1:0] adj_st = {{(W_POS-1){as_q[1]}}, as_q[0]};
    wire signed [W_POS-1:0] u_st   = {{(W_POS-1){us_q[1]}}, us_q[0]};
    // the next at_last (tr' == P - 1) by equalities of the register tr (tr >= 0 always), and the
    // step back past A (tr' < 0) without the add: no compare follows the tr add
    wire signed [W_TR-1:0] tr_px  = $signed({1'b0, i_period});
    wire signed [W_TR-1:0] tr_pm1 = i_period_m1;  // P - 1
    wire signed [W_TR-1:0] tr_pm2 = i_period_m2;  // P - 2
    wire        tr_is0   = tr_q == {W_TR{1'b0}};
    wire        tr_is1   = tr_q == {{(W_TR-1){1'b0}}, 1'b1};
    wire        tr_ismax = tr_q == {1'b0, {(W_TR-1){1'b1}}};
    wire        tr_back  = (s_neg && tr_is0) || (s_pos && tr_ismax);   // tr + s < 0
    wire        p_is1    = i_period == 13'd1;                          // 0 == P - 1
    wire        last_hold = tr_q == tr_pm1;
    wire        last_s    = s_pos ? (tr_q == tr_pm2) : s_neg ? (tr_q == tr_px) : last_hold;

    // 6. mark test on u before the count: u' = u + s in [0, L]. Without a count it is the mark
    //    register itself (in stage 3 mark_q is the test of u_q). For a count (s = +1: u in
    //    [-1, L - 1]; s = -1: u in [1, L + 1]) the tests are registers (mp_q, mn_q) formed in the
    //    previous call from u_q and L: u and L do not change in the call before a count
    //    (real counts are >= 2 calls apart, and homing is a count), so no compare precedes the
    //    mark register. L is held inverted (nlen_q = ~L, nlen1_q = ~(L + 1)), so each compare is
    //    the carry of a chain without an inverted operand: u < L <=> no carry of u + ~L + 1,
    //    u <= L + 1 <=> no carry of u + ~(L + 1) (W_P + 1 bits)
    wire        u_hz   = u_q[W_POS-1:W_P+1] == {(W_POS-W_P-1){1'b0}}; // 0 <= u < 2^14
    wire        u_m1   = u_q == {W_POS{1'b1}};                         // u == -1
    wire [W_P:0] u_lo  = u_q[W_P:0];
    wire [W_P+1:0] lt_s = {1'b0, u_lo} + {2'b01, nlen_q} + {{(W_P+1){1'b0}}, 1'b1};
    wire [W_P+1:0] le_s = {1'b0, u_lo} + {1'b0, nlen1_q};
    wire        u_lt   = !lt_s[W_P+1];
    wire        u_le1  = !le_s[W_P+1];
    wire        u_ge1  = u_lo != {(W_P+1){1'b0}};
    wire        mp_n   = u_m1 || (u_hz && u_lt);                      // u + 1 in [0, L]
    wire        mn_n   = u_hz && u_ge1 && u_le1;                      // u - 1 in [0, L]
    wire        in_rng = s_pos ? mp_q : s_neg ? mn_q : mark_q;

    // 5. the output step (ostep_n above). lag' is 0 (a call with unhome or rehome: the leave
    // drops a pending extra count), lag - sgn(lag) (a slot), lag + 1 / lag - 1 (an extra count
    // with pstep = +1 / -1) or lag, in 2-bit arithmetic (-1..1 under the block precondition; a
    // broken precondition wraps, as in hls); for each value of pstep the extra-count test
    // (dq_nz with that pstep) is a function of registers, so the late pstep only drives the
    // last select
    wire signed [W_LAG-1:0] lag_ml = lag_q - lsgn;
    wire signed [W_LAG-1:0] lag_p1 = lag_q + 2'sd1;
    wire signed [W_LAG-1:0] lag_m1 = lag_q - 2'sd1;
    // the extra-count test per pstep value without the leave term: a call with unhome or rehome
    // clears lag, which the last select applies (lv), so the unhome level meets lag' only in the
    // last LUT
    wire                    dq_p   = stage_q == ST_WINDOW && (fwd_q ? (!fr && !t_q[W_BR-1])
                                                               : (tr_pos && v_q[W_BR-1]));
    wire                    dq_m   = stage_q == ST_WINDOW && (fwd_q ? (tr_pos && v_q[W_BR-1])
                                                               : (!fr && !t_q[W_BR-1]));
    (* keep *) wire lv;
    assign lv = un_q || re_q;
    (* keep *) wire signed [W_LAG-1:0] lag_cp, lag_cm;   // lag' for pstep = +1 / -1
    assign lag_cp = dq_p ? lag_p1 : lag_q;
    assign lag_cm = dq_m ? lag_m1 : lag_q;
    // the next call may pay out an extra count: its slot, without unhome or rehome (look-ahead)
    wire                    xs_nx  = i_slot_nx && !(i_unhome_nx || i_rehome_nx);
    wire signed [W_LAG-1:0] lag_n  = lv ? {W_LAG{1'b0}} : pz ? (sl_q ? lag_ml : lag_q) : pn_q ? lag_cm : lag_cp;
    // sign bits and low parts of the Bresenham registers (outside the always block)
    wire              t_neg  = t_q[W_BR-1];
    wire              v_neg  = v_q[W_BR-1];
    wire [W_PH-1:0]   t_lo   = t_q[W_PH-1:0];
    wire [W_PH-1:0]   v_lo   = v_q[W_PH-1:0];
    wire [W_PH-1:0]   v_pp_lo = v_pp[W_PH-1:0];

    always @* begin
        stage_d    = stage_q;
        a_d        = a_q;
        fwd_d      = fwd_q;
        d_d        = d_q;
        tr_d       = tr_q;
        fresh_d    = fresh_q;
        num_d      = num_q;
        b_d        = b_q;
        c_d        = c_q;
        z_d        = z_q;
        nlen_d     = nlen_q;
        nlen1_d    = nlen1_q;
        wa_d       = wa_q;
        dm_d       = dm_q;
        dnew_d     = 1'b0;
        first_d    = 1'b0;

        // 1. taps
        paced_d    = paced_nx;
        fwd_last_d = pz ? fwd_last_q : pfwd;
        // 3. phase
        w_d        = w_n;

        // 4a. the window state (travel, Bresenham) by the stage before the call, without the
        //     leave / capture decisions (they read the late unhome level): in stage 1 it is held
        //     at its value at A (tr = 0, num = 0, fresh), so the capture needs no load; a stage-2
        //     call steps it even when it leaves (stage 1 then resets it in the next call)
        if (stage_q == ST_UNHOMED) begin
            tr_d    = {W_TR{1'b0}};
            fresh_d = 1'b1;
            num_d   = {W_PH{1'b0}};
        end else if (stage_q == ST_WINDOW) begin
            if (s_pos) begin
                if (fr) fresh_d = 1'b0;                   // num = 0: no carry; num' = d,
                                                          // t' = 2d - P, v' = 0 in the next call
                else if (!t_neg) num_d = t_lo;            // carry: num + d - P
                else             num_d = num_pd;
            end else if (s_neg && tr_pos) begin
                if (v_neg) num_d = v_pp_lo;               // borrow: num - d + P
                else       num_d = v_lo;
            end
            tr_d = tr_back ? {W_TR{1'b0}} : tr_s;
        end
        first_d = in2 && s_pos && fr;
        // 4b. stage machine
        if (leave) begin
            stage_d = ST_UNHOMED;                               // the adjustment stays in place
        end else if (stage_q == ST_UNHOMED) begin
            if (cap) begin
                stage_d = ST_WINDOW;
                a_d     = paced_d;
                fwd_d   = fwd_last_d;
                wa_d    = w_n;
                dm_d    = {!fwd_last_d, fwd_last_d ? z0_n : h_n};
                dnew_d  = 1'b1;
            end
        end else if (stage_q == ST_WINDOW) begin
            if (homing)       stage_d = ST_HOMED;
            else if (tr_back) stage_d = ST_UNHOMED;             // back past A
        end                                                     // ST_HOMED: the stage holds
        // the homing count (hom_q: stage 2, no leave, a count up from tr = P - 1, so never
        // the step back past A) loads B, C, Z and L: their enable is the flip-flop itself
        if (homing) begin
            b_d     = bs_q;
            c_d     = c_hom;
            z_d     = z_hom;
            nlen_d  = i_mark_len_n;
            nlen1_d = {1'b1, i_mark_len_n} + {(W_P+1){1'b1}};   // ~L - 1 = ~(L + 1)
        end
        // tr' > 0 without a compare after the tr add (tr >= 0 always: the step back past A
        // leaves with tr' = 0): 0 at A and on that step; +1 gives tr' >= 1; -1 gives tr' > 0 iff
        // tr >= 2; otherwise tr is held
        if (stage_q == ST_UNHOMED)     tr_pos_d = 1'b0;
        else if (stage_q == ST_WINDOW) tr_pos_d = !tr_back && (s_pos || (tr_pos_q && !(s_neg && tr_is1)));
        else                           tr_pos_d = tr_pos_q;
        if (dnew_q) d_d = d_new;      // (= d_cur there: the sum straight into the register)
        k_d       = d_br - px_br;     // from the register d: valid from the third call after A
        bs_d      = bs_nx;
        // at_last' = (tr' == P - 1), from the case that formed tr'
        if (stage_q == ST_UNHOMED || (stage_q == ST_WINDOW && tr_back)) at_last_d = p_is1;
        else if (stage_q == ST_WINDOW)                                   at_last_d = last_s;
        else                                                             at_last_d = last_hold;

        // 5. output step: the real count, or else one pending extra count
        ostep_d   = ostep_n;
        out_pos_d = op_nx;
        // (adj moves by sgn(lag) in a call without a real count: its step is a register of its
        // own, as_q, formed in the previous call with osu_q / osd_q, so the plain 38-bit chain
        // starts at flip-flops beside it)
        adj_d     = adj_q + adj_st;
        lag_d     = lag_n;

        // 6. reference mark
        // (a plain 38-bit up/down counter: its step is a register of its own, us_q = s_neg /
        // s_pos || s_neg, kept apart from sp_q / sn_q and their fan-out, so the carry chain starts
        // at flip-flops placed beside it and needs no split)
        u_d    = homing ? {W_POS{1'b0}} : u_q + u_st;
        mark_d = homing || (in3 && in_rng);
    end

    // num' = d and t' = 2d - P of the first count after A, loaded in the call after that count
    // (first) from the register d (loaded in the call after A, so at the latest in the call of
    // the first count); real counts are >= 2 calls apart, so no count reads (num, t) in between,
    // and no path runs from wA into these registers
    wire [W_PH-1:0]         num_nx    = first_q ? d_q : num_d;
    // t = num + d - P and v = num - d are formed from num in every call (the call after a count
    // sees the new num: real counts are >= 2 calls apart, so the next count finds them formed);
    // in the call after the first count they take num' = d directly (t = 2d - P, v = 0)
    wire signed [W_BR-1:0]  t_nx      = first_q ? t_ld : t_rc;
    wire signed [W_BR-1:0]  v_nx      = first_q ? {W_BR{1'b0}} : v_rc;

    always @(posedge i_clk) begin
        if (i_rst) begin
            stage_q    <= ST_UNHOMED;
            paced_q    <= {W_POS{1'b0}};
            out_pos_q  <= {W_POS{1'b0}};
            op_one_q   <= 1'b0;
            op_zero_q  <= 1'b1;
            pa_ones_q  <= 1'b0;
            pa_zero_q  <= 1'b1;
            pa_one_q   <= 1'b0;
            adj_q      <= {W_POS{1'b0}};
            fwd_last_q <= 1'b1;
            sw_prev_q  <= 1'b0;
            sw_seen_q  <= 1'b0;
            a_q        <= {W_POS{1'b0}};
            bs_q       <= {W_POS{1'b0}};
            bs_c_q     <= 1'b0;
            bs_pm_q    <= {(W_POS-W_CZ){1'b0}};
            fwd_q      <= 1'b1;
            bw_c_q     <= 1'b0;
            bw_b_q     <= 1'b0;
            bw_z_q     <= 1'b0;
            d_q        <= {W_PH{1'b0}};
            wa_q       <= {W_PH{1'b0}};
            dm_q       <= 2'd0;
            dnew_q     <= 1'b0;
            k_q        <= {W_BR{1'b0}};
            tr_q       <= {W_TR{1'b0}};
            tr_pos_q   <= 1'b0;
            at_last_q  <= 1'b0;
            fresh_q    <= 1'b0;
            first_q    <= 1'b0;
            num_q      <= {W_PH{1'b0}};
            t_q        <= {W_BR{1'b0}};
            v_q        <= {W_BR{1'b0}};
            lag_q      <= {W_LAG{1'b0}};
            w_q        <= {W_PH{1'b0}};
            t1_q       <= 1'b0;
            z0_q       <= 1'b0;
            h_q        <= 1'b0;
            w_init_q   <= 1'b0;
            u_q        <= {W_POS{1'b0}};
            nlen_q     <= {W_P{1'b1}};              // ~L of L = 0
            nlen1_q    <= {{W_P{1'b1}}, 1'b0};      // ~(L + 1) of L = 0
            b_q        <= {W_POS{1'b0}};
            c_q        <= {W_POS{1'b0}};
            z_q        <= {W_POS{1'b0}};
            ostep_q    <= 2'sd0;
            mark_q     <= 1'b0;
            idx_q      <= 1'b0;
            mp_q       <= 1'b0;
            mn_q       <= 1'b0;
        end else begin
            stage_q    <= stage_d;
            paced_q    <= paced_d;
            out_pos_q  <= out_pos_d;
            op_one_q   <= op_one_n;
            op_zero_q  <= op_zero_n;
            pa_ones_q  <= pa_ones_n;
            pa_zero_q  <= pa_zero_n;
            pa_one_q   <= pa_one_n;
            adj_q      <= adj_d;
            fwd_last_q <= fwd_last_d;
            sw_prev_q  <= i_sw;
            sw_seen_q  <= i_sw_valid;
            a_q        <= a_d;
            bs_q       <= bs_d;
            bs_c_q     <= bs_lo[W_CZ];
            bs_pm_q    <= bs_pm_n;
            fwd_q      <= fwd_d;
            bw_c_q     <= !fwd_d;
            bw_b_q     <= !fwd_d;
            bw_z_q     <= !fwd_d;
            d_q        <= d_d;
            wa_q       <= wa_d;
            dm_q       <= dm_d;
            dnew_q     <= dnew_d;
            k_q        <= k_d;
            tr_q       <= tr_d;
            tr_pos_q   <= tr_pos_d;
            at_last_q  <= at_last_d;
            fresh_q    <= fresh_d;
            first_q    <= first_d;
            num_q      <= num_nx;
            t_q        <= t_nx;
            v_q        <= v_nx;
            lag_q      <= lag_d;
            w_q        <= w_d;
            t1_q       <= t1_n;
            z0_q       <= z0_n;
            h_q        <= h_n;
            w_init_q   <= 1'b1;
            u_q        <= u_d;
            nlen_q     <= nlen_d;
            nlen1_q    <= nlen1_d;
            b_q        <= b_d;
            c_q        <= c_d;
            z_q        <= z_d;
            ostep_q    <= ostep_d;
            mark_q     <= mark_d;
            idx_q      <= mark_q && w_q == {{(W_PH-W_P+2){1'b0}}, i_period[W_P-1:2]};
            mp_q       <= mp_n;
            mn_q       <= mn_n;
        end
        // the count decode of the next call: its pstep against its fwd (the reset value in a
        // reset call)
        sp_q <= i_pstep_nx != 2'sd0 && (!i_pstep_nx[1] == (i_rst || fwd_d));
        sn_q <= i_pstep_nx != 2'sd0 && (!i_pstep_nx[1] != (i_rst || fwd_d));
        pp_q <= i_pstep_nx != 2'sd0 && !i_pstep_nx[1];
        hom_q <= !i_rst && stage_d == ST_WINDOW && !(i_unhome_nx || i_rehome_nx) && at_last_d &&
                 i_pstep_nx != 2'sd0 && (!i_pstep_nx[1] == fwd_d);
        us_q <= {i_pstep_nx != 2'sd0 && (!i_pstep_nx[1] != (i_rst || fwd_d)), i_pstep_nx != 2'sd0};
        pn_q <= i_pstep_nx[1];
        un_q <= i_unhome_nx;
        // the output step of the next call: its pstep, or else in its slot (without unhome or
        // rehome) the sign of the next lag (0 after a reset call)
        osu_q <= (i_pstep_nx == 2'sd0) ? (!i_rst && xs_nx && lag_n == 2'sd1) : (i_pstep_nx == 2'sd1);
        osd_q <= (i_pstep_nx == 2'sd0) ? (!i_rst && xs_nx && lag_n[1]) : i_pstep_nx[1];
        osd_w_q <= (i_pstep_nx == 2'sd0) ? (!i_rst && xs_nx && lag_n[1]) : i_pstep_nx[1];
        as_q  <= {i_pstep_nx == 2'sd0 && !i_rst && xs_nx && lag_n[1],
                  i_pstep_nx == 2'sd0 && !i_rst && xs_nx && lag_n != 2'sd0};
        sl_q <= i_slot_nx;
        re_q <= i_rehome_nx;
    end

    assign o_ostep   = ostep_q;
    assign o_out_pos = out_pos_q;
    assign o_mark    = mark_q;
    assign o_index   = idx_q;
    assign o_stage   = stage_q;
    assign o_a       = a_q;
    assign o_d       = d_cur;
    assign o_b       = b_q;
    assign o_c       = c_q;
    assign o_z       = z_q;
    assign o_adj     = adj_q;
    assign o_homed   = stage_q == ST_HOMED;

`ifdef FORMAL
    // ---- formal properties (read_verilog -formal; see docs/FORMAL.md) --------------------------
    // Assumptions: the block-level preconditions of DESIGN 4.5, which the top guarantees: P is a
    // free constant (f_per) with 8 <= P <= 4096, P % 8 == 0; pstep in {-1, 0, +1}; no real count
    // in two consecutive calls (pace M >= 2); no slot in the call of a real count, and a real
    // count that the pacer emitted while wide (rephase's stage two calls before: the pacer sees
    // the stage one call late and decides a count one call before rephase gets it) is followed
    // by a slot before the next count; mark_len in its legal range [P/4, P]. The switch,
    // its valid flag, rehome and unhome are free in every call.
    // References (f_*), written from the text of DESIGN 4.5 (not from the hardware form above):
    // the paced position, the stage machine, the travel tr = dir * (paced - A), the adjustment
    // target adj_tgt kept as adj0 + dir * q with the division state (q, r) of d * tr by P
    // (q = floor(d * tr / P), r = d * tr mod P, moved by one Bresenham step per count: no
    // multiply), and phases mod P: f_po of the output position, f_pt of paced + adj_tgt.
    reg               f_init;
    initial f_init = 1'b0;
    reg [W_P-1:0]     f_per;                 // P (no initial value: any, then kept)
    reg               f_pnz;                 // the previous call had a real count
    reg signed [1:0]  f_pnx;                 // i_pstep_nx of the previous call
    reg               f_unx, f_rnx;          // i_unhome_nx / i_rehome_nx of the previous call
    reg               f_snx;                 // i_slot_nx of the previous call
    reg [1:0]         f_sgp;                 // f_stage before the previous call (the pacer's wide)
    reg               f_owe;                 // a count emitted while wide waits for its slot
    reg               f_swp, f_sws;
    reg [1:0]         f_stage;
    reg               f_dlast, f_dir;        // direction of the last count, homing direction
    reg [W_POS-1:0]   f_paced, f_a, f_tgt, f_adj0, f_b, f_adjh;
    reg signed [W_TR-1:0] f_tr;
    reg [W_P-1:0]     f_q, f_r, f_d, f_pha, f_pt, f_po, f_phb, f_len;
    reg               f_anew;                // the previous call was A
    reg [1:0]         f_age;                 // calls since A, saturating at 3
    reg [W_POS-1:0]   f_adjr;                // adj + lag of the RTL after the homing call
    reg               f_idxo;                // the previous call: homed, paced in [B, C], ph_out = P/8
    reg               f_idxz;                // the previous call: homed, paced == Z

    wire [W_P-1:0]   f_p8  = {3'b000, f_per[W_P-1:3]};
    wire [W_P-1:0]   f_p4  = {2'b00, f_per[W_P-1:2]};
    wire [W_P-1:0]   f_p38 = f_p4 + f_p8;                       // 3P/8
    wire [W_P-1:0]   f_p78 = f_per - f_p8;                      // 7P/8
    wire [W_POS-1:0] f_perx = {{(W_POS-W_P){1'b0}}, f_per};
    // (x + y) mod P and (x - y) mod P for x, y in [0, P)
    function [W_P-1:0] f_addp(input [W_P-1:0] x, input [W_P-1:0] y, input [W_P-1:0] p);
        reg [W_P:0] s;
        begin
            s = {1'b0, x} + {1'b0, y};
            f_addp = (s >= {1'b0, p}) ? s - {1'b0, p} : s[W_P-1:0];
        end
    endfunction
    function [W_P-1:0] f_subp(input [W_P-1:0] x, input [W_P-1:0] y, input [W_P-1:0] p);
        begin
            f_subp = (x >= y) ? x - y : x + p - y;
        end
    endfunction
    // a step -1 / 0 / +1 of a phase mod P
    function [W_P-1:0] f_stp(input [W_P-1:0] x, input signed [1:0] s, input [W_P-1:0] p);
        begin
            f_stp = (s == 2'sd1) ? ((x + 1'b1 == p) ? {W_P{1'b0}} : x + 1'b1) :
                    (s == -2'sd1) ? ((x == {W_P{1'b0}}) ? p - 1'b1 : x - 1'b1) : x;
        end
    endfunction
    // dir * x on positions
    function [W_POS-1:0] f_dx(input fw, input [W_POS-1:0] x);
        begin
            f_dx = fw ? x : -x;
        end
    endfunction

    // ---- the reference of one call (DESIGN 4.5 steps 1, 2, 4) ----
    wire             f_pz     = i_pstep == 2'sd0;
    wire             f_pf     = i_pstep == 2'sd1;
    wire [W_POS-1:0] f_pacedn = f_paced + {{(W_POS-2){i_pstep[1]}}, i_pstep};
    wire             f_dlastn = f_pz ? f_dlast : f_pf;
    wire             f_rise   = i_sw && !f_swp && f_sws;
    wire             f_leave  = (i_unhome || i_rehome) && f_stage != ST_UNHOMED;
    wire             f_capt   = !f_leave && f_stage == ST_UNHOMED && f_rise && !i_unhome;
    wire             f_in2    = !f_leave && f_stage == ST_WINDOW;
    wire             f_sp     = !f_pz && (f_pf == f_dir);       // a count in the homing direction
    wire             f_sn     = !f_pz && (f_pf != f_dir);
    wire signed [W_TR-1:0] f_trn = f_tr + (f_sp ? 1 : 0) - (f_sn ? 1 : 0);
    wire             f_back   = f_in2 && f_trn < 0;
    wire             f_home   = f_in2 && f_trn == $signed({1'b0, f_per});
    // d of the reference: with FORMAL_PHASE the text's d, from the target phase at A (f_dn);
    // otherwise d as the RTL forms it in the call after A (its value is then not checked)
`ifdef FORMAL_PHASE
    wire [W_P-1:0]   f_dv     = f_d;
`else
    wire [W_P-1:0]   f_dv     = f_anew ? {1'b0, d_cur} : f_d;
`endif
    // one step of (q, r) = divmod(d * tr, P) for tr -> tr +- 1: the reference step of
    // rtl_ref/formal/fv_bresenham.v (the one proof rephase_div shows to divide)
    wire [W_P-1:0]   f_qn, f_rn;
    wire signed [1:0] f_dq;
    fv_bresenham u_f_div (.i_per(f_per), .i_d(f_dv), .i_q(f_q), .i_r(f_r),
                          .i_up(f_in2 && !f_back && f_sp), .i_dn(f_in2 && !f_back && f_sn),
                          .o_q(f_qn), .o_r(f_rn), .o_dq(f_dq));
    // adj_tgt moves by dir * dq; its phase with paced: (paced + adj_tgt) mod P
    wire signed [1:0] f_dtg   = f_dir ? f_dq : -f_dq;
    wire [W_POS-1:0] f_tgtn   = f_tgt + {{(W_POS-2){f_dtg[1]}}, f_dtg};
    wire [W_P-1:0]   f_ptn    = f_stp(f_stp(f_pt, i_pstep, f_per), f_dtg, f_per);
    // d at A from the target phase there: (7P/8 - phA) mod P forward, (phA - 3P/8) mod P back
    wire [W_P-1:0]   f_dn     = f_dlastn ? f_subp(f_p78, f_ptn, f_per) : f_subp(f_ptn, f_p38, f_per);
    // (phA + dir * ((tr + q) mod P)) mod P: the target phase inside the window
    wire [W_P:0]     f_tq     = f_tr[W_P:0] + {1'b0, f_q};
    wire [W_P-1:0]   f_tqm    = (f_tq >= {1'b0, f_per}) ? f_tq - {1'b0, f_per} : f_tq[W_P-1:0];
    wire [W_P-1:0]   f_pwin   = f_dir ? f_addp(f_pha, f_tqm, f_per) : f_subp(f_pha, f_tqm, f_per);
    // the RTL's pending count and mark length extended to positions; tr from the RTL's paced
    wire [W_POS-1:0] f_lagx   = {{(W_POS-W_LAG){lag_q[W_LAG-1]}}, lag_q};
    wire [W_POS-1:0] f_ta     = f_dx(f_dir, paced_q - f_a);
    wire [W_P-1:0]   len_q    = ~nlen_q;                          // L
    wire [W_POS-1:0] f_lenx   = {{(W_POS-W_P){1'b0}}, len_q};
    wire [W_P-1:0]   f_plag   = f_stp(f_po, lag_q[1:0], f_per);  // (out_pos + lag) mod P
    wire             f_xs     = i_slot && !(i_unhome || i_rehome);  // a slot that may pay out

    always @(posedge i_clk) begin
        f_per <= f_per;
        f_pnx <= i_pstep_nx;
        f_unx <= i_unhome_nx;
        f_rnx <= i_rehome_nx;
        f_snx <= i_slot_nx;
        f_sgp <= i_rst ? ST_UNHOMED : f_stage;
        // the index of DESIGN 4.5 step 5, of the reference state of this call (before the edge)
        f_idxo <= !i_rst && f_stage == ST_HOMED && f_dx(f_dir, f_paced - f_b) <= {{(W_POS-W_P){1'b0}}, f_len} &&
                  f_po == f_p8;
        f_idxz <= !i_rst && f_stage == ST_HOMED && f_paced == f_b + f_dx(f_dir, {{(W_POS-W_P){1'b0}}, f_p4});
        f_owe <= i_rst ? 1'b0 : !f_pz ? (f_sgp == ST_WINDOW) : i_slot ? 1'b0 : f_owe;
        if (i_rst) begin
            f_init  <= 1'b1;
            f_pnz   <= 1'b0;
            f_swp   <= 1'b0;
            f_sws   <= 1'b0;
            f_stage <= ST_UNHOMED;
            f_dlast <= 1'b1;
            f_dir   <= 1'b1;
            f_paced <= {W_POS{1'b0}};
            f_a     <= {W_POS{1'b0}};
            f_tgt   <= {W_POS{1'b0}};
            f_adj0  <= {W_POS{1'b0}};
            f_b     <= {W_POS{1'b0}};
            f_adjh  <= {W_POS{1'b0}};
            f_adjr  <= {W_POS{1'b0}};
            f_tr    <= {W_TR{1'b0}};
            f_q     <= {W_P{1'b0}};
            f_r     <= {W_P{1'b0}};
            f_d     <= {W_P{1'b0}};
            f_pha   <= {W_P{1'b0}};
            f_pt    <= {W_P{1'b0}};
            f_po    <= {W_P{1'b0}};
            f_phb   <= {W_P{1'b0}};
            f_len   <= {W_P{1'b0}};
            f_anew  <= 1'b0;
            f_age   <= 2'd3;
        end else begin
            f_pnz   <= !f_pz;
            f_swp   <= i_sw;
            f_sws   <= i_sw_valid;
            f_dlast <= f_dlastn;
            f_paced <= f_pacedn;
            f_tgt   <= f_tgtn;
            f_pt    <= f_ptn;
            f_po    <= f_stp(f_po, ostep_n, f_per);
            f_anew  <= f_capt;
            f_age   <= f_capt ? 2'd0 : (f_age == 2'd3 ? f_age : f_age + 2'd1);
            if (f_leave) begin
                f_stage <= ST_UNHOMED;
                // the text: adj0' = adj (the applied adjustment; a pending extra count is
                // dropped), adj_tgt' = adj0'; its phase with paced' = that of out_pos + pstep
                f_tgt   <= adj_q;
                f_pt    <= f_stp(f_po, i_pstep, f_per);
            end else if (f_capt) begin
                f_stage <= ST_WINDOW;
                f_dir   <= f_dlastn;
                f_a     <= f_pacedn;
                f_adj0  <= f_tgt;                 // stage 1: the target does not move
                f_tr    <= {W_TR{1'b0}};
                f_q     <= {W_P{1'b0}};
                f_r     <= {W_P{1'b0}};
                f_pha   <= f_ptn;
                f_d     <= f_dn;
            end else if (f_stage == ST_WINDOW) begin
                f_d  <= f_dv;
                f_tr <= f_trn;
                f_q  <= f_qn;
                f_r  <= f_rn;
                if (f_back) begin
                    f_stage <= ST_UNHOMED;
                end else if (f_home) begin
                    f_stage <= ST_HOMED;
                    f_b     <= f_a + f_dx(f_dir, f_perx);
                    f_len   <= i_mark_len;
                    f_phb   <= f_ptn;
                    f_adjh  <= f_tgtn;
                    f_adjr  <= adj_d + {{(W_POS-W_LAG){lag_d[W_LAG-1]}}, lag_d};
                end
            end
        end
    end

    wire signed [W_POS-1:0] f_lq = $signed({{(W_POS-W_P){1'b0}}, len_q});
    wire [W_POS-W_CZ-1:0] f_bspm = bs_q[W_POS-1:W_CZ] + {{(W_POS-W_CZ-1){!f_dir}}, 1'b1};  // + dir
    always @* begin
        assume(i_period == f_per);
        assume(i_period_m1 == $signed({1'b0, f_per}) - 14'sd1 && i_period_m2 == $signed({1'b0, f_per}) - 14'sd2);
        assume(f_per >= 13'd8 && f_per <= 13'd4096 && f_per[2:0] == 3'b000);
        assume(i_pstep != -2'sd2);
        assume(!f_init || i_pstep == f_pnx);                  // the look-ahead inputs are exact
        assume(!f_init || (i_unhome == f_unx && i_rehome == f_rnx));
        assume(!f_init || i_slot == f_snx);
        assume(!(i_slot && !f_pz));                           // no slot with a real count
        assume(!(f_owe && !f_pz));                            // a slot before the next count
        assume(!(f_init && f_pnz && !f_pz));                  // real counts >= 2 calls apart
        assume(i_mark_len >= f_p4 && i_mark_len <= f_per);
        assume(i_mark_len_n == ~i_mark_len);

        if (f_init) begin
            // the registered level copies are this call's unhome / rehome
            assert(un_q == i_unhome && re_q == i_rehome && sl_q == i_slot);
            // the registered count decode is that of this call's pstep against fwd
            assert(s_pos == (!pz && pfwd == fwd_q) && s_neg == (!pz && pfwd != fwd_q));
            // the other registered decodes: the sign of pstep, the steps of u, w / out_pos, adj
            assert(pp_q == (i_pstep == 2'sd1) && pn_q == (i_pstep == -2'sd1));
            assert(us_q == {s_neg, s_pos || s_neg});
            assert(osu_q == (i_pstep == 2'sd1 || (i_pstep == 2'sd0 && f_xs && lag_q == 2'sd1)));
            assert(osd_q == (i_pstep == -2'sd1 || (i_pstep == 2'sd0 && f_xs && lag_q[1])));
            assert(osd_w_q == osd_q);
            assert(as_q == {i_pstep == 2'sd0 && f_xs && lag_q[1], i_pstep == 2'sd0 && f_xs && lag_q != 2'sd0});
            // the output moves only in the call of a real count or of a slot (so consecutive
            // output counts are as far apart as the pacer's events: max(M, 2) calls)
            if (ostep_n != 2'sd0) assert(!f_pz || i_slot);
            // the paced stream, the stage machine and its inputs follow the text
            assert(paced_q == f_paced);
            assert(stage_q == f_stage && f_stage != 2'd0);
            assert(fwd_last_q == f_dlast && sw_prev_q == f_swp && sw_seen_q == f_sws);
            // output = paced + applied adjustment; the output moves by at most one count per
            // call; lag = adj_tgt - adj is -1, 0 or +1, non-zero only right after a real count
            // (so it is paid out in the next call), its sign register exact
            assert(out_pos_q == paced_q + adj_q);
            assert(bw_c_q == !fwd_q && bw_z_q == !fwd_q && bw_b_q == !fwd_q);
            assert(hom_q == (in2 && s_pos && at_last_q));
            assert(nlen1_q == ~({1'b0, len_q} + 1'b1));
            // the mark tests of a count: those of u and L, which did not change in a call without
            // a count (homing is a count)
            if (!f_pnz) assert(mp_q == (u_q >= -38'sd1 && u_q < f_lq) && mn_q == (u_q >= 38'sd1 && u_q <= f_lq + 38'sd1));
            assert(op_one_q == (out_pos_q[W_LO-1:0] == {W_LO{1'b1}}) &&
                   op_zero_q == (out_pos_q[W_LO-1:0] == {W_LO{1'b0}}));
            assert(pa_ones_q == (paced_q[W_LO-1:0] == {W_LO{1'b1}}) &&
                   pa_zero_q == (paced_q[W_LO-1:0] == {W_LO{1'b0}}) &&
                   pa_one_q == (paced_q[W_LO-1:0] == {{(W_LO-1){1'b0}}, 1'b1}));
            assert(paced_nx == pos_step(paced_q, i_pstep));
            assert(ostep_q != -2'sd2);
            assert(lag_q == {W_LAG{1'b0}} || (f_owe && (lag_q == 1 || lag_q == -1)));
            if (f_stage == ST_UNHOMED) assert(lag_q == {W_LAG{1'b0}});
            // the pacer's wide (the stage before the previous call) is on in stage 2 from the
            // call after A on (helper invariant: the only count without it, the first after A,
            // changes no lag)
            if (f_stage == ST_WINDOW && !f_anew) assert(f_sgp == ST_WINDOW);
            // the per-pstep forms of the extra-count test are the test itself
            if (i_pstep == 2'sd1)  assert((dq_p && !lv) == dq_nz);
            if (i_pstep == -2'sd1) assert((dq_m && !lv) == dq_nz);
            assert(dnew_q == f_anew && f_anew == (f_age == 2'd0));
            if (f_anew) assert(f_stage != ST_HOMED);                 // homing takes P counts
            if (first_q) assert(f_stage == ST_WINDOW && !fresh_q);   // right after the first count
            assert(!tr_q[W_TR-1] && tr_pos_q == (tr_q != {W_TR{1'b0}}));   // tr >= 0, tr_pos
`ifdef FORMAL_ADJ
            // the adjustment target of the text: adj + lag
            assert(adj_q + f_lagx == f_tgt);
            // the output position's phase (f_po); w = (ph_out + P/8) mod P with its wrap flags
            assert(f_po < f_per);
            if (!w_init_q) assert(f_po == {W_P{1'b0}} && lag_q == {W_LAG{1'b0}});  // after reset
            if (!w_init_q) assert(!t1_q && !z0_q && !h_q);      // the flags of w = P/8
            if (!w_init_q) assert(stage_q == ST_UNHOMED && !mark_q);  // (a reset call was the last)
            if (w_init_q) begin
                assert(w_q == f_addp(f_po, f_p8, f_per));
                assert(t1_q == (w_q == f_per - 1'b1));
                assert(z0_q == (w_q == {W_PH{1'b0}}));
                assert(h_q == ({1'b0, w_q} >= (f_per >> 1)));
            end
            // the index: the output state at phase P/8 (Z's phase, 4.5 phase check) inside [B, C]
            // of the previous call
            assert(idx_q == f_idxo);
            // from A on: d < P, loaded in the call after A
            if (f_stage != ST_UNHOMED) begin
                if (!f_anew) assert(f_d < f_per);
                assert(wa_q < f_per);
                assert(dm_q == {!fwd_q, fwd_q ? (wa_q == {W_PH{1'b0}}) : ({1'b0, wa_q} >= (f_per >> 1))});
                if (!dnew_q) assert({1'b0, d_q} == f_d);
            end
`ifdef FORMAL_PHASE
            // the phase of paced + adj_tgt (f_pt = f_po + lag); from A on, d = (7P/8 - phA) mod P
            // forward, (phA - 3P/8) mod P backward, phA that phase at A
            assert(f_pt < f_per);
            assert(f_pt == f_plag);
            if (f_stage != ST_UNHOMED) begin
                assert(f_pha < f_per);
                assert({1'b0, d_cur} == f_d);
                assert(wa_q == f_addp(f_pha, f_p8, f_per));         // w at A
                assert(f_d == (f_dir ? f_subp(f_p78, f_pha, f_per) : f_subp(f_pha, f_p38, f_per)));
            end
`endif
`endif
            if (f_stage != ST_UNHOMED) assert(a_q == f_a && fwd_q == f_dir);
            // ---- stage 2: the adjustment is adj0 + dir * floor(d * tr / P), tr in [0, P) ----
            if (f_stage == ST_WINDOW) begin
                assert(f_tr >= 0 && f_tr < $signed({1'b0, f_per}));
                assert(f_ta == {{(W_POS-W_TR){f_tr[W_TR-1]}}, f_tr});   // tr = dir * (paced - A)
                assert(tr_q == f_tr);
                assert(at_last_q == (f_tr == $signed({1'b0, f_per}) - 1));
                // A + dir*P in two parts: the low part's carry from the call after A on, bs from
                // the second, bs_pm (its high part + dir) from the third
                if (f_age >= 2'd1) assert(bs_c_q == bs_lo[W_CZ]);
                if (f_age >= 2'd2) assert(bs_q == f_a + f_dx(f_dir, f_perx));
                if (f_age == 2'd3) assert(bs_pm_q == f_bspm);
                if (f_age == 2'd0) assert(fresh_q);                  // no count yet after A
                if (f_age != 2'd3) assert(f_tr <= 1);                // counts >= 2 calls apart
                if (f_age == 2'd1) assert(f_tr == 0 || f_pnz);
                if (fresh_q) assert(f_tr == 0 && !first_q);
                if (f_age == 2'd1 && !fresh_q) assert(first_q);       // a count in the call after A
                if (first_q) assert(f_tr == 1 && f_pnz && f_age != 2'd0); // the call after the first count
`ifdef FORMAL_ADJ
                assert(f_r < f_per);
                // the facts F1..F3 of (q, r) = divmod(d * tr, P), proven for the reference
                // step by proof rephase_div (assumed here, so that this proof has no multiply)
                assume(f_q <= f_d && $signed({1'b0, f_q}) <= f_tr);
                if (f_tr == 0) assume(f_q == {W_P{1'b0}} && f_r == {W_P{1'b0}});
                if (f_tr == $signed({1'b0, f_per}) - 1)
                    assume(f_d == {W_P{1'b0}} ? (f_q == {W_P{1'b0}} && f_r == {W_P{1'b0}})
                                              : (f_q == f_d - 1'b1 && f_r == f_per - f_d));
                assert(f_tgt == f_adj0 + f_dx(f_dir, {{(W_POS-W_P){1'b0}}, f_q}));
`ifdef FORMAL_PHASE
                assert(f_pt == f_pwin);
`endif
                // hardware state: num = r; t = num + d - P, v = num - d after the first count;
                // k = d - P from the third call after A, d loaded in the call after A
                // (num, t) of the first count are loaded in the call after it (first), from d
                if (first_q) assert({1'b0, d_q} == f_r);
                else assert({1'b0, num_q} == f_r);
                if (f_age >= 2'd2) assert(k_q == $signed({2'b00, d_q}) - $signed({1'b0, f_per}));
                // t and v are formed from num in every call: exact unless the previous call
                // moved num (a real count; no count reads them then, counts >= 2 calls apart)
                if (fresh_q) assert(f_r == 0);
                else if (!first_q && !f_pnz) begin
                    assert(t_q == $signed({2'b00, num_q}) + $signed({2'b00, d_q}) - $signed({1'b0, f_per}));
                    assert(v_q == $signed({2'b00, num_q}) - $signed({2'b00, d_q}));
                end
`endif
            end
            // ---- stage 3 (homed) ----
            if (f_stage == ST_HOMED) begin
                // B - A = dir * P, Z - B = dir * P/4 (so Z - A = dir * (P + P/4)),
                // C - B = dir * mark_len of the homing call
                assert(b_q == f_b && f_b == f_a + f_dx(f_dir, f_perx));
                assert(z_q - a_q == f_dx(f_dir, f_perx + {{(W_POS-W_P){1'b0}}, f_p4}));
                assert(len_q == f_len && c_q == b_q + f_dx(f_dir, f_lenx));
                assert(nlen1_q == ~({1'b0, len_q} + 1'b1));
                // the adjustment is fixed from homing on: the output travels exactly as the
                // paced stream (out_pos = paced + adj, adj + lag = its value at homing, lag
                // paid out in the call after a count)
                assert(adj_q + f_lagx == f_adjr);
`ifdef FORMAL_ADJ
                assert(f_tgt == f_adjh && f_adjr == f_adjh);
`endif
`ifdef FORMAL_PHASE
                // the phase of B + adj at homing: 7P/8 forward, 3P/8 backward (so Z = B +
                // dir * P/4 is at P/8 in both directions)
                assert(f_phb == (f_dir ? f_p78 : f_p38));
`endif
                // the mark: exactly on the closed interval [B, C] of the paced position
                assert(paced_q == b_q + f_dx(f_dir, u_q));          // u = dir * (paced - B)
                assert(mark_q == (u_q <= f_lenx));
            end else begin
                assert(!mark_q);
            end
`ifdef FORMAL_PHASE
            // with the phase at homing of the text (stated, not proven: FORMAL.md), the index is
            // the paced position Z of the previous call
            assert(idx_q == f_idxz);
`endif
        end
    end
`endif

endmodule

`default_nettype wire
