// tb_calibration — seed-001 calibration forms and the least-squares scale/offset fit
// (golden/calibration), on synthetic data of known truth with seeded noise.
//
// 1. Encoder increment i = (end - start) / distance, with 32-bit counter wrap; Scale = K / i;
//    the constant-speed form Scale = K v / (1e6 counts/s) equals K / i for a simulated 1 MHz
//    encoder; bad inputs rejected.
// 2. Fit of reading = scale * position + offset + noise, Gaussian noise sigma: recovered scale
//    and offset within 5 standard errors derived from the noise, |b - truth| <= 5 sigma/sqrt(Sxx)
//    and 5 sigma sqrt(1/n + mean^2/Sxx); the fit's own standard errors and residual sigma agree
//    with the derived ones; over many seeded trials the z-scores have mean ~0 and spread ~1.
// 3. The interferometer case: readings are the multiplier's integer output counts for a register
//    set with one air index while the air has another; the fit recovers the index error in ppm
//    within the bound from quantisation noise (uniform: one raw count and one output count).
// 4. Degenerate inputs are rejected; a wrong truth is detected (negative control).
// ctest-args: --seed 11 --trials 400
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "host/air_index.h"
#include "golden/calibration.h"
#include "tb/tb_util.h"
#include "host/compensation.h"

namespace {

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
    char buf[300];
    std::snprintf(buf, sizeof buf, f, a, b, c, d);
    return buf;
}

__extension__ typedef __int128 i128;
int64_t floor_div(i128 n, i128 d) {
    i128 q = n / d;
    if (n % d != 0 && n < 0) --q;
    return static_cast<int64_t>(q);
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 11);
    const long long trials = tbu::arg_ll(argc, argv, "--trials", 400);
    tbu::result res("tb_calibration", seed);
    std::mt19937_64 rng(seed);

    // ---- 1. seed-001 forms ---------------------------------------------------------------------
    {
        // 250 mm travelled, 12 800 counts/mm (78.125 nm counts): 3 200 000 counts
        golden::increment_result i = golden::encoder_increment(1000, 3201000, 250.0);
        res.check(i.ok && i.counts == 3200000 && i.counts_per_mm == 12800.0, fmt("increment %.6f", i.counts_per_mm));
        // across the 32-bit wrap: start 2^31 - 100 (int32 max - 99), end wrapped to negative
        const int64_t start = 2147483547, end = -2147483648LL + 3199899;  // start + 3 200 000 - 2^32
        i = golden::encoder_increment(start, end, 250.0);
        res.check(i.ok && i.counts == 3200000, "wrap: counts " + std::to_string(static_cast<long long>(i.counts)));
        // negative direction
        i = golden::encoder_increment(3201000, 1000, -250.0);
        res.check(i.ok && i.counts_per_mm == 12800.0, "negative travel with negative distance");
        i = golden::encoder_increment(3201000, 1000, 250.0);
        res.check(i.ok && i.counts_per_mm == -12800.0, "negative counts, positive distance: sign");
        res.check(!golden::encoder_increment(0, 10, 0.0).ok, "distance 0 accepted");
        res.check(!golden::encoder_increment(0, 10, std::nan("")).ok, "distance NaN accepted");
        res.check(!golden::encoder_increment(0, 10, 1.0, 64).ok, "counter width 64 accepted");
        // Scale = K / i: K = 5000 bits/mm, i = 12800 counts/mm -> 0.390625 bits/count (exact)
        golden::scale_result s = golden::scale_from_increment(5000.0, 12800.0);
        res.check(s.ok && s.scale == 0.390625, fmt("K/i = %.9f", s.scale));
        res.check(!golden::scale_from_increment(5000.0, 0.0).ok, "i = 0 accepted");
        // constant speed: simulated encoder at 1e6 counts/s, v = 50 mm/s for 2 s: 2e6 counts over
        // 100 mm -> i = 20000 counts/mm, K/i = K v / 1e6 = 0.25 bits/count for K = 5000
        const double v = 50.0, t = 2.0;
        const golden::increment_result iv =
            golden::encoder_increment(0, static_cast<int64_t>(golden::kSimulatedEncoderCountsPerS * t), v * t);
        const golden::scale_result s1 = golden::scale_from_increment(5000.0, iv.counts_per_mm);
        const golden::scale_result s2 = golden::scale_from_speed(5000.0, v);
        res.check(iv.ok && s1.ok && s2.ok && s2.scale == 0.25 && std::fabs(s1.scale - s2.scale) < 1e-15,
                  fmt("constant-speed form %.12f vs K/i %.12f", s2.scale, s1.scale));
        // random K, v: the two forms agree to rounding
        // random K, v, t: the counter holds round(1e6 t) whole counts, so the increment form can
        // differ from the speed form by that rounding, 0.5 / (1e6 t) relative, and no more
        double worst = 0;
        for (int k = 0; k < 1000; ++k) {
            const double K = std::uniform_real_distribution<double>(10.0, 1e5)(rng);
            const double vv = std::uniform_real_distribution<double>(-500.0, 500.0)(rng);
            const double tt = std::uniform_real_distribution<double>(0.1, 10.0)(rng);
            const golden::increment_result ii = golden::encoder_increment(0, static_cast<int64_t>(std::llround(1e6 * tt)), vv * tt);
            const double a = golden::scale_from_increment(K, ii.counts_per_mm).scale, b = golden::scale_from_speed(K, vv).scale;
            const double rel = std::fabs(a / b - 1.0), bound = 0.5 / (1e6 * tt) + 1e-12;
            worst = std::fmax(worst, rel / bound);
            res.expect(rel <= bound, [&] { return fmt("constant-speed vs increment form: %.3e > %.3e", rel, bound); });
        }
        std::printf("  seed-001 forms: K/i and K v/1e6 agree to %.2f of the counter's rounding bound\n", worst);
    }

    // ---- 2. least squares on known truth + Gaussian noise --------------------------------------
    {
        const double scale_t = 1.0 - 12.5e-6, offset_t = 37.25, sigma = 1.5;  // counts
        const int n = 4000;
        double zs_sum = 0, zs_sq = 0, zo_sum = 0, zo_sq = 0, worst_sig = 0;
        long within = 0;
        for (long long trial = 0; trial < trials; ++trial) {
            std::normal_distribution<double> noise(0.0, sigma);
            std::uniform_real_distribution<double> where(0.0, 1.28e7);  // 0 .. 1 m in 78.125 nm counts
            Eigen::VectorXd x(n), y(n);
            for (int k = 0; k < n; ++k) {
                x(k) = std::floor(where(rng));
                y(k) = scale_t * x(k) + offset_t + noise(rng);
            }
            const golden::linear_fit f = golden::fit_scale_offset(x, y);
            if (!res.check(f.ok, "fit failed: " + f.error)) continue;
            // standard errors derived from the known noise
            const double xm = x.mean();
            const double sxx = (x.array() - xm).square().sum();
            const double se_s = sigma / std::sqrt(sxx);
            const double se_o = sigma * std::sqrt(1.0 / n + xm * xm / sxx);
            const double zs = (f.scale - scale_t) / se_s, zo = (f.offset - offset_t) / se_o;
            zs_sum += zs;
            zs_sq += zs * zs;
            zo_sum += zo;
            zo_sq += zo * zo;
            within += std::fabs(zs) <= 5.0 && std::fabs(zo) <= 5.0;
            if (trial < 3 || std::fabs(zs) > 5.0 || std::fabs(zo) > 5.0)
                res.check(std::fabs(zs) <= 5.0 && std::fabs(zo) <= 5.0,
                          fmt("trial: scale off by %.2f se, offset by %.2f se", zs, zo));
            // the fit's own estimates: s has relative sd 1/sqrt(2(n-2)) = 1.1 %; allow 5 sd (the
            // standard errors scale with s, so the same bound holds for them)
            const double tol = 5.0 / std::sqrt(2.0 * (n - 2));
            worst_sig = std::fmax(worst_sig, std::fabs(f.sigma / sigma - 1.0));
            res.expect(std::fabs(f.sigma / sigma - 1.0) <= tol && std::fabs(f.scale_se / se_s - 1.0) <= tol &&
                           std::fabs(f.offset_se / se_o - 1.0) <= tol,
                       [&] { return fmt("sigma %.4f (true %.4f), se ratio %.4f %.4f", f.sigma, sigma, f.scale_se / se_s, f.offset_se / se_o); });
            // residuals: mean zero and orthogonal to the positions (normal equations)
            // (numerically zero: readings of ~1e7 counts leave ~1e-8 of rounding in the correlation;
            // noise alone would give sigma/sqrt(n) = 0.024 counts and 1/sqrt(n) = 0.016)
            const double corr = (f.residuals.array() * (x.array() - xm)).sum() / (f.residuals.norm() * std::sqrt(sxx));
            res.expect(std::fabs(f.residuals.mean()) < 1e-6 * f.sigma && std::fabs(corr) < 1e-6,
                       [&] { return fmt("residuals not orthogonal: mean %.3e, correlation %.3e", f.residuals.mean(), corr); });
            res.expect(f.max_abs_residual < 6.0 * sigma, [&] { return fmt("max residual %.2f", f.max_abs_residual); });
        }
        const double m_s = zs_sum / static_cast<double>(trials), m_o = zo_sum / static_cast<double>(trials);
        const double sd_s = std::sqrt(zs_sq / static_cast<double>(trials) - m_s * m_s);
        const double sd_o = std::sqrt(zo_sq / static_cast<double>(trials) - m_o * m_o);
        // z-scores of an unbiased fit with correct standard errors: mean 0 (sd 1/sqrt(trials)),
        // sd 1 (sd of the estimate ~1/sqrt(2 trials)); 5-sigma bounds.
        const double tm = 5.0 / std::sqrt(static_cast<double>(trials)), tsd = 5.0 / std::sqrt(2.0 * static_cast<double>(trials));
        res.check(std::fabs(m_s) <= tm && std::fabs(m_o) <= tm, fmt("z-score means %.3f %.3f (bound %.3f)", m_s, m_o, tm));
        res.check(std::fabs(sd_s - 1.0) <= tsd && std::fabs(sd_o - 1.0) <= tsd,
                  fmt("z-score spread %.3f %.3f (bound 1 +- %.3f)", sd_s, sd_o, tsd));
        std::printf("  fit, %lld trials x %d points, truth scale 1 - 12.5 ppm, offset 37.25, noise 1.5 counts:\n"
                    "    all within 5 se: %ld; z(scale) mean %+.3f sd %.3f; z(offset) mean %+.3f sd %.3f; sigma estimate within %.1f %%\n",
                    trials, n, within, m_s, sd_s, m_o, sd_o, worst_sig * 100.0);
        res.check(within == trials, "some trials outside 5 standard errors");
    }

    // ---- 3. the interferometer: recover the air-index error from integer readings ---------------
    {
        // Register set for the nominal air (20 °C, 101.325 kPa, 50 %RH); the real air is warmer,
        // lower pressure and drier, so the real wavelength is longer and the reading short.
        lxt::air_input nominal, real;
        real.temp_c = 23.4;
        real.pressure_pa = 99200.0;
        real.rh_percent = 35.0;
        const double n_set = lxt::air_index_ciddor(nominal).n, n_true = lxt::air_index_ciddor(real).n;
        uint64_t R = 0;
        std::string err;
        res.check(lxt::ratio_from_index(632.991, n_set, 0.0, &R, &err), err);
        const double lam_air = 632.991 / n_true;               // nm per raw count, real air
        const long double s_reg = static_cast<long double>(R) / 4294967296.0L;
        // expected reading per true output count: s_reg * 78.125 / lam_air
        const double scale_expect = static_cast<double>(s_reg) * 78.125 / lam_air;
        const double ppm_expect = (n_true / n_set - 1.0) * 1e6;  // to the register's 1e-5 ppm
        const int n = 20000;
        Eigen::VectorXd x(n), y(n);
        std::uniform_real_distribution<double> where(0.0, 1.28e7);  // true positions, output counts
        const double frac0 = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
        for (int k = 0; k < n; ++k) {
            const double pos = where(rng);                                      // true position, counts
            const int64_t N = static_cast<int64_t>(std::floor(pos * 78.125 / lam_air + frac0));  // laser raw count
            x(k) = pos;
            y(k) = static_cast<double>(floor_div(static_cast<i128>(N) * static_cast<i128>(R), static_cast<i128>(1) << 32));
        }
        const golden::linear_fit f = golden::fit_scale_offset(x, y);
        res.check(f.ok, "fit failed: " + f.error);
        // noise: uniform quantisation of the raw count (one raw count = s_reg output counts) and of
        // the output count: sigma^2 = (s_reg^2 + 1)/12
        const double sig = std::sqrt((static_cast<double>(s_reg * s_reg) + 1.0) / 12.0);
        const double se_s = sig / std::sqrt(f.sxx);
        const double ppm_fit = (f.scale - 1.0) * 1e6;
        res.check(std::fabs(f.scale - scale_expect) <= 5.0 * se_s,
                  fmt("index error: fit %.5f ppm, expected %.5f ppm (5 se = %.5f ppm)", ppm_fit, (scale_expect - 1.0) * 1e6,
                      5.0 * se_s * 1e6));
        res.check(std::fabs(f.sigma / sig - 1.0) < 0.05, fmt("residual sigma %.4f, quantisation model %.4f", f.sigma, sig));
        // offset: the raw-count floor loses (frac0 - 0.5) raw counts on average and the output
        // floor 0.5 counts: offset = s_reg*(frac0 - 0.5) - 0.5
        const double off_expect = static_cast<double>(s_reg) * (frac0 - 0.5) - 0.5;
        const double se_o = sig * std::sqrt(1.0 / n + f.x_mean * f.x_mean / f.sxx);
        res.check(std::fabs(f.offset - off_expect) <= 5.0 * se_o, fmt("offset %.4f, expected %.4f (5 se %.4f)", f.offset, off_expect, 5 * se_o));
        std::printf("  interferometer: register for n = %.9f, air n = %.9f: index error %+.4f ppm; fit %+.4f ppm +- %.4f (1 se),\n"
                    "    residual sigma %.3f counts (quantisation %.3f), offset %.3f (expected %.3f)\n",
                    n_set, n_true, ppm_expect, ppm_fit, se_s * 1e6, f.sigma, sig, f.offset, off_expect);
        // negative control: a truth 20 se away is distinguished
        res.check(std::fabs(f.scale - (scale_expect + 20.0 * se_s)) > 5.0 * se_s, "negative control: wrong truth not detected");
        // the fit recovers the index error to its own quantisation: n_true/n_set from the scale
        res.check(std::fabs(ppm_fit - ppm_expect) <= 5.0 * se_s * 1e6 + 1e-4, "fitted ppm vs n_true/n_set");
    }

    // ---- 4. degenerate inputs ------------------------------------------------------------------
    {
        Eigen::VectorXd a(2), b(2);
        a << 1, 2;
        b << 1, 2;
        res.check(!golden::fit_scale_offset(a, b).ok, "2 points accepted");
        Eigen::VectorXd c = Eigen::VectorXd::Constant(10, 5.0), d = Eigen::VectorXd::LinSpaced(10, 0, 9);
        const golden::linear_fit same = golden::fit_scale_offset(c, d);
        res.check(!same.ok && same.error.find("same") != std::string::npos, "identical positions accepted: " + same.error);
        Eigen::VectorXd e = d;
        e(3) = std::nan("");
        res.check(!golden::fit_scale_offset(d, e).ok, "NaN reading accepted");
        res.check(!golden::fit_scale_offset(d, Eigen::VectorXd::Zero(9)).ok, "size mismatch accepted");
        // exact data: exact recovery
        Eigen::VectorXd yy = 1.5 * d.array() + 3.0;
        const golden::linear_fit ex = golden::fit_scale_offset(d, yy);
        res.check(ex.ok && std::fabs(ex.scale - 1.5) < 1e-12 && std::fabs(ex.offset - 3.0) < 1e-12 && ex.max_abs_residual < 1e-12,
                  "noise-free line not recovered exactly");
    }
    return res.finish();
}
