// input_filter.h — two-flop synchroniser plus stability (glitch) filter for one asynchronous pin.
//
// DESIGN §4.1. A change on the pin reaches the output once it has been seen on max(N,1)
// consecutive clocks after synchronisation; shorter pulses never pass. Latency pin -> output:
// max(N,1) + 1 calls. `valid` rises at the third call after reset, when the synchroniser first
// holds a real sample; that sample is loaded into the output unfiltered. `glitch` pulses in the
// call where the input returns to the output level after differing for 1..N-1 calls, so every
// suppressed pulse is reported.
// The pass decision is a register (`ready_`, DESIGN §4.1): the comparison of the counter with the
// filter length is made one call early, with that call's N, so the filtered level is one gate after
// registers (a write of N takes effect one call later).
//
// Resources: 4 flip-flops, a W_CNT-bit counter, a 2-bit fill counter, one comparator.
#ifndef LASERAX_HLS_INPUT_FILTER_H
#define LASERAX_HLS_INPUT_FILTER_H

#include "hls/lx_types.h"

namespace lx {

template <int W_CNT_>
struct input_filter_cfg {
    static constexpr int W_CNT = W_CNT_;  // filter length register width
    static constexpr int W_FILL = 2;      // counts the two synchroniser stages after reset
    using cnt_t = uint<W_CNT>;
    using fill_t = uint<W_FILL>;
};

template <int W_CNT>
class input_filter {
public:
    using cfg = input_filter_cfg<W_CNT>;
    using cnt_t = typename cfg::cnt_t;
    struct out_t {
        bool f = false;
        bool valid = false;
        bool glitch = false;  // pulse: a change shorter than max(N,1) calls was suppressed
    };

    void reset() { *this = input_filter{}; }  // every register to its initialiser (the reset value)

    const bool& level() const { return f_; }
    const bool& valid() const { return valid_; }  // (level(), valid(): the registers f, valid of the last out_t)

    // One clock. The pin reaches only the first synchroniser flop (s1); every other register reads
    // the synchronised copy s2 (DESIGN 4.1: no logic on the asynchronous input).
    out_t step(bool pin, cnt_t n) {
        const bool glitch = valid_ && s2_ == f_ && cnt_ != 0;
        if (!valid_) {
            if (fill_ == 2) {
                f_ = s2_;
                valid_ = true;
            } else {
                fill_ = fill_ + 1;
            }
        } else if (s2_ == f_) {
            cnt_ = 0;
        } else if (ready_) {
            f_ = s2_;
            cnt_ = 0;
        } else {
            cnt_ = cnt_ + 1;  // cnt + 1 < max(N(t-1), 1) <= 2^W_CNT - 1: fits
        }
        // pass decision of the next call, with this call's N (N = 0 and N = 1 both mean "accept
        // after one differing sample"): cnt + 1 >= max(N, 1), which is cnt + 1 >= N as cnt + 1 >= 1
        ready_ = uint<W_CNT + 1>(cnt_) + 1 >= n;
        s2_ = s1_;
        s1_ = pin;
        out_t o;
        o.f = f_;
        o.valid = valid_;
        o.glitch = glitch;
        return o;
    }

private:
    bool s1_ = false;
    bool s2_ = false;
    bool f_ = false;
    bool valid_ = false;
    bool ready_ = false;  // the next call passes a differing sample (cnt + 1 >= max(N, 1), N of this call)
    cnt_t cnt_ = 0;
    typename cfg::fill_t fill_ = 0;
};

}  // namespace lx

#endif  // LASERAX_HLS_INPUT_FILTER_H
