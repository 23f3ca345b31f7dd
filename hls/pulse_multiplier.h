// pulse_multiplier.h — raw laser counts to compensated output counts.
//
// DESIGN §4.3. After every call comp = floor((N * R + OFF) / 2^R_FRAC), a pure function of the
// current raw count N, ratio R and offset OFF (the comp_offset register, Q32.32 output counts:
// the thermal origin term -K168 * K169 * 1e-5). The accumulator acc holds N*R exactly and is
// updated with one multiply and one add per call ("multiplication and addition"):
//     acc' = acc + (N' - N) * R' + N * (R' - R)            (= N' * R')
// where N' - N is the step, or the step minus sign*2^W_RAW when the raw counter wraps (that term
// is a shift, not a multiply). The offset is added after the accumulator (one more adder, no
// state). A ratio or offset change therefore re-bases the position exactly and the jump leaves
// as `delta`, to be paced out by the output_pacer; nothing depends on the path.
//
// Widths: N 32 signed, R 37 unsigned (Q5.32), R'-R 38 signed, acc 70 signed, OFF 64 signed,
// comp 38 signed: |N*R| < 2^68 and |OFF| <= 2^63, so acc + OFF < 2^69 fits W_ACC and the comp
// (< 2^37) fits W_POS. Latency: 1 call (step in, comp/delta out).
#ifndef LASERAX_HLS_PULSE_MULTIPLIER_H
#define LASERAX_HLS_PULSE_MULTIPLIER_H

#include "hls/axis_config.h"

namespace lx {

struct pulse_multiplier_cfg {
    static constexpr int W_RAW = axis_widths::W_RAW;
    static constexpr int R_FRAC = axis_widths::R_FRAC;
    static constexpr int W_RATIO = axis_widths::W_RATIO;
    static constexpr int W_DRATIO = W_RATIO + 1;  // R' - R, signed
    static constexpr int W_ACC = axis_widths::W_ACC;
    static constexpr int W_OFFSET = axis_widths::W_OFFSET;
    using dratio_t = sint<W_DRATIO>;
    using nwide_t = sint<W_RAW + 1>;  // N + step before the wrap
};
// |acc| <= 2^(W_RAW-1) * (2^W_RATIO - 1) < 2^(W_RAW+W_RATIO-1) and |OFF| <= 2^(W_OFFSET-1):
// their sum must fit W_ACC, and the comp (sum >> R_FRAC) must fit W_POS.
static_assert(pulse_multiplier_cfg::W_OFFSET < pulse_multiplier_cfg::W_RAW + pulse_multiplier_cfg::W_RATIO - 1 &&
                  pulse_multiplier_cfg::W_RAW + pulse_multiplier_cfg::W_RATIO + 1 <= pulse_multiplier_cfg::W_ACC,
              "acc + offset must fit the accumulator width");
static_assert(pulse_multiplier_cfg::W_ACC - pulse_multiplier_cfg::R_FRAC <= axis_widths::W_POS,
              "comp must fit W_POS");

class pulse_multiplier {
public:
    using cfg = pulse_multiplier_cfg;
    struct out_t {
        pos_t comp = 0;
        delta_t delta = 0;
    };

    pulse_multiplier() { reset(); }

    void reset() {
        n_ = 0;
        r_ = 0;
        acc_ = 0;
        comp_ = 0;
    }

    // Preset port (position load, also used by the testbenches to reach the 32-bit wrap without
    // 2^31 calls): N and R are loaded and acc = N * R is formed with the same multiplier; comp is
    // formed with the offset given (the next call's delta is measured from it).
    void preset(raw_t n, ratio_t ratio, offset_t offset = 0) {
        n_ = n;
        r_ = ratio;
        acc_ = acc_t(n) * ratio;
        comp_ = acc_t(acc_ + acc_t(offset)) >> cfg::R_FRAC;
    }

    out_t step(step_t step, ratio_t ratio, offset_t offset) {
        const cfg::nwide_t n_sum = cfg::nwide_t(n_) + step;
        const raw_t n_next = n_sum;  // wraps at W_RAW bits
        const cfg::dratio_t dr = cfg::dratio_t(ratio) - cfg::dratio_t(r_);
        acc_t acc = acc_ + acc_t(n_) * dr;  // the one multiplier: re-base to the updated ratio
        if (step > 0) acc = acc + acc_t(ratio);
        if (step < 0) acc = acc - acc_t(ratio);
        if (n_sum != cfg::nwide_t(n_next)) {
            // Raw counter wrapped: N' = N + step -/+ 2^W_RAW, so subtract/add R' << W_RAW.
            const acc_t wrap_term = acc_t(ratio) << cfg::W_RAW;
            acc = (step > 0) ? acc_t(acc - wrap_term) : acc_t(acc + wrap_term);
        }
        const pos_t comp_next = acc_t(acc + acc_t(offset)) >> cfg::R_FRAC;  // floor: arithmetic shift
        out_t o;
        o.comp = comp_next;
        o.delta = delta_t(comp_next) - delta_t(comp_);
        n_ = n_next;
        r_ = ratio;
        acc_ = acc;
        comp_ = comp_next;
        return o;
    }

private:
    raw_t n_;
    ratio_t r_;
    acc_t acc_;
    pos_t comp_;
};

}  // namespace lx

#endif  // LASERAX_HLS_PULSE_MULTIPLIER_H
