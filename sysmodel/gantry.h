// gantry.h — cycle-accurate system simulation of a twin-rail gantry (docs/GANTRY.md): two
// instances of the single-axis HLS top (lx::laserax_top, X1 and X2) feeding a controller model that
// decodes their sin/cos outputs like a real controller's interpolator, and the homing sequence of
// the "referencing a twin axis" sections of Laser scale referencing (docs/SOURCES.md):
//
//   power-up   each laser becomes ready (starts counting) at its own position while the square
//              gantry is positioned on its motor encoders: the two compensators power up with
//              independent sin/cos phases (the "power-up phases")
//   pass 1     X1 master searches its home (reference mark with sin == cos > 0), X2 tracks
//              X1's measured position; both continue to a clearance point past the home
//   back off   locked move back behind both reference switches
//   pass 2     X2 master searches its home, X1 tracks
//   park       X1 master again, moves to its home, X2 tracks
//   check      skew = ctrl1 - ctrl2 against the limit with the offset parameter; alarm -> stop
//   deskew     X2 alone moves until skew == offset
//
// The controller sees only what a real one sees: the sin/cos DAC codes and the reference mark of
// each axis, the compensators' alarm status, and it writes the rehome/clear registers. It never
// reads positions or state out of the cores; the physical positions and the cores' taps are
// recorded for the report and the tests only.
//
// One simulation call is one 10 ns clock of both cores. Motion is time-scaled (a homing speed of
// 1/16 output count per clock) so that whole sequences run in milliseconds.
#ifndef LASERAX_TOOLS_GANTRY_H
#define LASERAX_TOOLS_GANTRY_H

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "golden/gantry_model.h"

namespace lxt {

struct gantry_config {
    int period = 256;             // P, output counts per sin/cos period (8..4096, multiple of 8)
    int resolution = 2048;        // controller interpolation: units per sin/cos period (>= P, % 8 == 0)
    double compliance = 0.5;      // 0 < c <= 1: share of the drives' differential motion that
                                  // appears as real skew (1: rails independent)
    int offset = 0;               // controller offset parameter: expected ctrl1 - ctrl2 (counts)
    int switch_offset = 0;        // real offset of X2's switch (and encoder mark) from X1's (counts)
    int skew_limit = -1;          // counts; alarm when |skew - offset| > limit; -1: P
    int phase[2] = {0, 0};        // power-up phases: output phase of each axis at its point A
    golden::gantry_arm arm = golden::gantry_arm::own;
    bool conventional = false;    // conventional encoders (fixed-phase mark) instead of the IP
    // motion (counts, calls)
    double v_home = 1.0 / 16;     // homing search speed
    double v_max = 0.25;          // velocity limit of the other moves
    double a_max = 1.0 / 1024;    // acceleration limit
    double kv = 1.0 / 64;         // position loop gain (1/call), velocity feed-forward on top
    double v_drive = 0.45;        // drive velocity clamp (the compensator's pacer takes <= 0.5)
    int amplitude = 32767;        // sin/cos amplitude (IP and encoder)
    int settle_calls = 64;        // in position this many calls = settled
    long long max_calls = 0;      // 0: automatic from P
    int trace_every = 8;          // trace decimation (a row also at every sequence step change)
};

// Checks the configuration; "" if usable.
std::string gantry_check(const gantry_config& c);

// The physical set-up (switches, laser grids and ready points, encoder marks) that the
// simulation uses, in the golden model's terms; the controller parameters are filled in too.
golden::gantry_setup gantry_setup_for(const gantry_config& c);

// Controller-side sin/cos interpolator: atan2 of the DAC codes quantised to `resolution` units per
// period, unwrapped by period counting (like a real controller's interpolation + period counter).
class sincos_interpolator {
public:
    void reset(int period, int resolution);
    // One sample. Returns false when the phase moved by more than a quarter period since the last
    // sample (the signal is too fast for the interpolator: counts may be lost).
    bool feed(int64_t sin_code, int64_t cos_code);
    bool primed() const { return primed_; }
    int64_t units() const { return units_; }
    // Position in output counts: round(units * P / resolution).
    int64_t counts() const { return to_counts(units_); }
    int64_t to_counts(int64_t units) const;
    // The last sample moved forward across phase P/8 (sin == cos > 0); crossing() is the unwrapped
    // position of that phase.
    bool crossed() const { return crossed_; }
    int64_t crossing() const { return crossing_; }
    int phase_units() const { return u_; }

private:
    int period_ = 256, res_ = 2048;
    bool primed_ = false, crossed_ = false;
    int u_ = 0;
    int64_t units_ = 0, crossing_ = 0;
};

// One line of the per-stage table: taken when the sequence step has settled.
struct gantry_row {
    enum kind_t { lock = 0, x1_homed, backoff, x2_homed, park, check, deskewed, n_kinds };
    int kind = lock;
    std::string name;
    long long cycle = 0;
    int64_t ctrl[2] = {0, 0};     // controller position (counts): from its home if homed, else
    bool homed[2] = {false, false};  // from where its signal started
    double real[2] = {0, 0};      // physical position relative to the axis' own home point (counts)
    double rack = 0;              // physical x1 - x2 (counts; 0 = square)
    bool skew_valid = false;      // both homed: skew = ctrl1 - ctrl2
    int64_t skew = 0;
    bool alarm = false;
    // taps, for the report and the tests (the controller never reads them)
    int stage[2] = {0, 0};        // compensator stage (0 for encoders)
    int64_t real_count[2] = {0, 0};  // compensator's real count (paced); encoders: physical cell
};

struct gantry_trace_row {
    long long cycle = 0;
    int step = 0;                 // sequence step (gantry_step_name)
    double x_nm[2] = {0, 0};
    double setpoint[2] = {0, 0};  // controller setpoints, counts (raw frame)
    int64_t ctrl[2] = {0, 0};
    bool homed[2] = {false, false};
    double rack = 0;              // physical x1 - x2, counts
    bool skew_valid = false;
    int64_t skew = 0;
    int stage[2] = {0, 0};
    bool mark[2] = {false, false}, sw[2] = {false, false};
    int64_t sin[2] = {0, 0}, cos[2] = {0, 0};
    bool alarm = false;
};

const char* gantry_step_name(int step);

struct gantry_result {
    bool ok = false;              // the sequence ran to its end (with or without skew alarm)
    std::string error;            // why not
    golden::gantry_setup setup;
    std::vector<gantry_row> rows;
    // compensator taps (laser): every completed homing (stage 2 -> 3) as its d; A and Z of the
    // first; stage 1 -> 2 transitions
    std::vector<int64_t> homings[2];
    int64_t a[2] = {0, 0}, z[2] = {0, 0};
    int rises[2] = {0, 0};
    // controller home latch: the codes it saw there
    int64_t latch_sin[2] = {0, 0}, latch_cos[2] = {0, 0};
    bool latch_mark[2] = {false, false};
    // rack in real counts relative to the lock: after pass 1, after pass 2, at the check
    int64_t rack[3] = {0, 0, 0};
    bool checked = false;
    int64_t skew_check = 0, skew_error = 0, skew_final = 0;
    bool alarm = false;
    double rack_final_nm = 0;       // physical x1 - x2 at the end
    double drive_rack_final_nm = 0; // drives' u1 - u2 at the end (rack / compliance)
    double max_rack = 0;            // largest |x1 - x2| during the sequence (counts, dynamic)
    bool both_referenced = false;   // controller homed both, compensators homed (stage 3)
    long long calls = 0;
};

gantry_result run_gantry(const gantry_config& c,
                         const std::function<void(const gantry_trace_row&)>& sink = nullptr);

const char* gantry_arm_name(golden::gantry_arm a);
bool gantry_parse_arm(const std::string& s, golden::gantry_arm* a);

}  // namespace lxt

#endif  // LASERAX_TOOLS_GANTRY_H
