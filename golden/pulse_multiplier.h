// golden/pulse_multiplier.h — golden model of DESIGN.md 4.3 (pulse_multiplier).
//
// Definition: after every call comp = floor((N * R + OFF) / 2^32), with N' = wrap32(N + step),
// R' = the ratio register of this call and OFF the comp_offset register of this call (signed
// 64-bit, Q32.32 output counts); delta = comp' - comp (previous call's comp).
// Computed directly as floor((long double)N * R + (long double)OFF) * 2^-32.
//
// Exactness: R / 2^32 only changes the exponent (exact). long double on x86-64 has a 64-bit
// significand, so the product N * R (an integer) is exact whenever |N * R| < 2^64; then the
// sum N * R + OFF (an integer) is exact whenever it stays below 2^64 in magnitude, and so is the
// scaling by 2^-32 and the floor. With R < 2^37 (W_RATIO) and |OFF| <= 2^63 that holds for every
// ratio and offset while |N| < 2^26 (about 42 m of travel); beyond it the long double sum may be
// rounded and comp may differ from the exact value (tb/ checks that range against __int128).
// comp and delta are kept as int64_t (no 38-bit W_POS wrap: |comp| < 2^37 and |delta| < 2^37
// always fit in W_POS anyway).
#pragma once
#include <cstdint>

namespace golden {

class pulse_multiplier {
public:
    struct out {
        int64_t comp;   // floor(N' * R' / 2^32)
        int64_t delta;  // comp' - comp
    };
    void reset();
    out step(int step, uint64_t ratio_q32, int64_t offset_q32);

private:
    int64_t n_ = 0;     // N, kept in [-2^31, 2^31) (32-bit signed wrap)
    uint64_t r_ = 0;    // R (Q5.32)
    int64_t comp_ = 0;
};

}  // namespace golden
