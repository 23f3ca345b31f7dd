// output_pacer.h — rate limiter for the compensated count stream.
//
// DESIGN §4.4. Incoming count deltas (any size: a ratio update can jump by thousands) are added to
// a signed backlog; one count at a time leaves, at most one per max(M, 2) calls. Nothing is
// dropped: the backlog drains at 1/M counts per call once motion stops, and a backlog above the
// threshold raises an alarm (pulse plus sticky flag, cleared by `clear` once the backlog is below
// again). The emitted count is decided from the registers before the call (registered output).
// Events (an emitted count or a slot) are at least max(M, 2) calls apart; a count emitted while
// `wide` (rephase in its window, stage 2) owes a slot, M calls later and before the next count,
// in which rephase delivers its extra count (DESIGN §4.4, §4.5), so the output of the chain moves
// at most once per M calls in every stage.
//
// Two addends: the multiplier delta and the error-map delta (small, W_ADD bits) enter separately,
// so no adder precedes the backlog's own (the sum is formed in the carry-save layer of the lower
// half): B' = B + delta + add - emit.
//
// Hardware form (no carry chain over 23 bits): the backlog is kept as X = B + e_prev (the emitted
// count leaves X one call later, when no count can be emitted), split at L = 20 bits with a
// registered carry, X = (hi + cq) * 2^20 + lo, cq in -1 .. +2. The emit decision needs only sign
// and zero of X: equality trees on hi (== 0, -1, -2, +1) and lo (== 0) and the sign bit of hi, no
// chain (the RTL registers the first level of the trees, 4-bit pieces, and timer == 0 with the
// halves). The taps paced and backlog are formed off the loop, two calls late; ovs compares the
// backlog tap with the threshold in split pieces over two more calls.
//
// Widths: lo 20 unsigned, hi 20 signed, cq 3 signed, add 18 signed, timer 16, paced tap 19 + 19
// bits, backlog tap 20 + 20 bits. Latency: delta in at call t, the first count leaves at call
// t+1; its slot (if owed) M calls later; taps paced, backlog: 2 calls; ovs: 4 calls (threshold of
// the previous call).
#ifndef LASERAX_HLS_OUTPUT_PACER_H
#define LASERAX_HLS_OUTPUT_PACER_H

#include "hls/axis_config.h"

namespace lx {

struct output_pacer_cfg {
    static constexpr int W_PACE = 16;  // M register
    static constexpr int W_THR = 32;   // backlog alarm threshold
    static constexpr int W_BACKLOG = axis_widths::W_BACKLOG;
    static constexpr int W_POS = axis_widths::W_POS;
    static constexpr int L = W_BACKLOG / 2;          // 20: backlog split point
    static constexpr int W_HI = W_BACKLOG - L;       // 20
    static constexpr int LP = W_POS / 2;             // 19: paced split point
    static constexpr int W_PHI = W_POS - LP;         // 19
    static constexpr int W_THI = W_THR - L;          // 12: upper half of thr
    static constexpr int LH = L / 2;                 // 10: halves of the lower compare
    static constexpr int W_ADD = 18;                 // second addend (error-map delta), signed
    static_assert(W_ADD + 1 < L, "the second addend must stay inside the lower half");
    using pace_t = uint<W_PACE>;
    using thr_t = uint<W_THR>;
    using lo_t = uint<L>;
    using hi_t = sint<W_HI>;
    using add_t = sint<W_ADD>;
    using cy_t = sint<2>;          // tap carries -1, 0, +1
    using cq_t = sint<3>;          // backlog carry -1 .. +2
    using t_t = sint<L + 3>;       // lo + delta_lo + add - e: -2^(W_ADD-1) - 1 .. 2^(L+1) + 2^(W_ADD-1) - 2
    using plo_t = uint<LP>;
    using phi_t = sint<W_PHI>;
    using pt_t = sint<LP + 2>;     // plo + e: -1 .. 2^LP
    using cmp_t = sint<W_HI + 2>;  // hi half against the thr half
    using thi_t = uint<W_THI>;
};

class output_pacer {
public:
    using cfg = output_pacer_cfg;
    struct out_t {
        step_t pstep = 0;
        bool slot = false;    // the slot owed to the count before it (for rephase's extra count)
        pos_t paced = 0;      // tap: P(t-2)
        backlog_t backlog = 0;  // tap: B(t-2)
        bool ovs = false;     // |B(t-4)| > thr(t-1)
        bool ovs_st = false;
    };

    void reset() { *this = output_pacer{}; }  // every register to its initialiser (the reset value)

    out_t step(const delta_t& delta, const cfg::add_t& add, const cfg::pace_t& pace_m, const cfg::thr_t& thr,
               bool clear, bool wide) {
        // ---- ovs, second stage: select with the registered lower carry ----
        const bool ovs = o_cl_ ? o_y1_ : o_y0_;
        // ---- ovs, first stage: the backlog tap B(t-3) (register b_) against thr of this call ----
        ovs_stage1(thr);

        // ---- event decision from the registers of the previous call: an emitted count (sign
        //      and zero of X) while no slot is owed, or else the slot ----
        const bool ready = timer_ == 0 && !g_prev_;
        const step_t emit = (ready && !h_) ? emit_of_x() : step_t(0);
        const bool slot = ready && h_;

        // ---- taps (registers of the previous call; e_prev_ is e(t-1)) ----
        // backlog: stage B (B(t-2) from the stage-A registers), stage A (B(t-1) halves)
        b_ = cat_s<cfg::W_HI, cfg::L>(cfg::hi_t(a_hi_ + a_cy_), a_lo_);
        const cfg::t_t al = cfg::t_t(cfg::t_t(lo_) - e_prev_);
        a_lo_ = cfg::lo_t(al);
        a_cy_ = cfg::cy_t(al >> cfg::L);
        a_hi_ = cfg::hi_t(hi_ + cq_);
        // paced: split counter fed by e(t-1); the lower half is delayed one call
        p_lo_d_ = p_lo_;
        p_hi_ = cfg::phi_t(p_hi_ + p_cy_);
        const cfg::pt_t ps = cfg::pt_t(cfg::pt_t(p_lo_) + e_prev_);
        p_lo_ = cfg::plo_t(ps);
        p_cy_ = cfg::cy_t(ps >> cfg::LP);

        // ---- X' = X + delta + add - e_prev (split, registered carry; add joins the lower half) ----
        const cfg::t_t t = cfg::t_t(cfg::t_t(lo_) + cfg::t_t(cfg::lo_t(delta)) + cfg::t_t(add) - e_prev_);
        const cfg::hi_t d_hi = cfg::hi_t(delta >> cfg::L);
        hi_ = cfg::hi_t(hi_ + d_hi + cq_);
        lo_ = cfg::lo_t(t);
        cq_ = cfg::cq_t(t >> cfg::L);

        // ---- timer, slot owed, event flag ----
        if (emit != 0 || slot) {
            timer_ = pace_m - 1;  // (M = 0 loads 65535)
        } else if (timer_ != 0) {
            timer_ = dec_above_zero(timer_);  // (timer > 0: no wrap)
        }
        if (emit != 0) {
            h_ = wide;
        } else if (slot) {
            h_ = false;
        }
        g_prev_ = emit != 0 || slot;
        e_prev_ = emit;

        if (clear) ovs_st_ = false;
        if (ovs) ovs_st_ = true;

        out_t o;
        o.pstep = emit;
        o.slot = slot;
        o.paced = cat_s<cfg::W_PHI, cfg::LP>(p_hi_, p_lo_d_);  // (exact: no wrap)
        o.backlog = b_;
        o.ovs = ovs;  // (the select of registers: no register of its own)
        o.ovs_st = ovs_st_;
        return o;
    }

private:
    // the emit decision: sign and zero of X = (hi + cq) * 2^L + lo (trees, no chain)
    step_t emit_of_x() const {
        const bool hi_neg = hi_ < 0;
        bool h_zero = false;  // hi + cq == 0
        bool h_neg = false;   // hi + cq < 0
        if (cq_ == 0) {
            h_zero = hi_ == 0;
            h_neg = hi_neg;
        } else if (cq_ == 1) {
            h_zero = hi_ == -1;
            h_neg = hi_neg && hi_ != -1;
        } else if (cq_ == 2) {
            h_zero = hi_ == -2;
            h_neg = hi_neg && hi_ != -1 && hi_ != -2;
        } else {
            h_zero = hi_ == 1;
            h_neg = hi_neg || hi_ == 0;
        }
        const bool x_nz = !(h_zero && lo_ == 0);
        if (!x_nz) return 0;
        return h_neg ? step_t(-1) : step_t(1);
    }

    // ovs, first stage: the backlog tap B(t-3) (register b_, its halves) against thr (o_y1, o_y0,
    // o_cl)
    void ovs_stage1(cfg::thr_t thr) {
        const cfg::hi_t b_hi = cfg::hi_t(b_ >> cfg::L);
        const cfg::lo_t b_lo = cfg::lo_t(b_);
        const cfg::thi_t t_hi = cfg::thi_t(thr >> cfg::L);
        const cfg::lo_t t_lo = cfg::lo_t(thr);
        // B > thr: b_hi > t_hi, or equal halves and b_lo > t_lo
        const bool gt = (cfg::cmp_t(b_hi) > cfg::cmp_t(t_hi)) ||
                        (cfg::cmp_t(b_hi) == cfg::cmp_t(t_hi) && b_lo > t_lo);
        // B < -thr: (b_hi + t_hi + cs) < 0 with cs the carry of b_lo + t_lo, cs = cl ? cu1 : cu0
        // from the 10-bit halves; both outcomes of cl are registered
        const cfg::cmp_t u = cfg::cmp_t(b_hi) + cfg::cmp_t(t_hi);
        const bool neg0 = u < 0;
        const bool neg1 = cfg::cmp_t(u + 1) < 0;
        const uint<cfg::LH> bl_h = uint<cfg::LH>(b_lo >> cfg::LH), bl_l = uint<cfg::LH>(b_lo);
        const uint<cfg::LH> tl_h = uint<cfg::LH>(t_lo >> cfg::LH), tl_l = uint<cfg::LH>(t_lo);
        const bool cl = ((uint<cfg::LH + 1>(bl_l) + tl_l) >> cfg::LH) != 0;
        const bool cu0 = ((uint<cfg::LH + 1>(bl_h) + tl_h) >> cfg::LH) != 0;
        const bool cu1 = ((uint<cfg::LH + 1>(bl_h) + tl_h + 1) >> cfg::LH) != 0;
        o_y1_ = gt || (cu1 ? neg1 : neg0);
        o_y0_ = gt || (cu0 ? neg1 : neg0);
        o_cl_ = cl;
    }

    cfg::lo_t lo_ = 0;       // X = (hi + cq) * 2^L + lo
    cfg::hi_t hi_ = 0;
    cfg::cq_t cq_ = 0;
    step_t e_prev_ = 0;      // emitted count of the previous call (pstep register)
    bool g_prev_ = false;    // the previous call had an event (a count or a slot)
    bool h_ = false;         // a slot is owed (a count was emitted while wide)
    cfg::pace_t timer_ = 0;
    cfg::hi_t a_hi_ = 0;     // backlog tap, stage A: hi + cq, lo - e_prev (with carry)
    cfg::lo_t a_lo_ = 0;
    cfg::cy_t a_cy_ = 0;
    backlog_t b_ = 0;        // backlog tap, stage B: B(t-2), the halves hi (signed) * 2^L + lo
    cfg::plo_t p_lo_ = 0;    // paced tap: split counter
    cfg::plo_t p_lo_d_ = 0;
    cfg::phi_t p_hi_ = 0;
    cfg::cy_t p_cy_ = 0;
    bool o_y1_ = false;  // ovs first stage: the result for either lower carry, the carry
    bool o_y0_ = false;
    bool o_cl_ = false;
    bool ovs_st_ = false;
};

}  // namespace lx

#endif  // LASERAX_HLS_OUTPUT_PACER_H
