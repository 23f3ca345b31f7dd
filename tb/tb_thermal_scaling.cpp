// tb_thermal_scaling — workpiece expansion (host/thermal), its two parameterisations, the fold
// into the pulse-multiplier ratio register, and the host helper / `laserax compensate`.
//
// 1. Presets, lookup, and rejection of out-of-range alpha / temperature.
// 2. (origin, alpha, T) and the seed-002 form (K168, K169) give the same output counts
//    floor(position + correction), exactly, over random positions, origins, materials and
//    temperatures, including positions where the correction is an exact integer (where binary
//    floating point flips the floor; counted and reported). Each result is also checked against
//    the real-valued correction.
// 3. Folding (1 + alpha (20 - T)) into the Q5.32 ratio: with R = rha(2^32 s), s the exact scale,
//    the multiplier output floor(N R / 2^32) against the exact floor(N s) over 32-bit raw counts:
//        |N R / 2^32 - N s| = |N| |R - 2^32 s| / 2^32 <= |N| 2^-33  (<= 1/4 count for |N| <= 2^31)
//    so the outputs differ by at most one count, and only where N s lies within |N| 2^-33 of an
//    integer. A random walk through golden::pulse_multiplier confirms the model computes that
//    floor; a ratio 2 LSB off is caught by the same check (negative control).
// 3b. The origin through the multiplier's offset register (comp = floor((N R + OFF) / 2^32)):
//    on an integer scale S (so x = S N is a whole count and the exact thermal forms apply), the
//    registers from (origin, alpha, T) and from (K168, K169) are identical, and the hardware
//    output equals the exact floor(x + (x - origin) g) except where that value lies within the
//    quantisation bound (|N| + 1) 2^-33 of an integer, and then by one count. The golden
//    multiplier (with the offset) is checked on the same samples; an offset 2 LSB off is caught
//    (negative control).
// 4. Host helper round trip: settings -> register -> effective scale / ppm -> register.
// 5. `laserax compensate`: output for three conditions, and exit 2 with a message on bad input.
// ctest-args: --seed 3 --samples 1000000
// ctest-args-O0: --seed 3 --samples 50000
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "host/air_index.h"
#include "golden/pulse_multiplier.h"
#include "host/thermal.h"
#include "tb/tb_util.h"
#include "tools/laserax/compensate_cmd.h"
#include "host/compensation.h"
#include "sysmodel/sim.h"

namespace {

__extension__ typedef __int128 i128;

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
    char buf[300];
    std::snprintf(buf, sizeof buf, f, a, b, c, d);
    return buf;
}
std::string s64(int64_t v) { return std::to_string(static_cast<long long>(v)); }

int64_t floor_div(i128 n, i128 d) {
    i128 q = n / d;
    if (n % d != 0 && n < 0) --q;
    return static_cast<int64_t>(q);
}
// multiplier output floor(N * R / 2^32), exact
int64_t mult_out(int64_t n, uint64_t r) { return floor_div(i128(n) * i128(r), i128(1) << 32); }

// Runs `laserax compensate` with the words of `line`; returns the exit code, output in *out.
int run_cmd(const std::string& line, std::string* out, std::string* err) {
    std::vector<std::string> args = {"compensate"};
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && line[i] == ' ') ++i;
        size_t j = i;
        while (j < line.size() && line[j] != ' ') ++j;
        if (j > i) args.push_back(line.substr(i, j - i));
        i = j;
    }
    FILE* fo = std::tmpfile();
    FILE* fe = std::tmpfile();
    if (!fo || !fe) return -1;
    const int rc = lxt::cmd_compensate(args, 1, fo, fe);
    for (FILE* f : {fo, fe}) {
        std::string& s = f == fo ? *out : *err;
        s.clear();
        std::fflush(f);
        std::rewind(f);
        char buf[512];
        size_t k;
        while ((k = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, k);
        std::fclose(f);
    }
    return rc;
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 3);
    const long long samples = tbu::arg_ll(argc, argv, "--samples", 200000);
    tbu::result res("tb_thermal_scaling", seed);
    std::mt19937_64 rng(seed);
    auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    auto irange = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };

    // ---- 1. presets and limits -----------------------------------------------------------------
    size_t npre = 0;
    const lxt::material_preset* pre = lxt::material_presets(&npre);
    {
        const struct {
            const char* name;
            double alpha;
        } want[] = {{"steel", 11.5}, {"cast-iron", 10.5}, {"aluminium", 23.1}, {"granite", 7.9}, {"invar", 1.2}};
        res.check(npre == 5, "expected 5 material presets");
        for (const auto& w : want) {
            const lxt::material_preset* m = lxt::find_material(w.name);
            res.check(m && m->alpha_ppm_per_c == w.alpha, std::string("preset ") + w.name);
        }
        res.check(lxt::find_material("STEEL") != nullptr && lxt::find_material("aluminum") != nullptr,
                  "material lookup is not case-insensitive / does not know 'aluminum'");
        res.check(lxt::find_material("unobtanium") == nullptr, "unknown material found");
        lxt::thermal_params tp;
        res.check(!lxt::make_thermal(301.0, 20.0, 0, &tp).ok, "alpha 301 ppm/degC accepted");
        res.check(!lxt::make_thermal(11.5, 80.5, 0, &tp).ok, "material temperature 80.5 degC accepted");
        res.check(!lxt::make_thermal(11.5, -20.5, 0, &tp).ok, "material temperature -20.5 degC accepted");
        res.check(!lxt::make_thermal(std::nan(""), 20.0, 0, &tp).ok, "alpha NaN accepted");
        res.check(!lxt::make_thermal(11.5, 20.0, (int64_t(1) << 53) + 1, &tp).ok, "origin beyond 2^53 accepted");
        res.check(lxt::make_thermal(-300.0, 80.0, -(int64_t(1) << 53), &tp).ok, "limits rejected");
        // steel at 25 °C: alpha (20 - T) = -57.5 ppm, K169 = -5.75 (ETEL encoder scaling: units of 1e-5)
        res.check(lxt::make_thermal(11.5, 25.0, 1000, &tp).ok, "steel at 25 degC rejected");
        const lxt::encoder_scaling es = lxt::to_encoder_scaling(tp);
        res.check(es.k168 == 1000 && es.k169_e7 == -57500000 && lxt::k169_value(es) == -5.75,
                  "steel at 25 degC: K168/K169 " + s64(es.k168) + " " + s64(es.k169_e7));
        res.check(std::fabs(lxt::temp_from_k169(-5.75, 11.5) - 25.0) < 1e-12, "temp_from_k169 inverse");
        // 100 000 counts (7.8125 mm) from the origin: correction -5.75 counts -> floor(100000 - 5.75)
        res.check(lxt::thermal_output_counts(tp, 101000) == 100994 && lxt::encoder_scaling_output_counts(es, 101000) == 100994,
                  "worked example 100000 counts steel 25 degC");
        res.check(lxt::thermal_output_counts(tp, -99000) == -98995, "worked example -100000 counts");
        // steel at 17 °C, 2 000 000 counts from the origin: correction exactly +69 counts (in double
        // the seed's form gives 68.999999999999986 and would floor to +68)
        lxt::thermal_params t17;
        res.check(lxt::make_thermal(11.5, 17.0, 0, &t17).ok, "steel at 17 degC rejected");
        res.check(lxt::thermal_output_counts(t17, 2000000) == 2000069 &&
                      lxt::encoder_scaling_output_counts(lxt::to_encoder_scaling(t17), 2000000) == 2000069,
                  "steel at 17 degC, 2e6 counts: not +69");
    }

    // ---- 2. both parameterisations, exact ------------------------------------------------------
    {
        long mism_exact = 0, naive_forms_differ = 0, naive_vs_exact = 0, ties = 0, real_bad = 0, k169_bad = 0;
        const int64_t posmax = int64_t(1) << 37;  // W_POS range
        for (long long s = 0; s < samples; ++s) {
            // material: a preset (often) or any alpha with 0.001 ppm/°C resolution
            double alpha_ppm;
            if (rng() % 3 != 0) alpha_ppm = pre[rng() % npre].alpha_ppm_per_c;
            else alpha_ppm = static_cast<double>(irange(-50000, 250000)) / 1000.0;
            // temperature: 0.001 °C resolution, -20..80 °C (half of them whole or tenth degrees)
            double temp;
            const uint64_t tk = rng() % 4;
            if (tk == 0) temp = static_cast<double>(irange(-20, 80));
            else if (tk == 1) temp = static_cast<double>(irange(-200, 800)) / 10.0;
            else temp = static_cast<double>(irange(-20000, 80000)) / 1000.0;
            const int64_t origin = rng() % 4 == 0 ? 0 : irange(-posmax, posmax);
            lxt::thermal_params tp;
            if (!res.check(lxt::make_thermal(alpha_ppm, temp, origin, &tp).ok, "make_thermal rejected a legal value")) continue;
            const lxt::encoder_scaling es = lxt::to_encoder_scaling(tp);
            if (lxt::k169_e7_from_physical(alpha_ppm, temp) != es.k169_e7) ++k169_bad;
            // position: random, or one where the correction is an exact integer (a tie for floor)
            int64_t pos;
            const i128 prod = i128(tp.alpha_e9) * i128(lxt::kRefTempMc - tp.temp_mc);
            if (rng() % 2 == 0 && prod != 0) {
                // smallest d with d * prod divisible by 1e12
                i128 g1 = prod < 0 ? -prod : prod, g2 = i128(1000000000000LL);
                while (g2 != 0) {
                    const i128 rem = g1 % g2;
                    g1 = g2;
                    g2 = rem;
                }
                const i128 step = i128(1000000000000LL) / g1;
                const i128 mmax = i128(posmax) / step;
                if (mmax < 1) {
                    pos = irange(-posmax, posmax);
                } else {
                    const int64_t m = irange(-static_cast<int64_t>(mmax), static_cast<int64_t>(mmax));
                    pos = static_cast<int64_t>(i128(origin) + i128(m) * step);
                    if (pos > 2 * posmax || pos < -2 * posmax) pos = origin;
                    ++ties;
                }
            } else {
                pos = irange(-posmax, posmax);
            }
            const int64_t o1 = lxt::thermal_output_counts(tp, pos);
            const int64_t o2 = lxt::encoder_scaling_output_counts(es, pos);
            if (o1 != o2) {
                ++mism_exact;
                res.check(false, "forms differ: pos " + s64(pos) + " origin " + s64(origin) + " alpha " +
                                     fmt("%.3f T %.3f: ", alpha_ppm, temp) + s64(o1) + " vs " + s64(o2));
            }
            // against the real-valued correction (long double): floor within [x - 1, x]
            const long double x = static_cast<long double>(pos) +
                                  static_cast<long double>(pos - origin) * static_cast<long double>(prod) / 1e12L;
            const long double slack = 1e-6L;
            if (!(static_cast<long double>(o1) <= x + slack && static_cast<long double>(o1) > x - 1.0L - slack)) ++real_bad;
            // naive binary floating point, both forms
            const double a = alpha_ppm * 1e-6;
            const double n1 = std::floor(static_cast<double>(pos) + static_cast<double>(pos - origin) * a * (20.0 - temp));
            const double k169 = a * (20.0 - temp) * 1e5;
            const double n2 = std::floor(static_cast<double>(pos) + static_cast<double>(pos - es.k168) * k169 / 100000.0);
            if (n1 != n2) ++naive_forms_differ;
            if (n1 != static_cast<double>(o1) || n2 != static_cast<double>(o1)) ++naive_vs_exact;
        }
        res.check(mism_exact == 0, "exact forms differ in " + std::to_string(mism_exact) + " samples");
        res.check(real_bad == 0, std::to_string(real_bad) + " outputs outside [x-1, x] of the real-valued result");
        res.check(k169_bad == 0, std::to_string(k169_bad) + " K169 from the seed formula (7 decimals) != exact conversion");
        res.check(ties > samples / 4, "too few exact-integer corrections generated");
        std::printf("  forms (1)/(2): %lld samples (%ld with an exact-integer correction), output counts identical in all;\n"
                    "    naive double: the two forms floor differently in %ld samples, differ from the exact floor in %ld\n",
                    samples, ties, naive_forms_differ, naive_vs_exact);
    }

    // ---- 3. fold into the ratio register -----------------------------------------------------
    {
        long n_checks = 0, floor_diff = 0, two_stage_bad = 0;
        double worst_ratio = 0.0, worst_err = 0.0;
        int fold_lo = 0, fold_hi = 0;
        const int conditions = 400;
        const int per = std::max(1, static_cast<int>(samples / conditions / 2));
        for (int c = 0; c < conditions; ++c) {
            lxt::comp_inputs ci;
            ci.air_temp_c = uni(15.0, 30.0);
            ci.pressure_pa = uni(90e3, 110e3);
            ci.rh_percent = uni(0.0, 90.0);
            ci.equation = rng() % 2 ? lxt::air_equation::ciddor : lxt::air_equation::edlen;
            ci.alpha_ppm_per_c = rng() % 4 == 0 ? uni(-5.0, 30.0) : pre[rng() % npre].alpha_ppm_per_c;
            ci.material_temp_c = uni(10.0, 35.0);
            const lxt::comp_outputs co = lxt::compute_compensation(ci);
            if (!res.check(co.ok, "compute_compensation failed: " + co.error)) continue;
            const long double rex = co.scale_exact * 4294967296.0L;  // exact register value
            res.check(std::fabs(static_cast<double>(static_cast<long double>(co.ratio) - rex)) <= 0.5,
                      "register not the rounded exact ratio");
            // uncompensated-for-expansion register for the two-stage comparison
            uint64_t r0 = 0;
            std::string e0;
            res.check(lxt::ratio_from_index(ci.wavelength_nm, co.n, 0.0, &r0, &e0), e0);
            for (int k = 0; k < per; ++k) {
                int64_t n;
                const uint64_t sel = rng() % 8;
                if (sel == 0) n = INT32_MAX;
                else if (sel == 1) n = INT32_MIN;
                else n = irange(INT32_MIN, INT32_MAX);
                const int64_t hw = mult_out(n, co.ratio);
                const long double y = static_cast<long double>(n) * co.scale_exact;  // exact position, counts
                const long double err = static_cast<long double>(n) * (static_cast<long double>(co.ratio) - rex) / 4294967296.0L;
                const long double bound = std::fabs(static_cast<long double>(n)) / 8589934592.0L;  // |N| 2^-33
                const long double eps = 1e-7L;
                ++n_checks;
                if (std::fabs(err) > bound + eps)
                    res.check(false, "N " + s64(n) + fmt(": error %.3e counts exceeds |N| 2^-33 = %.3e", static_cast<double>(err),
                                                          static_cast<double>(bound)));
                if (bound > 0) worst_ratio = std::fmax(worst_ratio, static_cast<double>(std::fabs(err) / bound));
                worst_err = std::fmax(worst_err, static_cast<double>(std::fabs(err)));
                const int64_t ex = static_cast<int64_t>(std::floor(y));
                if (hw != ex) {
                    ++floor_diff;
                    // allowed only by one count, and only with an integer within |err| of y
                    const long double boundary = static_cast<long double>(std::max(hw, ex));
                    res.check(std::llabs(hw - ex) == 1 && std::fabs(y - boundary) <= std::fabs(err) + eps,
                              "N " + s64(n) + ": output " + s64(hw) + " vs exact " + s64(ex) +
                                  fmt(" (y frac distance %.3e, err %.3e)", static_cast<double>(std::fabs(y - boundary)),
                                      static_cast<double>(err)));
                }
                // two-stage (air register, then the exact expansion correction about raw count 0 on
                // the output counts): -1 <= folded - two-stage <= 2 (see the derivation in the report)
                lxt::thermal_params tz = co.thermal;
                tz.origin = 0;
                const int64_t q = lxt::thermal_output_counts(tz, mult_out(n, r0));
                const int64_t dfs = hw - q;
                fold_lo = std::min(fold_lo, static_cast<int>(dfs));
                fold_hi = std::max(fold_hi, static_cast<int>(dfs));
                if (dfs < -1 || dfs > 2) ++two_stage_bad;
            }
            // the golden multiplier computes floor(N R / 2^32) along a walk (N from 0)
            if (c < 8) {
                golden::pulse_multiplier pm;
                pm.reset();
                int64_t n = 0;
                constexpr int L = golden::pulse_multiplier::L_MUL;  // comp is L_MUL calls late (DESIGN 4.3)
                int64_t nh[L + 1] = {};
                int dir = (c % 2) ? 1 : -1;
                bool ok = true;
                for (int t = 0; t < 200000 && ok; ++t) {
                    int st = (rng() % 5 == 0) ? -dir : dir;
                    if (rng() % 7 == 0) st = 0;
                    n += st;
                    for (int i = L; i > 0; --i) nh[i] = nh[i - 1];
                    nh[0] = n;
                    const golden::pulse_multiplier::out o = pm.step(st, co.ratio, 0);  // offset: section 3b
                    // from reset the ratio is taken by the re-base that the first call triggers
                    // (DESIGN 4.3): exact from call 1 + K_REBASE + L_MUL on
                    if (t >= 1 + golden::pulse_multiplier::K_REBASE + L) ok = o.comp == mult_out(nh[L], co.ratio);
                }
                res.check(ok, "golden pulse_multiplier differs from floor(N R / 2^32)");
            }
        }
        res.check(two_stage_bad == 0, std::to_string(two_stage_bad) + " folded vs two-stage differences outside [-1, 2]");
        std::printf("  ratio fold: %ld (N, condition) pairs over |N| <= 2^31: max |N R/2^32 - N s| = %.4f counts\n"
                    "    (bound |N| 2^-33 <= 0.25; worst error/bound %.3f = 2|R - 2^32 s|); output differs from floor(N s)\n"
                    "    in %ld pairs, always by 1 count next to an integer; folded - two-stage in [%d, %d]\n",
                    n_checks, worst_err, worst_ratio, floor_diff, fold_lo, fold_hi);
        res.check(worst_err <= 0.25 + 1e-7, "error above 1/4 count");
        // negative control: a register 2 LSB off breaks the bound at full-scale N
        {
            lxt::comp_inputs ci;
            const lxt::comp_outputs co = lxt::compute_compensation(ci);
            const long double rex = co.scale_exact * 4294967296.0L;
            const int64_t n = INT32_MAX;
            const long double err = static_cast<long double>(n) * (static_cast<long double>(co.ratio + 2) - rex) / 4294967296.0L;
            res.check(std::fabs(err) > static_cast<long double>(n) / 8589934592.0L,
                      "negative control: a ratio 2 LSB off was not caught by the bound");
        }
    }

    // ---- 3b. origin through the offset register ------------------------------------------------
    {
        long n_checks = 0, near_int = 0, bad = 0, differ = 0;
        for (long long k = 0; k < samples / 4; ++k) {
            const int64_t scale = irange(1, 16);  // output counts per raw count, exact
            lxt::thermal_params tp;
            const double alpha_ppm = static_cast<double>(irange(-50000, 250000)) / 1000.0;
            const double temp = static_cast<double>(irange(-20000, 80000)) / 1000.0;
            const int64_t origin = k % 5 == 0 ? 0 : irange(-(int64_t(1) << 34), int64_t(1) << 34);  // +-1342 m
            if (!res.check(lxt::make_thermal(alpha_ppm, temp, origin, &tp).ok, "make_thermal rejected a legal input")) continue;
            const lxt::encoder_scaling es = lxt::to_encoder_scaling(tp);
            lxt::encoder_scaling es2;  // the seed-002 parameters as a user would enter them
            es2.k168 = origin;
            es2.k169_e7 = lxt::k169_e7_from_physical(alpha_ppm, temp);
            int64_t off = 0, off2 = 0;
            std::string err;
            if (!res.check(lxt::comp_offset_from_scaling(es, &off, &err) && lxt::comp_offset_from_scaling(es2, &off2, &err), err)) continue;
            res.check(off == off2 && es.k169_e7 == es2.k169_e7, "offset register from (origin, alpha, T) != from (K168, K169)");
            // R = rha(S (1 + g) 2^32) with g = k169_e7 / 1e12, exact in int128
            const i128 den = 1000000000000;
            const i128 rnum = i128(scale) * (den + es.k169_e7) * (i128(1) << 32);
            const uint64_t r = static_cast<uint64_t>((rnum * 2 + den) / (den * 2));
            const int64_t n = k % 7 == 0 ? (k % 2 ? INT32_MAX : INT32_MIN) : irange(INT32_MIN, INT32_MAX);
            const int64_t x = scale * n;
            const int64_t exact = lxt::thermal_output_counts(tp, x);
            res.check(exact == lxt::encoder_scaling_output_counts(es2, x), "thermal forms differ");
            const int64_t hw = floor_div(i128(n) * i128(r) + off, i128(1) << 32);
            golden::pulse_multiplier pm;
            pm.reset();
            // one golden step from N = 0 (exact range: |N| = 1), then the re-base of the reset pair
            // settles: 1 + K_REBASE + L_MUL calls (DESIGN 4.3)
            golden::pulse_multiplier::out pmo = pm.step(1, r, off);
            for (int i = 0; i < 1 + golden::pulse_multiplier::K_REBASE + golden::pulse_multiplier::L_MUL; ++i) pmo = pm.step(0, r, off);
            res.check(pmo.comp == floor_div(i128(r) + off, i128(1) << 32), "golden multiplier with offset");
            // distance of the exact value y = x + (x - origin) g from the nearest integer, in units of 1/den
            const i128 ynum = i128(x) * den + (i128(x) - origin) * es.k169_e7;
            const i128 frac = ynum - i128(floor_div(ynum, den)) * den;  // 0 .. den-1
            const i128 dist = frac < den - frac ? frac : den - frac;
            // bound (|N| + 1) 2^-33 counts, in units of 1/den (rounded up)
            const i128 bnd = ((i128(n < 0 ? -n : n) + 1) * den + (i128(1) << 33) - 1) / (i128(1) << 33);
            ++n_checks;
            if (hw != exact) ++differ;
            if (dist <= bnd) {
                ++near_int;
                if (hw - exact < -1 || hw - exact > 1) ++bad;
            } else if (hw != exact) {
                ++bad;
                if (bad < 5)
                    res.check(false, "offset form: N " + s64(n) + " S " + s64(scale) + " origin " + s64(origin) + ": hardware " +
                                         s64(hw) + " exact " + s64(exact));
            }
            if (k == 0) {  // negative control: an offset 2 LSB off violates the bound somewhere near
                const int64_t hw2 = floor_div(i128(n) * i128(r) + off + 2 * (int64_t(1) << 32), i128(1) << 32);
                res.check(hw2 != exact, "negative control: an offset 2 counts off was not caught");
            }
        }
        res.check(bad == 0, std::to_string(bad) + " hardware outputs (ratio + offset registers) differ from the exact thermal form");
        std::printf("  origin via comp_offset: %ld samples, registers identical from (origin, alpha, T) and (K168, K169);\n"
                    "    hardware == exact floor(x + (x - origin) g) wherever the exact value is farther than (|N|+1) 2^-33\n"
                    "    from an integer; %ld samples were within that bound, %ld of them differ by one count\n",
                    n_checks, near_int, differ);
    }

    // ---- 4. host helper round trip -------------------------------------------------------------
    {
        // DESIGN 5 reset value of the ratio register: rha(632.991 / 1.000271 / 78.125 * 2^32)
        uint64_t r = 0;
        std::string err;
        res.check(lxt::ratio_from_index(632.991, 1.000271, 0.0, &r, &err) && r == 34789620252ULL,
                  "ratio for n = 1.000271 is " + std::to_string(r) + ", DESIGN reset value 34789620252");
        res.check(r == lxt::ratio_for(632.991, 1.000271, 78.125), "compensation and sim.h ratio_for disagree");
        // register -> scale -> register is the identity
        for (int k = 0; k < 20000; ++k) {
            const uint64_t rr = 1 + rng() % lxt::kRatioMax;
            uint64_t back = 0;
            const lxt::ratio_readback b = lxt::scale_from_ratio(rr, 632.991);
            if (!lxt::ratio_from_scale(b.scale, &back, &err) || back != rr) {
                res.check(false, "round trip of register " + std::to_string(rr) + " gave " + std::to_string(back));
                break;
            }
        }
        res.check(!lxt::ratio_from_scale(0.0L, &r, &err) && !err.empty(), "scale 0 accepted");
        res.check(!lxt::ratio_from_scale(32.0L, &r, &err), "scale 32 (>= 2^37 LSB) accepted");
        res.check(lxt::ratio_from_scale(static_cast<long double>(lxt::kRatioMax) / 4294967296.0L, &r, &err) && r == lxt::kRatioMax,
                  "largest register rejected");
        // settings -> register -> effective scale: ppm and air index back within the register's
        // quantisation (0.5 LSB of R, i.e. 0.5/R relative)
        double worst_ppm = 0, worst_n = 0;
        for (int k = 0; k < 2000; ++k) {
            lxt::comp_inputs ci;
            ci.air_temp_c = uni(0.0, 40.0);
            ci.pressure_pa = uni(60e3, 120e3);
            ci.rh_percent = uni(0.0, 100.0);
            ci.wavelength_nm = rng() % 2 ? 632.991 : uni(350.0, 650.0);
            ci.equation = rng() % 2 ? lxt::air_equation::ciddor : lxt::air_equation::edlen;
            ci.alpha_ppm_per_c = uni(-10.0, 30.0);
            ci.material_temp_c = uni(0.0, 40.0);
            ci.origin_um = uni(-1e6, 1e6);
            const lxt::comp_outputs co = lxt::compute_compensation(ci);
            if (!res.check(co.ok, "compute_compensation: " + co.error)) continue;
            const lxt::ratio_readback b = lxt::scale_from_ratio(co.ratio, ci.wavelength_nm);
            const double q_ppm = 0.5 / static_cast<double>(co.ratio) * 1e6 * (1.0 + co.total_ppm * 1e-6);
            worst_ppm = std::fmax(worst_ppm, std::fabs(b.ppm_vs_vacuum - co.total_ppm) / q_ppm);
            res.expect(std::fabs(b.ppm_vs_vacuum - co.total_ppm) <= q_ppm + 1e-9 && b.ppm_vs_vacuum == co.register_ppm,
                       [&] { return fmt("readback %.9f ppm vs predicted %.9f ppm", b.ppm_vs_vacuum, co.total_ppm); });
            const double n_back = lxt::air_index_from_ratio(co.ratio, ci.wavelength_nm, co.expansion);
            worst_n = std::fmax(worst_n, std::fabs(n_back - co.n) / (0.5 / static_cast<double>(co.ratio)));
            res.expect(std::fabs(n_back - co.n) <= 0.5 / static_cast<double>(co.ratio) * 1.0003 + 1e-15,
                       [&] { return fmt("air index back %.12f vs %.12f", n_back, co.n); });
            // the parts: (1+g)/n - 1 = (1/n - 1) + g/n
            res.expect(std::fabs(co.total_ppm - (co.air_ppm + co.expansion / co.n * 1e6)) < 1e-8,
                       [&] { return fmt("total %.9f != air %.9f + expansion/n", co.total_ppm, co.air_ppm); });
            res.expect(co.scaling.k168 == static_cast<int64_t>(std::floor(ci.origin_um * 12.8 + 0.5)),
                       [&] { return "K168 " + s64(co.scaling.k168) + fmt(" for origin %.6f um", ci.origin_um); });
        }
        std::printf("  round trip (2000 settings): readback ppm within %.3f, air index within %.3f of the 0.5-LSB quantisation\n",
                    worst_ppm, worst_n);
        // invalid settings are reported, not extrapolated
        lxt::comp_inputs bad;
        bad.air_temp_c = 45.0;
        bad.equation = lxt::air_equation::edlen;
        lxt::comp_outputs co = lxt::compute_compensation(bad);
        res.check(!co.ok && co.error.find("temperature") != std::string::npos, "Edlen at 45 degC accepted: " + co.error);
        bad.equation = lxt::air_equation::ciddor;
        co = lxt::compute_compensation(bad);
        res.check(co.ok && !co.edlen.ok, "Ciddor at 45 degC rejected or Edlen evaluated");
        bad.material_temp_c = 95.0;
        bad.alpha_ppm_per_c = 11.5;
        res.check(!lxt::compute_compensation(bad).ok, "material at 95 degC accepted");
    }

    // ---- 5. laserax compensate -------------------------------------------------------------------
    {
        std::string out, err;
        const char* shown[] = {"--temp-c 20 --pressure-kpa 101.325 --rh 50",
                               "--temp-c 15 --pressure-kpa 95 --rh 20 --material steel --material-temp-c 15",
                               ("--temp-c 30 --pressure-pa 105000 --rh 80 --equation edlen --alpha-ppm 23.1 --material-temp-c 25 "
                                "--origin-um 150000")};
        for (const char* line : shown) {
            const int rc = run_cmd(line, &out, &err);
            res.check(rc == 0, std::string("laserax compensate ") + line + " exit " + std::to_string(rc) + ": " + err);
            res.check(out.find("ratio register") != std::string::npos && out.find("K169") != std::string::npos &&
                          out.find("Edlen - Ciddor") != std::string::npos,
                      std::string("output incomplete for ") + line);
            std::printf("  $ laserax compensate %s\n%s", line, out.c_str());
        }
        // the printed register is the helper's
        {
            lxt::comp_inputs ci;
            ci.air_temp_c = 30;
            ci.pressure_pa = 105000;
            ci.rh_percent = 80;
            ci.equation = lxt::air_equation::edlen;
            ci.alpha_ppm_per_c = 23.1;
            ci.material_temp_c = 25;
            ci.origin_um = 150000;
            const lxt::comp_outputs co = lxt::compute_compensation(ci);
            char want[64];
            std::snprintf(want, sizeof want, "%llu  (0x%llX)", static_cast<unsigned long long>(co.ratio),
                          static_cast<unsigned long long>(co.ratio));
            res.check(co.ok && out.find(want) != std::string::npos, std::string("printed register is not ") + want);
            res.check(co.scaling.k168 == 1920000 && co.scaling.k169_e7 == 23100 * (20000 - 25000),
                      "K168/K169 for aluminium at 25 degC, origin 150 mm");
        }
        const struct {
            const char* line;
            const char* word;  // expected in the message
        } bad[] = {
            {"--bogus 1", "unknown option"},
            {"--temp-c", "needs a value"},
            {"--temp-c abc", "is not a finite number"},
            {"--temp-c 20x", "is not a finite number"},
            {"--temp-c 45 --equation edlen", "temperature"},
            {"--temp-c 101", "temperature"},
            {"--rh 120", "--rh: 120 is out of range"},
            {"--pressure-kpa 5", "pressure"},
            {"--pressure-pa 101325 --pressure-kpa 101.325", "once"},
            {"--wavelength-nm 2000", "wavelength"},
            {"--wavelength-nm 1064 --equation edlen", "wavelength"},
            {"--co2-ppm 5000", "CO2"},
            {"--material unobtanium", "unknown material"},
            {"--material steel --alpha-ppm 11", "not both"},
            {"--alpha-ppm 500", "expansion coefficient"},
            {"--material invar --material-temp-c 120", "material temperature"},
            {"--equation lorentz", "allowed edlen, ciddor"},
            {"--temp-c nan", "is not a finite number"},
        };
        int n_bad = 0;
        for (const auto& b : bad) {
            const int rc = run_cmd(b.line, &out, &err);
            res.check(rc == 2 && err.find(b.word) != std::string::npos && out.empty(),
                      std::string("laserax compensate ") + b.line + ": exit " + std::to_string(rc) + ", stderr '" + err + "'");
            n_bad += rc == 2;
        }
        res.check(run_cmd("--help", &out, &err) == 0 && out.find("usage") != std::string::npos, "--help");
        std::printf("  laserax compensate: %d bad invocations exit 2 with a message, e.g. \"%s\"\n", n_bad,
                    (run_cmd("--temp-c 45 --equation edlen", &out, &err), err.substr(0, err.size() - 1).c_str()));
    }
    return res.finish();
}
