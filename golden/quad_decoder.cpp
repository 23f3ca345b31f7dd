// golden/quad_decoder.cpp — see quad_decoder.h (DESIGN.md 4.2).
#include "golden/quad_decoder.h"

#include <algorithm>

namespace golden {

namespace {

int quad_index(bool a, bool b) {
    // (A,B) = (0,0)->0, (1,0)->1, (1,1)->2, (0,1)->3   (A leads B = forward = +1)
    if (!a && !b) return 0;
    if (a && !b) return 1;
    if (a && b) return 2;
    return 3;
}

int64_t wrap32(int64_t v) {
    // two's-complement wrap to 32 bits without signed overflow: go through uint32_t
    const uint32_t u = static_cast<uint32_t>(static_cast<uint64_t>(v));
    return u >= 0x80000000u ? static_cast<int64_t>(u) - (int64_t{1} << 32) : static_cast<int64_t>(u);
}

}  // namespace

void quad_decoder::reset() { *this = quad_decoder{}; }

quad_decoder::out quad_decoder::step(bool a, bool b, bool lerr, int64_t glitch_n,
                                     int64_t min_spacing, bool clear) {
    const input_filter::out oa = fa_.step(a, glitch_n);
    const input_filter::out ob = fb_.step(b, glitch_n);
    const input_filter::out oe = fe_.step(lerr, glitch_n);
    // Reading: "valid" of this call — the three filters are reset together and step together,
    // so their valid flags are identical; the AND is used.
    const bool valid = oa.valid && ob.valid && oe.valid;
    const bool fa = oa.f, fb = ob.f, fe = oe.f;
    const bool glitch = oa.glitch || ob.glitch;  // a suppressed pulse on A or B

    // Reading: lerr = fe && primed uses `primed` before the call (the register that selects
    // the branch below), so in the call that primes the decoder lerr is 0.
    const bool lerr_out = primed_ && fe;

    int stp = 0;
    bool illegal = false;
    if (!primed_) {
        primed_ = valid;  // no count before the filter is valid
    } else if (fe) {
        // laser error: track, do not count
    } else {
        const int diff = ((quad_index(fa, fb) - quad_index(pa_, pb_)) % 4 + 4) % 4;
        if (diff == 1) stp = +1;
        else if (diff == 3) stp = -1;
        else if (diff == 2) illegal = true;
    }
    pa_ = fa;
    pb_ = fb;

    // Overspeed: spacing = number of calls from the previous counted step to this one
    // (DESIGN: since + 1 with since reset to 65535, i.e. the first step is never overspeed;
    // the 16-bit saturation is irrelevant because min_spacing <= 65535 (W_SPACING)), compared
    // with min_spacing of the previous call (DESIGN 4.2: a write acts one call later).
    bool ovs = false;
    const int64_t ms = ms_prev_;
    ms_prev_ = min_spacing;
    if (stp != 0) {
        if (have_last_step_ && ms > 0) {
            const int64_t spacing = calls_ - last_step_call_;
            ovs = spacing < ms;
        }
        have_last_step_ = true;
        last_step_call_ = calls_;
    }
    ++calls_;

    raw_count_ = wrap32(raw_count_ + stp);

    // clear acts first; this call's events set their flags again
    if (clear) {
        illegal_st_ = false;
        ovs_st_ = false;
        glitch_st_ = false;
        err_cnt_ = 0;
    }
    illegal_st_ = illegal_st_ || illegal;
    ovs_st_ = ovs_st_ || ovs;
    glitch_st_ = glitch_st_ || glitch;
    if (illegal) err_cnt_ = std::min(err_cnt_ + 1, 255);
    // lerr_alarm: set while fe && primed; clear clears it only if fe is 0 in that call
    // (fe itself, not fe && primed: with fe = 1 before priming the clear is also ignored).
    if (clear && !fe) lerr_alarm_ = false;
    if (lerr_out) lerr_alarm_ = true;

    return out{stp, raw_count_, illegal, ovs, err_cnt_, illegal_st_, ovs_st_, lerr_out, lerr_alarm_, glitch_st_};
}

}  // namespace golden
