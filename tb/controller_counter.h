// tb/controller_counter.h — a controller-side quadrature counter, the kind that counts our
// digital A/B/Z in a motion controller (an FPGA encoder input such as a Mesa hostmot2 counter,
// or an MCU's encoder timer), for the testbenches (issue 36; docs/CONTROLLER.md). Written from
// the usual rules of such counters, not from this project's decoder:
//
//   * its own clock, ctl_clock_mhz, unrelated to ours (any ratio, with a start phase); the pins
//     are sampled every sample_div of its clocks (a sample-rate enable), so the sample period is
//     T_s = sample_div / ctl_clock_mhz. Sample k is taken at phase_ns + k * T_s, time 0 being
//     the start of our clock 0. It sees the pin levels of our clock interval that contains it
//     ([i T_clk, (i+1) T_clk) holds the levels given to clock() call i). A sample closer than
//     aperture_ns / 2 to one of our clock edges at which a pin changes is metastable: that pin
//     reads the old or the new level, chosen by a pseudo-random sequence (seed).
//   * per input line (A, B, Z) an integrating filter: an up/down counter c in 0..N that counts
//     up on a sample at 1 and down on a sample at 0 (held at the ends); the filtered line
//     becomes 1 when c reaches N and 0 when c reaches 0, and keeps its value in between. A level
//     passes only if it is sampled N times in a row (more ups than downs in general). N is
//     filter_n; 0 and 1 both mean "filter off": the filtered line is the last sample.
//   * a 4x decoder of the filtered A/B state: the states 00, 10, 11, 01 (A, B) in that order
//     count +1 each (A leads B: up), the reverse -1; a change of both lines in one sample is
//     a quadrature error (counted, the count is left as it was).
//   * an index latch on the chosen edge (rising or falling) of the filtered Z, or, gated, of
//     the gated index G = filtered Z && (filtered A, B) == (gate_a, gate_b) (so a gated rising
//     edge latches at the first sample where Z and the gate state are both present, whichever
//     came first). Each latch records the count after this sample's update.
//   All lines start low with their filters at 0, so the count starts at 0 in state 00; with
//   prime, they start at the levels of the first clock() call instead, filters settled there
//   (a controller that starts counting on lines that are already at their levels), count 0.
//
//   * line drivers: oe (our q_oe) low three-states A/B/Z; the receivers' open-line detection sets
//     the sticky line_fault at the next sample and the lines read their failsafe level, 1.
//
// clock(qa, qb, qz[, oe]) is called once per our clock with the pin levels of that clock; it evaluates
// every sample instant that falls in that clock (samples within aperture_ns / 2 before the edge
// that starts the next clock are evaluated in the next call, when that clock's levels are known).
// Prints nothing. Double arithmetic on time: sample k's time is computed directly from k.
#ifndef LASERAX_TB_CONTROLLER_COUNTER_H
#define LASERAX_TB_CONTROLLER_COUNTER_H

#include <cmath>
#include <cstdint>
#include <vector>

namespace lxtb {

struct controller_cfg {
    double our_clock_mhz = 100.0;  // our clock (one clock() call per period)
    double ctl_clock_mhz = 50.0;   // the controller's clock
    int sample_div = 1;            // samples every sample_div controller clocks (>= 1)
    double phase_ns = 0.0;         // time of the first sample after the start of our clock 0 (>= 0)
    int filter_n = 0;              // filter length in samples; 0 or 1: filter off
    double aperture_ns = 0.0;      // metastable window around each of our clock edges (< our period)
    uint64_t seed = 1;             // the metastable resolutions
    bool index_rising = true;      // latch on the rising (true) or falling edge of the filtered Z
    bool index_gate = false;       // latch only when the filtered A/B state is (gate_a, gate_b)
    bool gate_a = true, gate_b = true;
    bool prime = false;            // lines start at the first call's levels (count 0 there)
};

class controller_counter {
public:
    explicit controller_counter(const controller_cfg& c) : cfg_(c) {
        t_clk_ = 1000.0 / cfg_.our_clock_mhz;
        t_s_ = 1000.0 * (cfg_.sample_div < 1 ? 1 : cfg_.sample_div) / cfg_.ctl_clock_mhz;
        n_ = cfg_.filter_n < 1 ? 1 : cfg_.filter_n;
        half_ap_ = cfg_.aperture_ns > 0 ? cfg_.aperture_ns / 2 : 0.0;
        rng_ = cfg_.seed ? cfg_.seed : 0x9E3779B97F4A7C15ull;
    }

    // true if the configuration is usable (positive finite clocks, aperture below our period)
    bool valid() const {
        return std::isfinite(t_clk_) && t_clk_ > 0 && std::isfinite(t_s_) && t_s_ > 0 && cfg_.phase_ns >= 0 &&
               cfg_.aperture_ns >= 0 && cfg_.aperture_ns < t_clk_;
    }

    void clock(bool qa, bool qb, bool qz, bool oe = true) {
        const bool now[3] = {qa || !oe, qb || !oe, qz || !oe};
        if (calls_ == 0) {
            for (int l = 0; l < 3; ++l) prev_[l] = now[l];
            if (cfg_.prime) {
                for (int l = 0; l < 3; ++l) {
                    out_[l] = now[l];
                    c_[l] = now[l] ? n_ : 0;
                }
                g_prev_ = gated();
            }
        }
        const double edge = static_cast<double>(calls_) * t_clk_;  // start of this clock
        const double end = edge + t_clk_ - half_ap_;                // samples before: this call
        for (;;) {
            const double t = cfg_.phase_ns + static_cast<double>(k_) * t_s_;
            if (t >= end) break;
            ++k_;
            if (!oe) line_fault_ = true;
            bool v[3];
            const bool meta = t < edge + half_ap_;  // within the window of this clock's edge
            for (int l = 0; l < 3; ++l) v[l] = (meta && now[l] != prev_[l]) ? coin() : now[l];
            sample(v);
        }
        for (int l = 0; l < 3; ++l) prev_[l] = now[l];
        ++calls_;
    }

    int64_t count() const { return count_; }
    uint64_t quad_errors() const { return qerr_; }
    uint64_t steps() const { return steps_; }                      // every +1 and -1 counted
    const std::vector<int64_t>& index_counts() const { return index_; }  // count at each latch
    uint64_t index_events() const { return index_.size(); }
    uint64_t samples() const { return k_; }
    bool filtered(int line) const { return out_[line]; }           // 0 A, 1 B, 2 Z
    bool line_fault() const { return line_fault_; }                // a sample saw the drivers off

private:
    static int gray(bool a, bool b) { return a ? (b ? 2 : 1) : (b ? 3 : 0); }
    // the (gated) index of the filtered lines
    bool gated() const { return out_[2] && (!cfg_.index_gate || (out_[0] == cfg_.gate_a && out_[1] == cfg_.gate_b)); }

    bool coin() {
        rng_ ^= rng_ << 13;
        rng_ ^= rng_ >> 7;
        rng_ ^= rng_ << 17;
        return (rng_ >> 32) & 1u;
    }

    void sample(const bool v[3]) {
        const int old_state = gray(out_[0], out_[1]);
        for (int l = 0; l < 3; ++l) {
            if (v[l] && c_[l] < n_) ++c_[l];
            if (!v[l] && c_[l] > 0) --c_[l];
            if (c_[l] == n_) out_[l] = true;
            if (c_[l] == 0) out_[l] = false;
        }
        const int d = (gray(out_[0], out_[1]) - old_state + 4) % 4;
        if (d == 1) {
            ++count_;
            ++steps_;
        } else if (d == 3) {
            --count_;
            ++steps_;
        } else if (d == 2) {
            ++qerr_;
        }
        const bool g = gated();
        const bool edge = cfg_.index_rising ? (g && !g_prev_) : (!g && g_prev_);
        g_prev_ = g;
        if (edge) index_.push_back(count_);
    }

    controller_cfg cfg_;
    double t_clk_ = 10.0, t_s_ = 20.0, half_ap_ = 0.0;
    int n_ = 1;
    uint64_t rng_ = 1;
    uint64_t calls_ = 0, k_ = 0;
    bool prev_[3] = {false, false, false};
    int c_[3] = {0, 0, 0};
    bool out_[3] = {false, false, false};
    bool g_prev_ = false;  // the (gated) index of the previous sample
    bool line_fault_ = false;
    int64_t count_ = 0;
    uint64_t qerr_ = 0, steps_ = 0;
    std::vector<int64_t> index_;
};

}  // namespace lxtb

#endif
