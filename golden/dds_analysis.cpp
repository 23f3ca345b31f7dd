// golden/dds_analysis.cpp — see dds_analysis.h.
#include "golden/dds_analysis.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>

namespace golden {

dds_quality analyse_dds(const std::vector<int64_t>& sin_codes, const std::vector<int64_t>& cos_codes, int64_t amp) {
    dds_quality q;
    const Eigen::Index P = static_cast<Eigen::Index>(sin_codes.size());
    if (P == 0 || cos_codes.size() != sin_codes.size() || amp <= 0) return q;
    const long double two_pi = 6.283185307179586476925286766559L;
    Eigen::ArrayXd err_s(P), err_c(P);
    Eigen::ArrayXcd z(P);
    for (Eigen::Index k = 0; k < P; ++k) {
        const long double ang = two_pi * static_cast<long double>(k) / static_cast<long double>(P);
        const long double es = static_cast<long double>(amp) * std::sin(ang);
        const long double ec = static_cast<long double>(amp) * std::cos(ang);
        err_s(k) = static_cast<double>(static_cast<long double>(sin_codes[static_cast<size_t>(k)]) - es);
        err_c(k) = static_cast<double>(static_cast<long double>(cos_codes[static_cast<size_t>(k)]) - ec);
        z(k) = std::complex<double>(static_cast<double>(cos_codes[static_cast<size_t>(k)]),
                                    static_cast<double>(sin_codes[static_cast<size_t>(k)]));
    }
    q.max_err_lsb = std::max(err_s.abs().maxCoeff(), err_c.abs().maxCoeff());
    const double err_pow = (err_s.square().sum() + err_c.square().sum()) / static_cast<double>(2 * P);
    q.rms_err_lsb = std::sqrt(err_pow);
    const double sig_pow = static_cast<double>(amp) * static_cast<double>(amp) / 2.0;
    q.snr_db = 10.0 * std::log10(sig_pow / std::max(err_pow, 1e-300));
    q.ideal_snr_db = 10.0 * std::log10(6.0 * static_cast<double>(amp) * static_cast<double>(amp));
    // DFT of cos + j sin: the carrier sits in bin 1; everything else is spur or noise
    Eigen::ArrayXd mag(P);
    for (Eigen::Index m = 0; m < P; ++m) {
        std::complex<double> acc(0.0, 0.0);
        for (Eigen::Index k = 0; k < P; ++k) {
            const double a = -2.0 * 3.14159265358979323846 * static_cast<double>((m * k) % P) / static_cast<double>(P);
            acc += z(k) * std::complex<double>(std::cos(a), std::sin(a));
        }
        mag(m) = std::abs(acc);
    }
    const double carrier = mag(1 % P);
    mag(1 % P) = 0;
    const double spur = std::max(mag.maxCoeff(), 1e-300);
    q.sfdr_dbc = 20.0 * std::log10(carrier / spur);
    return q;
}

}  // namespace golden
