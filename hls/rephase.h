// rephase.h — referencing state machine: stage 1/2/3, points A, B, Z, C, phase adjustment d.
//
// DESIGN §4.5 (the seed's Figure 4). Positions are counted on the paced stream of real output
// counts. At A (rising edge of the debounced reference switch) the block computes the extra
// advance d in [0, P) that puts the output phase at P/8 (sin == cos > 0) at Z = A + dir*(P + P/4),
// and spreads it over the P counts from A to B as adj = adj0 + dir * floor(d * tr / P), where tr is
// the real travel beyond A. Hardware form: no divider anywhere —
//   * floor(d*tr/P) is kept by a Bresenham pair (q, num): a forward count adds d to num and carries
//     into q when num reaches P; a backward count undoes exactly that, so the adjustment is a
//     function of position inside the window and reversal unwinds it;
//   * the output phase (paced + adj_tgt) mod P is kept by a wrapping counter `ph`, so ph_A needs
//     no modulo.
// The extra count is delivered in the call after the real count it rides on (the pacer keeps real
// counts >= 2 calls apart), so the output never moves more than one count per call.
//
// Widths: positions 38 signed, d/num/q/ph 12 unsigned, tr 14 signed, stage 2.
// Latency: 1 call (pstep in, ostep/out_pos/mark out); extra counts +1 call.
#ifndef LASERAX_HLS_REPHASE_H
#define LASERAX_HLS_REPHASE_H

#include "hls/axis_config.h"

namespace lx {

struct rephase_cfg {
    static constexpr int W_PH = axis_widths::W_PH;   // d, num, q, ph: 0..P-1 (q: 0..P)
    static constexpr int W_P = axis_widths::W_P;     // period and mark_len registers
    static constexpr int W_TR = axis_widths::W_P + 1;  // travel beyond A, -1..P, signed
    static constexpr int W_SUM = axis_widths::W_P + 1; // num + d < 2P, unsigned
    using ph_t = uint<W_PH>;
    using q_t = uint<W_P>;
    using tr_t = sint<W_TR>;
    using sum_t = uint<W_SUM>;
    using stage_t = uint<2>;
};

class rephase {
public:
    using cfg = rephase_cfg;
    struct out_t {
        step_t ostep = 0;
        pos_t out_pos = 0;
        bool mark = false;
        cfg::stage_t stage = 0;
        pos_t a = 0, b = 0, c = 0, z = 0, adj = 0;
        cfg::ph_t d = 0;
        bool homed = false;
    };

    rephase() { reset(); }

    void reset() {
        stage_ = 1;
        paced_ = 0;
        fwd_last_ = true;
        sw_prev_ = false;
        sw_seen_ = false;
        a_ = 0;
        fwd_ = true;
        d_ = 0;
        tr_ = 0;
        num_ = 0;
        q_ = 0;
        adj0_ = 0;
        adj_tgt_ = 0;
        adj_ = 0;
        ph_ = 0;
        b_ = 0;
        c_ = 0;
        z_ = 0;
    }

    out_t step(step_t pstep, bool sw, bool sw_valid, bool rehome, bool unhome, period_t period,
               period_t mark_len) {
        const cfg::ph_t p8 = period >> 3;            // P/8 (P is a multiple of 8)
        const cfg::ph_t p_last = period - 1;
        // 1. real position and phase of the target output position
        paced_ = paced_ + pstep;
        if (pstep != 0) fwd_last_ = pstep > 0;
        ph_ = ph_step(ph_, pstep, p_last);

        // 2. stage machine
        const bool rise = sw && !sw_prev_ && sw_seen_;
        if ((unhome || rehome) && stage_ != 1) {
            stage_ = 1;
            adj0_ = adj_tgt_;  // freeze: no phase jump
        } else if (stage_ == 1) {
            if (rise && !unhome) {
                stage_ = 2;
                a_ = paced_;
                fwd_ = fwd_last_;
                tr_ = 0;
                num_ = 0;
                q_ = 0;
                // d = (7P/8 - ph_A) mod P forward, (ph_A - 3P/8) mod P backward
                using dd_t = sint<cfg::W_P + 2>;
                const dd_t dd = fwd_ ? dd_t(dd_t(period) - dd_t(p8) - dd_t(ph_))
                                     : dd_t(dd_t(ph_) - dd_t(3) * dd_t(p8));
                d_ = (dd < 0) ? cfg::ph_t(dd + period) : cfg::ph_t(dd);
            }
        } else if (stage_ == 2) {
            const step_t s = fwd_ ? pstep : step_t(-pstep);  // step in the homing direction
            step_t dq = 0;
            if (s > 0) {
                const cfg::sum_t sum = cfg::sum_t(num_) + d_;
                if (sum >= period) {
                    num_ = sum - period;
                    dq = 1;
                } else {
                    num_ = sum;
                }
            } else if (s < 0 && tr_ > 0) {
                if (num_ < d_) {
                    num_ = cfg::sum_t(num_) + period - d_;
                    dq = -1;
                } else {
                    num_ = num_ - d_;
                }
            }
            tr_ = tr_ + s;
            q_ = q_ + dq;
            if (tr_ < 0) {
                stage_ = 1;  // back past A: q == 0 here, adjustment already 0
                tr_ = 0;
            } else {
                const step_t dadj = fwd_ ? dq : step_t(-dq);
                adj_tgt_ = adj_tgt_ + dadj;
                ph_ = ph_step(ph_, dadj, p_last);
                if (tr_ == sint<cfg::W_TR>(period)) {
                    stage_ = 3;
                    adj0_ = adj_tgt_;
                    const pos_t pp = pos_t(period);
                    b_ = fwd_ ? pos_t(a_ + pp) : pos_t(a_ - pp);
                    c_ = fwd_ ? pos_t(b_ + mark_len) : pos_t(b_ - mark_len);
                    z_ = fwd_ ? pos_t(b_ + 2 * p8) : pos_t(b_ - 2 * p8);
                }
            }
        }
        sw_prev_ = sw;
        sw_seen_ = sw_valid;

        // 3. output step: the real count, or else the pending extra count
        step_t ostep = pstep;
        if (pstep == 0) {
            if (adj_tgt_ > adj_) ostep = 1;
            if (adj_tgt_ < adj_) ostep = -1;
            adj_ = adj_ + ostep;
        }

        // 4. reference mark: a pure function of real position once homed
        const pos_t lo = fwd_ ? b_ : c_;
        const pos_t hi = fwd_ ? c_ : b_;
        const bool mark = stage_ == 3 && paced_ >= lo && paced_ <= hi;

        out_t o;
        o.ostep = ostep;
        o.out_pos = paced_ + adj_;
        o.mark = mark;
        o.stage = stage_;
        o.a = a_;
        o.b = b_;
        o.c = c_;
        o.z = z_;
        o.adj = adj_;
        o.d = d_;
        o.homed = stage_ == 3;
        return o;
    }

private:
    // phase counter modulo P: +1 wraps P-1 -> 0, -1 wraps 0 -> P-1
    static cfg::ph_t ph_step(cfg::ph_t ph, step_t s, cfg::ph_t p_last) {
        if (s > 0) return (ph == p_last) ? cfg::ph_t(0) : cfg::ph_t(ph + 1);
        if (s < 0) return (ph == 0) ? p_last : cfg::ph_t(ph - 1);
        return ph;
    }

    cfg::stage_t stage_;
    pos_t paced_;
    bool fwd_last_, sw_prev_, sw_seen_;
    pos_t a_;
    bool fwd_;
    cfg::ph_t d_;
    cfg::tr_t tr_;
    cfg::ph_t num_;
    cfg::q_t q_;
    pos_t adj0_, adj_tgt_, adj_;
    cfg::ph_t ph_;
    pos_t b_, c_, z_;
};

}  // namespace lx

#endif  // LASERAX_HLS_REPHASE_H
