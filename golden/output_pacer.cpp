// golden/output_pacer.cpp — see output_pacer.h (DESIGN.md 4.4).
#include "golden/output_pacer.h"

namespace golden {

void output_pacer::reset() { *this = output_pacer{}; }

output_pacer::out output_pacer::step(int64_t delta, int64_t pace_m, uint64_t thr, bool clear) {
    // emit uses the registers before the call (backlog before this call's delta is added)
    int emit = 0;
    if (calls_ >= next_emit_call_ && backlog_ != 0) emit = backlog_ > 0 ? 1 : -1;

    backlog_ = backlog_ + delta - emit;
    paced_ += emit;
    // Reading: "at least M calls apart" with the M of the call that emits (DESIGN: the timer
    // is loaded with M-1 at the emission, a later change of M does not shorten/lengthen the
    // running wait). pace_m < 1 is outside the register's legal range (2..65535).
    if (emit != 0) next_emit_call_ = calls_ + pace_m;
    ++calls_;

    const uint64_t mag = backlog_ < 0 ? static_cast<uint64_t>(-backlog_) : static_cast<uint64_t>(backlog_);
    const bool ovs = mag > thr;
    // ovs_st set by ovs, cleared by clear when !ovs (set wins)
    ovs_st_ = ovs || (ovs_st_ && !clear);
    return out{emit, paced_, backlog_, ovs, ovs_st_};
}

}  // namespace golden
