// golden/pso.h — golden model of docs/PSO_COUNTERS.md §2 (position-synchronised output).
//
// Written from the definitions, in terms of positions and distances rather than registers:
//   * the tracked position P (int64 per axis) and the start S of the open tracking window;
//     a reversal closes the window at the previous position, max|P - S| >= K closes it at the
//     current one; the estimate is est(t) = sum of closed chords + chord(P(t) - S), where
//     chord(v) = |v| rounded to the nearest 2^-32 count (sqrtl, then an exact integer check);
//   * part-speed: est(t) = floor(Phi(t)), Phi = sum of the clamped commanded rate (exact);
//   * the k-th fire is the first call t+7 with est(t) - (sum of the thresholds already fired)
//     >= thr_k (absolute bookkeeping of fired thresholds, no remainder register); no fire in the
//     first seven calls of a run (docs/PSO_COUNTERS.md §2.5, §2.9);
//   * the threshold of a fire is taken at the previous fire, or at the start of the run: thr_1
//     is fire_dist of run call 0 (or entry 0 as the RAM stands after that call); with fire k-1
//     in call G, thr_k is fire_dist of call G-3 (or the entry of fire k's index as the RAM
//     stands after call G-3); none is taken by the fire that makes the array done;
//   * spacing_err: every 17 run calls, the check of the command sampled 17 calls before (its
//     threshold: the one taken last, after the sample call's fire);
//   * the pulse is high at call t when t - (call of the last emit) < pulse width of that emit;
//   * register stage (§2.2): the registers passed to step() in call t are in force in call t+1;
//     every register named above is the value in force (the reset values after construction).
// Distances are long double counts; every value is a multiple of 2^-32 below 2^32 counts, so
// long double (64-bit significand) holds them exactly.
#pragma once
#include <cstdint>
#include <vector>

namespace golden {

struct pso_regs {
    bool enable = false;
    bool part_speed = false;
    unsigned axis_mask = 3;      // bit i: axis i is tracked
    int win_k = 16;              // tracking window, counts
    uint64_t fire_dist = 128ULL << 32;  // Q24.32 counts
    bool arr_en = false;
    int arr_len = 1;
    bool arr_wrap = false;
    bool arr_we = false;
    int arr_addr = 0;
    uint64_t arr_data = 0;       // Q24.32 counts
    int pulse_w = 10;
    bool win_en = false;
    int win_src = 0;             // 0..2 axis position, 3 part-speed pulse count
    int64_t win_low = 0, win_high = 0;
    int min_period = 0;          // clocks, 0 = off
    bool clear = false;
};

struct pso_in {
    int step[3] = {0, 0, 0};
    int64_t pos[3] = {0, 0, 0};
    uint64_t ps_inc = 0;  // Q0.32 counts per clock
};

class pso {
public:
    static constexpr int kAxes = 3;
    static constexpr int kMaxK = 16;
    static constexpr int kFireLat = 7;   // calls from a step to its fire
    static constexpr int kSpLat = 17;    // calls from a spacing sample to its flag
    static constexpr int kArrDepth = 64;
    static constexpr long double kMinDist = 4.0L;       // counts (> 2 sqrt3: no fire in two calls in a row)
    static constexpr long double kClockHz = 100e6L;
    static constexpr long double kPulseHzMax = 24e6L;
    struct out {
        bool fire = false, emit = false, pulse = false, in_win = false;
        long double dist = 0;  // counts since the last fire
        int idx = 0;
        bool arr_done = false;
        uint32_t fire_cnt = 0;
        int overlap_cnt = 0;
        bool overlap = false, overlap_st = false;
        bool rate_over = false, rate_over_st = false;
        bool spacing_err = false, spacing_st = false;
        bool freq_err = false, freq_st = false;
        bool ps_pulse = false;
        int64_t ps_count = 0;
        bool cfg_err = false;
    };

    pso();
    void reset();
    // r: the register values presented in this call (in force from the next call on)
    out step(const pso_in& in, const pso_regs& r);

    bool config_ok(const pso_regs& r) const;
    // Largest part-speed increment whose pulse rate stays <= 24 MHz: floor(24e6 / 100e6 * 2^32).
    static uint64_t inc_max();
    // round(|v| * 2^32) for an integer vector with sum of squares s (the chord of the definition).
    static uint64_t chord_q32(int64_t s);

private:
    void reset_run();

    std::vector<uint64_t> ram_;
    std::vector<uint64_t> ram_m2_;  // the RAM as it stood after the previous call
    std::vector<uint64_t> ram_m3_;  // the RAM as it stood after the call before it, i.e. "after
                                    //   call n-3" of the next call
    std::vector<uint64_t> ram_g3_;  // within step(): the RAM as it stood after call t-3
    pso_regs force_;                // register values in force (presented in the previous call)
    // run state
    bool running_ = false;
    bool ps_ = false, arr_en_ = false, arr_wrap_ = false;
    unsigned mask_ = 0;
    int arr_len_ = 1;
    int64_t t_ = 0;                 // call index in the run
    int64_t p_[3] = {0, 0, 0};      // tracked position
    int64_t s_[3] = {0, 0, 0};      // window start
    long double closed_ = 0;        // sum of closed chords
    long double phi_ = 0;           // part-speed commanded distance
    int64_t ps_count_ = 0;
    long double est_hist_[kFireLat] = {};   // estimate after call t-1 .. t-7
    bool inwin_hist_[kFireLat] = {};
    uint64_t fd_m1_ = 0;            // fire_dist of the previous call
    uint64_t fd_m2_ = 0;            // fire_dist of the call before it
    uint64_t fd_m3_ = 0;            // fire_dist of the call before that
    bool sp_pending_ = false;       // spacing check of the last sample
    long double fired_ = 0;         // sum of the thresholds fired
    long double thr_ = 0;           // threshold of the next fire (taken at the last fire / run start)
    int idx_ = 0;
    bool done_ = false;
    bool fired_last_ = false;       // the previous call fired (no fire in the call after a fire)
    long double frozen_ = 0;
    bool have_emit_ = false;
    int64_t last_emit_ = 0;
    int last_w_ = 0;
    // kept across runs (cleared by reset / cfg error)
    uint32_t fire_cnt_ = 0;
    int ovl_cnt_ = 0;
    bool overlap_st_ = false, rate_over_st_ = false, spacing_st_ = false, freq_st_ = false;
};

// ---- part-speed helpers (Aerotech Part-Speed PSO): feed rates in units/s, counts per unit ------
// Maximum programmed vector feed rate: pulse generator limit / counts per unit.
double pso_max_feed(double counts_per_unit, double pulse_hz = 24e6);
// Minimum firing spacing (units) at a feed rate for a laser limited to laser_hz pulses/s.
double pso_min_spacing(double feed_units_per_s, double laser_hz);
// Vector speed of up to three virtual axes, sqrt(vx^2 + vy^2 + vz^2).
double pso_vector_speed(double vx, double vy, double vz);
// Commanded rate register: round(counts_per_unit * feed / clock_hz * 2^32), Q0.32 counts per
// clock; *over is set when the rate exceeds 24 MHz (the block then clamps and flags rate_over).
uint64_t pso_rate_increment(double counts_per_unit, double feed_units_per_s, bool* over, double clock_hz = 100e6);
// Laser minimum period register: ceil(clock / laser_hz) clocks (0 when laser_hz <= 0).
int pso_min_period_clocks(double laser_hz, double clock_hz = 100e6);
// Distance register value: round(counts * 2^32).
uint64_t pso_dist_q32(long double counts);
// Firing positions along the path (counts, increasing) -> array entries (differences, Q.32):
// entry k = round(D_k * 2^32) - round(D_{k-1} * 2^32), so the absolute positions are exact.
std::vector<uint64_t> pso_array_from_positions(const std::vector<long double>& positions);

}  // namespace golden
