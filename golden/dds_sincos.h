// golden/dds_sincos.h — golden model of DESIGN.md 4.6 (dds_sincos).
//
// Definition: S(ph) = rha(amp * sin(2*pi*ph/P)), C(ph) = rha(amp * cos(2*pi*ph/P)), rha =
// round half away from zero (std::llround). The outputs of a call are the codes computed in the
// previous call (s1, c1: the read stage); the call computes s1, c1 from the phase before its
// update, with its P and amp; then ph' = (ph + ostep) mod P (true modulo). An ostep at call t
// moves the outputs at call t+2. Reset: outputs and s1, c1 0/0, ph = 0.
//
// Computed directly with long double sin/cos over the full circle (no quarter-wave table, no
// quadrant logic). Accuracy: the long double argument and sin/cos are within a few 1e-19 of
// the true value, so amp*sin (amp < 2^17) is within ~1e-13 of the true value, far below the
// distance of any non-tie value to a rounding boundary. Exact ties (amp odd and sin/cos = +-1/2,
// i.e. angles k*30 deg by Niven's theorem) and the exact values 0, +-1 are taken from the
// exact rational value instead of sinl/cosl, so rha's tie rule is applied to the true value.
//
// Speed (issue 13): the codes are a pure function of (k, P, amp), so each instance memoises them
// in a table indexed by k for the (P, amp) of the last call (a generation number invalidates the
// whole table when P or amp changes), and the codes of the last lookup; reset() clears the
// registers, not the memo.
#pragma once
#include <cstdint>
#include <vector>

namespace golden {

class dds_sincos {
public:
    struct out {
        int64_t sin;
        int64_t cos;
    };
    void reset();
    out step(int ostep, int64_t period, int64_t amplitude);

private:
    void codes(int64_t k, int64_t P, int64_t amplitude, int64_t& s, int64_t& c);

    struct memo_entry {
        int64_t s = 0, c = 0;
        uint32_t gen = 0;  // valid if equal to memo_gen_
    };
    static constexpr int64_t kMemoMaxP = 1 << 16;  // larger periods (never valid) are not memoised
    std::vector<memo_entry> memo_;
    int64_t memo_P_ = 0, memo_amp_ = 0;
    uint32_t memo_gen_ = 0;
    // and the codes of the last (k, P, amp) looked up (the phase stands still in most calls)
    bool last_ok_ = false;
    int64_t last_k_ = 0, last_P_ = 0, last_amp_ = 0, last_s_ = 0, last_c_ = 0;

    int64_t ph_ = 0;       // phase in [0, P)
    int64_t s1_ = 0;       // codes of the read stage (reset 0/0)
    int64_t c1_ = 0;
    int64_t sin_q_ = 0;    // output registers (reset 0/0)
    int64_t cos_q_ = 0;
};

}  // namespace golden
