// golden/pulse_multiplier.cpp — see pulse_multiplier.h (DESIGN.md 4.3).
#include "golden/pulse_multiplier.h"

#include <cmath>

namespace golden {

namespace {

int64_t wrap32(int64_t v) {
    // two's-complement wrap to 32 bits without signed overflow: go through uint32_t
    const uint32_t u = static_cast<uint32_t>(static_cast<uint64_t>(v));
    return u >= 0x80000000u ? static_cast<int64_t>(u) - (int64_t{1} << 32) : static_cast<int64_t>(u);
}

}  // namespace

void pulse_multiplier::reset() { *this = pulse_multiplier{}; }

pulse_multiplier::out pulse_multiplier::step(int step, uint64_t ratio_q32, int64_t offset_q32) {
    n_ = wrap32(n_ + step);
    r_ = ratio_q32;  // Reading: R' is the ratio input of this call, taken as given (the
                     // register is 37 bits wide; callers keep it < 2^37)
    // N*R and N*R + OFF are integers, exact while below 2^64; the scaling by 2^-32 is exact.
    const long double sum = static_cast<long double>(n_) * static_cast<long double>(r_) + static_cast<long double>(offset_q32);
    const int64_t comp = static_cast<int64_t>(std::floor(sum / 4294967296.0L));
    const int64_t delta = comp - comp_;
    comp_ = comp;
    return out{comp, delta};
}

}  // namespace golden
