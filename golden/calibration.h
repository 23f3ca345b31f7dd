// golden/calibration.h — scale calibration of an incremental axis from measured data (issue 3).
//
// RTC5 linear movements (docs/SOURCES.md: the RTC5 manual, "Determining scaling factors")
// calibrates an encoder-driven correction:
//   encoder increment   i = (counter end - counter start) / distance travelled   [counts/mm]
//   scaling factor      Scale = K / i                                          [bits/count]
//   constant speed      Scale = K * v / (10^6 counts/s)     (simulated encoder at 1 MHz, v in mm/s)
// with K the calibration factor in bits/mm. The encoder counters are 32-bit and wrap (the count
// continues from the minimum after the maximum), so the counter difference is taken modulo 2^32
// (valid while the travel is below 2^31 counts). Signs follow the direction of travel.
//
// The general form used for this axis: a least-squares fit of a linear scale factor and offset
//   reading = scale * position + offset + residual
// from many (position, reading) pairs, e.g. reference-interferometer positions against the
// counts the controller reads. Solved with Eigen (column-pivoting Householder QR on the centred
// design [x - mean(x), 1], so positions of 10^7 counts do not cost conditioning); standard errors
// from the residual variance s^2 = sum r^2 / (n - 2):
//   se(scale) = s / sqrt(Sxx),  se(offset) = s * sqrt(1/n + mean(x)^2 / Sxx),  Sxx = sum (x - mean)^2.
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <string>

namespace golden {

struct increment_result {
    bool ok = false;
    std::string error;
    int64_t counts = 0;          // counter difference after the modulo-2^bits unwrap
    double counts_per_mm = 0.0;  // i
};

// i = (end - start) / distance. counter_bits 1..63: the counters wrap at that width (the source: 32).
increment_result encoder_increment(int64_t counter_start, int64_t counter_end, double distance_mm, int counter_bits = 32);

struct scale_result {
    bool ok = false;
    std::string error;
    double scale = 0.0;  // bits per count
};

// Scale = K / i
scale_result scale_from_increment(double k_bits_per_mm, double counts_per_mm);
// Scale = K * v / (1e6 counts/s)
scale_result scale_from_speed(double k_bits_per_mm, double v_mm_per_s);
constexpr double kSimulatedEncoderCountsPerS = 1e6;

struct linear_fit {
    bool ok = false;
    std::string error;
    long n = 0;
    double scale = 0.0, offset = 0.0;         // reading = scale * position + offset
    double scale_se = 0.0, offset_se = 0.0;   // standard errors from the residual variance
    double sigma = 0.0;                       // residual standard deviation, sqrt(sum r^2 / (n-2))
    double rms_residual = 0.0;                // sqrt(sum r^2 / n)
    double max_abs_residual = 0.0;
    double x_mean = 0.0, sxx = 0.0;
    Eigen::VectorXd residuals;                // reading - (scale * position + offset)
};

// Needs n >= 3 finite pairs and at least two distinct positions.
linear_fit fit_scale_offset(const Eigen::VectorXd& position, const Eigen::VectorXd& reading);

}  // namespace golden
