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

    input_filter() { reset(); }

    void reset() {
        s1_ = false;
        s2_ = false;
        f_ = false;
        valid_ = false;
        cnt_ = 0;
        fill_ = 0;
        ready_ = false;
        quiet_ = false;
        key_ = KEY_NONE;
    }

    // the block state for the caller's own clock enable (see step): settled at the level of pin
    bool settled(bool pin) const { return unsigned(pin) == key_; }
    const bool& level() const { return f_; }
    const bool& valid() const { return valid_; }  // (level(), valid(): the registers f, valid of the last out_t)
    bool quiet() const { return quiet_; }  // settled at level() (valid, cnt = 0, s1 = s2 = f)
    // the call of step() in the settled state (settled(pin)): only the pass decision is loaded
    void hold(cnt_t n) { ready_ = n <= 1; }

    // same: n is that of the previous call (a caller's register stage that knows it, e.g.
    // laserax_top::tick; false by default): a settled filter is quiet (cnt = 0), so its pass
    // decision holds n <= 1 of the previous call, and hold() would load the same value (issue 13:
    // simulation speed; same outputs)
    out_t step(bool pin, cnt_t n, bool same = false) {
        // settled (quiet_: valid, cnt = 0, s1 = s2 = f) and the pin still at that level: the call
        // below would hold every register but the pass decision (cnt + 1 = 1 >= N) and return
        // (f, 1, 0); a clock enable of the rest (issue 13: simulation speed; same outputs)
        if (settled(pin)) {
            if (!same) hold(n);
            out_t q;
            q.f = f_;
            q.valid = true;
            q.glitch = false;
            return q;
        }
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
        quiet_ = valid_ && cnt_ == 0 && s1_ == s2_ && s2_ == f_;
        key_ = quiet_ ? uint<2>(s1_ ? 1 : 0) : uint<2>(KEY_NONE);
        out_t o;
        o.f = f_;
        o.valid = valid_;
        o.glitch = glitch;
        return o;
    }

private:
    bool s1_, s2_, f_, valid_;
    bool quiet_;  // valid_ && cnt_ == 0 && s1_ == s2_ == f_ (registered with them)
    // the pin level of a settled call: s1_ while quiet_, else KEY_NONE (no pin equals it): one
    // compare for settled() (issue 13: simulation speed)
    static constexpr unsigned KEY_NONE = 2;
    uint<2> key_;
    bool ready_;  // the next call passes a differing sample (cnt + 1 >= max(N, 1), N of this call)
    cnt_t cnt_;
    typename cfg::fill_t fill_;
};

}  // namespace lx

#endif  // LASERAX_HLS_INPUT_FILTER_H
