// compensate_cmd.cpp — `laserax compensate`, see compensate_cmd.h.
#include "tools/laserax/compensate_cmd.h"

#include "tools/laserax/cli_util.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "host/air_index.h"
#include "host/thermal.h"
#include "host/compensation.h"
#include "host/regmap.h"

namespace lxt {

const char* const kCompensateUsage =
    "usage: laserax compensate [options]\n"
    "  --wavelength-nm L     vacuum wavelength (default 632.991)\n"
    "  --temp-c T            air temperature, degC (default 20)\n"
    "  --pressure-pa P       air pressure, Pa (default 101325)\n"
    "  --pressure-kpa P      air pressure, kPa (instead of --pressure-pa)\n"
    "  --rh H                relative humidity, % (default 50)\n"
    "  --co2-ppm C           CO2, umol/mol (default 450; Ciddor only)\n"
    "  --material NAME       workpiece material preset (steel, cast-iron, aluminium, granite, invar)\n"
    "  --alpha-ppm X         workpiece expansion coefficient, ppm/degC (instead of --material)\n"
    "  --material-temp-c TM  workpiece temperature, degC (default: the air temperature)\n"
    "  --origin-um U         thermal origin (zero-correction point, K168), um (default 0)\n"
    "  --equation E          edlen or ciddor: the index used for the register (default ciddor)\n"
    "  --regs-out FILE       also write the register writes to FILE, one `offset name value` per line\n"
    "ranges: Ciddor 300..1700 nm, -40..100 degC, 10..140 kPa; modified Edlen 350..650 nm, 0..40 degC,\n"
    "        60..120 kPa; RH 0..100 %; CO2 0..2000 umol/mol; workpiece -20..80 degC, |alpha| <= 300 ppm/degC\n";

namespace {


void print_index(FILE* out, const char* label, const lxt::air_index_result& r, double u95) {
    if (r.ok) std::fprintf(out, "    %-16s n = %.10f   (n - 1 = %.4f ppm, equation U95 %.1e)\n", label, r.n, (r.n - 1.0) * 1e6, u95);
    else std::fprintf(out, "    %-16s not evaluated: %s\n", label, r.error.c_str());
}

}  // namespace

int cmd_compensate(const std::vector<std::string>& args, size_t first) { return cmd_compensate(args, first, stdout, stderr); }

int cmd_compensate(const std::vector<std::string>& args, size_t first, FILE* out, FILE* err) {
    comp_inputs in;
    std::string material, regs_out;
    bool have_alpha = false, have_mtemp = false, have_pa = false, have_kpa = false, have_co2 = false;
    // ranges here only keep every conversion defined; compute_compensation() then applies the
    // validity ranges of the air equations and reports anything outside them
    cli cl("laserax compensate", args, first, kCompensateUsage, out, err);
    while (cl.next()) {
        if (cl.is("--wavelength-nm")) cl.get_real(0.0, 1e5, &in.wavelength_nm, true, false);
        else if (cl.is("--temp-c")) cl.get_real(-273.15, 1000.0, &in.air_temp_c);
        else if (cl.is("--pressure-pa")) have_pa = cl.get_real(0.0, 1e7, &in.pressure_pa, true, false);
        else if (cl.is("--pressure-kpa")) {
            double kpa = 0;
            if (cl.get_real(0.0, 1e4, &kpa, true, false)) {
                in.pressure_pa = kpa * 1e3;
                have_kpa = true;
            }
        } else if (cl.is("--rh")) cl.get_real(0.0, 100.0, &in.rh_percent);
        else if (cl.is("--co2-ppm")) have_co2 = cl.get_real(0.0, 1e6, &in.co2_ppm);
        else if (cl.is("--alpha-ppm")) have_alpha = cl.get_real(-1e3, 1e3, &in.alpha_ppm_per_c);
        else if (cl.is("--material-temp-c")) have_mtemp = cl.get_real(-273.15, 1000.0, &in.material_temp_c);
        else if (cl.is("--origin-um")) cl.get_real(-1e9, 1e9, &in.origin_um);
        else if (cl.is("--material")) cl.get_text(&material);
        else if (cl.is("--regs-out")) cl.get_text(&regs_out);
        else if (cl.is("--equation")) {
            std::string e;
            if (cl.get_choice({"edlen", "ciddor"}, &e))
                in.equation = e == "edlen" ? lxt::air_equation::edlen : lxt::air_equation::ciddor;
        } else cl.unknown();
    }
    if (cl.failed()) return cl.status();
    if (have_pa && have_kpa) {
        std::fprintf(err, "laserax compensate: give the pressure once (--pressure-pa or --pressure-kpa)\n");
        return 2;
    }
    if (have_alpha && !material.empty()) {
        std::fprintf(err, "laserax compensate: give either --material or --alpha-ppm, not both\n");
        return 2;
    }
    std::string mat_label = "none (no expansion correction)";
    if (!material.empty()) {
        const lxt::material_preset* m = lxt::find_material(material);
        if (!m) {
            std::fprintf(err, "laserax compensate: unknown material '%s' (known: %s; or use --alpha-ppm)\n",
                         material.c_str(), lxt::material_names().c_str());
            return 2;
        }
        in.alpha_ppm_per_c = m->alpha_ppm_per_c;
        mat_label = m->name;
    } else if (have_alpha) {
        mat_label = "user alpha";
    }
    if (!have_mtemp) in.material_temp_c = (!material.empty() || have_alpha) ? in.air_temp_c : 20.0;

    // the registers through the host helper (regmap.h): a reset image with ratio and comp_offset
    reg_image img;
    comp_outputs c;
    std::string cerr;
    if (!apply_compensation(in, &img, &c, &cerr)) {
        std::fprintf(err, "laserax compensate: %s\n", cerr.c_str());
        return 2;
    }
    const std::vector<reg_write> writes = compensation_writes(img);
    if (!regs_out.empty()) {
        FILE* f = std::fopen(regs_out.c_str(), "w");
        const std::string text = format_writes(writes);
        const bool ok = f != nullptr && std::fwrite(text.data(), 1, text.size(), f) == text.size();
        if ((f != nullptr && std::fclose(f) != 0) || !ok) {
            std::fprintf(err, "laserax compensate: cannot write %s\n", regs_out.c_str());
            return 2;
        }
    }
    lxt::air_input ai;
    ai.wavelength_nm = in.wavelength_nm;
    ai.temp_c = in.air_temp_c;
    ai.pressure_pa = in.pressure_pa;
    ai.rh_percent = in.rh_percent;
    ai.co2_ppm = in.co2_ppm;

    std::fprintf(out, "laserax compensate: vacuum wavelength %.6g nm; air %g degC, %.6g Pa, %g %%RH, CO2 %g umol/mol\n",
                 in.wavelength_nm, in.air_temp_c, in.pressure_pa, in.rh_percent, in.co2_ppm);
    std::fprintf(out, "  water vapour: saturation %.2f Pa, partial %.2f Pa\n", c.ciddor.ok ? c.ciddor.psv_pa : c.edlen.psv_pa,
                 c.ciddor.ok ? c.ciddor.pv_pa : c.edlen.pv_pa);
    std::fprintf(out, "  refractive index of air\n");
    print_index(out, "Ciddor", c.ciddor, lxt::ciddor_expanded_uncertainty(ai));
    print_index(out, "modified Edlen", c.edlen, lxt::edlen_expanded_uncertainty(ai));
    if (c.ciddor.ok && c.edlen.ok)
        std::fprintf(out, "    Edlen - Ciddor   %+.2f ppb (parts in 10^9)\n", (c.edlen.n - c.ciddor.n) * 1e9);
    std::fprintf(out, "    used             %s\n", lxt::air_equation_name(in.equation));
    if (have_co2 && in.equation == lxt::air_equation::edlen)
        std::fprintf(out, "    note: the Edlen equation is fixed at 450 umol/mol CO2; --co2-ppm only affects Ciddor\n");
    std::fprintf(out, "  workpiece: %s, alpha %.3f ppm/degC, at %.3f degC, origin %g um\n", mat_label.c_str(),
                 static_cast<double>(c.thermal.alpha_e9) / 1e3, static_cast<double>(c.thermal.temp_mc) / 1e3, in.origin_um);
    std::fprintf(out, "  compensation relative to lambda_vac / 78.125 nm (%.9f output counts per raw count):\n",
                 in.wavelength_nm / kOutputCountNmComp);
    std::fprintf(out, "    air (1/n - 1)           %+12.5f ppm\n", c.air_ppm);
    std::fprintf(out, "    expansion alpha(20-T)   %+12.5f ppm\n", c.expansion_ppm);
    std::fprintf(out, "    total (1+g)/n - 1       %+12.5f ppm   (register applies %+.5f ppm)\n", c.total_ppm, c.register_ppm);
    std::fprintf(out, "  ratio register (Q5.32)    %llu  (0x%llX) = %.10Lf output counts per raw count\n",
                 static_cast<unsigned long long>(c.ratio), static_cast<unsigned long long>(c.ratio),
                 scale_from_ratio(c.ratio, in.wavelength_nm).scale);
    std::fprintf(out, "  comp_offset (Q32.32)      %lld  (%.6Lf output counts = -K168 * K169 * 1e-5)\n",
                 static_cast<long long>(c.comp_offset), static_cast<long double>(c.comp_offset) / 4294967296.0L);
    std::fprintf(out, "  ETEL encoder scaling: K168 = %lld counts (%.4f um), K169 = %.7f (units of 1e-5)\n",
                 static_cast<long long>(c.scaling.k168), static_cast<double>(c.scaling.k168) * kOutputCountNmComp / 1000.0,
                 lxt::k169_value(c.scaling));
    if (std::fabs(static_cast<double>(c.scaling.k168) - c.origin_counts_exact) > 1e-9)
        std::fprintf(out, "    note: origin rounded to a whole count (%.4f -> %lld)\n", c.origin_counts_exact,
                     static_cast<long long>(c.scaling.k168));
    std::fprintf(out, "  register writes (docs/REGISTERS.md, low word first)%s%s:\n",
                 regs_out.empty() ? "" : ", also in ", regs_out.c_str());
    for (const reg_write& w : writes)
        std::fprintf(out, "    0x%04X  %-20s 0x%08X\n", w.offset, w.name.c_str(), w.value);
    return 0;
}

}  // namespace lxt
