// golden/output_pacer.h — golden model of DESIGN.md 4.4 (output_pacer).
//
// The backlog B (counts owed to the output) is emitted one count at a time, in the direction of
// its sign. An event is an emitted count or a slot (a paced call without a count, offered to
// rephase for its extra count): a count emitted while `wide` (rephase in its window) is followed by
// a slot before the next count, and consecutive events are at least max(M, 2) calls apart. The
// pacing is modelled as "earliest call index of the next event" = (call of the last event) +
// max(M, 2), with M taken in the call of the event (equivalent to DESIGN's timer loaded with M-1
// plus the "no two events in consecutive calls" rule; M = 0 is the 16-bit timer loaded with
// 65535, i.e. a gap of 65536 calls), and a flag "slot owed". The outputs paced and backlog are taps two calls late (P(t-2), B(t-2)),
// ovs compares |B(t-4)| with the threshold of the previous call.
// Invariant checked by construction: paced + backlog = sum of the deltas up to two calls earlier.
#pragma once
#include <cstdint>

namespace golden {

class output_pacer {
public:
    struct out {
        int pstep;        // emitted count of this call: -1, 0, +1
        bool slot;        // this call is the slot owed to the count before it
        int64_t paced;    // P(t-2): emitted counts up to two calls earlier (tap)
        int64_t backlog;  // B(t-2) (tap)
        bool ovs;         // |B(t-4)| > thr(t-1) (pulse)
        bool ovs_st;      // sticky
    };
    void reset();
    out step(int64_t delta, int64_t pace_m, uint64_t thr, bool clear, bool wide);

private:
    int64_t calls_ = 0;          // call index since reset
    int64_t next_event_call_ = 0; // first call index at which an event is allowed
    bool slot_owed_ = false;     // a count emitted while wide waits for its slot
    int64_t backlog_ = 0;        // B(t-1) before the call
    int64_t paced_ = 0;          // P(t-1)
    // history of (B, P) after the calls t-1 .. t-4 (index 0 = t-1); 0 before reset
    int64_t hist_b_[4] = {0, 0, 0, 0};
    int64_t hist_p_[4] = {0, 0, 0, 0};
    uint64_t thr_prev_ = 0;      // threshold of the previous call (0 before reset)
    bool ovs_st_ = false;
};

}  // namespace golden
