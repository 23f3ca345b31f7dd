// host/thermal.cpp — see thermal.h (forms (1) and (2), fixed-point parameters, exactness).
#include "host/thermal.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace lxt {

namespace {

__extension__ typedef __int128 i128;

const material_preset kPresets[] = {
    {"steel", 11.5, "carbon steel; 'Thermal expansion' table: steel 11.0..13.0 at 20 degC"},
    {"cast-iron", 10.5, "grey/ductile iron; Engineering ToolBox grey 10.8, ductile 10.6..11.2"},
    {"aluminium", 23.1, "'Thermal expansion' table, aluminium at 20 degC"},
    {"granite", 7.9, "Engineering ToolBox, granite"},
    {"invar", 1.2, "'Thermal expansion' table, Invar (Fe-36Ni) at 20 degC"},
};

constexpr double kAlphaMaxPpm = 300.0;
constexpr double kTempMinC = -20.0, kTempMaxC = 80.0;
constexpr int64_t kPosMax = int64_t(1) << 53;

// floor(n / d) for d > 0
i128 floor_div(i128 n, i128 d) {
    i128 q = n / d;
    if (n % d != 0 && n < 0) --q;
    return q;
}

int64_t rha_ll(double x) { return static_cast<int64_t>(x < 0 ? -std::floor(-x + 0.5) : std::floor(x + 0.5)); }

constexpr i128 kDen = i128(1000000000000LL);  // 1e12: alpha_e9 * dT_mc units, = 1e7 (K169 decimals) * 1e5

}  // namespace

const material_preset* material_presets(size_t* count) {
    if (count) *count = sizeof kPresets / sizeof kPresets[0];
    return kPresets;
}

const material_preset* find_material(const std::string& name) {
    std::string low;
    for (char c : name) low += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (low == "aluminum") low = "aluminium";
    if (low == "castiron" || low == "cast_iron") low = "cast-iron";
    for (const material_preset& m : kPresets)
        if (low == m.name) return &m;
    return nullptr;
}

std::string material_names() {
    std::string s;
    for (const material_preset& m : kPresets) {
        if (!s.empty()) s += ", ";
        s += m.name;
    }
    return s;
}

thermal_status make_thermal(double alpha_ppm_per_c, double temp_c, int64_t origin_counts, thermal_params* out) {
    thermal_status st;
    char buf[160];
    if (!(std::fabs(alpha_ppm_per_c) <= kAlphaMaxPpm)) {
        std::snprintf(buf, sizeof buf, "expansion coefficient %g ppm/degC is outside -%g .. %g ppm/degC", alpha_ppm_per_c,
                      kAlphaMaxPpm, kAlphaMaxPpm);
        st.error = buf;
        return st;
    }
    if (!(temp_c >= kTempMinC && temp_c <= kTempMaxC)) {
        std::snprintf(buf, sizeof buf, "material temperature %g degC is outside %g .. %g degC (linear expansion model)",
                      temp_c, kTempMinC, kTempMaxC);
        st.error = buf;
        return st;
    }
    if (origin_counts > kPosMax || origin_counts < -kPosMax) {
        st.error = "origin is outside +-2^53 counts";
        return st;
    }
    out->alpha_e9 = rha_ll(alpha_ppm_per_c * static_cast<double>(kAlphaUnitsPerPpm));
    out->temp_mc = rha_ll(temp_c * static_cast<double>(kTempUnitsPerC));
    out->origin = origin_counts;
    st.ok = true;
    return st;
}

encoder_scaling to_encoder_scaling(const thermal_params& p) {
    // K169 = alpha*(20-T)*1e5 = alpha_e9*1e-9 * (20000-temp_mc)*1e-3 * 1e5 = alpha_e9*(20000-temp_mc) * 1e-7
    return encoder_scaling{p.origin, p.alpha_e9 * (kRefTempMc - p.temp_mc)};
}

int64_t k169_e7_from_physical(double alpha_ppm_per_c, double temp_c) {
    const double k169 = alpha_ppm_per_c * 1e-6 * (20.0 - temp_c) * 1e5;  // the units of ETEL encoder scaling
    return rha_ll(k169 * static_cast<double>(kK169Decimals));
}

double temp_from_k169(double k169, double alpha_ppm_per_c) { return 20.0 - k169 / (alpha_ppm_per_c * 1e-6 * 1e5); }

double gradient(const thermal_params& p) {
    return static_cast<double>(p.alpha_e9 * (kRefTempMc - p.temp_mc)) / 1e12;
}

double k169_value(const encoder_scaling& s) { return static_cast<double>(s.k169_e7) / static_cast<double>(kK169Decimals); }

int64_t thermal_output_counts(const thermal_params& p, int64_t position) {
    const i128 num = (i128(position) - i128(p.origin)) * i128(p.alpha_e9) * i128(kRefTempMc - p.temp_mc);
    return static_cast<int64_t>(i128(position) + floor_div(num, kDen));
}

int64_t encoder_scaling_output_counts(const encoder_scaling& s, int64_t position) {
    // (position - K168) * K169 / 100000 with K169 = k169_e7 / 1e7
    const i128 num = (i128(position) - i128(s.k168)) * i128(s.k169_e7);
    return static_cast<int64_t>(i128(position) + floor_div(num, i128(kK169Decimals) * 100000));
}

double thermal_correction(double position, double origin, double alpha_per_c, double temp_c) {
    return (position - origin) * alpha_per_c * (20.0 - temp_c);
}

double encoder_scaling_correction(double position, double k168, double k169) {
    return (position - k168) * k169 / 100000.0;
}

}  // namespace lxt
