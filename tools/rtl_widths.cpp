// rtl_widths — writes rtl_ref/laserax_widths.vh, the port and datapath widths of the reference RTL
// as Verilog macros, taken from the configuration structs of hls/ (the one place where the
// widths are written; DESIGN.md §3). Every rtl_ref/ block includes the header and declares its
// ports with these macros, so a width changed in hls/ reaches the RTL by regenerating this file
// (tb_generated_files checks that the committed header is what this program writes now, and
// scripts/check_rtl_widths.py that no rtl_ref/ port is declared with a literal width).
//   rtl_widths --out FILE      (the command line is recorded in the header)
#include <fstream>
#include <iostream>
#include <string>

#include "hls/axis_config.h"
#include "hls/dds_sincos.h"
#include "hls/encoder_counter.h"
#include "hls/error_map.h"
#include "hls/laserax_top.h"
#include "hls/output_pacer.h"
#include "hls/pso.h"
#include "hls/pulse_multiplier.h"
#include "hls/quad_decoder.h"
#include "hls/rephase.h"

namespace {

struct writer {
    std::ostream& os;
    void group(const char* title) { os << "\n// " << title << "\n"; }
    // `define LX_<name> <value>  // <source>
    void def(const std::string& name, long long value, const std::string& source) {
        std::string line = "`define LX_" + name + " " + std::to_string(value);
        if (line.size() < 40) line.resize(40, ' ');
        os << line << " // " << source << "\n";
    }
};

void write(std::ostream& os, const std::string& command) {
    using lx::axis_widths;
    os << "// laserax_widths.vh — widths of the rtl_ref/ ports and datapaths, from the configuration\n"
          "// structs of hls/ (DESIGN.md §3; each macro names its source).\n"
          "// GENERATED FILE, do not edit. Command: "
       << command
       << "\n"
          "// Every rtl_ref/ block includes it (`include \"laserax_widths.vh\", found next to the\n"
          "// including file: Yosys by default, Icarus with -grelative-include).\n"
          "`ifndef LASERAX_WIDTHS_VH\n"
          "`define LASERAX_WIDTHS_VH\n";
    writer w{os};
    w.group("chain (lx::axis_widths)");
    w.def("W_STEP", 2, "lx::step_t: -1, 0, +1");
    w.def("W_RAW", axis_widths::W_RAW, "axis_widths::W_RAW: raw laser count");
    w.def("R_FRAC", axis_widths::R_FRAC, "axis_widths::R_FRAC: ratio fraction bits");
    w.def("W_RATIO", axis_widths::W_RATIO, "axis_widths::W_RATIO: ratio Q5.32");
    w.def("W_ACC", axis_widths::W_ACC, "axis_widths::W_ACC: exact N*R + OFF");
    w.def("W_OFFSET", axis_widths::W_OFFSET, "axis_widths::W_OFFSET: comp offset Q32.32");
    w.def("W_POS", axis_widths::W_POS, "axis_widths::W_POS: positions, output counts");
    w.def("W_DELTA", axis_widths::W_DELTA, "axis_widths::W_DELTA: comp(t) - comp(t-1)");
    w.def("W_BACKLOG", axis_widths::W_BACKLOG, "axis_widths::W_BACKLOG: pacer backlog");
    w.def("W_P", axis_widths::W_P, "axis_widths::W_P: period register");
    w.def("W_PH", axis_widths::W_PH, "axis_widths::W_PH: phase 0..P-1");
    w.def("W_TBL", axis_widths::W_TBL, "axis_widths::W_TBL: DDS table word");
    w.def("W_TBL_ADDR", axis_widths::W_TBL_ADDR, "axis_widths::W_TBL_ADDR: DDS table address");
    w.def("W_DAC", axis_widths::W_DAC_MAX, "axis_widths::W_DAC_MAX: sin/cos codes");
    w.def("W_DACW", axis_widths::W_DACW, "axis_widths::W_DACW: dac_width register");
    w.group("quad_decoder (lx::quad_decoder_cfg)");
    w.def("QD_W_GLITCH", lx::quad_decoder_cfg::W_GLITCH, "quad_decoder_cfg::W_GLITCH");
    w.def("QD_W_SPACING", lx::quad_decoder_cfg::W_SPACING, "quad_decoder_cfg::W_SPACING");
    w.def("QD_W_ERRCNT", lx::quad_decoder_cfg::W_ERRCNT, "quad_decoder_cfg::W_ERRCNT");
    w.group("output_pacer (lx::output_pacer_cfg)");
    w.def("OP_W_PACE", lx::output_pacer_cfg::W_PACE, "output_pacer_cfg::W_PACE");
    w.def("OP_W_THR", lx::output_pacer_cfg::W_THR, "output_pacer_cfg::W_THR");
    w.def("OP_W_ADD", lx::output_pacer_cfg::W_ADD, "output_pacer_cfg::W_ADD: error-map delta");
    w.group("error_map (lx::error_map_cfg)");
    w.def("EM_W_K", lx::error_map_cfg::W_K, "error_map_cfg::W_K: spacing_log2 register");
    w.def("EM_W_N", lx::error_map_cfg::W_N, "error_map_cfg::W_N: n_points register");
    w.def("EM_W_ADDR", lx::error_map_cfg::W_ADDR, "error_map_cfg::W_ADDR: table address");
    w.def("EM_W_CORR", lx::error_map_cfg::W_CORR, "error_map_cfg::W_CORR: table word");
    w.def("EM_W_C", lx::error_map_cfg::W_C, "error_map_cfg::W_C: correction");
    w.def("EM_W_CDELTA", lx::error_map_cfg::W_CDELTA, "error_map_cfg::W_CDELTA: corr' - corr");
    w.group("rephase (lx::rephase_cfg)");
    w.def("W_STAGE", lx::rephase_cfg::W_STAGE, "rephase_cfg::W_STAGE: stage output");
    w.group("dds_sincos (lx::dds_sincos_cfg)");
    w.def("DDS_W_AMP", lx::dds_sincos_cfg::W_AMP, "dds_sincos_cfg::W_AMP: amplitude register");
    w.def("DDS_W_R", lx::dds_sincos_cfg::W_R, "dds_sincos_cfg::W_R: r and P/4 - r");
    w.group("laserax_top (lx::laserax_top_cfg)");
    w.def("TOP_W_DEBOUNCE", lx::laserax_top_cfg::W_DEBOUNCE, "laserax_top_cfg::W_DEBOUNCE");
    w.def("TOP_W_PIN_CFG", lx::laserax_top_cfg::W_PIN_CFG, "laserax_top_cfg::W_PIN_CFG: pin_cfg register");
    w.group("encoder_counter (lx::encoder_counter_cfg)");
    w.def("EC_W_CNT", lx::encoder_counter_cfg::W_CNT, "encoder_counter_cfg::W_CNT: counters");
    w.def("EC_W_SRC", lx::encoder_counter_cfg::W_SRC, "encoder_counter_cfg::W_SRC: source register");
    w.def("EC_W_INC", lx::encoder_counter_cfg::W_INC, "encoder_counter_cfg::W_INC: simulation rate");
    w.def("EC_W_SCALE", lx::encoder_counter_cfg::W_SCALE, "encoder_counter_cfg::W_SCALE: Q8.24");
    w.def("EC_W_PER", lx::encoder_counter_cfg::W_PER, "encoder_counter_cfg::W_PER: correction period");
    w.def("EC_W_POSIN", lx::encoder_counter_cfg::W_POSIN, "encoder_counter_cfg::W_POSIN");
    w.def("EC_W_CORR", lx::encoder_counter_cfg::W_CORR, "encoder_counter_cfg::W_CORR");
    w.group("pso (lx::pso_cfg)");
    w.def("PSO_N_AXES", lx::pso_cfg::N_AXES, "pso_cfg::N_AXES: axes, axis_mask register");
    w.def("PSO_D_FRAC", lx::pso_cfg::D_FRAC, "pso_cfg::D_FRAC: distance fraction bits");
    w.def("PSO_W_DIST", lx::pso_cfg::W_DIST, "pso_cfg::W_DIST: fire_dist, array entries");
    w.def("PSO_W_REM", lx::pso_cfg::W_REM, "pso_cfg::W_REM: dist, signed");
    w.def("PSO_K_MAX", lx::pso_cfg::K_MAX, "pso_cfg::K_MAX: longest tracking window");
    w.def("PSO_W_K", lx::pso_cfg::W_K, "pso_cfg::W_K: win_k register");
    w.def("PSO_S_MAX", lx::pso_cfg::S_MAX, "pso_cfg::S_MAX: chord ROM, last address");
    w.def("PSO_W_S", lx::pso_cfg::W_S, "pso_cfg::W_S: chord ROM address");
    w.def("PSO_W_CHORD", lx::pso_cfg::W_CHORD, "pso_cfg::W_CHORD: chord ROM word");
    w.def("PSO_W_INCR", lx::pso_cfg::W_INCR, "pso_cfg::W_INCR: estimate step");
    w.def("PSO_W_INC", lx::pso_cfg::W_INC, "pso_cfg::W_INC: part-speed rate Q0.32");
    w.def("PSO_W_ADDR", lx::pso_cfg::W_ADDR, "pso_cfg::W_ADDR: array address");
    w.def("PSO_W_LEN", lx::pso_cfg::W_LEN, "pso_cfg::W_LEN: arr_len register, index");
    w.def("PSO_W_PW", lx::pso_cfg::W_PW, "pso_cfg::W_PW: pulse width register");
    w.def("PSO_W_GAP", lx::pso_cfg::W_GAP, "pso_cfg::W_GAP: min_period register");
    w.def("PSO_W_FCNT", lx::pso_cfg::W_FCNT, "pso_cfg::W_FCNT: emitted-pulse counter");
    w.def("PSO_W_OVL", lx::pso_cfg::W_OVL, "pso_cfg::W_OVL: overlap counter");
    w.def("PSO_W_PROD", lx::pso_cfg::W_PROD, "pso_cfg::W_PROD: inc * min_period");
    w.def("PSO_W_SPHI", lx::pso_cfg::W_SPHI, "pso_cfg::W_SPHI: spacing shift-add upper part");
    w.def("PSO_W_SRC", lx::pso_cfg::W_SRC, "pso_cfg::W_SRC: win_src register");
    os << "\n`endif\n";
}

}  // namespace

int main(int argc, char** argv) {
    std::string out;
    std::string cmd = "rtl_widths";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--out" && i + 1 < argc) {
            out = argv[++i];
            cmd += " --out " + out;
        } else {
            std::cerr << "rtl_widths: unknown argument '" << a << "'\nusage: rtl_widths --out FILE\n";
            return 2;
        }
    }
    if (out.empty()) {
        std::cerr << "usage: rtl_widths --out FILE\n";
        return 2;
    }
    std::ofstream f(out);
    if (!f) {
        std::cerr << "rtl_widths: cannot write " << out << "\n";
        return 1;
    }
    write(f, cmd);
    f.close();
    if (!f) {
        std::cerr << "rtl_widths: write failed: " << out << "\n";
        return 1;
    }
    return 0;
}
