// golden/pulse_multiplier.cpp — see pulse_multiplier.h (DESIGN.md 4.3).
#include "golden/pulse_multiplier.h"

#include <cmath>

namespace golden {

namespace {

int64_t wrap_bits(int64_t v, int bits) {
    // two's-complement wrap to `bits` bits without signed overflow: go through uint64_t
    const uint64_t m = (uint64_t{1} << bits) - 1;
    const uint64_t u = static_cast<uint64_t>(v) & m;
    const uint64_t sign = uint64_t{1} << (bits - 1);
    return (u & sign) ? static_cast<int64_t>(u | ~m) : static_cast<int64_t>(u);
}

}  // namespace

void pulse_multiplier::reset() { *this = pulse_multiplier{}; }

void pulse_multiplier::preset(int64_t n, uint64_t ratio_q32, int64_t offset_q32) {
    reset();
    n_ = wrap_bits(n, 32);
    r_tgt_ = ratio_q32;
    off_tgt_ = offset_q32;
    const int64_t c = value_comp();
    for (int64_t& h : hist_) h = c;
}

int64_t pulse_multiplier::value_comp() const {
    using ld = long double;
    ld v;
    if (rebasing_)
        v = static_cast<ld>(n0_) * static_cast<ld>(r_old_) +
            static_cast<ld>(n_ - n0_) * static_cast<ld>(r_tgt_) + static_cast<ld>(off_old_);
    else
        v = static_cast<ld>(n_) * static_cast<ld>(r_tgt_) + static_cast<ld>(off_tgt_);
    // floor(V / 2^32) fits 39 bits; wrap to W_POS = 38 (only the wrap-during-re-base corner needs it)
    return wrap_bits(static_cast<int64_t>(std::floor(v / 4294967296.0L)), 38);
}

pulse_multiplier::out pulse_multiplier::step(int step, uint64_t ratio_q32, int64_t offset_q32) {
    // the step of this call counts at the target ratio before the call
    n_ = wrap_bits(n_ + step, 32);
    // a re-base in progress ends K_REBASE calls after its start
    if (rebasing_ && ++since_ >= K_REBASE) rebasing_ = false;
    const bool start = !rebasing_ && pending_;
    if (start) {
        rebasing_ = true;
        since_ = 0;
        n0_ = n_;
        r_old_ = r_tgt_;
        off_old_ = off_tgt_;
        r_tgt_ = ratio_q32;
        off_tgt_ = offset_q32;
    }
    // the input pair of this call against the target after it, seen by the next call
    pending_ = ratio_q32 != r_tgt_ || offset_q32 != off_tgt_;
    const int64_t comp_prev = hist_[L_MUL];  // the output of the previous call
    for (int i = L_MUL; i > 0; --i) hist_[i] = hist_[i - 1];
    hist_[0] = value_comp();
    // outputs: comp_int of L_MUL calls ago and its change; the difference of two W_POS values
    // fits W_DELTA = 39 bits exactly
    return out{hist_[L_MUL], hist_[L_MUL] - comp_prev};
}

}  // namespace golden
