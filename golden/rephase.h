// golden/rephase.h — golden model of DESIGN.md 4.5 (rephase).
//
// Stage 1 (un-homed) -> rising edge of the debounced switch at paced position A -> Stage 2:
// over the P real counts A..B = A + dir*P the output receives d extra counts in direction dir,
// adj_tgt = adj0 + dir*floor(d*tr/P) (tr = dir*(paced - A), the floor computed with a double
// division: d*tr < 2^24 and P <= 4096, so the double quotient is exact enough for an exact
// floor) -> Stage 3 (homed) at B: adj0 += dir*d, B, C = B + dir*mark_len, Z = B + dir*P/4.
// The phase of the output at B is 7P/8 (dir = +1) or 3P/8 (dir = -1), so at Z it is P/8.
// Phases use a true modulo ((x % P) + P) % P on int64 positions; positions are int64_t
// (no 38-bit W_POS wrap). Requires P > 0 with P % 8 == 0 (configuration check).
#pragma once
#include <cstdint>

namespace golden {

class rephase {
public:
    struct out {
        int ostep;        // output count of this call: -1, 0, +1
        int64_t out_pos;  // paced' + adj'
        bool mark;        // stage' == 3 && paced' in [b', c'] (closed)
        bool index;       // stage == 3 && paced == z of the previous call (DESIGN 4.5 step 5)
        int stage;        // 1..3
        int64_t a, d, b, c;  // registers (0 at reset, updated when set)
        int64_t z;        // b + dir*P/4, set at homing (0 before the first homing, then kept)
        int64_t adj;      // applied adjustment adj'
        bool homed;       // stage == 3
    };
    void reset();
    out step(int pstep, bool slot, bool sw, bool sw_valid, bool rehome, bool unhome, int64_t period,
             int64_t mark_len);

private:
    int stage_ = 1;
    int64_t paced_ = 0;
    int dir_last_ = +1;
    bool sw_prev_ = false;
    bool sw_seen_ = false;
    int64_t a_ = 0;
    int dir_ = 0;
    int64_t d_ = 0;
    int64_t adj0_ = 0;
    int64_t adj_tgt_ = 0;
    int64_t adj_ = 0;
    int64_t b_ = 0, c_ = 0, z_ = 0;
};

}  // namespace golden
