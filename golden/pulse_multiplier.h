// golden/pulse_multiplier.h — golden model of DESIGN.md 4.3 (pulse_multiplier), from its Definition.
//
// N' = wrap32(N + step). A call starts a re-base when none is in progress (the last start was at
// least K_REBASE calls ago) and the input pair (R, OFF) of the previous call differed from the
// target pair as it was after that call (reset: target (0, 0), nothing pending); it records
// N0 = N after the call, R_old / OFF_old = the previous target pair, and the input pair of this
// call as the new target. The value of call t is
//     V = N0 * R_old + (N - N0) * R_tgt + OFF_old     while t < start + K_REBASE,
//     V = N * R_tgt + OFF_tgt                          otherwise,
// comp_int = floor(V / 2^32) wrapped to W_POS = 38 bits, and the outputs are delayed by L_MUL calls:
// comp(t) = comp_int(t - L_MUL), delta(t) = comp(t) - comp(t - 1).
// V is computed in long double: every product and the sum are integers, exact while they stay
// below 2^64 in magnitude, i.e. for any ratio and offset while |N| < 2^26 (tb/ checks beyond that
// against __int128). The model knows nothing of the accumulator split or the serial multiplier.
#pragma once
#include <cstdint>

namespace golden {

class pulse_multiplier {
public:
    static constexpr int K_REBASE = 40;  // DESIGN 4.3
    static constexpr int L_MUL = 3;      // DESIGN 4.3
    struct out {
        int64_t comp;   // comp_int of L_MUL calls ago
        int64_t delta;  // comp - previous comp
    };
    void reset();
    // Testbench aid (DESIGN 4.3 "Preset port"): N, the target pair and an idle block; every
    // delayed comp_int holds the value of the preset.
    void preset(int64_t n, uint64_t ratio_q32, int64_t offset_q32);
    out step(int step, uint64_t ratio_q32, int64_t offset_q32);

private:
    int64_t value_comp() const;
    int64_t n_ = 0;          // N, kept in [-2^31, 2^31) (32-bit signed wrap)
    uint64_t r_tgt_ = 0;     // target pair
    int64_t off_tgt_ = 0;
    bool rebasing_ = false;  // a re-base is in progress
    bool pending_ = false;   // the previous call's input pair differed from the target
    long long since_ = 0;    // calls since its start (0 in the start call)
    int64_t n0_ = 0;
    uint64_t r_old_ = 0;
    int64_t off_old_ = 0;
    int64_t hist_[L_MUL + 1] = {0, 0, 0, 0};  // comp_int of the last L_MUL + 1 calls, newest first
};

}  // namespace golden
