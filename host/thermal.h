// host/thermal.h — workpiece thermal expansion correction (issue 3, compensation, host side).
//
// A workpiece at temperature T is longer than at the 20 °C reference temperature (ISO 1) by the
// factor (1 + alpha (T - 20)). To report positions in the workpiece's 20 °C dimensions the scale
// reading is corrected about a fixed point (the origin, where the correction is zero):
//
//     correction = (position - origin) * alpha * (20 - T)                              (1)
//     output     = floor(position + correction)                (integer output counts)
//
// ETEL encoder scaling (docs/SOURCES.md) writes the same linear correction as
//
//     Correction = (position - K168) * K169 / 100000                                    (2)
//
// with position, K168 and Correction in the controller's position increments (here: output
// counts of 78.125 nm) and K169 the gradient in units of 1e-5 (one unit of K169 = 10 µm/m =
// 10 ppm). Hence
//
//     K168 = origin [counts],   K169 = alpha [1/°C] * (20 - T) [°C] * 1e5   (dimensionless)
//
// e.g. steel (11.5 ppm/°C) at 25 °C: K169 = -5.75. K169 must therefore carry decimals; it is
// kept here with 7 decimals (k169_e7 = K169 * 1e7). (A controller that takes an integer K169
// only would lose up to 5 ppm to rounding.)
//
// Exactness. Both forms are evaluated in exact integer arithmetic (__int128), on fixed-point
// parameters: alpha in 1e-9/°C (0.001 ppm/°C) and T in 0.001 °C. Then
//     alpha*(20-T) = alpha_e9 * (20000 - temp_mc) * 1e-12       and
//     K169         = alpha_e9 * (20000 - temp_mc) * 1e-7,  i.e.  k169_e7 = alpha_e9 * (20000 - temp_mc)
// exactly, so (1) and (2) are the same rational number for every position and both floors agree
// bit for bit. (In binary floating point they do not: alpha*(20-T) is not representable, and a
// correction that should be an exact integer comes out on either side of it. Steel at 17 °C,
// 2 000 000 counts (156.25 mm) from the origin: the correction is exactly 69 counts; in double,
// form (1) gives 69 and form (2) 68.999999999999986, so the two floors differ by one count.)
//
// Input limits (make_thermal rejects anything else): |alpha| <= 300 ppm/°C (every engineering
// material including most plastics), material temperature -20 .. 80 °C (the correction is
// linear in T about 20 °C; alpha itself drifts by a few percent over that span), |positions| and
// |origin| <= 2^53 counts.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace lxt {

struct material_preset {
    const char* name;        // lower case, as accepted by find_material
    double alpha_ppm_per_c;  // linear expansion coefficient near 20 °C, 1e-6 / °C
    const char* source;
};

// The presets (generic handbook values; a measured alpha of the actual part is always better):
//   steel       11.5  carbon/low-alloy steel; inside the 11.0..13.0 range of the "Thermal
//                     expansion" coefficient table (Wikipedia, values at 20 °C), which lists
//                     carbon steel at 10.8
//   cast-iron   10.5  grey/ductile cast iron; Engineering ToolBox "Coefficients of Linear
//                     Thermal Expansion" lists grey cast iron at 10.8, amesweb.info's room-
//                     temperature table ductile irons at 10.6..11.2
//   aluminium   23.1  pure aluminium near 20 °C ("Thermal expansion" table)
//   granite      7.9  Engineering ToolBox "Coefficients of Linear Thermal Expansion"
//   invar        1.2  Fe-36Ni, "Thermal expansion" table (at 20 °C)
const material_preset* material_presets(size_t* count);
const material_preset* find_material(const std::string& name);  // case-insensitive; nullptr if unknown
std::string material_names();                                   // "steel, cast-iron, ..."

constexpr int64_t kAlphaUnitsPerPpm = 1000;   // alpha_e9 per ppm/°C
constexpr int64_t kTempUnitsPerC = 1000;      // temp_mc per °C
constexpr int64_t kRefTempMc = 20000;         // 20 °C
constexpr int64_t kK169Decimals = 10000000;   // k169_e7 per unit of K169

struct thermal_params {
    int64_t alpha_e9 = 0;       // alpha in 1e-9 / °C
    int64_t temp_mc = 20000;    // material temperature in 0.001 °C
    int64_t origin = 0;         // zero-correction point, output counts
};

struct encoder_scaling {
    int64_t k168 = 0;     // zero-correction point, output counts
    int64_t k169_e7 = 0;  // K169 * 1e7 (K169 = gradient * 1e5)
};

struct thermal_status {
    bool ok = false;
    std::string error;
};

// Quantises (alpha in ppm/°C, T in °C) to the fixed-point grid (round half away from zero) and
// checks the limits.
thermal_status make_thermal(double alpha_ppm_per_c, double temp_c, int64_t origin_counts, thermal_params* out);

// (origin, alpha, T) -> (K168, K169): exact.
encoder_scaling to_encoder_scaling(const thermal_params& p);
// K169 from the physical values with that source's formula in floating point, rounded to 7 decimals
// (gives the same k169_e7 as to_encoder_scaling for values on the fixed-point grid).
int64_t k169_e7_from_physical(double alpha_ppm_per_c, double temp_c);
// Material temperature that a K169 means for a given alpha (inverse; alpha != 0).
double temp_from_k169(double k169, double alpha_ppm_per_c);

double gradient(const thermal_params& p);      // alpha*(20-T) (one rounding to double)
double k169_value(const encoder_scaling& s);   // K169 as a real number

// Output counts floor(position + correction), exact, form (1) and form (2).
int64_t thermal_output_counts(const thermal_params& p, int64_t position);
int64_t encoder_scaling_output_counts(const encoder_scaling& s, int64_t position);

// Real-valued corrections in counts (reports; not used for the exact outputs).
double thermal_correction(double position, double origin, double alpha_per_c, double temp_c);
double encoder_scaling_correction(double position, double k168, double k169);

}  // namespace lxt
