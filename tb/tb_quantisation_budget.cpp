// tb_quantisation_budget — worst-case error of the fixed-point compensation path against the
// exact physics over a 10 m axis (issue 3; the derivation is in docs/QUANTISATION.md).
//
// For a seeded random sample of shop-floor conditions (15..30 degC, 90..110 kPa, 0..90 %RH,
// every material preset at 10..30 degC) and for the extreme corners, the host computes the exact
// scale s = (1 + alpha (20 - T)) * lambda_vac / n / 78.125 nm (long double) and the Q5.32
// register R = round(s * 2^32), and for the thermal origin x0 (K168, random within the 10 m
// axis) the offset register OFF = round(-x0 g 2^32), g = alpha (20 - T). At the far end of a 10 m
// axis (N = 10 m / lambda_air raw counts, both ends of the travel), the hardware position
// (N R + OFF) / 2^32 differs from the exact N s - x0 g by at most
// |N| |R/2^32 - s| + |OFF/2^32 + x0 g| <= (|N| + 1) 2^-33 counts; the test evaluates that
// difference (N R + OFF is exact in long double here) and asserts it stays below 1 nm and below
// the analytic bound.
// floor() to whole output counts is the output resolution (78.125 nm), not part of the budget.
#include <algorithm>
#include <cmath>
#include <random>

#include "tb/tb_util.h"
#include "host/compensation.h"

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 17);
    const long long samples = tbu::arg_ll(argc, argv, "--samples", 20000);
    tbu::result res("tb_quantisation_budget", seed);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double alphas[] = {0.0, 1.2, 7.9, 10.5, 11.5, 23.1};  // invar .. aluminium, ppm/degC
    const long double axis_nm = 1e10L;                           // 10 m in nm
    long double worst_nm = 0, worst_bound_nm = 0;
    for (long long i = 0; i < samples; ++i) {
        lxt::comp_inputs in;
        const bool corner = i < 64;
        auto pick = [&](double lo, double hi, int bit) { return corner ? ((i >> bit) & 1 ? hi : lo) : lo + (hi - lo) * u(rng); };
        in.air_temp_c = pick(15.0, 30.0, 0);
        in.pressure_pa = pick(90000.0, 110000.0, 1);
        in.rh_percent = pick(0.0, 90.0, 2);
        in.alpha_ppm_per_c = alphas[static_cast<size_t>(corner ? (i >> 3) % 6 : static_cast<long long>(rng() % 6))];
        in.material_temp_c = pick(10.0, 30.0, 5);
        in.origin_um = corner ? ((i >> 6) & 1 ? 1e7 : -1e7) : -1e7 + 2e7 * u(rng);
        const lxt::comp_outputs c = lxt::compute_compensation(in);
        if (!res.check(c.ok, "compensation rejected shop-floor conditions: " + c.error)) continue;
        const long double lambda_air_nm = static_cast<long double>(in.wavelength_nm) / static_cast<long double>(c.n);
        const long double n_raw = std::floor(axis_nm / lambda_air_nm);  // raw counts at 10 m
        const long double g = static_cast<long double>(c.scaling.k169_e7) / 1e12L;  // exact grid value
        long double err_counts = 0;
        for (const long double nn : {n_raw, -n_raw}) {
            // N R + OFF: |N R| < 2^61 and |OFF| < 2^63, exact in the 64-bit significand
            const long double hw = (nn * static_cast<long double>(c.ratio) + static_cast<long double>(c.comp_offset)) / 4294967296.0L;
            const long double exact = nn * c.scale_exact - static_cast<long double>(c.scaling.k168) * g;
            err_counts = std::max(err_counts, std::fabs(hw - exact));
        }
        const long double err_nm = err_counts * 78.125L;
        const long double bound_nm = (n_raw + 1) * std::ldexp(1.0L, -33) * 78.125L;
        worst_nm = std::max(worst_nm, err_nm);
        worst_bound_nm = std::max(worst_bound_nm, bound_nm);
        res.expect(err_nm <= bound_nm * (1.0L + 1e-12L) && err_nm < 1.0L, [&] {
            return "conditions T=" + std::to_string(in.air_temp_c) + " p=" + std::to_string(in.pressure_pa) +
                   " RH=" + std::to_string(in.rh_percent) + ": " + std::to_string(static_cast<double>(err_nm)) +
                   " nm at 10 m";
        });
    }
    std::printf("  worst fixed-point error at 10 m: %.4f nm (analytic bound (|N| + 1) 2^-33 counts = %.4f nm; budget 1 nm)\n",
                static_cast<double>(worst_nm), static_cast<double>(worst_bound_nm));
    res.check(worst_bound_nm < 1.0L, "the analytic bound itself exceeds 1 nm");
    return res.finish();
}
