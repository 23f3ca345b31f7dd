// golden/quad_decoder.h — golden model of DESIGN.md 4.2 (quad_decoder).
//
// Three input_filters (A, B, LERR, all with length glitch_n), then 4x quadrature decoding from
// the definition: (A,B) -> phase index (0,0)->0, (1,0)->1, (1,1)->2, (0,1)->3 and
// step = f((index_new - index_old) mod 4): 0 -> 0, 1 -> +1, 3 -> -1, 2 -> illegal.
// Overspeed uses the number of calls between two counted steps (no saturating counter; the
// first step after reset is never overspeed). raw_count wraps as a 32-bit signed value.
#pragma once
#include <cstdint>

#include "golden/input_filter.h"

namespace golden {

class quad_decoder {
public:
    struct out {
        int step;           // -1, 0, +1
        int64_t raw_count;  // 32-bit signed, wrapping, sign-extended
        bool illegal;       // pulse
        bool ovs;           // pulse
        int err_cnt;        // saturating at 255
        bool illegal_st;
        bool ovs_st;
        bool lerr;          // fe && primed
        bool lerr_alarm;
        bool glitch_st;     // sticky: the A or B filter suppressed a pulse
    };
    void reset();
    out step(bool a, bool b, bool lerr, int64_t glitch_n, int64_t min_spacing, bool clear);

private:
    input_filter fa_, fb_, fe_;
    bool primed_ = false;
    bool pa_ = false, pb_ = false;   // previous (A,B) levels
    int64_t calls_ = 0;              // call index since reset
    bool have_last_step_ = false;    // a step has been counted since reset
    int64_t last_step_call_ = 0;     // call index of the last counted step
    int64_t ms_prev_ = 0;            // min_spacing of the previous call (0 after reset: no step yet)
    int64_t raw_count_ = 0;          // always kept in [-2^31, 2^31)
    int err_cnt_ = 0;
    bool illegal_st_ = false, ovs_st_ = false, lerr_alarm_ = false, glitch_st_ = false;
};

}  // namespace golden
