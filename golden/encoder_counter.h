// golden/encoder_counter.h — golden model of docs/PSO_COUNTERS.md §3 (encoder counters) and the
// scale-factor helpers of §3.5 (RTC5 linear movements, docs/SOURCES.md; its formulas are in
// golden/calibration.h).
//
// Written from the definitions: each counter is kept as an unwrapped int64 count and shown as
// its 32-bit two's complement residue; the simulation is the exact commanded count
// Phi = sum(rate / 2^32) since the last reset, one count per integer crossed; the correction
// tick is "period calls after the previous tick"; "passed" for wait-for-encoder is the sign of
// the residue of (count - value) in [-2^31, 2^31). long double is exact for all of these
// (integers < 2^64, Phi a multiple of 2^-32 below 2^32).
#pragma once
#include <cstdint>
#include <vector>

#include "golden/calibration.h"

namespace golden {

struct encoder_counter_regs {
    int src[2] = {0, 0};                 // 0 quadrature step, 1 simulation
    uint64_t sim_inc[2] = {42949673, 42949673};  // Q0.32 counts per clock (1 MHz)
    bool sim_down[2] = {false, false};
    int64_t scale[2] = {0, 0};           // Q8.24 bits per count
    bool rst_req[2] = {false, false};
    bool load[2] = {false, false};
    int64_t load_val[2] = {0, 0};
    bool rst_on_trig = false;
    int corr_period = 1000;
    bool wait_arm = false;
    int wait_ch = 0;
    int64_t wait_val = 0;
    bool wait_down = false;
};

struct encoder_counter_in {
    int qstep[2] = {0, 0};
    bool trig = false;
    int64_t pos[2] = {0, 0};
};

// The correction is visible this many calls after its sample call (docs/PSO_COUNTERS.md §3.2);
// corr_period must be at least this.
constexpr int kEncoderCorrLatency = 33;

class encoder_counter {
public:
    struct out {
        int64_t cnt[2] = {0, 0};   // signed 32-bit value
        int step[2] = {0, 0};
        bool rst_done[2] = {false, false};
        bool rst_pending[2] = {false, false};
        int64_t corr[2] = {0, 0};
        bool tick = false;
        bool waiting = false;
        bool reached = false;
        bool cfg_err = false;
    };
    encoder_counter() = default;
    void reset();
    out step(const encoder_counter_in& in, const encoder_counter_regs& r);
    static bool config_ok(const encoder_counter_regs& r);

private:
    int64_t u_[2] = {0, 0};          // unwrapped count
    long double phi_[2] = {0, 0};    // simulation: commanded count since the last reset
    bool sim_due_[2] = {false, false};  // an integer was crossed in the previous call
    bool pending_[2] = {false, false};
    int64_t corr_[2] = {0, 0};
    int64_t t_ = 0;                  // calls since the run started
    int64_t last_tick_ = -1;         // last sample call
    int64_t due_ = -1;               // call that shows the sampled correction (-1: none)
    int64_t pend_[2] = {0, 0};       // the sampled correction
    bool waiting_ = false;
    int64_t judged_diff_ = 0;        // wait: s32(counter after call t-2 - value), for call t
    bool judged_ok_ = false;         //   no arm in call t-1
    int w_ch_ = 0;
    int64_t w_val_ = 0;
    bool w_down_ = false;
};

// 32-bit two's complement value of an integer (the counter reading of an unwrapped count).
int64_t wrap_s32(int64_t v);
// Wrap-aware difference of two 32-bit readings: the value of (b - a) mod 2^32 in [-2^31, 2^31).
int64_t counter_diff(int64_t a, int64_t b);

// ---- calibration helpers (RTC5 linear movements) ----------------------------------------------
// The source's forms themselves are in golden/calibration.h (issue 3): encoder_increment (start/end
// readings, modulo-2^32 difference), scale_from_increment (Scale = K / i), scale_from_speed
// (Scale = K * v / 10^6 counts/s) and fit_scale_offset (Eigen least squares). What the counter
// block adds:

// Increment i [counts/mm] from many readings taken during one move: the 32-bit readings are
// unwrapped in order (consecutive readings less than 2^31 counts apart), then
// reading = i * position + offset is fitted with golden::fit_scale_offset (Eigen QR). The
// result's `scale` is i, its `offset` is relative to the first reading.
linear_fit encoder_increment_fit(const std::vector<double>& pos_mm, const std::vector<int64_t>& readings);
// Constant-speed form for any simulation rate: Scale = K * v / rate [bits/count]; with the
// default 10^6 counts/s it equals scale_from_speed. v is signed (workpiece velocity along the
// image axis); the simulated counter counts up (sim_down = 0), so the sign of v is the sign of
// the scale. A counter that counts down for +v (sim_down = 1, or an encoder mounted the other
// way round: i < 0) needs the opposite sign, which Scale = K / i gives by itself.
double encoder_scale_at_rate(double k_bits_per_mm, double v_mm_per_s, double rate_counts_per_s);
// Q8.24 register value of a scale: round half away from zero; *ok false when out of range.
int64_t encoder_scale_to_q(double scale, bool* ok);
// Simulation rate register for a counting rate: round(rate / clock * 2^32).
uint64_t encoder_sim_inc(double counts_per_s, double clock_hz = 100e6);

}  // namespace golden
