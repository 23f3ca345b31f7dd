// host/pacing.h — pacing for the controller's counter: the smallest pace_m register value that a
// controller counting our digital quadrature (qa/qb/qz) through its own sampler and digital
// filter follows without losing a count, and the output speed that pace_m allows
// (docs/CONTROLLER.md; issue 36).
//
// At the pins every quadrature state (and the index pulse, one state wide) lasts at least
// pace_m clocks of our clock (DESIGN 4.4: consecutive output counts at least M clocks apart).
// A controller samples the pins at f_s (its clock divided by its sample-rate prescaler) and runs
// each line through an N-sample integrating filter (an up/down counter 0..N that follows the
// sampled level; the filtered line switches at 0 and N). A level passes the filter only if it
// holds for N samples in a row, so every level must last longer than N sample periods:
//
//     pace_m * T_clk  >  N * T_s * (1 + kPacingClockTolerance) + kPacingApertureNs
//
// N = 0 or 1 is "filter off": the level must still be seen by one sample (N is taken as 1).
// The two margins are for asynchronous sampling: the controller's clock is not derived from ours,
// so its real sample period may be longer than the nominal one (crystal tolerances on both
// sides: kPacingClockTolerance covers 1000 ppm), and a sample taken within a synchroniser's
// aperture of an edge may resolve to either level (kPacingApertureNs). With the nominal ratio an
// exact multiple (T_s * N = k * T_clk) the smallest safe value is k + 1: a level of exactly k
// clocks holds exactly N samples only at the nominal frequency and for a phase away from the edge.
//
// Reference (issue 36, a Mesa hostmot2 counter on a 50 MHz card): filter on, 25 MHz sampling,
// 15 samples -> 61; 50 MHz sampling, 15 samples -> 31; filter "off" (hostmot2 still takes 3
// samples at 50 MHz) -> 7.
#ifndef LASERAX_HOST_PACING_H
#define LASERAX_HOST_PACING_H

#include <string>

namespace lxt {

constexpr double kPacingClockTolerance = 1e-3;  // relative: 1000 ppm on the controller's sample period
constexpr double kPacingApertureNs = 1.0;       // synchroniser aperture at each edge, ns
constexpr int kPaceMMin = 2;                    // pace_m register range (docs/REGISTERS.md)
constexpr int kPaceMMax = 65535;
constexpr double kPacingDefaultClockMhz = 100.0;

struct pacing_result {
    bool ok = false;
    std::string error;            // why not, when !ok
    int pace_m = 0;               // smallest safe pace_m (>= kPaceMMin)
    double min_level_ns = 0;      // the level length the controller needs: N T_s (1 + tol) + aperture
    double max_counts_per_s = 0;  // the output speed that pace_m allows
    double max_mm_per_s = 0;
};

struct pacing_speed {
    bool ok = false;
    std::string error;
    double counts_per_s = 0;  // one output count per pace_m clocks
    double mm_per_s = 0;      // counts of kOutputCountNmComp (78.125 nm)
};

// The smallest safe pace_m for a controller sampling at sample_mhz through a filter_len-sample
// filter (0 or 1: off), with our clock at clock_mhz. Invalid inputs (not finite, <= 0, a negative
// filter length) and a filter too long for the 16-bit register (pace_m > 65535) give !ok and a
// message; never throws.
pacing_result min_safe_pace_m(double sample_mhz, long long filter_len, double clock_mhz = kPacingDefaultClockMhz);

// The largest output speed pace_m allows (one count per pace_m clocks); pace_m outside
// 2..65535 or an invalid clock give !ok.
pacing_speed max_speed_for_pace_m(long long pace_m, double clock_mhz = kPacingDefaultClockMhz);

}  // namespace lxt

#endif
