// pulse_multiplier.h — raw laser counts to compensated output counts, by addition.
//
// DESIGN §4.3 (normative; the golden model follows its Definition, this file its Hardware form).
// The exact value V = N * R + OFF (Q.32 output counts) is kept as V = acc + T (mod 2^70):
//   acc  the step accumulator: +-R per raw count (a 32-bit fraction adder `lo` with a registered
//        carry into the 38-bit integer part `hi` one call later) — no multiplier in the loop;
//   T    the base: the offset plus the re-base products N0 * (R' - R), changed only by the
//        re-base sequencer.
// A ratio / offset change (seen by a registered compare) starts a re-base in the next idle call:
// steps count at the target ratio from the call after the start, a serial shift-and-add
// multiplier (one bit of N0 per call, 39-bit adder) forms N0 * dR over 32 calls, X = T + OFF' -
// OFF_old (as ~(~S + OFF_old), S = T + OFF') and T_new = X + P follow in 18-bit quarters, and T is replaced K_REBASE = 40 calls after the start,
// from when V = N * R' + OFF' exactly again (the re-base theorem, DESIGN §4.3).
// Output pipeline: stage 2 hi += inc + c, carry of lo + T_lo; stage 3 comp_int = hi + T_hi + c2;
// stage 4 comp and delta = comp_int - comp. comp/delta of call t are those of the step of call
// t - L_MUL (L_MUL = 3).
//
// Widths (pulse_multiplier_cfg): N 32, R 37 unsigned, dR 38 signed (two halves), acc/T/P 70,
// lo 32, hi 38, serial partial product 39, S and X 70 (the offsets sign-extended), the T
// additions in 18-bit quarters.
#ifndef LASERAX_HLS_PULSE_MULTIPLIER_H
#define LASERAX_HLS_PULSE_MULTIPLIER_H

#include "hls/axis_config.h"

namespace lx {

struct pulse_multiplier_cfg {
    static constexpr int W_RAW = axis_widths::W_RAW;          // 32
    static constexpr int R_FRAC = axis_widths::R_FRAC;        // 32
    static constexpr int W_RATIO = axis_widths::W_RATIO;      // 37
    static constexpr int R_INT = axis_widths::R_INT;          // 5
    static constexpr int W_ACC = axis_widths::W_ACC;          // 70
    static constexpr int W_OFFSET = axis_widths::W_OFFSET;    // 64
    static constexpr int W_POS = axis_widths::W_POS;          // 38
    static constexpr int W_HI = W_ACC - R_FRAC;               // 38, integer part of acc and T
    static constexpr int W_DRATIO = W_RATIO + 1;              // 38, R' - R, signed
    static constexpr int W_PP = W_DRATIO + 1;                 // 39, serial partial product
    static constexpr int W_DRL = 20;                          // low half of the dR subtraction
    static constexpr int N_TQ = 4;                            // T additions in four quarters
    static constexpr int W_TQ = (W_ACC + N_TQ - 1) / N_TQ;    // 18 bits (the last 16)
    static constexpr int W_INC = W_HI + 1;                    // 39, increment of hi per call
    static constexpr int K_REBASE = 40;                       // calls from a start to the replaced T
    static constexpr int L_MUL = 3;                           // extra calls of output latency
    static constexpr int MUL_STEPS = W_RAW;                   // 32 serial multiply calls
    // sequencer call numbers (cnt = calls since the start)
    static constexpr int C_DR0 = 1, C_DR1 = 2;                // dR halves (N0 taken in C_DR0)
    static constexpr int C_S0 = 1;                            // 1..4: S = T + OFF' (kept inverted), by quarters
    static constexpr int C_MUL0 = C_DR1 + 2;                  // 4: first multiply call (the RTL
                                                              // registers its addend in call 3)
    static constexpr int C_X0 = C_S0 + 1;                     // 2..5: X = ~(~S + OFF_old), by quarters
    static constexpr int C_ADD0 = C_MUL0 + MUL_STEPS;         // 36..39: T_new = X + P, by quarters
    static constexpr int C_ADD3 = C_ADD0 + N_TQ - 1;          // 39
    static constexpr int W_CNT = clog2p1(K_REBASE);           // 6
    static constexpr long long N_MAX = (1LL << (W_RAW - 1)) - 1;  // ends of the raw count
    static constexpr long long N_MIN = -(1LL << (W_RAW - 1));

    using lo_t = uint<R_FRAC>;
    using hi_t = sint<W_HI>;
    using inc_t = sint<W_INC>;
    using dratio_t = sint<W_DRATIO>;
    using pp_t = sint<W_PP>;
    using drl_t = uint<W_DRL>;
    using drh_t = uint<W_DRATIO - W_DRL>;
    using tq_t = uint<W_TQ>;
    using cnt_t = uint<W_CNT>;
    using nwide_t = sint<W_RAW + 1>;   // N + step before the wrap
    using carry_t = uint<1>;
};
static_assert(pulse_multiplier_cfg::W_OFFSET < pulse_multiplier_cfg::W_RAW + pulse_multiplier_cfg::W_RATIO - 1 &&
                  pulse_multiplier_cfg::W_RAW + pulse_multiplier_cfg::W_RATIO + 1 <= pulse_multiplier_cfg::W_ACC,
              "N*R + OFF must fit the accumulator width");
static_assert(pulse_multiplier_cfg::W_HI == pulse_multiplier_cfg::W_POS, "comp is the integer part");
static_assert(pulse_multiplier_cfg::C_ADD3 < pulse_multiplier_cfg::K_REBASE, "T_new ready before it is applied");
static_assert(pulse_multiplier_cfg::C_X0 + pulse_multiplier_cfg::N_TQ <= pulse_multiplier_cfg::C_ADD0,
              "X = T + OFF' - OFF_old done before X + P starts");

class pulse_multiplier {
public:
    using cfg = pulse_multiplier_cfg;
    struct out_t {
        pos_t comp = 0;
        delta_t delta = 0;
    };

    void reset() { *this = pulse_multiplier{}; }  // every register to its initialiser (the reset value)

    // Preset port (testbench aid, not in the RTL): N and the pair (R, OFF) are loaded, the
    // sequencer is idle, acc = N * R and T = OFF (formed here with a multiply: not hardware), and
    // every pipeline stage holds comp_int of the preset value, so the next call's delta is
    // measured from it.
    void preset(raw_t n, ratio_t ratio, offset_t offset = 0) {
        reset();
        n_ = n;
        r_use_ = ratio;
        load_wrap_increments();
        off_tgt_ = offset;
        const acc_t acc = acc_t(n) * acc_t(ratio);
        lo_ = cfg::lo_t(acc);
        hi_ = cfg::hi_t(acc >> cfg::R_FRAC);
        const acc_t t = acc_t(offset);
        t_lo_ = cfg::lo_t(t);
        t_hi_ = cfg::hi_t(t >> cfg::R_FRAC);
        t_hi_d_ = t_hi_;
        const acc_t v = acc_t(acc + t);
        ci_ = pos_t(v >> cfg::R_FRAC);
        c2_ = carry32(lo_, t_lo_);
        comp_ = ci_;
    }

    out_t step(step_t step, const ratio_t& ratio, const offset_t& offset) {
        // ---- stage 4: outputs (comp_int of three calls ago) --------------------------------
        const delta_t delta_next = delta_t(ci_) - delta_t(comp_);
        const pos_t comp_next = ci_;
        // ---- stage 3: comp_int = hi + T_hi + carry(lo + T_lo), both halves of T of the same call
        const pos_t ci_next = pos_t(hi_ + t_hi_d_ + c2_);
        // ---- stage 2: integer part of acc, carry of the fraction plus T_lo (lo_ still holds
        //      the fraction of the previous call: {hi_next, lo_} is acc of that call) ----------
        const cfg::hi_t hi_next = cfg::hi_t(hi_ + inc_ + c_);
        const cfg::carry_t c2_next = carry32(lo_, t_lo_);

        // ---- stage 1: the step at the ratio in use (the target ratio before this call) --------
        const cfg::nwide_t n_sum = cfg::nwide_t(n_) + step;
        const raw_t n_next = n_sum;  // wraps at W_RAW bits
        // N wraps when it steps past an end: an equality test of N, not the carry of the adder
        const bool wrap = (step > 0 && n_ == raw_t(cfg::N_MAX)) || (step < 0 && n_ == raw_t(cfg::N_MIN));
        const cfg::lo_t r_frac = cfg::lo_t(r_use_);
        const cfg::inc_t r_int = cfg::inc_t(r_use_ >> cfg::R_FRAC);  // -R_int - 1 is ~R_int: no adder
        cfg::lo_t lo_next = lo_;
        cfg::carry_t c_next = 0;
        cfg::inc_t inc_next = 0;
        if (step > 0) {
            const uint<cfg::R_FRAC + 1> s = uint<cfg::R_FRAC + 1>(lo_) + r_frac;
            lo_next = cfg::lo_t(s);
            c_next = cfg::carry_t(s >> cfg::R_FRAC);
            inc_next = r_int;
        } else if (step < 0) {
            const uint<cfg::R_FRAC + 1> s = uint<cfg::R_FRAC + 1>(lo_) + cfg::lo_t(~r_frac) + 1;
            lo_next = cfg::lo_t(s);
            c_next = cfg::carry_t(s >> cfg::R_FRAC);
            inc_next = cfg::inc_t(-r_int - 1);
        }
        if (wrap) {
            // N' = N + step -/+ 2^32: the integer part moves by -/+ R more (R << 32 in Q.32); the
            // two increments were formed when the ratio was loaded, so this is a mux
            inc_next = (step > 0) ? inc_wp_ : cfg::inc_t(~inc_wp_);  // ~(R_int - R) = ~R_int + R
        }

        // ---- re-base sequencer: a running one (T applied in its last call), then a start -----
        //      (pend_: the pair of the previous call differed from the target, registered compare)
        cfg::lo_t t_lo_next = t_lo_;
        cfg::hi_t t_hi_next = t_hi_;
        if (busy_) sequencer_step(t_lo_next, t_hi_next);
        const bool start = !busy_ && pend_;
        if (start) {
            // N0 (N after this call's step, which still counts at the old ratio) and dR are
            // taken from registers in the next calls (sequencer_step)
            r_old_ = r_use_;
            off_old_ = off_tgt_;
            pp_ = 0;
            pl_ = 0;
            r_use_ = ratio;
            load_wrap_increments();
            off_tgt_ = offset;
            busy_ = true;
            cnt_ = 1;
        }
        pend_ = !start && (ratio != r_use_ || offset != off_tgt_);

        // ---- register update --------------------------------------------------------------
        out_t o;
        o.comp = comp_next;
        o.delta = delta_next;
        comp_ = comp_next;
        ci_ = ci_next;
        hi_ = hi_next;
        c2_ = c2_next;
        t_hi_d_ = t_hi_;
        t_lo_ = t_lo_next;
        t_hi_ = t_hi_next;
        n_ = n_next;
        lo_ = lo_next;
        c_ = c_next;
        inc_ = inc_next;
        return o;
    }

private:
    // R_int - R: the increment of the integer part at a wrap of N with step +1 (its inversion
    // ~R_int + R is the one of step -1)
    void load_wrap_increments() {
        const cfg::inc_t r_int = cfg::inc_t(r_use_ >> cfg::R_FRAC);
        const cfg::inc_t r_all = cfg::inc_t(r_use_);
        inc_wp_ = cfg::inc_t(r_int - r_all);
    }

    // Quarter Q of a + b (18 bits; the carry in is 0 for Q = 0, else the carry out of quarter
    // Q - 1, registered in cy) into dst, inverted (~sum) with inv. Q is a template argument: every
    // slice is a constant part-select (no run-time shifter).
    template <int Q>
    static void add_quarter(uint<cfg::W_ACC>& dst, const uint<cfg::W_ACC>& a, const uint<cfg::W_ACC>& b,
                            cfg::carry_t& cy, bool inv) {
        static_assert(Q >= 0 && Q < cfg::N_TQ, "add_quarter: quarter 0 .. N_TQ - 1");
        constexpr int sh = Q * cfg::W_TQ;
        const uint<cfg::W_TQ + 1> sum =
            uint<cfg::W_TQ + 1>(cfg::tq_t(a >> sh)) + cfg::tq_t(b >> sh) + (Q == 0 ? cfg::carry_t(0) : cy);
        cy = cfg::carry_t(sum >> cfg::W_TQ);
        const cfg::tq_t r = inv ? cfg::tq_t(~cfg::tq_t(sum)) : cfg::tq_t(sum);
        const uint<cfg::W_ACC> mask = uint<cfg::W_ACC>(cfg::tq_t(~cfg::tq_t(0))) << sh;
        dst = (dst & ~mask) | ((uint<cfg::W_ACC>(r) << sh) & mask);
    }
    // The quarter q (0 .. N_TQ - 1, a sequencer call number minus the first call of the addition)
    // of the addition: a case over the four constant slices.
    static void add_quarter_of(unsigned q, uint<cfg::W_ACC>& dst, const uint<cfg::W_ACC>& a,
                               const uint<cfg::W_ACC>& b, cfg::carry_t& cy, bool inv) {
        static_assert(cfg::N_TQ == 4, "add_quarter_of: four quarters");
        switch (q) {
            case 0: add_quarter<0>(dst, a, b, cy, inv); break;
            case 1: add_quarter<1>(dst, a, b, cy, inv); break;
            case 2: add_quarter<2>(dst, a, b, cy, inv); break;
            default: add_quarter<3>(dst, a, b, cy, inv); break;
        }
    }

    static cfg::carry_t carry32(cfg::lo_t a, cfg::lo_t b) {
        const uint<cfg::R_FRAC + 1> s = uint<cfg::R_FRAC + 1>(a) + b;
        return cfg::carry_t(s >> cfg::R_FRAC);
    }

    // One call of a running re-base (cnt_ = calls since the start call, 1..K_REBASE).
    void sequencer_step(cfg::lo_t& t_lo_next, cfg::hi_t& t_hi_next) {
        const int cnt = cnt_.to_int();
        // (compositions in an unsigned W_ACC: two's complement bit patterns, no signed shifts)
        using uacc_t = uint<cfg::W_ACC>;
        // the call after the start: N0 = N(start) is the register N now; dR = R' - R_old (38
        // bits) in two halves from registers, the low half's carry registered
        if (cnt == cfg::C_DR0) {
            n0_ = n_;
            const uint<cfg::W_DRL + 1> s =
                uint<cfg::W_DRL + 1>(cfg::drl_t(r_use_)) + cfg::drl_t(~cfg::drl_t(r_old_)) + 1;
            dr_ = cfg::dratio_t((uint<cfg::W_DRATIO>(dr_) & ~uint<cfg::W_DRATIO>(cfg::drl_t(~cfg::drl_t(0)))) |
                                uint<cfg::W_DRATIO>(cfg::drl_t(s)));
            drc_ = cfg::carry_t(s >> cfg::W_DRL);
        } else if (cnt == cfg::C_DR1) {
            const cfg::drh_t h = cfg::drh_t(cfg::drh_t(uint<cfg::W_DRATIO>(r_use_) >> cfg::W_DRL) +
                                            cfg::drh_t(~cfg::drh_t(uint<cfg::W_DRATIO>(r_old_) >> cfg::W_DRL)) + drc_);
            dr_ = cfg::dratio_t((uint<cfg::W_DRATIO>(h) << cfg::W_DRL) |
                                uint<cfg::W_DRATIO>(cfg::drl_t(uint<cfg::W_DRATIO>(dr_))));
        }
        // S = T + OFF' (OFF' sign-extended to W_ACC) by quarters, kept inverted, each a call ahead
        // of the X quarter that reads it: X = ~(~S + OFF_old) = T + OFF' - OFF_old (~a = -a - 1),
        // so no operand is inverted in front of an adder (in the RTL an inverted operand of a carry
        // chain costs a LUT per bit; the inversion of a sum is free)
        const uacc_t t_x = (uacc_t(t_hi_) << cfg::R_FRAC) | uacc_t(t_lo_);
        if (cnt >= cfg::C_S0 && cnt < cfg::C_S0 + cfg::N_TQ)
            add_quarter_of(unsigned(cnt - cfg::C_S0), ns_, t_x, uacc_t(acc_t(off_tgt_)), scy_, true);
        // serial signed multiply P = N0 * dR: bit i of N0 per call, the sign bit subtracts
        if (cnt >= cfg::C_MUL0 && cnt < cfg::C_MUL0 + cfg::MUL_STEPS) {
            const int i = cnt - cfg::C_MUL0;
            const bool bit = (n0_ & 1) != 0;  // N0 shifts right: bit i of the snapshot
            n0_ = raw_t(n0_ >> 1);
            cfg::pp_t add = 0;
            if (bit) add = (i == cfg::MUL_STEPS - 1) ? cfg::pp_t(-cfg::pp_t(dr_)) : cfg::pp_t(dr_);
            const cfg::pp_t sum = cfg::pp_t(pp_ + add);
            pl_ = cfg::lo_t((pl_ >> 1) | (cfg::lo_t(sum & 1) << (cfg::R_FRAC - 1)));
            pp_ = cfg::pp_t(sum >> 1);  // arithmetic shift
        }
        const uacc_t p_x = (uacc_t(pp_) << cfg::R_FRAC) | uacc_t(pl_);
        // X = ~(~S + OFF_old) (calls C_X0..), then T_new = X + P (calls C_ADD0..), one 18-bit
        // quarter per call with a registered carry
        if (cnt >= cfg::C_X0 && cnt < cfg::C_X0 + cfg::N_TQ)
            add_quarter_of(unsigned(cnt - cfg::C_X0), x_, ns_, uacc_t(acc_t(off_old_)), acy_, true);
        if (cnt >= cfg::C_ADD0 && cnt <= cfg::C_ADD3)
            add_quarter_of(unsigned(cnt - cfg::C_ADD0), y_, x_, p_x, acy_, false);
        if (cnt == cfg::K_REBASE) {
            const uacc_t tn = y_;
            t_lo_next = cfg::lo_t(tn);
            t_hi_next = cfg::hi_t(tn >> cfg::R_FRAC);
            busy_ = false;
            cnt_ = 0;
        } else {
            cnt_ = cnt_ + 1;
        }
    }

    // stage 1
    raw_t n_ = 0;
    ratio_t r_use_ = 0;
    offset_t off_tgt_ = 0;
    cfg::lo_t lo_ = 0;
    cfg::carry_t c_ = 0;
    cfg::inc_t inc_ = 0;
    cfg::inc_t inc_wp_ = 0;  // increment at a wrap of N with step +1, formed when the ratio is loaded
    // stages 2..4
    cfg::hi_t hi_ = 0;
    cfg::carry_t c2_ = 0;
    pos_t ci_ = 0;
    pos_t comp_ = 0;
    // base T (two halves) and the delayed high half used by stage 3
    cfg::lo_t t_lo_ = 0;
    cfg::hi_t t_hi_ = 0;
    cfg::hi_t t_hi_d_ = 0;
    // re-base sequencer
    bool busy_ = false;
    bool pend_ = false;
    cfg::cnt_t cnt_ = 0;
    raw_t n0_ = 0;
    cfg::dratio_t dr_ = 0;
    ratio_t r_old_ = 0;        // the target ratio before the start
    cfg::carry_t drc_ = 0;     // carry of the low dR half
    cfg::pp_t pp_ = 0;
    cfg::lo_t pl_ = 0;
    offset_t off_old_ = 0;
    uint<cfg::W_ACC> ns_ = 0;  // ~S, S = T + OFF' (built a quarter per call)
    cfg::carry_t scy_ = 0;
    uint<cfg::W_ACC> x_ = 0;  // T + OFF' - OFF_old, then T_new (built a quarter per call)
    uint<cfg::W_ACC> y_ = 0;
    cfg::carry_t acy_ = 0;
};

}  // namespace lx

#endif  // LASERAX_HLS_PULSE_MULTIPLIER_H
