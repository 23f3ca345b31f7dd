// golden/input_filter.cpp — see input_filter.h (DESIGN.md 4.1, golden definition).
#include "golden/input_filter.h"

#include <algorithm>

namespace golden {

void input_filter::reset() { *this = input_filter{}; }

input_filter::out input_filter::step(bool pin, int64_t n) {
    const int64_t need = std::max<int64_t>(n_prev_, 1);  // N(t-1); N = 0 and N = 1 are the same
    n_prev_ = n;
    bool glitch = false;
    if (calls_ >= 2) {
        const bool x = pin_m2_;  // x(t) = pin(t-2)
        if (!valid_) {
            // first sample x(2) = pin(0): loaded, not filtered
            f_ = x;
            valid_ = true;
            run_ = 0;
        } else if (x != f_) {
            ++run_;  // x has differed from the output on run_ consecutive calls ending at t
            if (run_ >= need) {
                f_ = x;
                run_ = 0;
            }
        } else {
            glitch = run_ > 0;  // x came back after differing for 1..N-1 calls: suppressed pulse
            run_ = 0;           // a pulse shorter than max(N,1) calls never passes
        }
    } else {
        ++calls_;
    }
    pin_m2_ = pin_m1_;
    pin_m1_ = pin;
    return out{f_, valid_, glitch};
}

}  // namespace golden
