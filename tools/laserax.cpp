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

#include "tools/common/cli_util.h"
#include "tools/common/compensate_cmd.h"
#include "tools/common/compensation.h"
#include "tools/common/counters_cmd.h"
#include "tools/common/gantry_cmd.h"
#include "tools/common/homing.h"
#include "tools/common/pso_cmd.h"
#include "tools/common/trace.h"
#include "tools/common/vectors.h"

namespace {

const char* kUsage =
    "usage: laserax [run] [options]\n"
    "       laserax vectors [--out DIR] [--seed N] [--calls N]\n"
    "       laserax compensate [--temp-c T] [--pressure-kpa P] [--rh RH] [--material M] ...  (--help)\n"
    "       laserax pso [options] | laserax counters [options] | laserax gantry [options]   (--help for each)\n"
    "run options:\n"
    "  --pitch-um U      sin/cos period in um: 20, 25, 40, 50, 100 (default 20 = 256 counts)\n"
    "  --period P        period in output counts (8..4096, multiple of 8); overrides --pitch-um\n"
    "  --dir D           homing direction, +1 or -1 (default +1)\n"
    "  --speed MM_S      homing speed in mm/s (default 5)\n"
    "  --air-index N     refractive index of air (default 1.000271)\n"
    "  --air-temp-c T, --pressure-kpa P, --rh H       air for the Ciddor equation (sets the index)\n"
    "  --alpha-ppm A, --material-temp-c TM           workpiece expansion folded into the ratio\n"
    "  --origin-um X     thermal origin (K168) from raw count 0, written to the comp_offset register\n"
    "  --ratio R         ratio register, Q5.32 integer (default from the air index)\n"
    "  --seed S          power-up position and fringe phase (default 1)\n"
    "  --cycles N        stop after N clocks (default: when the run is complete)\n"
    "  --bounce-nm X     switch contact bounce zone (default 0)\n"
    "  --out DIR         output folder (default out)\n"
    "  --every-clock     trace.csv gets a row for every clock\n"
    "  --no-plot         do not call the plotting script\n";


struct args {
    std::vector<std::string> v;
    size_t i = 0;
    bool more() const { return i < v.size(); }
    std::string next(const std::string& opt) {
        if (i >= v.size()) {
            std::fprintf(stderr, "laserax: %s needs a value\n%s", opt.c_str(), kUsage);
            std::exit(2);
        }
        return v[i++];
    }
};

double to_double(const std::string& s, const std::string& opt) {
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0' || !std::isfinite(x)) {
        std::fprintf(stderr, "laserax: %s: not a number: '%s'\n", opt.c_str(), s.c_str());
        std::exit(2);
    }
    return x;
}

long long to_ll(const std::string& s, const std::string& opt) {
    char* end = nullptr;
    errno = 0;
    const long long x = std::strtoll(s.c_str(), &end, 0);
    if (end == s.c_str() || *end != '\0' || errno != 0) {
        std::fprintf(stderr, "laserax: %s: not an integer: '%s'\n", opt.c_str(), s.c_str());
        std::exit(2);
    }
    return x;
}

int cmd_run(args& a, const std::string& cmdline) {
    lxt::homing_params p;
    std::string out = "out";
    bool every = false, plot = true;
    lxt::comp_inputs env;
    bool use_env = false;
    while (a.more()) {
        const std::string o = a.next("");
        if (o == "--pitch-um") {
            const double um = to_double(a.next(o), o);
            const double counts = um * 1000.0 / lxt::kOutputCountNm;
            if (counts != std::floor(counts)) {
                std::fprintf(stderr, "laserax: --pitch-um %g is not a whole number of 78.125 nm counts\n", um);
                return 2;
            }
            p.period = static_cast<int>(counts);
        } else if (o == "--period") p.period = static_cast<int>(to_ll(a.next(o), o));
        else if (o == "--dir") p.dir = static_cast<int>(to_ll(a.next(o), o));
        else if (o == "--speed") p.speed_mm_s = to_double(a.next(o), o);
        else if (o == "--air-index") p.air_index = to_double(a.next(o), o);
        else if (o == "--air-temp-c") { env.air_temp_c = to_double(a.next(o), o); use_env = true; }
        else if (o == "--pressure-kpa") { env.pressure_pa = 1000.0 * to_double(a.next(o), o); use_env = true; }
        else if (o == "--rh") { env.rh_percent = to_double(a.next(o), o); use_env = true; }
        else if (o == "--alpha-ppm") { env.alpha_ppm_per_c = to_double(a.next(o), o); use_env = true; }
        else if (o == "--material-temp-c") { env.material_temp_c = to_double(a.next(o), o); use_env = true; }
        else if (o == "--origin-um") { env.origin_um = to_double(a.next(o), o); use_env = true; }
        else if (o == "--ratio") p.ratio = static_cast<uint64_t>(to_ll(a.next(o), o));
        else if (o == "--seed") p.seed = static_cast<uint64_t>(to_ll(a.next(o), o));
        else if (o == "--cycles") p.max_cycles = to_ll(a.next(o), o);
        else if (o == "--bounce-nm") p.bounce_nm = to_double(a.next(o), o);
        else if (o == "--out") out = a.next(o);
        else if (o == "--every-clock") every = true;
        else if (o == "--no-plot") plot = false;
        else {
            std::fprintf(stderr, "laserax: unknown option '%s'\n%s", o.c_str(), kUsage);
            return 2;
        }
    }
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
        if (p.ratio == 0) p.ratio = comp.ratio;
        p.comp_offset = comp.comp_offset;
    }
    if (!(p.air_index >= 1.0 && p.air_index < 1.01)) {
        std::fprintf(stderr, "laserax: --air-index must be in [1, 1.01)\n");
        return 2;
    }
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
    std::printf("laserax homing: period %d counts (%.3f um), direction %+d, %.3g mm/s, seed %llu\n", p.period,
                p.period * count_um, p.dir, p.speed_mm_s, static_cast<unsigned long long>(p.seed));
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
            const std::string c = py + " scripts/plot_homing.py " + out + "/trace.csv " + out + "/homing.png";
            std::fflush(stdout);
            if (std::system(c.c_str()) == 0) std::printf("  wrote %s/homing.png\n", out.c_str());
            else std::printf("  plot skipped (scripts/plot_homing.py failed; run `make deps`)\n");
        } else {
            std::printf("  plot skipped: /usr/bin/python3 not found (apt-get install python3-matplotlib)\n");
        }
    }
    return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    args a;
    std::string cmdline = "laserax";
    for (int i = 1; i < argc; ++i) {
        a.v.push_back(argv[i]);
        cmdline += std::string(" ") + argv[i];
    }
    std::string cmd = "run";
    if (a.more() && a.v[0].rfind("--", 0) != 0) cmd = a.next("");
    if (cmd == "run") return cmd_run(a, cmdline);
    if (cmd == "vectors") return lxt::cmd_vectors(a.v, a.i, cmdline);
    if (cmd == "compensate") return lxt::cmd_compensate(a.v, a.i);
    if (cmd == "pso") return lxt::cmd_pso(a.v, a.i);
    if (cmd == "counters") return lxt::cmd_counters(a.v, a.i);
    if (cmd == "gantry") return lxt::cmd_gantry(a.v, a.i);
    if (cmd == "help" || cmd == "-h" || cmd == "--help") {
        std::printf("%s", kUsage);
        return 0;
    }
    std::fprintf(stderr, "laserax: unknown command '%s'\n%s", cmd.c_str(), kUsage);
    return 2;
}
