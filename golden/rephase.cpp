// golden/rephase.cpp — see rephase.h (DESIGN.md 4.5).
#include "golden/rephase.h"

#include <algorithm>
#include <cmath>

namespace golden {

namespace {

// DESIGN 4.5 step 2: while `unhome` is active in stage 1 a rising switch edge is ignored (no homing
// on an invalid position); the edge is consumed since sw_prev' = sw.
constexpr bool kUnhomeBlocksHomingInStage1 = true;

// true modulo, result in [0, m) (m > 0; m <= 0 is an invalid configuration, returns 0)
int64_t mod(int64_t x, int64_t m) { return m > 0 ? ((x % m) + m) % m : 0; }

int sgn(int64_t v) { return (v > 0) - (v < 0); }

}  // namespace

void rephase::reset() { *this = rephase{}; }

rephase::out rephase::step(int pstep, bool slot, bool sw, bool sw_valid, bool rehome, bool unhome,
                           int64_t period, int64_t mark_len) {
    const int64_t P = period;
    // 5. index: the test of the previous call's registers (before this call's update)
    const bool index = stage_ == 3 && paced_ == z_;

    // 1. paced stream. Reading: dir_last' = pstep with pstep in {-1, +1} (stored as its sign).
    paced_ += pstep;
    if (pstep != 0) dir_last_ = pstep > 0 ? +1 : -1;

    // 2. stage machine (uses paced' and dir_last')
    int stage_next = stage_;
    if ((unhome || rehome) && stage_ != 1) {
        stage_next = 1;
        adj0_ = adj_;      // freeze the applied adjustment (no phase jump; an extra count still
        adj_tgt_ = adj0_;  // waiting for its slot is dropped); adj_tgt' = adj0' (Stage-1 invariant)
    } else if (stage_ == 1) {
        // rise uses sw_prev / sw_seen before the call (sw_seen = previous call's sw_valid),
        // so a switch already closed at power-up is not an edge.
        const bool rise = sw && !sw_prev_ && sw_seen_;
        if (rise && !(kUnhomeBlocksHomingInStage1 && unhome)) {
            stage_next = 2;
            a_ = paced_;
            dir_ = dir_last_;
            const int64_t ph_a = mod(paced_ + adj0_, P);
            // Reading: 7P/8 and 3P/8 are integers (P % 8 == 0 by the configuration check);
            // "dir" in the d' formulas is the new dir' = dir_last'.
            d_ = dir_ > 0 ? mod(7 * P / 8 - ph_a, P) : mod(ph_a - 3 * P / 8, P);
        }
        adj_tgt_ = adj0_;  // un-homed: adj_tgt = adj0
    } else if (stage_ == 2) {
        const int64_t tr = dir_ * (paced_ - a_);
        if (tr < 0) {
            // back past A. Reading: adj_tgt' = adj0 (the Stage-1 invariant; the value held
            // from the call at tr = 0 is adj0 anyway, so no jump).
            stage_next = 1;
            adj_tgt_ = adj0_;
        } else if (tr >= P) {
            stage_next = 3;
            adj0_ = adj0_ + dir_ * d_;
            b_ = a_ + dir_ * P;
            c_ = b_ + dir_ * mark_len;
            // Reading: Z (home_pos = b + dir*P/4) is stored at the homing call with that
            // call's P, and kept like b and c (after an unhome, until the next homing).
            z_ = b_ + dir_ * (P / 4);
            adj_tgt_ = adj0_;
        } else {
            // 0 <= tr < P: floor(d*tr/P) with a double division (d*tr < 2^24, exact)
            const double q = static_cast<double>(d_ * tr) / static_cast<double>(P);
            adj_tgt_ = adj0_ + dir_ * static_cast<int64_t>(std::floor(q));
        }
    } else {
        adj_tgt_ = adj0_;  // stage 3: homed, phase locked, switch ignored
    }
    sw_prev_ = sw;
    sw_seen_ = sw_valid;
    stage_ = stage_next;

    // 3. output step: a real count passes as is; in the pacer's slot move adj one count toward
    //    adj_tgt'; otherwise no count
    int ostep = 0;
    if (pstep != 0) {
        ostep = pstep;
    } else if (slot) {
        ostep = sgn(adj_tgt_ - adj_);
        adj_ += ostep;
    }
    const int64_t out_pos = paced_ + adj_;

    // 4. mark: closed interval between b' and c' (either order)
    const bool mark = stage_ == 3 && paced_ >= std::min(b_, c_) && paced_ <= std::max(b_, c_);

    return out{ostep, out_pos, mark, index, stage_, a_, d_, b_, c_, z_, adj_, stage_ == 3};
}

}  // namespace golden
