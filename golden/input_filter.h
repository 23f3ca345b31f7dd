// golden/input_filter.h — floating-point-side golden model of DESIGN.md 4.1 (input_filter).
//
// Written from the 4.1 "Definition (golden)": with x(t) = pin(t-2) (two-flop synchroniser),
// the output at call t takes the value x(t) once x has differed from the previous output on
// max(N(t-1),1) consecutive calls ending at t (N(t-1): the filter length of the previous call);
// the first sample x(2) = pin(0) is loaded unfiltered and `valid` is 1 from call index 2 on
// (calls counted from 0 after reset).
//
// The model keeps an explicit pin history and the length of the current run of "x differs
// from the output"; it has no fixed-width counter (the filter length n is used as given;
// callers stay inside the register width, W_GLITCH = 8 or W_DEBOUNCE = 16 bits).
#pragma once
#include <algorithm>
#include <cstdint>

namespace golden {

class input_filter {
public:
    struct out {
        bool f;      // filtered level (0 until valid)
        bool valid;  // 1 from call index 2 after reset
        bool glitch; // pulse: x returned to the output level after differing for 1..N-1 calls
    };
    void reset();
    // One call = one clock edge. n: filter length (n <= 1 means: a change passes after one call).
    out step(bool pin, int64_t n);

private:
    int64_t calls_ = 0;   // calls since reset, saturated at 2 (only "t >= 2" matters)
    bool pin_m1_ = false; // pin(t-1)
    bool pin_m2_ = false; // pin(t-2) = x(t)
    bool f_ = false;
    bool valid_ = false;
    int64_t run_ = 0;     // consecutive calls (ending at the previous call) with x != f
    int64_t n_prev_ = 0;  // N(t-1); first used at call index 3, set at every call
};

// Defined here (inline) so that the decoder's three filters are inlined into its step (simulation
// speed of the testbenches); the definition is the golden one of DESIGN.md 4.1.
inline input_filter::out input_filter::step(bool pin, int64_t n) {
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
