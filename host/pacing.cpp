#include "host/pacing.h"

#include <cmath>
#include <cstdio>

#include "host/compensation.h"

namespace lxt {

namespace {

bool positive_finite(double v) { return std::isfinite(v) && v > 0; }

std::string num(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

}  // namespace

pacing_speed max_speed_for_pace_m(long long pace_m, double clock_mhz) {
    pacing_speed r;
    if (!positive_finite(clock_mhz)) {
        r.error = "clock frequency " + num(clock_mhz) + " MHz is not a positive finite number";
        return r;
    }
    if (pace_m < kPaceMMin || pace_m > kPaceMMax) {
        r.error = "pace_m " + std::to_string(pace_m) + " is outside the register range 2..65535";
        return r;
    }
    r.counts_per_s = clock_mhz * 1e6 / static_cast<double>(pace_m);
    r.mm_per_s = r.counts_per_s * kOutputCountNmComp * 1e-6;
    r.ok = true;
    return r;
}

pacing_result min_safe_pace_m(double sample_mhz, long long filter_len, double clock_mhz) {
    pacing_result r;
    if (!positive_finite(clock_mhz)) {
        r.error = "clock frequency " + num(clock_mhz) + " MHz is not a positive finite number";
        return r;
    }
    if (!positive_finite(sample_mhz)) {
        r.error = "controller sample rate " + num(sample_mhz) + " MHz is not a positive finite number";
        return r;
    }
    if (filter_len < 0) {
        r.error = "controller filter length " + std::to_string(filter_len) + " is negative (0 or 1: filter off)";
        return r;
    }
    const double n = filter_len < 1 ? 1.0 : static_cast<double>(filter_len);
    const double t_clk_ns = 1000.0 / clock_mhz;
    const double t_s_ns = 1000.0 / sample_mhz;
    r.min_level_ns = n * t_s_ns * (1.0 + kPacingClockTolerance) + kPacingApertureNs;
    // smallest integer M with M * T_clk > min_level: floor(min_level / T_clk) + 1
    const double clocks = r.min_level_ns / t_clk_ns;
    if (!std::isfinite(clocks) || clocks >= static_cast<double>(kPaceMMax)) {
        r.error = "a " + std::to_string(filter_len) + "-sample filter at " + num(sample_mhz) + " MHz needs levels of " +
                  num(r.min_level_ns) + " ns = " + num(clocks) + " clocks: more than pace_m can hold (at most 65535)";
        return r;
    }
    long long m = static_cast<long long>(std::floor(clocks)) + 1;
    if (m < kPaceMMin) m = kPaceMMin;
    r.pace_m = static_cast<int>(m);
    const pacing_speed s = max_speed_for_pace_m(m, clock_mhz);
    r.max_counts_per_s = s.counts_per_s;
    r.max_mm_per_s = s.mm_per_s;
    r.ok = true;
    return r;
}

}  // namespace lxt
