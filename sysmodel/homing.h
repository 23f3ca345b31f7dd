// homing.h — the default scenario: one axis at a random power-up phase homing through the
// reference switch at a constant speed, both models stepped together and compared every call.
// Used by `laserax run`, by the repeatability test and by the benchmark.
#ifndef LASERAX_TOOLS_HOMING_H
#define LASERAX_TOOLS_HOMING_H

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sysmodel/sim.h"

namespace lxt {

struct homing_params {
    int period = 256;             // output counts per sin/cos period
    int dir = 1;                  // homing direction
    double speed_mm_s = 5.0;      // homing speed
    double air_index = kAirIndexDefault;
    uint64_t ratio = 0;           // 0: computed from air_index
    int64_t comp_offset = 0;      // Q32.32 offset register (thermal origin)
    uint64_t seed = 1;            // power-up position and fringe phase
    long long max_cycles = 0;     // 0: until the run is complete
    double clock_hz = kClockHz;
    int glitch_n = 2;
    int sw_debounce = 16;
    int pace_m = 61;              // the register's reset value (REGISTERS.md)
    double bounce_nm = 0;         // switch contact bounce zone
    int pin_cfg = 8;              // the pin_cfg register (DESIGN 4.7: qz_window, ab_rot, hiz_alarm)
    bool return_pass = false;     // after the homing move, back past the switch (Z crossed both ways)
};

// One row of the trace: the columns of out/trace.csv.
struct trace_row {
    long long cycle;
    double true_nm;
    bool pin_a, pin_b, sw, lerr;
    lx::axis_out out;
};

struct homing_event {
    std::string name;  // A, B, Z, C
    long long cycle = -1;
    double true_nm = 0;
    int64_t paced = 0;     // real position (rephase's paced stream)
    int64_t out_pos = 0;   // what the controller counts
};

struct homing_result {
    std::vector<homing_event> events;  // A, B, Z, C in that order (cycle -1 if never reached)
    int64_t d = 0;
    int64_t sin_at_z = 0, cos_at_z = 0;
    bool mark_at_z = false;
    long long cycles = 0;
    std::string mismatch;              // first hls/golden difference, empty if none
    double lambda_nm = 0;              // one raw count in nm
    uint64_t ratio = 0;
    double switch_edge_nm = 0;
    double start_nm = 0;
};

// Runs the scenario. If `sink` is set it is called for every call (every clock).
homing_result run_homing(const homing_params& p, const std::function<void(const trace_row&)>& sink = nullptr);

}  // namespace lxt

#endif
