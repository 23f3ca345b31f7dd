// host/air_index.cpp — see air_index.h for the equations' sources and the input ranges.
#include "host/air_index.h"

#include <cmath>
#include <cstdio>

namespace lxt {

namespace {

constexpr double kT0 = 273.15;  // 0 °C in kelvin

// ---- saturation vapour pressure ---------------------------------------------------------------

// Wagner & Pruss 1993 (IAPWS 1992), eq. (2.5): ln(p/p_c) = (T_c/T) * sum a_i tau^e_i.
constexpr double kTc = 647.096;    // K
constexpr double kPc = 22.064e6;   // Pa
constexpr double kWpA[6] = {-7.85951783, 1.84408259, -11.7866497, 22.6807411, -15.9618719, 1.80122502};

// Wagner, Saul & Pruss 1994, sublimation pressure: ln(p/p_t) = A1 (1 - th^-1.5) + A2 (1 - th^-1.25).
constexpr double kTt = 273.16;     // K, triple point
constexpr double kPt = 611.657;    // Pa
constexpr double kIceA1 = -13.928169;
constexpr double kIceA2 = 34.7078238;

// IAPWS-IF97, region 4 (saturation line), coefficients n1..n10.
constexpr double kIf97N[10] = {0.11670521452767e4,  -0.72421316703206e6, -0.17073846940092e2,
                               0.12020824702470e5,  -0.32325550322333e7, 0.14915108613530e2,
                               -0.48232657361591e4, 0.40511340542057e6,  -0.23855557567849,
                               0.65017534844798e3};

// ---- Ciddor 1996 -----------------------------------------------------------------------------
// refractivity of standard air (15 °C, 101 325 Pa, dry, 450 µmol/mol CO2), eq. (1), sigma in 1/um
constexpr double kK0 = 238.0185, kK1 = 5792105.0, kK2 = 57.362, kK3 = 167917.0;
// refractivity of standard water vapour (20 °C, 1333 Pa), eq. (3), with the 1.022 correction
constexpr double kW0 = 295.235, kW1 = 2.6422, kW2 = -0.032380, kW3 = 0.004028;
// CIPM-81/91 compressibility
constexpr double kA0 = 1.58123e-6, kA1 = -2.9331e-8, kA2 = 1.1043e-10;
constexpr double kB0 = 5.707e-6, kB1 = -2.051e-8;
constexpr double kC0 = 1.9898e-4, kC1 = -2.376e-6;
constexpr double kD = 1.83e-11, kE = -0.765e-8;
// enhancement factor f = alpha + beta p + gamma t^2
constexpr double kFAlpha = 1.00062, kFBeta = 3.14e-8, kFGamma = 5.6e-7;
constexpr double kR = 8.314510;   // J/(mol K), as in Ciddor 1996 (cancels in the density ratios)
constexpr double kMv = 0.018015;  // kg/mol, water

// ---- Birch & Downs 1993/1994 (NIST A-IV) ----------------------------------------------------
constexpr double kEA = 8342.54, kEB = 2406147.0, kEC = 15998.0, kED = 96095.43;
constexpr double kEE = 0.601, kEF = 0.00972, kEG = 0.003661;

bool in_range(double x, double lo, double hi) { return x >= lo && x <= hi; }  // false for NaN

std::string fmt_range(const char* what, double x, double lo, double hi, const char* unit, const char* eq) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s %g %s is outside the %s range %g .. %g %s", what, x, unit, eq, lo, hi, unit);
    return buf;
}

// Range check common to both equations. Returns "" or the first violation. Non-finite inputs are
// always errors (even with allow_extrapolation).
std::string check_inputs(const air_input& in, const air_limits& L, bool with_co2, const char* eq, bool* outside) {
    *outside = false;
    const double vals[5] = {in.wavelength_nm, in.temp_c, in.pressure_pa, in.rh_percent, with_co2 ? in.co2_ppm : 0.0};
    const char* names[5] = {"wavelength", "temperature", "pressure", "relative humidity", "CO2"};
    for (int i = 0; i < 5; ++i)
        if (!std::isfinite(vals[i])) return std::string(names[i]) + " is not a finite number";
    // hard physical limits, never extrapolated
    if (!(in.wavelength_nm > 0)) return "wavelength must be > 0 nm";
    if (!(in.pressure_pa > 0)) return "pressure must be > 0 Pa";
    if (!(in.temp_c > -kT0)) return "temperature must be above absolute zero";
    if (!in_range(in.rh_percent, 0.0, 100.0)) return fmt_range("relative humidity", in.rh_percent, 0, 100, "%", eq);
    if (with_co2 && !(in.co2_ppm >= 0 && in.co2_ppm < 1e6)) return "CO2 must be 0 .. 1e6 umol/mol";
    std::string e;
    if (!in_range(in.wavelength_nm, L.lambda_min_nm, L.lambda_max_nm))
        e = fmt_range("wavelength", in.wavelength_nm, L.lambda_min_nm, L.lambda_max_nm, "nm", eq);
    else if (!in_range(in.temp_c, L.t_min_c, L.t_max_c))
        e = fmt_range("air temperature", in.temp_c, L.t_min_c, L.t_max_c, "degC", eq);
    else if (!in_range(in.pressure_pa, L.p_min_pa, L.p_max_pa))
        e = fmt_range("pressure", in.pressure_pa, L.p_min_pa, L.p_max_pa, "Pa", eq);
    else if (with_co2 && !in_range(in.co2_ppm, L.co2_min_ppm, L.co2_max_ppm))
        e = fmt_range("CO2", in.co2_ppm, L.co2_min_ppm, L.co2_max_ppm, "umol/mol", eq);
    *outside = !e.empty();
    return e;
}

}  // namespace

const char* air_equation_name(air_equation e) { return e == air_equation::edlen ? "edlen" : "ciddor"; }

air_limits ciddor_limits() { return air_limits{300.0, 1700.0, -40.0, 100.0, 10e3, 140e3, 0.0, 100.0, 0.0, 2000.0}; }
air_limits edlen_limits() { return air_limits{350.0, 650.0, 0.0, 40.0, 60e3, 120e3, 0.0, 100.0, 450.0, 450.0}; }

double svp_water_wagner_pruss(double t_k) {
    if (!(t_k >= kTt && t_k <= kTc)) return 0.0;
    const double tau = 1.0 - t_k / kTc;
    const double s = kWpA[0] * tau + kWpA[1] * std::pow(tau, 1.5) + kWpA[2] * std::pow(tau, 3.0) +
                     kWpA[3] * std::pow(tau, 3.5) + kWpA[4] * std::pow(tau, 4.0) + kWpA[5] * std::pow(tau, 7.5);
    return kPc * std::exp(kTc / t_k * s);
}

double svp_ice_wagner(double t_k) {
    if (!(t_k >= 190.0 && t_k <= kTt)) return 0.0;
    const double th = t_k / kTt;
    return kPt * std::exp(kIceA1 * (1.0 - std::pow(th, -1.5)) + kIceA2 * (1.0 - std::pow(th, -1.25)));
}

double svp_water_if97(double t_k) {
    if (!(t_k >= 273.15 && t_k <= kTc)) return 0.0;
    const double* n = kIf97N;
    const double th = t_k + n[8] / (t_k - n[9]);
    const double A = th * th + n[0] * th + n[1];
    const double B = n[2] * th * th + n[3] * th + n[4];
    const double C = n[5] * th * th + n[6] * th + n[7];
    const double x = 2.0 * C / (-B + std::sqrt(B * B - 4.0 * A * C));
    return 1e6 * x * x * x * x;  // MPa -> Pa
}

double saturation_vapour_pressure_pa(double temp_c) {
    const double t_k = temp_c + kT0;
    return t_k >= kTt ? svp_water_wagner_pruss(t_k) : svp_ice_wagner(t_k);
}

namespace {
double vapour_pressure(double temp_c, const air_options& opt) {
    const double t_k = temp_c + kT0;
    if (opt.if97_vapour_pressure && t_k >= kTt) return svp_water_if97(t_k);
    return saturation_vapour_pressure_pa(temp_c);
}
}  // namespace

double enhancement_factor(double pressure_pa, double temp_c) {
    return kFAlpha + kFBeta * pressure_pa + kFGamma * temp_c * temp_c;
}

double ciddor_compressibility(double p, double t_k, double xw) {
    const double t = t_k - kT0;
    const double pt = p / t_k;
    return 1.0 - pt * (kA0 + kA1 * t + kA2 * t * t + (kB0 + kB1 * t) * xw + (kC0 + kC1 * t) * xw * xw) +
           pt * pt * (kD + kE * xw * xw);
}

air_index_result air_index_ciddor(const air_input& in, const air_options& opt) {
    air_index_result r;
    bool outside = false;
    r.error = check_inputs(in, ciddor_limits(), true, "Ciddor", &outside);
    if (!r.error.empty() && !(outside && opt.allow_extrapolation)) return r;
    r.error.clear();
    r.extrapolated = outside;

    const double t = in.temp_c, T = t + kT0, p = in.pressure_pa, xc = in.co2_ppm;
    r.psv_pa = vapour_pressure(t, opt);
    r.pv_pa = in.rh_percent / 100.0 * r.psv_pa;
    r.xv = enhancement_factor(p, t) * r.pv_pa / p;
    if (!(r.xv < 1.0)) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "water vapour %.0f Pa (x f = %.3f) at %g %%RH and %g degC exceeds the pressure %g Pa",
                      r.pv_pa, enhancement_factor(p, t), in.rh_percent, t, p);
        r.error = buf;
        r.extrapolated = false;
        return r;
    }
    const double lam_um = in.wavelength_nm * 1e-3;
    const double S = 1.0 / (lam_um * lam_um);
    // refractivities of standard dry air (with CO2) and standard water vapour
    const double r_as = 1e-8 * (kK1 / (kK0 - S) + kK3 / (kK2 - S));
    const double r_axs = r_as * (1.0 + 0.534e-6 * (xc - 450.0));
    const double r_ws = 1.022e-8 * (kW0 + kW1 * S + kW2 * S * S + kW3 * S * S * S);
    const double Ma = 1e-3 * (28.9635 + 12.011e-6 * (xc - 400.0));  // kg/mol, dry air with CO2
    // densities: standard dry air (15 °C, 101 325 Pa, x_w = 0), standard vapour (20 °C, 1333 Pa,
    // x_w = 1), and the dry-air and vapour components of the actual moist air
    const double Zaxs = ciddor_compressibility(101325.0, 288.15, 0.0);
    const double rho_axs = 101325.0 * Ma / (Zaxs * kR * 288.15);
    const double Zws = ciddor_compressibility(1333.0, 293.15, 1.0);
    const double rho_ws = 1333.0 * kMv / (Zws * kR * 293.15);
    const double Zm = ciddor_compressibility(p, T, r.xv);
    const double rho_a = p * Ma * (1.0 - r.xv) / (Zm * kR * T);
    const double rho_w = p * kMv * r.xv / (Zm * kR * T);
    r.n = 1.0 + (rho_a / rho_axs) * r_axs + (rho_w / rho_ws) * r_ws;
    r.ok = true;
    return r;
}

air_index_result air_index_edlen(const air_input& in, const air_options& opt) {
    air_index_result r;
    bool outside = false;
    r.error = check_inputs(in, edlen_limits(), false, "modified Edlen", &outside);
    if (!r.error.empty() && !(outside && opt.allow_extrapolation)) return r;
    r.error.clear();
    r.extrapolated = outside;

    const double t = in.temp_c, T = t + kT0, p = in.pressure_pa;
    r.psv_pa = vapour_pressure(t, opt);
    r.pv_pa = in.rh_percent / 100.0 * r.psv_pa;
    if (!(r.pv_pa < p)) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "water vapour %.0f Pa at %g %%RH and %g degC exceeds the pressure %g Pa", r.pv_pa,
                      in.rh_percent, t, p);
        r.error = buf;
        r.extrapolated = false;
        return r;
    }
    const double lam_um = in.wavelength_nm * 1e-3;
    const double S = 1.0 / (lam_um * lam_um);
    const double ns_1 = 1e-8 * (kEA + kEB / (130.0 - S) + kEC / (38.9 - S));  // standard air
    const double X = (1.0 + 1e-8 * (kEE - kEF * t) * p) / (1.0 + kEG * t);
    const double ntp_1 = p * ns_1 * X / kED;                                    // dry, at t and p
    const double wfac = opt.nist_water_term ? 292.75 / T : 1.0;
    r.n = 1.0 + ntp_1 - 1e-10 * wfac * (3.7345 - 0.0401 * S) * r.pv_pa;
    r.ok = true;
    return r;
}

air_index_result air_index(air_equation e, const air_input& in, const air_options& opt) {
    return e == air_equation::edlen ? air_index_edlen(in, opt) : air_index_ciddor(in, opt);
}

double ciddor_expanded_uncertainty(const air_input& in) {
    const double p = in.pressure_pa, t = in.temp_c;
    const double pv = in.rh_percent / 100.0 * saturation_vapour_pressure_pa(t);
    const double lam_um = in.wavelength_nm * 1e-3;
    const double c1 = 0.003 * p / (t + 273.0);
    const double c2 = 4.0 + 6e-8 * (p - 1e5) * (p - 1e5) + 0.06 * (t - 20.0) * (t - 20.0);
    const double d = 6e-6 / (lam_um * lam_um * lam_um * lam_um);
    const double c3 = 8e-4 * 8e-4 + d * d;
    return 1e-8 * std::sqrt(c1 * c1 * c2 + pv * pv * c3);
}

double edlen_expanded_uncertainty(const air_input& in) {
    const double uc = ciddor_expanded_uncertainty(in);
    return std::sqrt(uc * uc + 2e-8 * 2e-8);
}

}  // namespace lxt
