// golden/calibration.cpp — see calibration.h (the forms of RTC5 linear movements, docs/SOURCES.md;
// least-squares scale/offset fit).
#include "golden/calibration.h"

#include <cmath>
#include <cstdio>

namespace golden {

increment_result encoder_increment(int64_t counter_start, int64_t counter_end, double distance_mm, int counter_bits) {
    increment_result r;
    if (counter_bits < 1 || counter_bits > 63) {
        r.error = "counter width must be 1..63 bits";
        return r;
    }
    if (!std::isfinite(distance_mm) || distance_mm == 0.0) {
        r.error = "distance travelled must be a finite, non-zero number of mm";
        return r;
    }
    // difference modulo 2^bits, as a signed value in [-2^(bits-1), 2^(bits-1))
    const uint64_t mask = (uint64_t(1) << counter_bits) - 1;
    const uint64_t half = uint64_t(1) << (counter_bits - 1);
    const uint64_t d = (static_cast<uint64_t>(counter_end) - static_cast<uint64_t>(counter_start)) & mask;
    r.counts = d >= half ? static_cast<int64_t>(d) - static_cast<int64_t>(half) - static_cast<int64_t>(half)
                         : static_cast<int64_t>(d);
    r.counts_per_mm = static_cast<double>(r.counts) / distance_mm;
    r.ok = true;
    return r;
}

scale_result scale_from_increment(double k_bits_per_mm, double counts_per_mm) {
    scale_result r;
    if (!std::isfinite(k_bits_per_mm) || !std::isfinite(counts_per_mm) || counts_per_mm == 0.0) {
        r.error = "K and i must be finite and i non-zero";
        return r;
    }
    r.scale = k_bits_per_mm / counts_per_mm;
    r.ok = true;
    return r;
}

scale_result scale_from_speed(double k_bits_per_mm, double v_mm_per_s) {
    scale_result r;
    if (!std::isfinite(k_bits_per_mm) || !std::isfinite(v_mm_per_s)) {
        r.error = "K and v must be finite";
        return r;
    }
    r.scale = k_bits_per_mm * v_mm_per_s / kSimulatedEncoderCountsPerS;
    r.ok = true;
    return r;
}

linear_fit fit_scale_offset(const Eigen::VectorXd& position, const Eigen::VectorXd& reading) {
    linear_fit f;
    const Eigen::Index n = position.size();
    if (reading.size() != n) {
        f.error = "position and reading counts differ";
        return f;
    }
    if (n < 3) {
        f.error = "at least 3 (position, reading) pairs are needed";
        return f;
    }
    if (!position.allFinite() || !reading.allFinite()) {
        f.error = "non-finite position or reading";
        return f;
    }
    f.n = static_cast<long>(n);
    const double nd = static_cast<double>(n);
    f.x_mean = position.mean();
    Eigen::MatrixXd A(n, 2);
    A.col(0) = position.array() - f.x_mean;
    A.col(1).setOnes();
    f.sxx = A.col(0).squaredNorm();
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    if (!(f.sxx > 0.0) || qr.rank() < 2) {
        f.error = "the positions must not all be the same";
        return f;
    }
    const Eigen::Vector2d c = qr.solve(reading);
    f.scale = c(0);
    f.offset = c(1) - c(0) * f.x_mean;  // reading at position 0
    f.residuals = reading - A * c;
    const double ss = f.residuals.squaredNorm();
    f.sigma = std::sqrt(ss / (nd - 2.0));
    f.rms_residual = std::sqrt(ss / nd);
    f.max_abs_residual = f.residuals.cwiseAbs().maxCoeff();
    f.scale_se = f.sigma / std::sqrt(f.sxx);
    f.offset_se = f.sigma * std::sqrt(1.0 / nd + f.x_mean * f.x_mean / f.sxx);
    f.ok = true;
    return f;
}

}  // namespace golden
