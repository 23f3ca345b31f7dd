// host/air_index.h — refractive index of air for the laser's vacuum wavelength (issue 3,
// compensation, host side: the host driver library).
//
// Two independent equations, both in the form published by NIST's Engineering Metrology Toolbox
// ("Index of Refraction of Air", J. A. Stone and J. H. Zimmerman, emtoolbox.nist.gov/Wavelength/
// Documentation.asp, Appendix A):
//
//  * modified Edlén: K. P. Birch and M. J. Downs, "An updated Edlén equation for the refractive
//    index of air", Metrologia 30, 155-162 (1993), with "Correction to the updated Edlén
//    equation ...", Metrologia 31, 315-316 (1994). Standard air of that equation: 15 °C,
//    101 325 Pa, dry, 450 µmol/mol CO2 (fixed: co2_ppm is not used by it). By default the water
//    vapour term carries NIST's factor 292.75 / T[K] (NIST's own modification for temperatures
//    away from 20 °C; set air_options::nist_water_term = false for the plain Birch & Downs term).
//    The water vapour partial pressure is RH/100 * p_sv (no enhancement factor), as in NIST A-IV.
//
//  * Ciddor: P. E. Ciddor, "Refractive index of air: new equations for the visible and near
//    infrared", Applied Optics 35, 1566-1573 (1996). Densities from the BIPM CIPM-81/91
//    equation for moist air (Davis 1992, Metrologia 29, 67): compressibility Z(p, T, x_w) and
//    enhancement factor f = 1.00062 + 3.14e-8 p + 5.6e-7 t^2. CO2 enters through the molar
//    mass of dry air and the refractivity of standard air.
//
// Saturation vapour pressure of water (relative humidity -> partial pressure):
//  * above the triple point (T >= 273.16 K): W. Wagner and A. Pruss, "International equations for
//    the saturation properties of ordinary water substance. Revised according to the
//    International Temperature Scale of 1990", J. Phys. Chem. Ref. Data 22, 783 (1993) (the
//    IAPWS 1992 saturation-pressure equation, T_c = 647.096 K, p_c = 22.064 MPa);
//  * below it, over ice: W. Wagner, A. Saul and A. Pruss, J. Phys. Chem. Ref. Data 23, 515 (1994)
//    (the form NIST A-I uses below 0 °C), p_t = 611.657 Pa.
//  The IAPWS-IF97 region-4 saturation equation (the one NIST A-I uses above 0 °C) is provided as
//  svp_water_if97() for cross-checking; the two agree within 1e-4 (relative) from 0 to 100 °C
//  (IF97 is held to 0.025 % of the scientific formulation), i.e. within 3e-10 in n.
//
// Input ranges. Inputs outside them are REJECTED (ok = false, error says which input and the
// range); nothing is extrapolated unless air_options::allow_extrapolation is set explicitly (the
// result is then flagged `extrapolated`; the testbench uses that to compare with NIST's own
// table outside the adopted Edlén range):
//
//   quantity          Ciddor                 modified Edlén (adopted here)
//   wavelength        300 .. 1700 nm         350 .. 650 nm
//   air temperature   -40 .. 100 °C          0 .. 40 °C
//   pressure          10 .. 140 kPa          60 .. 120 kPa
//   relative humidity 0 .. 100 %             0 .. 100 %
//   CO2               0 .. 2000 µmol/mol     (fixed 450 µmol/mol, input ignored)
//   and always: water vapour partial pressure (times f for Ciddor) below the total pressure.
//
// Ciddor's limits are the input limits of the NIST calculator (its stated range for Ciddor's
// equation). The Edlén limits are this project's, deliberately narrower because NIST advises
// Ciddor for conditions far from the laboratory; they are where NIST's own comparison table
// (Documentation, sec. VII) keeps the two equations within about 2e-8: dry air at 5..50 °C and
// 60..120 kPa agrees to <= 1.5e-8 and 40 °C/75 %RH to 1.2e-8, while 50 °C/100 %RH differs by
// 6.0e-8 and -40 °C by 1.09e-7; 300 nm in warm humid air differs by 7.8e-8, so the wavelength
// is held to a conservative visible band.
// Both cover the shop floor (15..30 °C, 90..110 kPa, 0..90 %RH) at 632.991 nm.
//
// Units: wavelength in nm (vacuum), temperature in °C (ITS-90), pressure in Pa, RH in percent,
// CO2 in µmol/mol (ppm). No exceptions, no heap except the error string.
#pragma once
#include <string>

namespace lxt {

enum class air_equation { edlen, ciddor };

const char* air_equation_name(air_equation e);

struct air_input {
    double wavelength_nm = 632.991;  // vacuum wavelength
    double temp_c = 20.0;            // air temperature
    double pressure_pa = 101325.0;   // total pressure
    double rh_percent = 50.0;        // relative humidity (over water above 0 °C, over ice below)
    double co2_ppm = 450.0;          // CO2 mole fraction in µmol/mol (Ciddor only)
};

struct air_options {
    bool allow_extrapolation = false;  // evaluate outside the adopted range (result flagged)
    bool nist_water_term = true;       // Edlén: NIST's 292.75/T factor on the water vapour term
    bool if97_vapour_pressure = false; // above 0 °C use IAPWS-IF97 (what the NIST calculator uses)
                                       // instead of Wagner & Pruss (for reproducing NIST's table)
};

struct air_index_result {
    bool ok = false;            // false: n is not valid, error says why
    bool extrapolated = false;  // evaluated outside the adopted range (allow_extrapolation only)
    double n = 0.0;             // phase refractive index
    double psv_pa = 0.0;        // saturation vapour pressure used
    double pv_pa = 0.0;         // water vapour partial pressure RH/100 * psv
    double xv = 0.0;            // Ciddor: mole fraction of water vapour (0 for Edlén)
    std::string error;          // empty when ok
};

struct air_limits {
    double lambda_min_nm, lambda_max_nm;
    double t_min_c, t_max_c;
    double p_min_pa, p_max_pa;
    double rh_min, rh_max;
    double co2_min_ppm, co2_max_ppm;  // Ciddor only
};

air_limits ciddor_limits();
air_limits edlen_limits();

air_index_result air_index_ciddor(const air_input& in, const air_options& opt = air_options{});
air_index_result air_index_edlen(const air_input& in, const air_options& opt = air_options{});
air_index_result air_index(air_equation e, const air_input& in, const air_options& opt = air_options{});

// Saturation vapour pressure in Pa at T in kelvin. Return 0 outside the equation's range
// (water: 273.16 .. 647.096 K; ice: 190 .. 273.16 K; IF97: 273.15 .. 647.096 K).
double svp_water_wagner_pruss(double t_k);
double svp_ice_wagner(double t_k);
double svp_water_if97(double t_k);
// Over water at and above the triple point (273.16 K), over ice below it; temperature in °C.
double saturation_vapour_pressure_pa(double temp_c);

// Ciddor / CIPM-81/91 pieces (exposed for the testbench).
double enhancement_factor(double pressure_pa, double temp_c);
double ciddor_compressibility(double pressure_pa, double t_k, double xw);

// Expanded (k = 2) uncertainty of the equations themselves (not of the sensors), NIST A-V:
// Ciddor: 1e-8 * sqrt((0.003 p/(t+273))^2 (4 + 6e-8 (p - 1e5)^2 + 0.06 (t - 20)^2)
//                     + pv^2 ((8e-4)^2 + (6e-6/lambda_um^4)^2))
// Edlén: Ciddor's combined in quadrature with 2e-8 (NIST adds a further term growing with
// |t - 20|; that term is not modelled, so edlen_expanded_uncertainty is meant for t near 20 °C).
double ciddor_expanded_uncertainty(const air_input& in);
double edlen_expanded_uncertainty(const air_input& in);

}  // namespace lxt
