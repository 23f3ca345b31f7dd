// rephase.h — referencing state machine: stage 1/2/3, points A, B, Z, C, phase adjustment d.
//
// DESIGN §4.5 (Figure 4 of Laser scale referencing, docs/SOURCES.md). Positions are counted on
// the paced stream of real output counts. At A (rising edge of the debounced reference switch) the block computes the extra
// advance d in [0, P) that puts the output phase at P/8 (sin == cos > 0) at Z = A + dir*(P + P/4),
// and spreads it over the P counts from A to B as adj = adj0 + dir * floor(d * tr / P), where tr is
// the real travel beyond A. Hardware form (§4.5 "Hardware form"; every per-call path is one
// narrow carry chain from registers, the 38-bit positions are taps):
//   * floor(d*tr/P) is kept by a Bresenham state (num, t = num + d - P, v = num - d): the carry
//     of a forward count is the sign of t, the borrow of a backward count the sign of v, so the
//     extra count of this call is known from registers before the count arrives; a count moves
//     num (one 14-bit add of registers), t = num + k and v = num - d are formed from the
//     registers in every call, so they are exact again before the next count (k = d - P is a
//     register, computed the call after A; the first count after A never carries and needs no
//     k: `fresh`; its (num, t, v) = (d, 2d - P, 0) are loaded in the call after it, from the
//     register d: `first`);
//   * the pending extra counts are a small signed lag (adj_tgt - adj): ostep = pstep, or else in
//     the pacer's slot sgn(lag); no 38-bit adjustment target and no 38-bit compare; a call with
//     unhome or rehome clears lag (the leave drops a pending extra count, DESIGN §4.5 step 2);
//   * the phase is kept as w = (ph_out + P/8) mod P of the output position (w moves by ostep,
//     -1..1, with registered wrap flags); at A no extra count is pending, so it is the target
//     phase there; at A it is registered (wA) with the form of d (a mode from the direction and
//     the flags w == 0, w >= P/2), and d is formed from them in the call after A (one add: P - wA
//     forward, wA -/+ P/2 backward; o.d shows it from A on);
//   * the mark is a relative counter u = dir * (paced - B) from homing on: mark = u in [0, L]
//     (L = mark_len at homing);
//   * the homing call is flagged a call ahead (`at_last`: tr == P - 1) and B = A + dir*P is formed
//     in the calls before it (`bs`, two parts over two calls), so B is copied and C, Z are formed
//     by a 13-bit add and a select of the high part (bs's, or bs_pm = bs's + dir) in that call.
// The extra count is delivered in the pacer's slot, M calls after the real count it follows and
// before the next (the pacer owes a slot to every count it emits while the window is open), so
// consecutive output counts are at least max(M, 2) calls apart in every stage.
//
// Widths: positions 38 signed (taps: paced, out_pos, adj, A, B, C, Z; the mark counter u),
// d/num/w 12 unsigned, t/v/k 14 signed, tr 14 signed, lag 2 signed (-1..1), stage 2.
// Latency: 1 call (pstep, slot in, ostep/out_pos/mark out); extra counts in the slot.
// Block-level preconditions (laserax_top guarantees them): P is constant while the block runs (a
// change of P restarts the chain from reset); real counts are >= 2 calls apart, no slot comes with
// a real count, and a count that changes lag is followed by a slot before the next count, so
// |lag| <= 1, lag = 0 at A (w is then the target phase) and k is in time for the first carry. A block-level
// caller that breaks them gets the same bits here and in rtl_ref/, not necessarily those of the
// golden model (DESIGN §4.5 "Hardware form").
#ifndef LASERAX_HLS_REPHASE_H
#define LASERAX_HLS_REPHASE_H

#include "hls/axis_config.h"

namespace lx {

struct rephase_cfg {
    static constexpr int W_PH = axis_widths::W_PH;     // d, num, w: 0..P-1
    static constexpr int W_P = axis_widths::W_P;       // period and mark_len registers, L
    static constexpr int W_TR = axis_widths::W_P + 1;  // travel beyond A, -1..P, signed
    static constexpr int W_BR = axis_widths::W_P + 1;  // Bresenham t, v, k in [-P, P), signed
    static constexpr int W_LAG = 2;  // adj_tgt - adj, signed: -1..1 (counts >= 2 calls apart)
    static constexpr int W_CZ = axis_widths::W_P;          // low part of B = A + dir*P, C, Z
    static constexpr int W_CZH = axis_widths::W_POS - W_CZ;  // their high part
    using ph_t = uint<W_PH>;
    using p_t = uint<W_P>;
    using tr_t = sint<W_TR>;
    using br_t = sint<W_BR>;
    using lag_t = sint<W_LAG>;
    static constexpr int W_STAGE = 2;  // the stage output: 1, 2, 3
    using stage_t = uint<W_STAGE>;    // the stage output: a stage_id value
    // the referencing stages (DESIGN 4.5): the values of the stage register and of out_t::stage
    enum stage_id : unsigned {
        STAGE_UNHOMED = 1,  // stage 1: un-homed, waiting for the switch edge (A)
        STAGE_WINDOW = 2,   // stage 2: from A towards B, d paid out over P counts
        STAGE_HOMED = 3     // stage 3: homed, phase locked, mark on [B, C]
    };
    using dm_t = uint<2>;       // the form of d at A (d_of)
    using czl_t = uint<W_CZ>;
    using czh_t = uint<W_CZH>;
};

class rephase {
public:
    using cfg = rephase_cfg;
    struct out_t {
        step_t ostep = 0;
        pos_t out_pos = 0;
        bool mark = false;
        bool index = false;  // mark && w == P/4 of the previous call (DESIGN 4.5 step 5)
        cfg::stage_t stage = 0;
        pos_t a = 0, b = 0, c = 0, z = 0, adj = 0;
        cfg::ph_t d = 0;
        bool homed = false;
    };

    void reset() { *this = rephase{}; }  // every register to its initialiser (the reset value)

    // One clock (DESIGN 4.5, Hardware form).
    out_t step(step_t pstep, bool slot, bool sw, bool sw_valid, bool rehome, bool unhome, period_t period,
               period_t mark_len) {
        const cfg::p_t pp = period;
        const cfg::ph_t p8 = period >> 3;  // P/8 (P is a multiple of 8)
        const bool leave = (unhome || rehome) && stage_ != cfg::STAGE_UNHOMED;
        const bool in2 = stage_ == cfg::STAGE_WINDOW && !leave;
        const bool in3 = stage_ == cfg::STAGE_HOMED && !leave;
        const cfg::p_t len_prev = len_;
        const step_t s = fwd_ ? pstep : step_t(-pstep);  // step in the homing direction
        // 7. index: the register of the mark and the output phase of the previous call, w == P/4
        //    at Z only inside [B, C] (DESIGN 4.5, Hardware form)
        idx_ = mark_ && w_ == cfg::ph_t(pp >> 2);

        // 1. taps: real position, direction of the last real count
        paced_ = paced_ + pstep;
        if (pstep != 0) fwd_last_ = pstep > 0;

        // 2. the extra count of this call, from registers: carry of a forward count (t >= 0),
        //    borrow of a backward count inside the window (v < 0)
        //    ((num, t) are not valid before the first count after A and in the call after it:
        //    a forward count there is a first count, no carry)
        const bool fr = fresh_ || first_;
        step_t dq = 0;
        if (in2 && s > 0 && !fr && t_ >= 0) dq = 1;
        if (in2 && s < 0 && tr_ > 0 && v_ < 0) dq = -1;
        const step_t dadj = fwd_ ? dq : step_t(-dq);

        // 3. phase of the output position, w = (ph_out + P/8) mod P: moves by ostep (-1..1). At A
        //    no extra count is pending (lag = 0: the block precondition), so this is the phase of
        //    the target position there. The wrap flags t1 (w == P - 1) and z0 (w == 0) are
        //    registers, formed for the next value from w by equality with P - 2, P, 1, all ones.
        // (the sign of pstep: -2, outside the pacer's -1..1, counts -1 here as in rtl_ref/)
        // (an extra count only in the pacer's slot, and none in a call with unhome or rehome)
        const bool lv = unhome || rehome;
        step_t ostep = pstep > 0 ? step_t(1) : pstep < 0 ? step_t(-1) : step_t(0);
        if (pstep == 0 && slot && !lv) {
            if (lag_ > 0) ostep = 1;
            if (lag_ < 0) ostep = -1;
        }
        move_w(ostep, w_init_ ? w_ : p8, pp);  // (ph = 0 after reset)

        // 4. stage machine
        // d: formed from the phase at A in the call after A (dnew), then held
        const cfg::ph_t d_reg = d_;
        const cfg::ph_t d_cur = dnew_ ? d_of(wa_, dm_, pp) : d_;
        const bool first = first_;
        dnew_ = false;
        const pos_t a_prev = a_;
        const bool fwd_prev = fwd_;
        const bool rise = sw && !sw_prev_ && sw_seen_;
        // 4a. the window state (travel, Bresenham) by the stage before the call, without the
        //     leave / capture decisions: held at its value at A (tr = 0, num = 0, fresh) in
        //     stage 1, so the capture loads none of it; a stage-2 call steps it even when it
        //     leaves (stage 1 resets it in the next call)
        const bool homing = in2 && s > 0 && at_last_;  // tr' == P
        bool back = false;
        // t = num + d - P and v = num - d are formed from the registers num, k, d in every call
        // (so after a count they are exact again in the next call, before the next count)
        const cfg::br_t t_rc = cfg::br_t(cfg::br_t(num_) + k_);
        const cfg::br_t v_rc = cfg::br_t(cfg::br_t(num_) - cfg::br_t(d_reg));
        if (stage_ == cfg::STAGE_UNHOMED) {
            tr_ = 0;
            fresh_ = true;
            num_ = 0;
        } else if (stage_ == cfg::STAGE_WINDOW) {
            if (s > 0) {
                if (fr) {  // num = 0: no carry; num' = d, t' = 2d - P, v' = 0 in the next call
                    fresh_ = false;
                } else if (t_ >= 0) {  // num + d >= P: carry
                    num_ = cfg::ph_t(t_);
                } else {
                    num_ = cfg::ph_t(num_ + d_);
                }
            } else if (s < 0 && tr_ > 0) {
                if (v_ < 0) {  // num < d: borrow
                    num_ = cfg::ph_t(v_ + cfg::br_t(pp));
                } else {
                    num_ = cfg::ph_t(v_);
                }
            }
            tr_ = tr_ + s;
            if (tr_ < 0) {
                back = true;
                tr_ = 0;
            }
        }
        first_ = in2 && s > 0 && fr;
        // 4b. stage machine
        if (leave) {
            stage_ = cfg::STAGE_UNHOMED;  // the adjustment in place stays (no phase jump)
        } else {
            switch (stage_) {
            case cfg::STAGE_UNHOMED:
                if (rise && !unhome) {
                    stage_ = cfg::STAGE_WINDOW;
                    a_ = paced_;
                    fwd_ = fwd_last_;
                    wa_ = w_;  // the phase at A; d follows from it in the next call
                    dm_ = cfg::dm_t((fwd_ ? 0 : 2) + ((fwd_ ? z0_ : h_) ? 1 : 0));
                    dnew_ = true;
                }
                break;
            case cfg::STAGE_WINDOW:
                if (back) {
                    stage_ = cfg::STAGE_UNHOMED;  // back past A: the adjustment is 0 here
                } else if (homing) {
                    stage_ = cfg::STAGE_HOMED;
                    const pos_t bb = bs_;  // A + dir*P, formed in an earlier call
                    b_ = bb;
                    c_ = b_add(bb, bs_pm_, cfg::czl_t(mark_len), fwd_);
                    z_ = b_add(bb, bs_pm_, cfg::czl_t(2 * p8), fwd_);
                    len_ = mark_len;
                }
                break;
            default:  // STAGE_HOMED: holds, the switch is ignored
                break;
            }
        }
        // the call after the first count after A: num = d, t = 2d - P from the register d (loaded
        // in the call after A; no count reads them in between, counts are >= 2 calls apart)
        t_ = t_rc;
        v_ = v_rc;
        if (first) {
            num_ = d_reg;
            t_ = cfg::br_t(cfg::br_t(d_reg) + cfg::br_t(d_reg) - cfg::br_t(pp));
            v_ = 0;
        }
        d_ = d_cur;
        // k = d - P from the register d (before this call's load): valid from the third call
        // after A, and the first carry can come no earlier (counts >= 2 calls apart)
        k_ = cfg::br_t(cfg::br_t(d_reg) - cfg::br_t(pp));
        form_bs(a_prev, fwd_prev, pp);
        at_last_ = tr_ == tr_t(pp) - 1;
        sw_prev_ = sw;
        sw_seen_ = sw_valid;

        // 5. output step (ostep above): the real count, or else in a slot one pending extra
        //    count; unhome or rehome drops a pending one (the leave, DESIGN §4.5 step 2)
        if (lv) {
            lag_ = 0;
        } else if (pstep != 0) {
            lag_ = lag_ + dadj;
        } else {
            lag_ = lag_ - ostep;
        }
        if (pstep == 0) adj_ = adj_ + ostep;
        out_pos_ = out_pos_ + ostep;

        // 6. reference mark: u = dir * (paced - B) from homing on, mark = u in [0, L]
        // (the tests for a count are registers, mp (forward) and mn (backward), formed in the
        // previous call from u and L, which do not change in the call before a count. Without a
        // count it is the mark register itself, which in stage 3 is the test of u)
        const bool in_rng = s > 0 ? mp_ : s < 0 ? mn_ : mark_;
        mark_tests(len_prev);  // from u and L before this call's update
        u_ = homing ? pos_t(0) : pos_t(u_ + s);
        const bool mark = homing || (in3 && in_rng);
        mark_ = mark;

        return outputs(ostep, mark, dnew_ ? d_of(wa_, dm_, pp) : d_);
    }

private:
    // the outputs of a call from the registers after it (step)
    out_t outputs(step_t ostep, bool mark, cfg::ph_t d) const {
        out_t o;
        o.ostep = ostep;
        o.out_pos = out_pos_;
        o.mark = mark;
        o.index = idx_;
        o.stage = cfg::stage_t(static_cast<unsigned>(stage_));
        o.a = a_;
        o.b = b_;
        o.c = c_;
        o.z = z_;
        o.adj = adj_;
        o.d = d;
        o.homed = stage_ == cfg::STAGE_HOMED;
        return o;
    }

    // 3. the phase w of the output position moved by ostep (-1..1) from w0 (w, or P/8 before the
    //    first call), with its wrap flags (step)
    void move_w(step_t ostep, cfg::ph_t w0, cfg::p_t pp) {
        using x_t = sint<cfg::W_P + 2>;
        const x_t px = x_t(pp);
        // the flags after reset are those of w = P/8 for every legal P (>= 8): false
        const bool t1 = t1_;
        const bool z0 = z0_;
        const bool h = h_;  // w >= P/2 (for the form of d at A)
        const cfg::ph_t p2 = cfg::ph_t(pp >> 1);
        const cfg::ph_t p2m1 = cfg::ph_t((px - 2) >> 1);  // P/2 - 1, from P - 2 as in rtl_ref/
        if (ostep > 0) {
            w_ = t1 ? cfg::ph_t(0) : cfg::ph_t(w0 + 1);
            t1_ = t1 ? (px == 1) : (x_t(w0) == px - 2);
            z0_ = t1 ? true : (w0 == cfg::ph_t(-1));
            h_ = t1 ? false : (h || w0 == p2m1);
        } else if (ostep < 0) {
            w_ = z0 ? cfg::ph_t(px - 1) : cfg::ph_t(w0 - 1);
            t1_ = z0 ? true : (x_t(w0) == px);
            z0_ = z0 ? (cfg::ph_t(px - 1) == 0) : (w0 == 1);
            h_ = z0 ? true : (h && w0 != p2);
        } else {
            w_ = w0;
            t1_ = t1;
            z0_ = z0;
        }
        w_init_ = true;
    }

    using tr_t = cfg::tr_t;

    // d from the phase w at A: (7P/8 - ph) mod P = (P - w) mod P forward,
    // (ph - 3P/8) mod P = (w - P/2) mod P backward. The form is the mode m registered at A from
    // the direction and the flags z0 (w == 0), h (w >= P/2): 0 P - w, 1 (forward, w == 0) 0,
    // 2 w + P/2, 3 w - P/2 (rtl_ref/: one 12-bit add of two operands, each a LUT of registers)
    static cfg::ph_t d_of(cfg::ph_t w, cfg::dm_t m, cfg::p_t p) {
        const cfg::ph_t p2 = cfg::ph_t(p >> 1);
        if (m == 0) return cfg::ph_t(p - w);
        if (m == 1) return cfg::ph_t(0);
        if (m == 2) return cfg::ph_t(w + p2);
        return cfg::ph_t(w - p2);
    }

    // bs = A + dir*P (register of the call, used at homing): the low W_CZ bits now, the high
    // part with the low part's carry of the previous call (bs_c), as x + (y ^ bwd) + bwd; bs_pm
    // is the high part of bs before the call + dir (DESIGN 4.5 "Hardware form"); formed in every
    // call from the registers A and dir (read only by the homing call)
    void form_bs(const pos_t& a, bool fwd, cfg::p_t pp) {
        using l1_t = uint<cfg::W_CZ + 1>;
        const cfg::czl_t ones = cfg::czl_t((1u << cfg::W_CZ) - 1u);
        const cfg::czl_t y = fwd ? cfg::czl_t(pp) : cfg::czl_t(ones - cfg::czl_t(pp));  // P ^ ones
        const l1_t lo = l1_t(l1_t(cfg::czl_t(a)) + l1_t(y) + l1_t(fwd ? 0 : 1));
        const cfg::czh_t hi = cfg::czh_t(cfg::czh_t(a >> cfg::W_CZ) + cfg::czh_t(fwd ? 0 : -1) +
                                         cfg::czh_t(bs_c_ ? 1 : 0));
        bs_pm_ = cfg::czh_t(cfg::czh_t(bs_ >> cfg::W_CZ) + cfg::czh_t(fwd ? 1 : -1));
        bs_c_ = (lo >> cfg::W_CZ) != 0;
        bs_ = pos_t((uint<axis_widths::W_POS>(hi) << cfg::W_CZ) | uint<axis_widths::W_POS>(cfg::czl_t(lo)));
    }

    // the mark tests for a count in the next call, from u and L of this call before its update
    // (rtl_ref/: mp_q, mn_q): u in [-1, L - 1] for a forward count, [1, L + 1] for a backward one
    void mark_tests(cfg::p_t len) {
        mp_ = u_ >= -1 && u_ < pos_t(len);
        mn_ = u_ >= 1 && u_ <= pos_t(pos_t(len) + 1);
    }

    // C / Z at homing: b + dir*y (y < 2^W_CZ) as a W_CZ-bit add; the high part is b's, or b's + dir
    // (b_pm) when the low add carries (forward) or does not (backward)
    static pos_t b_add(const pos_t& b, cfg::czh_t b_pm, cfg::czl_t y, bool fwd) {
        using l1_t = uint<cfg::W_CZ + 1>;
        const cfg::czl_t ones = cfg::czl_t((1u << cfg::W_CZ) - 1u);
        const cfg::czl_t yx = fwd ? y : cfg::czl_t(ones - y);
        const l1_t lo = l1_t(l1_t(cfg::czl_t(b)) + l1_t(yx) + l1_t(fwd ? 0 : 1));
        const bool c = (lo >> cfg::W_CZ) != 0;
        const cfg::czh_t hi = (c == fwd) ? b_pm : cfg::czh_t(b >> cfg::W_CZ);
        return pos_t((uint<axis_widths::W_POS>(hi) << cfg::W_CZ) | uint<axis_widths::W_POS>(cfg::czl_t(lo)));
    }

    cfg::stage_id stage_ = cfg::STAGE_UNHOMED;
    pos_t paced_ = 0;
    pos_t out_pos_ = 0;
    pos_t adj_ = 0;
    bool fwd_last_ = true;
    bool sw_prev_ = false;
    bool sw_seen_ = false;
    pos_t a_ = 0;
    pos_t bs_ = 0;
    bool bs_c_ = false;
    cfg::czh_t bs_pm_ = 0;
    bool fwd_ = true;
    cfg::ph_t d_ = 0;
    cfg::ph_t wa_ = 0;
    cfg::dm_t dm_ = 0;
    bool dnew_ = false;
    cfg::br_t k_ = 0;
    cfg::tr_t tr_ = 0;
    bool at_last_ = false;
    bool fresh_ = false;
    bool first_ = false;
    cfg::ph_t num_ = 0;
    cfg::br_t t_ = 0;
    cfg::br_t v_ = 0;
    cfg::lag_t lag_ = 0;
    cfg::ph_t w_ = 0;
    bool t1_ = false;
    bool z0_ = false;
    bool h_ = false;
    bool w_init_ = false;
    pos_t u_ = 0;
    cfg::p_t len_ = 0;
    bool mark_ = false;        // the mark
    bool idx_ = false;         // the index (mark && w == P/4 of the call before)
    bool mp_ = false;     // the mark tests of a forward / backward count in the next call
    bool mn_ = false;
    pos_t b_ = 0;
    pos_t c_ = 0;
    pos_t z_ = 0;
};

}  // namespace lx

#endif  // LASERAX_HLS_REPHASE_H
