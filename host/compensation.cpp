// compensation.cpp — see compensation.h.
#include "host/compensation.h"

#include <cmath>
#include <cstdio>

namespace lxt {

bool ratio_from_scale(long double scale, uint64_t* ratio, std::string* err) {
    const long double r = scale * 4294967296.0L;
    if (!(r >= 0.5L && r < static_cast<long double>(kRatioMax) + 0.5L)) {
        if (err) {
            char buf[160];
            std::snprintf(buf, sizeof buf, "ratio %.6Lg output counts per raw count is outside the Q5.32 register (1 .. 2^37-1 LSB)",
                          scale);
            *err = buf;
        }
        return false;
    }
    *ratio = static_cast<uint64_t>(std::floor(r + 0.5L));  // r > 0: half away from zero = half up
    return true;
}

bool ratio_from_index(double wavelength_nm, double n, double expansion, uint64_t* ratio, std::string* err) {
    const long double scale = static_cast<long double>(wavelength_nm) / static_cast<long double>(n) /
                              static_cast<long double>(kOutputCountNmComp) * (1.0L + static_cast<long double>(expansion));
    return ratio_from_scale(scale, ratio, err);
}

__extension__ typedef __int128 i128_t;

bool comp_offset_from_scaling(const lxt::encoder_scaling& s, int64_t* comp_offset, std::string* err) {
    // |K168| <= 2^34 (1000 m), |k169_e7| <= 3e10 < 2^35: the product times 2^32 stays below 2^101.
    const i128_t num = -static_cast<i128_t>(s.k168) * static_cast<i128_t>(s.k169_e7) * (static_cast<i128_t>(1) << 32);
    const i128_t den = 1000000000000;  // 1e12: k169_e7 * 1e-12 = g
    const i128_t mag = ((num < 0 ? -num : num) * 2 + den) / (den * 2);  // round half away from zero
    const i128_t off = num < 0 ? -mag : mag;
    const i128_t lim = static_cast<i128_t>(1) << 63;
    if (off >= lim || off < -lim) {
        if (err) *err = "thermal offset origin * alpha * (20 - T) does not fit the 64-bit comp_offset register (|offset| < 2^31 counts)";
        return false;
    }
    *comp_offset = static_cast<int64_t>(off);
    return true;
}

double origin_from_comp_offset(int64_t comp_offset, int64_t k169_e7) {
    return -static_cast<double>(static_cast<long double>(comp_offset) / 4294967296.0L * 1e12L / static_cast<long double>(k169_e7));
}

ratio_readback scale_from_ratio(uint64_t ratio, double wavelength_nm) {
    ratio_readback b;
    b.scale = static_cast<long double>(ratio) / 4294967296.0L;
    const long double vac = static_cast<long double>(wavelength_nm) / static_cast<long double>(kOutputCountNmComp);
    b.ppm_vs_vacuum = static_cast<double>((b.scale / vac - 1.0L) * 1e6L);
    return b;
}

double air_index_from_ratio(uint64_t ratio, double wavelength_nm, double expansion) {
    const long double scale = static_cast<long double>(ratio) / 4294967296.0L;
    return static_cast<double>(static_cast<long double>(wavelength_nm) / static_cast<long double>(kOutputCountNmComp) *
                               (1.0L + static_cast<long double>(expansion)) / scale);
}

comp_outputs compute_compensation(const comp_inputs& in) {
    comp_outputs o;
    lxt::air_input ai;
    ai.wavelength_nm = in.wavelength_nm;
    ai.temp_c = in.air_temp_c;
    ai.pressure_pa = in.pressure_pa;
    ai.rh_percent = in.rh_percent;
    ai.co2_ppm = in.co2_ppm;
    o.edlen = lxt::air_index_edlen(ai);
    o.ciddor = lxt::air_index_ciddor(ai);
    const lxt::air_index_result& sel = in.equation == lxt::air_equation::edlen ? o.edlen : o.ciddor;
    if (!sel.ok) {
        o.error = sel.error;
        return o;
    }
    o.n = sel.n;

    if (!std::isfinite(in.origin_um) || std::fabs(in.origin_um) > 1e9) {
        o.error = "origin must be a finite position within +-1000 m";
        return o;
    }
    o.origin_counts_exact = in.origin_um * 1000.0 / kOutputCountNmComp;
    const int64_t origin = static_cast<int64_t>(std::floor(o.origin_counts_exact + 0.5));
    const lxt::thermal_status ts = lxt::make_thermal(in.alpha_ppm_per_c, in.material_temp_c, origin, &o.thermal);
    if (!ts.ok) {
        o.error = ts.error;
        return o;
    }
    o.scaling = lxt::to_encoder_scaling(o.thermal);
    o.expansion = lxt::gradient(o.thermal);

    o.scale_exact = static_cast<long double>(in.wavelength_nm) / static_cast<long double>(o.n) /
                    static_cast<long double>(kOutputCountNmComp) * (1.0L + static_cast<long double>(o.expansion));
    if (!ratio_from_scale(o.scale_exact, &o.ratio, &o.error)) return o;
    if (!comp_offset_from_scaling(o.scaling, &o.comp_offset, &o.error)) return o;
    o.air_ppm = (1.0 / o.n - 1.0) * 1e6;
    o.expansion_ppm = o.expansion * 1e6;
    o.total_ppm = static_cast<double>(((1.0L + static_cast<long double>(o.expansion)) / static_cast<long double>(o.n) - 1.0L) * 1e6L);
    o.register_ppm = scale_from_ratio(o.ratio, in.wavelength_nm).ppm_vs_vacuum;
    o.ok = true;
    return o;
}

}  // namespace lxt
