// laserax — command-line front end of the laser axis interface models.
//
//   laserax [run] [options]     homing scenario (default): event table, out/trace.csv,
//                               out/trace.vcd, out/events.csv, out/homing.png
//   laserax vectors [--out DIR] golden vectors (CSV + $readmemh hex) for every block and the chain
//   laserax help
#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "tools/laserax/cli_util.h"
#include "tools/laserax/compensate_cmd.h"
#include "host/compensation.h"
#include "tools/laserax/counters_cmd.h"
#include "tools/laserax/gantry_cmd.h"
#include "sysmodel/homing.h"
#include "tools/laserax/pacing_cli.h"
#include "tools/laserax/pso_cmd.h"
#include "tools/laserax/trace.h"
#include "tools/laserax/vectors.h"

namespace {

const char* kUsage =
    "usage: laserax [run] [options]\n"
    "       laserax vectors [--out DIR] [--seed N] [--calls N] [controller options]   (--help)\n"
    "       laserax compensate [--temp-c T] [--pressure-kpa P] [--rh RH] [--material M] ...  (--help)\n"
    "       laserax pso [options] | laserax counters [options] | laserax gantry [options]   (--help for each)\n"
    "run options:\n"
    "  --pitch-um U      sin/cos period in um, a multiple of 8 counts of 78.125 nm, 0.625..320\n"
    "                    (e.g. 20, 25, 40, 50, 100; default 20 = 256 counts)\n"
    "  --period P        period in output counts (8..4096, multiple of 8); overrides --pitch-um\n"
    "  --dir D           homing direction, +1 or -1 (default +1)\n"
    "  --speed MM_S      homing speed in mm/s, 0.01..1000 (default 5)\n"
    "  --air-index N     refractive index of air, [1, 1.01) (default 1.000271)\n"
    "  --air-temp-c T, --pressure-kpa P, --rh H       air for the Ciddor equation (sets the index)\n"
    "  --alpha-ppm A, --material-temp-c TM           workpiece expansion folded into the ratio\n"
    "  --origin-um X     thermal origin (K168) from raw count 0, written to the comp_offset register\n"
    "  --air-temp-c -40..100, --pressure-kpa 10..200, --rh 0..100, --alpha-ppm -100..100,\n"
    "  --material-temp-c -40..100, --origin-um -1e6..1e6\n"
    "  --ratio R         ratio register, Q5.32 integer 1..2^37-1 (default from the air index)\n"
    "  --seed S          power-up position and fringe phase, 0..2^64-1 (default 1)\n"
    "  --cycles N        stop after N clocks, 1..50000000 (default: when the run is complete;\n"
    "                    a run stops at 50000000 clocks in any case)\n"
    "  --bounce-nm X     switch contact bounce zone, 0..1e6 (default 0)\n"
    "  --pace-m M        pace_m register: output counts at least M clocks apart, 2..65535\n"
    "                    (default 61, the register's reset value)\n"
    "  --out DIR         output folder (default out)\n"
    "  --every-clock     trace.csv gets a row for every clock\n"
    "  --no-plot         do not call the plotting script\n"
    "controller options (run and vectors):\n";

std::string usage_text() { return std::string(kUsage) + lxt::kControllerUsage; }

// The run's cycle cap: a homing run stops after at most this many clocks (0.5 s at 100 MHz).
constexpr long long kMaxCycles = 50000000;

int cmd_run(const std::vector<std::string>& argv, size_t first, const std::string& cmdline) {
    lxt::homing_params p;
    std::string out = "out";
    bool every = false, plot = true;
    lxt::comp_inputs env;
    bool use_env = false;
    lxt::controller_opts ctl;
    lxt::cli c("laserax run", argv, first, usage_text());
    bool have_period = false, have_ratio = false;
    double pitch_um = 0;
    bool have_pitch = false;
    while (c.next()) {
        if (c.is("--pitch-um")) have_pitch = c.get_real(0.625, 320.0, &pitch_um);
        else if (c.is("--period")) have_period = c.get_int(8, 4096, &p.period, 8);
        else if (c.is("--dir")) {
            std::string d;
            if (c.get_choice({"+1", "1", "-1"}, &d)) p.dir = d == "-1" ? -1 : 1;
        } else if (c.is("--speed")) c.get_real(0.01, 1000.0, &p.speed_mm_s);
        else if (c.is("--air-index")) c.get_real(1.0, 1.01, &p.air_index, false, true);
        else if (c.is("--air-temp-c")) use_env = c.get_real(-40.0, 100.0, &env.air_temp_c) || use_env;
        else if (c.is("--pressure-kpa")) {
            double kpa = 0;
            if (c.get_real(10.0, 200.0, &kpa)) {
                env.pressure_pa = 1000.0 * kpa;
                use_env = true;
            }
        } else if (c.is("--rh")) use_env = c.get_real(0.0, 100.0, &env.rh_percent) || use_env;
        else if (c.is("--alpha-ppm")) use_env = c.get_real(-100.0, 100.0, &env.alpha_ppm_per_c) || use_env;
        else if (c.is("--material-temp-c")) use_env = c.get_real(-40.0, 100.0, &env.material_temp_c) || use_env;
        else if (c.is("--origin-um")) use_env = c.get_real(-1e6, 1e6, &env.origin_um) || use_env;
        else if (c.is("--ratio")) have_ratio = c.get_u64(1, (uint64_t(1) << 37) - 1, &p.ratio);
        else if (c.is("--seed")) c.get_u64(0, UINT64_MAX, &p.seed);
        else if (c.is("--cycles")) c.get_int(1, kMaxCycles, &p.max_cycles);
        else if (c.is("--bounce-nm")) c.get_real(0.0, 1e6, &p.bounce_nm);
        else if (c.is("--pace-m")) c.get_int(2, 65535, &p.pace_m);
        else if (lxt::parse_controller_option(c, &ctl)) continue;
        else if (c.is("--out")) c.get_text(&out);
        else if (c.is("--every-clock")) every = true;
        else if (c.is("--no-plot")) plot = false;
        else c.unknown();
    }
    if (c.failed()) return c.status();
    if (have_pitch && !have_period) {
        const double counts = pitch_um * 1000.0 / lxt::kOutputCountNm;  // 1 .. 4096: fits an int
        if (counts != std::floor(counts) || static_cast<int>(counts) % 8 != 0 || counts < 8) {
            std::fprintf(stderr,
                         "laserax run: --pitch-um: %g um is not a legal period (allowed: a multiple of 8 counts of "
                         "78.125 nm, 0.625 .. 320 um)\n",
                         pitch_um);
            return 2;
        }
        p.period = static_cast<int>(counts);
    }
    if (p.max_cycles == 0) p.max_cycles = kMaxCycles;  // the cap (the user cannot pass 0)
    if (p.period < 8 || p.period > 4096 || p.period % 8 != 0) {
        std::fprintf(stderr, "laserax: period %d invalid: must be 8..4096 and a multiple of 8\n", p.period);
        return 2;
    }
    if (p.dir != 1 && p.dir != -1) {
        std::fprintf(stderr, "laserax: --dir must be +1 or -1\n");
        return 2;
    }
    if (!(p.speed_mm_s > 0 && p.speed_mm_s <= 1000)) {
        std::fprintf(stderr, "laserax: --speed must be in (0, 1000] mm/s\n");
        return 2;
    }
    lxt::comp_outputs comp;
    if (use_env) {
        comp = lxt::compute_compensation(env);
        if (!comp.ok) {
            std::fprintf(stderr, "laserax: environment rejected: %s\n", comp.error.c_str());
            return 2;
        }
        p.air_index = comp.n;
        if (!have_ratio) p.ratio = comp.ratio;
        p.comp_offset = comp.comp_offset;
    }
    if (!(p.air_index >= 1.0 && p.air_index < 1.01)) {
        std::fprintf(stderr, "laserax: --air-index must be in [1, 1.01)\n");
        return 2;
    }
    const int pace_rc = lxt::check_controller_pacing("laserax run", ctl, p.pace_m, p.clock_hz / 1e6,
                                                     "--pace-m " + std::to_string(p.pace_m),
                                                     "use a larger --pace-m, or --force-pace");
    if (pace_rc != 0) return pace_rc;
    if (!lxt::make_dirs(out, "laserax")) return 1;
    lxt::trace_writer tw;
    std::string err;
    if (!tw.open(out, every, p.period, cmdline, &err)) {
        std::fprintf(stderr, "laserax: %s\n", err.c_str());
        return 1;
    }
    const lxt::homing_result r = lxt::run_homing(p, [&](const lxt::trace_row& row) { tw.add(row); });
    tw.close();

    const double count_um = lxt::kOutputCountNm / 1000.0;
    std::printf("laserax homing: period %d counts (%.3f um), direction %+d, %.3g mm/s, pace_m %d, seed %llu\n",
                p.period, p.period * count_um, p.dir, p.speed_mm_s, p.pace_m, static_cast<unsigned long long>(p.seed));
    std::printf("  raw count %.4f nm (air index %.7f), ratio register %llu (%.9f output counts per raw count)\n",
                r.lambda_nm, p.air_index, static_cast<unsigned long long>(r.ratio), static_cast<double>(r.ratio) / 4294967296.0);
    if (use_env)
        std::printf("  environment: air %.2f degC, %.3f kPa, %.1f %%RH -> n = %.9f (Ciddor), air %+.4f ppm; workpiece "
                    "alpha %.2f ppm/degC at %.2f degC -> %+.4f ppm; total %+.4f ppm; origin %g um -> comp_offset %lld "
                    "(%+.4f counts)\n",
                    env.air_temp_c, env.pressure_pa / 1000.0, env.rh_percent, comp.n, comp.air_ppm, env.alpha_ppm_per_c,
                    env.material_temp_c, comp.expansion_ppm, comp.total_ppm, env.origin_um,
                    static_cast<long long>(comp.comp_offset), static_cast<double>(comp.comp_offset) / 4294967296.0);
    std::printf("  power-up %.1f nm before the switch, %lld clocks simulated (%.3f ms at %.0f MHz)\n",
                -p.dir * r.start_nm, r.cycles, static_cast<double>(r.cycles) / p.clock_hz * 1e3, p.clock_hz / 1e6);
    std::printf("\n  %-5s %10s %14s %12s %12s %12s %10s\n", "event", "cycle", "true_nm", "real_counts", "real_um",
                "ctrl_counts", "from_A");
    int64_t a_paced = r.events[0].paced, a_out = r.events[0].out_pos;
    FILE* ev = std::fopen((out + "/events.csv").c_str(), "w");
    if (ev) std::fprintf(ev, "# laserax homing events. Command: %s\nevent,cycle,paced_pos,out_pos,true_nm\n", cmdline.c_str());
    bool ok = r.mismatch.empty();
    for (const lxt::homing_event& e : r.events) {
        if (e.cycle < 0) {
            std::printf("  %-5s %10s  (not reached)\n", e.name.c_str(), "-");
            ok = false;
            continue;
        }
        std::printf("  %-5s %10lld %14.1f %12lld %12.4f %12lld %+10lld\n", e.name.c_str(), e.cycle, e.true_nm,
                    static_cast<long long>(e.paced), static_cast<double>(e.paced) * count_um, static_cast<long long>(e.out_pos),
                    static_cast<long long>(p.dir * (e.paced - a_paced)));
        if (ev) std::fprintf(ev, "%s,%lld,%lld,%lld,%.3f\n", e.name.c_str(), e.cycle, static_cast<long long>(e.paced),
                             static_cast<long long>(e.out_pos), e.true_nm);
    }
    if (ev) std::fclose(ev);
    const bool z_ok = r.events[2].cycle >= 0 && p.dir * (r.events[2].paced - a_paced) == p.period + p.period / 4;
    std::printf("\n  rephase d = %lld counts; the controller counted %lld counts from A to B for %d real counts\n",
                static_cast<long long>(r.d), static_cast<long long>(p.dir * (r.events[1].out_pos - a_out)), p.period);
    std::printf("  at Z: sin %lld, cos %lld, reference mark %d -> %s\n", static_cast<long long>(r.sin_at_z),
                static_cast<long long>(r.cos_at_z), r.mark_at_z ? 1 : 0,
                (r.sin_at_z == r.cos_at_z && r.sin_at_z > 0 && r.mark_at_z) ? "sin == cos > 0, mark active" : "WRONG");
    std::printf("  Z - A = %lld counts (%s)\n", static_cast<long long>(p.dir * (r.events[2].paced - a_paced)),
                z_ok ? "= P + P/4" : "WRONG");
    std::printf("  hls vs golden: %s\n", r.mismatch.empty() ? "bit-exact on every clock" : r.mismatch.c_str());
    std::printf("  wrote %s/trace.csv (%lld rows), %s/trace.vcd, %s/events.csv\n", out.c_str(), tw.csv_rows(), out.c_str(),
                out.c_str());
    ok = ok && z_ok && r.sin_at_z == r.cos_at_z && r.mark_at_z;
    if (plot) {
        const std::string py = "/usr/bin/python3";
        struct stat st;
        if (stat(py.c_str(), &st) == 0) {
            const std::string plot_cmd = py + " scripts/plot_homing.py " + out + "/trace.csv " + out + "/homing.png";
            std::fflush(stdout);
            if (std::system(plot_cmd.c_str()) == 0) std::printf("  wrote %s/homing.png\n", out.c_str());
            else std::printf("  plot skipped (scripts/plot_homing.py failed; run `make deps`)\n");
        } else {
            std::printf("  plot skipped: /usr/bin/python3 not found (apt-get install python3-matplotlib)\n");
        }
    }
    return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    struct {
        std::vector<std::string> v;
        size_t i = 0;
    } a;
    std::string cmdline = "laserax";
    for (int i = 1; i < argc; ++i) {
        a.v.push_back(argv[i]);
        cmdline += std::string(" ") + argv[i];
    }
    std::string cmd = "run";
    if (!a.v.empty() && a.v[0].rfind("--", 0) != 0) cmd = a.v[a.i++];
    if (cmd == "run") return cmd_run(a.v, a.i, cmdline);
    if (cmd == "vectors") return lxt::cmd_vectors(a.v, a.i, cmdline);
    if (cmd == "compensate") return lxt::cmd_compensate(a.v, a.i);
    if (cmd == "pso") return lxt::cmd_pso(a.v, a.i);
    if (cmd == "counters") return lxt::cmd_counters(a.v, a.i);
    if (cmd == "gantry") return lxt::cmd_gantry(a.v, a.i);
    if (cmd == "help" || cmd == "-h" || cmd == "--help") {
        std::printf("%s", usage_text().c_str());
        return 0;
    }
    std::fprintf(stderr, "laserax: unknown command '%s'\n%s", cmd.c_str(), usage_text().c_str());
    return 2;
}
