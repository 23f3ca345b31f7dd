// output_pacer.h — rate limiter for the compensated count stream.
//
// DESIGN §4.4. Incoming count deltas (any size: a ratio update can jump by thousands) are added to
// a signed backlog; one count at a time leaves, at most one per M calls. Nothing is dropped: the
// backlog drains at 1/M counts per call once motion stops, and a backlog above the threshold
// raises an alarm (pulse plus sticky flag, cleared by `clear` once the backlog is below again).
// The emitted count is decided from the registers before the call (registered output).
//
// Widths: backlog 40 signed, timer 16, paced position 38 signed. Latency: delta in at call t,
// the first count leaves at call t+1.
#ifndef LASERAX_HLS_OUTPUT_PACER_H
#define LASERAX_HLS_OUTPUT_PACER_H

#include "hls/axis_config.h"

namespace lx {

struct output_pacer_cfg {
    static constexpr int W_PACE = 16;  // M register
    static constexpr int W_THR = 32;   // backlog alarm threshold
    static constexpr int W_BACKLOG = axis_widths::W_BACKLOG;
    using pace_t = uint<W_PACE>;
    using thr_t = uint<W_THR>;
    using mag_t = uint<W_BACKLOG>;  // |backlog|
};

class output_pacer {
public:
    using cfg = output_pacer_cfg;
    struct out_t {
        step_t pstep = 0;
        pos_t paced = 0;
        backlog_t backlog = 0;
        bool ovs = false;
        bool ovs_st = false;
    };

    output_pacer() { reset(); }

    void reset() {
        backlog_ = 0;
        timer_ = 0;
        paced_ = 0;
        ovs_st_ = false;
    }

    out_t step(delta_t delta, cfg::pace_t pace_m, cfg::thr_t thr, bool clear) {
        step_t emit = 0;
        if (timer_ == 0 && backlog_ != 0) emit = (backlog_ > 0) ? step_t(1) : step_t(-1);
        const backlog_t bl = backlog_ + delta - emit;
        if (emit != 0) {
            timer_ = pace_m - 1;
        } else if (timer_ != 0) {
            timer_ = timer_ - 1;
        }
        paced_ = paced_ + emit;
        backlog_ = bl;
        const cfg::mag_t mag = (bl < 0) ? cfg::mag_t(-bl) : cfg::mag_t(bl);
        const bool ovs = mag > thr;
        if (clear) ovs_st_ = false;
        if (ovs) ovs_st_ = true;

        out_t o;
        o.pstep = emit;
        o.paced = paced_;
        o.backlog = backlog_;
        o.ovs = ovs;
        o.ovs_st = ovs_st_;
        return o;
    }

private:
    backlog_t backlog_;
    cfg::pace_t timer_;
    pos_t paced_;
    bool ovs_st_;
};

}  // namespace lx

#endif  // LASERAX_HLS_OUTPUT_PACER_H
