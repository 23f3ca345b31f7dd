// gantry_cmd.cpp — `laserax gantry`, see gantry_cmd.h.
#include "tools/laserax/gantry_cmd.h"

#include "tools/laserax/cli_util.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sstream>

#include "golden/gantry_model.h"
#include "sysmodel/gantry.h"

namespace lxt {

const char* const kGantryUsage =
    "laserax gantry [options]   twin-axis (gantry) referencing with two compensators (docs/GANTRY.md)\n"
    "  --period P          sin/cos period in output counts, 8..4096, multiple of 8 (default 256)\n"
    "  --seed S            random power-up phases of X1 and X2 from seed S, 0..2^63-1 (default 7)\n"
    "  --phase1 N          power-up phase of X1 (output phase at its point A, 0..P-1)\n"
    "  --phase2 N          power-up phase of X2\n"
    "  --skew-limit L      alarm when |skew - offset| > L counts, 0..2^30 (default P)\n"
    "  --offset O          offset parameter (squareness trim), counts, within +-4P; also the real offset of X2's\n"
    "                      switch unless --switch-offset is given (default 0)\n"
    "  --switch-offset O   real offset of X2's reference switch from X1's, counts\n"
    "  --compliance C      0 < C <= 1: share of commanded skew that becomes real skew (default 0.5)\n"
    "  --resolution R      controller interpolation, units per period, P..1048576, multiple of 8\n"
    "                      (default max(2048, P))\n"
    "  --arm MODE          use of rehome: own (default), both, hold (docs/GANTRY.md)\n"
    "  --conventional      conventional encoders (fixed-phase reference mark) instead of the IP\n"
    "  --map-grid N        skew map over N x N power-up phases, 1..4096 (default min(P, 16))\n"
    "  --no-map            no skew map\n"
    "  --no-plot           do not call scripts/plot_gantry.py\n"
    "  --out DIR           output folder (default out)\n";

namespace {




// The differences between a run and the golden model ("" if none).
std::string compare_golden(const lxt::gantry_result& r, const golden::gantry_prediction& g, bool conventional) {
    std::ostringstream e;
    auto ne = [](double a, int64_t b) { return a != static_cast<double>(b); };
    if (!conventional) {
        for (int i = 0; i < 2; ++i) {
            if (ne(g.a[i], r.a[i]) || ne(g.z[i], r.z[i])) e << " X" << i + 1 << " A/Z;";
            bool same = r.homings[i].size() == g.homings[i].size();
            for (size_t k = 0; same && k < r.homings[i].size(); ++k) same = !ne(g.homings[i][k], r.homings[i][k]);
            if (!same) e << " X" << i + 1 << " d;";
        }
    }
    for (int k = 0; k < 3; ++k)
        if (ne(g.rack[k], r.rack[k])) e << " rack " << k + 1 << ";";
    if (ne(g.skew_check, r.skew_check)) e << " skew at the check;";
    if (g.alarm != r.alarm) e << " alarm;";
    if (ne(g.skew_final, r.skew_final)) e << " final skew;";
    if (std::fabs(g.rack_final_nm - r.rack_final_nm) > g.rack_tol_nm + 1e-6) e << " final physical rack;";
    return e.str();
}

void print_table(const lxt::gantry_result& r, int period) {
    std::printf("\n  %-40s %9s | %9s %9s | %9s %9s | %7s %8s | %s\n", "step (settled)", "clock", "X1 ctrl", "X2 ctrl",
                "X1 real", "X2 real", "skew", "rack", "alarm");
    std::printf("  %-40s %9s | %19s | %19s | %7s %8s |\n", "", "", "(controller, counts)", "(physical, counts)",
                "ctrl", "real");
    for (const lxt::gantry_row& w : r.rows) {
        char c1[24], c2[24], sk[24];
        std::snprintf(c1, sizeof c1, "%lld%s", static_cast<long long>(w.ctrl[0]), w.homed[0] ? "" : "*");
        std::snprintf(c2, sizeof c2, "%lld%s", static_cast<long long>(w.ctrl[1]), w.homed[1] ? "" : "*");
        if (w.skew_valid) std::snprintf(sk, sizeof sk, "%lld", static_cast<long long>(w.skew));
        else std::snprintf(sk, sizeof sk, "-");
        std::printf("  %-40s %9lld | %9s %9s | %9.2f %9.2f | %7s %8.2f | %s\n", w.name.c_str(), w.cycle, c1, c2,
                    w.real[0], w.real[1], sk, w.rack, w.kind == lxt::gantry_row::check ? (w.alarm ? "ALARM" : "ok") : "");
    }
    std::printf("  (* = not homed yet: counts since the signal started; real = physical position from the axis' own\n"
                "   home point Z; skew = ctrl1 - ctrl2 once both are homed; rack = x1 - x2, 0 = square; 1 count =\n"
                "   78.125 nm, P = %d counts = %.3f um)\n",
                period, period * 0.078125);
}

}  // namespace

int cmd_gantry(const std::vector<std::string>& args, size_t first) {
    lxt::gantry_config c;
    std::string out = "out";
    long long seed = 7, period = 256, ph1 = -1, ph2 = -1, limit = -1, offset = 0, sw_off = 0, resolution = -1,
              grid = -1;
    bool have_sw_off = false, plot = true, map = true;
    double compliance = 0.5;
    golden::gantry_arm arm = golden::gantry_arm::own;
    cli cl("laserax gantry", args, first, kGantryUsage);
    bool have_res = false;
    while (cl.next()) {
        if (cl.is("--no-plot")) plot = false;
        else if (cl.is("--no-map")) map = false;
        else if (cl.is("--conventional")) c.conventional = true;
        else if (cl.is("--out")) cl.get_text(&out);
        else if (cl.is("--period")) cl.get_int(8, 4096, &period, 8);
        else if (cl.is("--seed")) cl.get_int(0, INT64_MAX, &seed);
        else if (cl.is("--phase1")) cl.get_int(0, 4095, &ph1);
        else if (cl.is("--phase2")) cl.get_int(0, 4095, &ph2);
        else if (cl.is("--skew-limit")) cl.get_int(0, 1LL << 30, &limit);
        else if (cl.is("--offset")) cl.get_int(-4 * 4096, 4 * 4096, &offset);
        else if (cl.is("--switch-offset")) have_sw_off = cl.get_int(-4 * 4096, 4 * 4096, &sw_off);
        else if (cl.is("--compliance")) cl.get_real(0.0, 1.0, &compliance, true, false);
        else if (cl.is("--resolution")) have_res = cl.get_int(8, 1LL << 20, &resolution, 8);
        else if (cl.is("--map-grid")) cl.get_int(1, 4096, &grid);
        else if (cl.is("--arm")) {
            std::string v;
            if (cl.value(&v) && !gantry_parse_arm(v, &arm)) cl.error("'" + v + "' is not allowed (allowed own, both, hold)");
        } else cl.unknown();
    }
    if (cl.failed()) return cl.status();
    if (have_res && resolution < period) {
        std::fprintf(stderr, "laserax gantry: --resolution: %lld is below the period %lld (allowed P..1048576, multiple of 8)\n",
                     resolution, period);
        return 2;
    }
    if (period < 8 || period > 4096 || period % 8 != 0) {
        std::fprintf(stderr, "laserax gantry: --period must be 8..4096 and a multiple of 8\n");
        return 2;
    }
    if (std::llabs(offset) > 4 * period || std::llabs(sw_off) > 4 * period) {
        std::fprintf(stderr, "laserax gantry: --offset / --switch-offset: must be within +-4P = +-%lld counts\n",
                     4 * period);
        return 2;
    }
    const int p = static_cast<int>(period);
    c.period = p;
    c.resolution = have_res ? static_cast<int>(resolution) : std::max(2048, p);
    c.compliance = compliance;
    c.offset = static_cast<int>(offset);
    c.switch_offset = static_cast<int>(have_sw_off ? sw_off : offset);
    c.skew_limit = limit < 0 ? -1 : static_cast<int>(std::min(limit, 1LL << 30));
    c.arm = arm;
    std::mt19937_64 rng(static_cast<uint64_t>(seed));
    std::uniform_int_distribution<int> ph(0, p - 1);
    const int r1 = ph(rng), r2 = ph(rng);
    c.phase[0] = ph1 >= 0 ? static_cast<int>(ph1) : r1;
    c.phase[1] = ph2 >= 0 ? static_cast<int>(ph2) : r2;
    if (ph1 >= p || ph2 >= p) {
        std::fprintf(stderr, "laserax gantry: --phase1 / --phase2: must be 0..P-1 = 0..%d\n", p - 1);
        return 2;
    }
    const std::string err = gantry_check(c);
    if (!err.empty()) {
        std::fprintf(stderr, "laserax gantry: %s\n", err.c_str());
        return 2;
    }
    if (!make_dirs(out, "laserax gantry")) return 1;
    const int lim = c.skew_limit < 0 ? p : c.skew_limit;

    std::printf("laserax gantry: P = %d counts (%.3f um), %s, controller %d units/period, compliance %.3g, arm %s\n", p,
                p * 0.078125, c.conventional ? "conventional encoders" : "laser + compensator (two laserax_top)",
                c.resolution, c.compliance, gantry_arm_name(c.arm));
    std::printf("  offset parameter %d counts, real switch offset %d counts, skew limit %d counts\n", c.offset,
                c.switch_offset, lim);

    // the sequence, with its trace
    const std::string trace_path = out + "/gantry_trace.csv";
    FILE* tf = std::fopen(trace_path.c_str(), "w");
    if (!tf) {
        std::fprintf(stderr, "laserax gantry: cannot write %s\n", trace_path.c_str());
        return 1;
    }
    std::fprintf(tf, "# laserax gantry trace: period=%d offset=%d switch_offset=%d skew_limit=%d compliance=%g arm=%s %s\n",
                 p, c.offset, c.switch_offset, lim, c.compliance, gantry_arm_name(c.arm),
                 c.conventional ? "conventional" : "laser");
    std::fprintf(tf, "# phase1=%d phase2=%d clock_ns=10 count_nm=78.125\n", c.phase[0], c.phase[1]);
    for (int s = 0; s < 13; ++s) std::fprintf(tf, "# step %d = %s\n", s, gantry_step_name(s));
    std::fprintf(tf, "cycle,step,x1_nm,x2_nm,sp1,sp2,ctrl1,ctrl2,homed1,homed2,rack,skew_valid,skew,stage1,stage2,"
                     "mark1,mark2,sw1,sw2,sin1,cos1,sin2,cos2,alarm\n");
    long long trace_rows = 0;
    const golden::gantry_setup setup0 = gantry_setup_for(c);
    const double x_ref = setup0.switch_nm[0];
    auto sink = [&](const gantry_trace_row& t) {
        ++trace_rows;
        std::fprintf(tf, "%lld,%d,%.3f,%.3f,%.3f,%.3f,%lld,%lld,%d,%d,%.4f,%d,%lld,%d,%d,%d,%d,%d,%d,%lld,%lld,%lld,%lld,%d\n",
                     t.cycle, t.step, t.x_nm[0] - x_ref, t.x_nm[1] - x_ref, t.setpoint[0], t.setpoint[1],
                     static_cast<long long>(t.ctrl[0]), static_cast<long long>(t.ctrl[1]), t.homed[0] ? 1 : 0,
                     t.homed[1] ? 1 : 0, t.rack, t.skew_valid ? 1 : 0, static_cast<long long>(t.skew), t.stage[0],
                     t.stage[1], t.mark[0] ? 1 : 0, t.mark[1] ? 1 : 0, t.sw[0] ? 1 : 0, t.sw[1] ? 1 : 0,
                     static_cast<long long>(t.sin[0]), static_cast<long long>(t.cos[0]),
                     static_cast<long long>(t.sin[1]), static_cast<long long>(t.cos[1]), t.alarm ? 1 : 0);
    };
    const gantry_result r = run_gantry(c, sink);
    std::fclose(tf);
    const golden::gantry_prediction g = golden::predict_gantry(r.setup);

    if (c.conventional) {
        std::printf("  power-up positions: X1 %d, X2 %d (no effect: the encoders' phase is fixed to the scale)\n",
                    c.phase[0], c.phase[1]);
    } else {
        std::printf("  power-up phases (output phase at A): X1 %d, X2 %d -> rephase d1 = %.0f, d2 = %.0f counts "
                    "(golden); temporary skew d2 - d1 = %+.0f counts (%+.3f um), seed bound +-%d\n",
                    c.phase[0], c.phase[1], g.d[0], g.d[1], g.rephase_skew, g.rephase_skew * 0.078125, p);
    }
    if (!r.ok) {
        std::printf("\n  SEQUENCE FAILED: %s\n", r.error.c_str());
        print_table(r, p);
        return 1;
    }
    print_table(r, p);
    if (!c.conventional) {
        std::printf("\n  compensator homings (d per homing, taps): X1");
        for (int64_t d : r.homings[0]) std::printf(" %lld", static_cast<long long>(d));
        std::printf(", X2");
        for (int64_t d : r.homings[1]) std::printf(" %lld", static_cast<long long>(d));
        std::printf("; rack in real counts after pass 1 / pass 2: %lld / %lld\n", static_cast<long long>(r.rack[0]),
                    static_cast<long long>(r.rack[1]));
    }
    std::printf("  home latches: X1 sin %lld cos %lld, X2 sin %lld cos %lld (mark active: %d, %d)\n",
                static_cast<long long>(r.latch_sin[0]), static_cast<long long>(r.latch_cos[0]),
                static_cast<long long>(r.latch_sin[1]), static_cast<long long>(r.latch_cos[1]), r.latch_mark[0] ? 1 : 0,
                r.latch_mark[1] ? 1 : 0);
    std::printf("  skew at the check %lld counts, offset %d -> error %+lld counts, limit %d: %s\n",
                static_cast<long long>(r.skew_check), c.offset, static_cast<long long>(r.skew_error), lim,
                r.alarm ? "ALARM (sequence stopped, no deskew)" : "within the limit");
    std::printf("  final: skew %lld counts (%s), physical rack %.1f nm, drives racked %.1f nm (compliance %.3g), "
                "largest rack during the sequence %.2f counts; %s\n",
                static_cast<long long>(r.skew_final), r.skew_final == c.offset ? "= offset" : "!= offset",
                r.rack_final_nm, r.drive_rack_final_nm, c.compliance, r.max_rack,
                r.both_referenced ? "both axes referenced" : "NOT both referenced");
    const std::string diff = compare_golden(r, g, c.conventional);
    std::printf("  golden model: %s\n", diff.empty() ? "agrees (A, d, Z, rack, skew, alarm, final skew, physical rack)"
                                                     : ("DIFFERS:" + diff).c_str());
    std::printf("  %lld clocks (%.3f ms of machine time); wrote %s (%lld rows)\n", r.calls, static_cast<double>(r.calls) * 1e-5,
                trace_path.c_str(), trace_rows);
    bool all_ok = diff.empty();

    // skew map over the power-up phases
    const std::string map_path = out + "/gantry_skew_map.csv";
    if (map) {
        const int n = static_cast<int>(grid > 0 ? std::min<long long>(grid, p) : std::min(p, 16));
        FILE* mf = std::fopen(map_path.c_str(), "w");
        if (!mf) {
            std::fprintf(stderr, "laserax gantry: cannot write %s\n", map_path.c_str());
            return 1;
        }
        std::fprintf(mf, "# laserax gantry skew map: period=%d offset=%d switch_offset=%d skew_limit=%d grid=%d %s arm=%s\n",
                     p, c.offset, c.switch_offset, lim, n, c.conventional ? "conventional" : "laser",
                     gantry_arm_name(c.arm));
        std::fprintf(mf, "phase1,phase2,d1,d2,skew_check,skew_error,golden_skew_error,alarm,golden_alarm,skew_final,"
                         "max_rack,calls,match\n");
        int worst = 0, alarms = 0, mismatches = 0, fails = 0;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                gantry_config m = c;
                m.phase[0] = static_cast<int>(static_cast<long long>(i) * p / n);
                m.phase[1] = static_cast<int>(static_cast<long long>(j) * p / n);
                const gantry_result mr = run_gantry(m);
                const golden::gantry_prediction mg = golden::predict_gantry(mr.setup);
                const bool match = mr.ok && compare_golden(mr, mg, m.conventional).empty();
                if (!mr.ok) ++fails;
                if (!match) ++mismatches;
                alarms += mr.alarm ? 1 : 0;
                worst = std::max(worst, static_cast<int>(std::llabs(mr.skew_error)));
                std::fprintf(mf, "%d,%d,%.0f,%.0f,%lld,%lld,%.0f,%d,%d,%lld,%.3f,%lld,%d\n", m.phase[0], m.phase[1],
                             mg.d[0], mg.d[1], static_cast<long long>(mr.skew_check),
                             static_cast<long long>(mr.skew_error), mg.skew_error, mr.alarm ? 1 : 0, mg.alarm ? 1 : 0,
                             static_cast<long long>(mr.skew_final), mr.max_rack, mr.calls, match ? 1 : 0);
            }
        }
        std::fclose(mf);
        std::printf("  skew map: %d x %d power-up phases, worst |skew - offset| %d counts (%.3f um), %d alarms, "
                    "%d failed runs, %d golden mismatches; wrote %s\n",
                    n, n, worst, worst * 0.078125, alarms, fails, mismatches, map_path.c_str());
        all_ok = all_ok && mismatches == 0;
    }

    if (plot) {
        const std::string py = "/usr/bin/python3";
        struct stat st;
        if (stat(py.c_str(), &st) != 0) {
            std::printf("  plots skipped: /usr/bin/python3 not found (apt-get install python3-matplotlib)\n");
        } else {
            std::string cmd = py + " scripts/plot_gantry.py --trace " + trace_path + " --sequence-png " + out +
                              "/gantry_sequence.png";
            if (map) cmd += " --map " + map_path + " --map-png " + out + "/gantry_skew_map.png";
            std::fflush(stdout);
            const int rc = std::system(cmd.c_str());
            if (rc == 0)
                std::printf("  wrote %s/gantry_sequence.png%s\n", out.c_str(),
                            map ? (", " + out + "/gantry_skew_map.png").c_str() : "");
            else
                std::printf("  plots skipped (scripts/plot_gantry.py failed; it needs numpy and matplotlib: make deps)\n");
        }
    }
    return all_ok ? 0 : 1;
}

}  // namespace lxt
