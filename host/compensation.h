// compensation.h — host helper for issue 3 (compensation): physical settings -> the Q5.32 ratio
// register of the pulse multiplier, the predicted compensation in ppm, and the seed-002 encoder
// scaling parameters (K168, K169); and back, register -> effective scale.
//
// The multiplier turns raw laser counts into output counts: comp = floor(N * R / 2^32)
// (DESIGN 4.3). One raw count is one air wavelength lambda_vac / n (DESIGN 1), one output count
// 78.125 nm, so the air-compensated ratio is lambda_vac / n / 78.125 nm. Workpiece expansion is
// folded in as the factor (1 + alpha (20 - T)) (host/thermal.h):
//
//     R = rha( lambda_vac / n / 78.125 nm * (1 + alpha (20 - T)) * 2^32 )     (round half away)
//
// The fold scales about raw count 0. The thermal origin (K168, output counts measured from raw
// count 0 in the air-compensated scale x = N * lambda / n / 78.125 nm) is the multiplier's offset
// register (DESIGN 4.3, comp = floor((N * R + comp_offset) / 2^32)):
//
//     x + (x - origin) g = x (1 + g) - origin g      =>   comp_offset = rha(-K168 * g * 2^32)
//
// with g = K169 * 1e-5 = k169_e7 * 1e-12 exactly (host/thermal.h), evaluated in __int128, so the
// position at the origin does not move when g changes (a material-temperature update while the
// axis stands at the origin leaves comp unchanged).
//
// Compensation in ppm is relative to the uncompensated vacuum scale lambda_vac / 78.125 nm:
//     total ppm = (scale / (lambda_vac / 78.125) - 1) * 1e6 = ((1 + g) / n - 1) * 1e6,  g = alpha (20 - T)
//     air ppm   = (1 / n - 1) * 1e6,          expansion ppm = g * 1e6.
// Register quantisation: |R - R_exact| <= 1/2, i.e. 0.5 / R relative (1.4e-5 ppm at R = 3.5e10).
#ifndef LASERAX_TOOLS_COMPENSATION_H
#define LASERAX_TOOLS_COMPENSATION_H

#include <cstdint>
#include <string>

#include "host/air_index.h"
#include "host/thermal.h"

namespace lxt {

constexpr double kOutputCountNmComp = 78.125;              // DESIGN 1 (same as kOutputCountNm)
constexpr uint64_t kRatioMax = (uint64_t(1) << 37) - 1;    // W_RATIO = 37 bits, legal 1 .. 2^37-1

struct comp_inputs {
    double wavelength_nm = 632.991;  // vacuum wavelength
    double air_temp_c = 20.0;
    double pressure_pa = 101325.0;
    double rh_percent = 50.0;
    double co2_ppm = 450.0;          // Ciddor only
    lxt::air_equation equation = lxt::air_equation::ciddor;  // the one used for the register
    double alpha_ppm_per_c = 0.0;    // workpiece expansion coefficient (0: no thermal correction)
    double material_temp_c = 20.0;
    double origin_um = 0.0;          // thermal origin (K168), um from raw count 0 / home;
                                     // rounded to the nearest output count (half up)
};

struct comp_outputs {
    bool ok = false;
    std::string error;
    lxt::air_index_result edlen, ciddor;  // both evaluated (either may be out of its range)
    double n = 0.0;                          // from the selected equation
    lxt::thermal_params thermal;          // quantised alpha / T (see host/thermal.h)
    lxt::encoder_scaling scaling;         // K168 (counts), K169 * 1e7
    double origin_counts_exact = 0.0;        // origin_um / 0.078125 before rounding to K168
    double expansion = 0.0;                  // g = alpha (20 - T), from the quantised values
    long double scale_exact = 0.0L;          // output counts per raw count, unrounded
    uint64_t ratio = 0;                      // the Q5.32 register
    int64_t comp_offset = 0;                 // the Q32.32 offset register (thermal origin)
    double air_ppm = 0.0;                    // (1/n - 1) * 1e6
    double expansion_ppm = 0.0;              // g * 1e6
    double total_ppm = 0.0;                  // exact ((1+g)/n - 1) * 1e6
    double register_ppm = 0.0;               // what the rounded register really applies
};

// Everything from the physical settings. ok = false with a message for out-of-range input.
comp_outputs compute_compensation(const comp_inputs& in);

// The ratio register for a scale (output counts per raw count): rha(scale * 2^32); false with a
// message if it is not in 1 .. 2^37-1.
bool ratio_from_scale(long double scale, uint64_t* ratio, std::string* err);
// lambda_vac / n / 78.125 * (1 + g) -> register (the formula above).
bool ratio_from_index(double wavelength_nm, double n, double expansion, uint64_t* ratio, std::string* err);

// comp_offset = rha(-K168 * K169 * 1e-5 * 2^32) (exact integer arithmetic); false with a message
// if it does not fit the register (|offset| < 2^31 output counts, W_OFFSET = 64).
bool comp_offset_from_scaling(const lxt::encoder_scaling& s, int64_t* comp_offset, std::string* err);
// Back: the origin (output counts, real) that an offset register means for a K169 (k169_e7 != 0).
double origin_from_comp_offset(int64_t comp_offset, int64_t k169_e7);

// Register -> effective scale and ppm relative to lambda_vac / 78.125 nm.
struct ratio_readback {
    long double scale = 0.0L;   // R / 2^32, exact
    double ppm_vs_vacuum = 0.0; // (scale / (lambda_vac / 78.125) - 1) * 1e6
};
ratio_readback scale_from_ratio(uint64_t ratio, double wavelength_nm);
// The air index a register implies once the expansion factor is known: n = lambda/78.125 (1+g) / scale.
double air_index_from_ratio(uint64_t ratio, double wavelength_nm, double expansion);

}  // namespace lxt

#endif
