// golden/output_pacer.cpp — see output_pacer.h (DESIGN.md 4.4).
#include "golden/output_pacer.h"

namespace golden {

void output_pacer::reset() { *this = output_pacer{}; }

output_pacer::out output_pacer::step(int64_t delta, int64_t pace_m, uint64_t thr, bool clear, bool wide) {
    // emit and slot use the registers before the call (backlog before this call's delta is added)
    const bool ready = calls_ >= next_event_call_;
    int emit = 0;
    if (ready && !slot_owed_ && backlog_ != 0) emit = backlog_ > 0 ? 1 : -1;
    const bool slot = ready && slot_owed_;

    backlog_ = backlog_ + delta - emit;
    paced_ += emit;
    // Reading: "at least max(M, 2) calls apart" with the M of the call that emits (DESIGN: the
    // timer is loaded with M-1 at the emission and no count follows in the next call; a later
    // change of M does not shorten/lengthen the running wait). M = 0: the 16-bit timer is loaded
    // with 65535, i.e. the next count is allowed 65536 calls later.
    if (emit != 0 || slot) {
        const int64_t gap = pace_m == 0 ? 65536 : (pace_m < 2 ? 2 : pace_m);
        next_event_call_ = calls_ + gap;
    }
    // a count emitted while rephase is in its window owes a slot (DESIGN 4.4: h' = wide)
    if (emit != 0) slot_owed_ = wide;
    if (slot) slot_owed_ = false;
    ++calls_;

    // ovs: |B(t-4)| > thr(t-1), B(t-4) = hist[3] before the shift
    const int64_t b4 = hist_b_[3];
    const uint64_t mag = b4 < 0 ? static_cast<uint64_t>(-b4) : static_cast<uint64_t>(b4);
    const bool ovs = mag > thr_prev_;
    thr_prev_ = thr;
    // ovs_st set by ovs, cleared by clear when !ovs (set wins)
    ovs_st_ = ovs || (ovs_st_ && !clear);

    // taps: B(t-2), P(t-2) = hist[1] before the shift
    const out o{emit, slot, hist_p_[1], hist_b_[1], ovs, ovs_st_};
    // the history shifts by one call (written out: as a loop the compiler calls memmove twice)
    hist_b_[3] = hist_b_[2];
    hist_b_[2] = hist_b_[1];
    hist_b_[1] = hist_b_[0];
    hist_p_[3] = hist_p_[2];
    hist_p_[2] = hist_p_[1];
    hist_p_[1] = hist_p_[0];
    hist_b_[0] = backlog_;
    hist_p_[0] = paced_;
    return o;
}

}  // namespace golden
