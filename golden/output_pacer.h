// golden/output_pacer.h — golden model of DESIGN.md 4.4 (output_pacer).
//
// The backlog (counts owed to the output) is emitted one count at a time, in the direction of
// its sign, with consecutive emitted counts at least M calls apart. The pacing is modelled as
// "earliest call index of the next emission" = (call of the last emission) + M, with M taken
// in the call of the emission (equivalent to DESIGN's timer loaded with M-1; requires M >= 1,
// the configuration check requires M >= 2).
// Invariant checked by construction: paced + backlog = sum of all deltas received.
#pragma once
#include <cstdint>

namespace golden {

class output_pacer {
public:
    struct out {
        int pstep;        // emitted count of this call: -1, 0, +1
        int64_t paced;    // paced'
        int64_t backlog;  // backlog'
        bool ovs;         // |backlog'| > thr (pulse)
        bool ovs_st;      // sticky
    };
    void reset();
    out step(int64_t delta, int64_t pace_m, uint64_t thr, bool clear);

private:
    int64_t calls_ = 0;          // call index since reset
    int64_t next_emit_call_ = 0; // first call index at which an emission is allowed
    int64_t backlog_ = 0;
    int64_t paced_ = 0;
    bool ovs_st_ = false;
};

}  // namespace golden
