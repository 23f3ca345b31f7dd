// ctest-args-O0: --samples-div 64 --small-sweeps 0 --alarm-stride 4 --period-max 320
// tb_gantry — twin-axis (gantry) referencing with two compensators (docs/GANTRY.md): the
// cycle-accurate system (two lx::laserax_top, a controller that decodes their sin/cos, coupled
// mechanics) against the floating-point golden model golden/gantry_model, over the power-up
// phases of X1 and X2:
//   exhaustive : every (phase1, phase2) for P = 8 and 16; the temporary skew stays within +-P,
//                reaches P - 1, and the deskew leaves exactly the offset parameter
//   sampled    : seeded random phases plus the two extreme combinations for P = 256, 320, 512,
//                640, 1280; worst-case skew per period printed, proportional to P
//   alarm      : a skew limit below the worst case alarms for exactly the combinations whose
//                skew exceeds it (and then no deskew); a limit >= P - 1 never alarms
//   arming     : the three ways of using rehome (own, both, hold), intermediate rack included
//   baseline   : conventional encoders: no rephase, no temporary skew
//   variants   : compliance, controller resolution, offset parameter != real switch offset
//   checker    : the verification itself flags a perturbed result (the test can fail)
// Every run is compared with the golden model: A, d of every compensator homing, Z, the rack
// after each pass, the skew at the check, the alarm, the final skew, the final physical rack.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "golden/gantry_model.h"
#include "tb/tb_util.h"
#include "sysmodel/gantry.h"

namespace {

// Everything a run must satisfy; "" or the first problem.
std::string verify(const lxt::gantry_config& c, const lxt::gantry_result& r, const golden::gantry_prediction& g) {
    std::ostringstream e;
    const int p = c.period;
    const int64_t limit = c.skew_limit < 0 ? p : c.skew_limit;
    auto eq = [](double a, int64_t b) { return a == static_cast<double>(b); };
    if (!r.ok) return "run failed: " + r.error;
    if (!r.checked) return "no skew check";
    if (!r.both_referenced) return "not both referenced at the end";
    const size_t want_rows = g.alarm ? 6 : 7;
    if (r.rows.size() != want_rows) {
        e << "rows " << r.rows.size() << ", expected " << want_rows;
        return e.str();
    }
    for (int i = 0; i < 2; ++i) {
        if (!r.latch_mark[i] || r.latch_sin[i] <= 0 || r.latch_cos[i] <= 0) {
            e << "X" << i + 1 << ": home latched without the mark or outside sin, cos > 0";
            return e.str();
        }
        if (!c.conventional) {
            if (r.latch_sin[i] != r.latch_cos[i]) {
                e << "X" << i + 1 << ": home latched with sin " << r.latch_sin[i] << " != cos " << r.latch_cos[i];
                return e.str();
            }
            if (r.homings[i].size() != g.homings[i].size()) {
                e << "X" << i + 1 << ": " << r.homings[i].size() << " compensator homings, golden " << g.homings[i].size();
                return e.str();
            }
            for (size_t k = 0; k < r.homings[i].size(); ++k)
                if (!eq(g.homings[i][k], r.homings[i][k])) {
                    e << "X" << i + 1 << ": homing " << k + 1 << " d " << r.homings[i][k] << ", golden " << g.homings[i][k];
                    return e.str();
                }
            if (!eq(g.a[i], r.a[i]) || !eq(g.z[i], r.z[i])) {
                e << "X" << i + 1 << ": A/Z " << r.a[i] << "/" << r.z[i] << ", golden " << g.a[i] << "/" << g.z[i];
                return e.str();
            }
        } else if (!r.homings[i].empty()) {
            return "conventional encoders: a compensator homing was recorded";
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (!eq(g.rack[k], r.rack[k])) {
            e << "rack after step " << k + 1 << ": " << r.rack[k] << " counts, golden " << g.rack[k];
            return e.str();
        }
        if (r.rack[k] <= -p || r.rack[k] >= p) {
            e << "rack " << r.rack[k] << " outside +-P";
            return e.str();
        }
    }
    if (!eq(g.skew_check, r.skew_check) || !eq(g.skew_error, r.skew_error)) {
        e << "skew at the check " << r.skew_check << " (error " << r.skew_error << "), golden " << g.skew_check << " ("
          << g.skew_error << ")";
        return e.str();
    }
    if (r.alarm != g.alarm || r.alarm != (std::llabs(r.skew_error) > limit)) {
        e << "alarm " << r.alarm << " for skew error " << r.skew_error << " and limit " << limit << ", golden " << g.alarm;
        return e.str();
    }
    if (!eq(g.skew_final, r.skew_final) || (!r.alarm && r.skew_final != c.offset) || (r.alarm && r.skew_final != r.skew_check)) {
        e << "final skew " << r.skew_final << ", golden " << g.skew_final << " (offset " << c.offset << ", alarm " << r.alarm << ")";
        return e.str();
    }
    if (std::fabs(r.rack_final_nm - g.rack_final_nm) > g.rack_tol_nm + 1e-6) {
        e << "final physical rack " << r.rack_final_nm << " nm, golden " << g.rack_final_nm << " +- " << g.rack_tol_nm;
        return e.str();
    }
    // the physical rack during motion (rephase skew plus the tracking axis' following error) stays
    // within the bound of Laser scale referencing too: below P + 1 counts (the following error is under one count)
    if (r.max_rack >= p + 1) {
        e << "physical rack reached " << r.max_rack << " counts during the sequence (P = " << p << ")";
        return e.str();
    }
    return "";
}

struct stats {
    int runs = 0, alarms = 0, at_worst = 0;
    int64_t worst = 0;
    double sum_abs = 0, max_dyn = 0;
    long long calls = 0;
    void add(const lxt::gantry_result& r) {
        ++runs;
        alarms += r.alarm ? 1 : 0;
        const int64_t a = std::llabs(r.skew_error);
        if (a > worst) {
            worst = a;
            at_worst = 0;
        }
        if (a == worst) ++at_worst;
        sum_abs += static_cast<double>(a);
        max_dyn = std::max(max_dyn, r.max_rack);
        calls += r.calls;
    }
};

// Phase at A that needs the rephase amount d: d = (7P/8 - phase) mod P.
int phase_for_d(int p, int d) { return ((7 * p / 8 - d) % p + p) % p; }

struct bench {
    tbu::result& res;
    int fails_printed = 0;
    explicit bench(tbu::result& r) : res(r) {}

    // Runs one configuration, verifies it against the golden model; returns the result.
    lxt::gantry_result run(const lxt::gantry_config& c, const std::string& what, stats* st = nullptr) {
        const lxt::gantry_result r = lxt::run_gantry(c);
        const golden::gantry_prediction g = golden::predict_gantry(r.setup);
        const std::string m = verify(c, r, g);
        res.expect(m.empty(), [&] {
            std::ostringstream o;
            o << what << " P=" << c.period << " phases (" << c.phase[0] << ", " << c.phase[1] << ") arm "
              << lxt::gantry_arm_name(c.arm) << (c.conventional ? " conventional" : "") << ": " << m;
            return o.str();
        });
        if (st) st->add(r);
        return r;
    }
};

lxt::gantry_config base(int p) {
    lxt::gantry_config c;
    c.period = p;
    c.resolution = std::max(2048, p);
    c.switch_offset = 3;
    c.offset = 3;
    c.skew_limit = p + 1;  // above P: never an alarm
    c.compliance = 0.5;
    return c;
}

}  // namespace

int main(int argc, char** argv) {
    const auto t0 = std::chrono::steady_clock::now();
    tbu::result res("tb_gantry", tbu::seed_from(argc, argv, 5));
    bench b(res);
    std::mt19937_64 rng(res.seed);

    struct table_row {
        int p;
        stats st;
        bool exhaustive;
    };
    std::vector<table_row> table;

    // --samples-div D: 1/D of the random combinations (the -O0 type back-end build; D > 1 also runs
    // 4 of the 16 P = 256 alarm combinations, the directed one included); the two
    // extreme combinations of every period and the exhaustive part are always run
    const long long samples_div = tbu::arg_ll(argc, argv, "--samples-div", 1);
    // --small-sweeps 0: leave out the repeated P = 8 / 16 sweeps (the P = 16 exhaustive skew sweep,
    // P = 8 at three alarm limits, the two other arming variants); the P = 8 exhaustive sweep and
    // the P = 16 alarm sweep (every combination) always run
    const bool small_sweeps = tbu::arg_ll(argc, argv, "--small-sweeps", 1) != 0;
    // --alarm-stride S: the P = 16 alarm sweep over the combinations with (phase1 + phase2) a
    // multiple of S only (the -O0 type back-end build: S = 4, 64 of the 256); its exact-count
    // check then covers that subset
    const long long alarm_stride = tbu::arg_ll(argc, argv, "--alarm-stride", 1);
    if (alarm_stride < 1 || alarm_stride > 16) {
        std::printf("tb_gantry: --alarm-stride must be 1..16\n");
        return 2;
    }
    // --period-max N: the sampled part only for the periods up to N (the -O0 build: 256 and 320;
    // the runs grow with P, P = 1280 alone was a third of that build's clocks)
    const long long period_max = tbu::arg_ll(argc, argv, "--period-max", 1280);
    if (period_max < 256) {
        std::printf("tb_gantry: --period-max must be >= 256\n");
        return 2;
    }
    if (samples_div < 1 || samples_div > 64) {
        std::printf("tb_gantry: --samples-div must be 1..64\n");
        return 2;
    }
    // ---- exhaustive: every combination of power-up phases, small periods ----------------------
    for (int p : {8, 16}) {
        if (p == 16 && !small_sweeps) continue;  // --small-sweeps 0: P = 8 only (P = 16: the alarm sweep)
        stats st;
        for (int a = 0; a < p; ++a)
            for (int bb = 0; bb < p; ++bb) {
                lxt::gantry_config c = base(p);
                c.phase[0] = a;
                c.phase[1] = bb;
                b.run(c, "exhaustive", &st);
            }
        res.check(st.worst == p - 1, "P=" + std::to_string(p) + ": worst skew " + std::to_string(st.worst) +
                                         " does not reach P - 1");
        res.check(st.alarms == 0, "P=" + std::to_string(p) + ": alarm with the limit above P");
        table.push_back({p, st, true});
    }

    // ---- sampled: seeded random phases + the two extreme combinations -------------------------
    const int sample_n[5] = {64, 48, 32, 32, 20};
    const int periods[5] = {256, 320, 512, 640, 1280};
    for (int k = 0; k < 5; ++k) {
        const int p = periods[k];
        if (p > period_max) continue;
        stats st;
        std::vector<std::pair<int, int>> combos = {{phase_for_d(p, p - 1), phase_for_d(p, 0)},
                                                   {phase_for_d(p, 0), phase_for_d(p, p - 1)}};
        std::uniform_int_distribution<int> ph(0, p - 1);
        for (int i = 0; i < sample_n[k] / samples_div; ++i) combos.push_back({ph(rng), ph(rng)});
        for (const auto& cb : combos) {
            lxt::gantry_config c = base(p);
            c.phase[0] = cb.first;
            c.phase[1] = cb.second;
            b.run(c, "sampled", &st);
        }
        res.check(st.worst == p - 1, "P=" + std::to_string(p) + ": worst skew " + std::to_string(st.worst) +
                                         " does not reach P - 1");
        res.check(st.alarms == 0, "P=" + std::to_string(p) + ": alarm with the limit above P");
        table.push_back({p, st, false});
    }

    std::printf("\nworst-case temporary skew (skew at the check - offset) per period, arm own, compliance 0.5:\n");
    std::printf("  %6s %10s %7s %12s %12s %9s %10s %12s %12s\n", "P", "combos", "worst", "worst [um]", "seed bound",
                "worst/P", "mean|e|", "max rack*", "clocks/run");
    for (const table_row& t : table) {
        std::printf("  %6d %10s %7lld %12.3f %12s %9.4f %10.1f %12.2f %12lld\n", t.p,
                    (std::to_string(t.st.runs) + (t.exhaustive ? " (all)" : "")).c_str(),
                    static_cast<long long>(t.st.worst), static_cast<double>(t.st.worst) * 0.078125,
                    ("+-" + std::to_string(t.p)).c_str(), static_cast<double>(t.st.worst) / t.p,
                    t.st.sum_abs / t.st.runs, t.st.max_dyn, static_cast<long long>(t.st.calls / t.st.runs));
    }
    std::printf("  (* largest physical rack |x1 - x2| while moving, counts: rephase skew + tracking error)\n");
    // proportional: worst / P is the same for every period (to one count)
    for (const table_row& t : table) {
        const double ratio = static_cast<double>(t.st.worst) / t.p;
        res.check(std::fabs(ratio - (1.0 - 1.0 / t.p)) < 1e-12 && golden::gantry_worst_skew(t.p) == static_cast<double>(t.st.worst),
                  "P=" + std::to_string(t.p) + ": worst skew not (P - 1), i.e. not proportional to P");
    }

    // ---- alarm behaviour -------------------------------------------------------------------------
    {
        const int p = 16, limit = 9;  // below the worst case 15
        int alarms = 0, expected = 0, mism = 0, runs = 0;
        for (int a = 0; a < p; ++a)
            for (int bb = 0; bb < p; ++bb) {
                if ((a + bb) % alarm_stride != 0) continue;
                ++runs;
                lxt::gantry_config c = base(p);
                c.phase[0] = a;
                c.phase[1] = bb;
                c.skew_limit = limit;
                const lxt::gantry_result r = b.run(c, "alarm limit 9");
                const golden::gantry_prediction g = golden::predict_gantry(r.setup);
                // skew error of this combination from the golden model: d2 - d1
                const bool exceeds = std::fabs(g.rephase_skew) > limit;
                expected += exceeds ? 1 : 0;
                alarms += r.alarm ? 1 : 0;
                if (r.alarm != exceeds) ++mism;
            }
        std::printf("\nalarm, P=16, limit 9 (< worst 15): %d of %d combinations alarm, %d exceed the limit, %d differ\n",
                    alarms, runs, expected, mism);
        res.check(mism == 0 && alarms == expected && alarms > 0 && alarms < runs,
                  "alarm set differs from the combinations that exceed the limit");
        // expected count by counting |d2 - d1| > 9 over all d1, d2 in 0..15: 2 * (1 + 2 + ... + 6) = 42
        if (alarm_stride == 1)
            res.check(expected == 42, "P=16, limit 9: expected 42 exceeding combinations, got " + std::to_string(expected));
    }
    if (small_sweeps) {
        const int p = 8;
        int alarms = 0;
        for (int lim : {p - 1, p, p + 1})
            for (int a = 0; a < p; ++a)
                for (int bb = 0; bb < p; ++bb) {
                    lxt::gantry_config c = base(p);
                    c.phase[0] = a;
                    c.phase[1] = bb;
                    c.skew_limit = lim;
                    alarms += b.run(c, "alarm limit >= P-1").alarm ? 1 : 0;
                }
        std::printf("alarm, P=8, limits 7, 8, 9 (>= worst 7): %d alarms in 192 runs\n", alarms);
        res.check(alarms == 0, "a limit >= P - 1 raised the alarm");
    }
    {
        const int p = 256, limit = 100;
        int alarms = 0, expected = 0, n = 0;
        std::uniform_int_distribution<int> ph(0, p - 1);
        const int runs = samples_div > 1 ? 4 : 16;  // (--samples-div: the directed one and three random)
        for (int i = 0; i < runs; ++i) {
            lxt::gantry_config c = base(p);
            c.phase[0] = ph(rng);
            c.phase[1] = ph(rng);
            if (i == 0) {
                c.phase[0] = phase_for_d(p, 200);
                c.phase[1] = phase_for_d(p, 50);
            }
            c.skew_limit = limit;
            const lxt::gantry_result r = b.run(c, "alarm P=256 limit 100");
            alarms += r.alarm ? 1 : 0;
            expected += std::llabs(r.skew_error) > limit ? 1 : 0;
            ++n;
        }
        std::printf("alarm, P=256, limit 100: %d of %d sampled combinations alarm (%d exceed)\n", alarms, n, expected);
        res.check(alarms == expected && alarms > 0, "P=256: alarm set differs from the exceeding combinations");
    }

    // ---- arming variants -------------------------------------------------------------------------
    for (golden::gantry_arm arm : {golden::gantry_arm::both, golden::gantry_arm::hold}) {
        if (!small_sweeps) break;
        for (int p : {8, 16}) {
            stats st;
            for (int a = 0; a < p; ++a)
                for (int bb = 0; bb < p; ++bb) {
                    lxt::gantry_config c = base(p);
                    c.arm = arm;
                    c.phase[0] = a;
                    c.phase[1] = bb;
                    b.run(c, "arming", &st);
                }
            res.check(st.worst == p - 1, std::string("arm ") + lxt::gantry_arm_name(arm) + ": worst skew not P - 1");
        }
    }
    for (golden::gantry_arm arm : {golden::gantry_arm::both, golden::gantry_arm::hold}) {
        lxt::gantry_config c = base(256);
        c.arm = arm;
        c.phase[0] = phase_for_d(256, 255);
        c.phase[1] = phase_for_d(256, 0);
        b.run(c, "arming P=256");
    }

    // ---- baseline: conventional encoders ------------------------------------------------------------
    {
        stats st;
        for (int p : {16, 256}) {
            const int n = p == 16 ? 16 : 4;
            for (int i = 0; i < n; ++i) {
                lxt::gantry_config c = base(p);
                c.conventional = true;
                c.phase[0] = (i * 5) % p;
                c.phase[1] = (i * 11 + 3) % p;
                b.run(c, "conventional", &st);
            }
        }
        std::printf("\nconventional encoders: %d runs, worst |skew - offset| = %lld counts (no rephase skew)\n", st.runs,
                    static_cast<long long>(st.worst));
        res.check(st.worst == 0, "conventional encoders: skew at the check differs from the offset");
    }

    // ---- variants: compliance, resolution, offset parameter ----------------------------------------
    {
        const int p = 16;
        const int combos[4][2] = {{phase_for_d(p, 15), phase_for_d(p, 0)}, {phase_for_d(p, 0), phase_for_d(p, 15)},
                                  {3, 9}, {12, 12}};
        for (const auto& cb : combos) {
            for (double comp : {0.1, 1.0}) {
                lxt::gantry_config c = base(p);
                c.compliance = comp;
                c.phase[0] = cb[0];
                c.phase[1] = cb[1];
                const lxt::gantry_result r = b.run(c, "compliance");
                // the drives rack by rack / compliance to produce the real rack
                res.expect(std::fabs(r.drive_rack_final_nm * comp - r.rack_final_nm) < 1e-6,
                           [&] { return std::string("compliance: drive rack inconsistent with the real rack"); });
            }
            for (int resol : {p, 4096}) {
                lxt::gantry_config c = base(p);
                c.resolution = resol;
                c.phase[0] = cb[0];
                c.phase[1] = cb[1];
                b.run(c, "resolution");
            }
            for (int off : {-4, 7}) {  // offset parameter != real switch offset (3): machine left out of square
                lxt::gantry_config c = base(p);
                c.offset = off;
                c.phase[0] = cb[0];
                c.phase[1] = cb[1];
                b.run(c, "offset");
            }
            {
                lxt::gantry_config c = base(p);
                c.switch_offset = -5;
                c.offset = -5;
                c.phase[0] = cb[0];
                c.phase[1] = cb[1];
                b.run(c, "switch offset");
            }
        }
        lxt::gantry_config c = base(320);  // res 2048 is not a multiple of 320 (6.4 units per count)
        c.phase[0] = phase_for_d(320, 319);
        c.phase[1] = phase_for_d(320, 0);
        c.compliance = 0.2;
        b.run(c, "resolution 2048 / P 320");
    }

    // ---- the verification flags a wrong result ------------------------------------------------------
    {
        lxt::gantry_config c = base(16);
        c.phase[0] = 5;
        c.phase[1] = 11;
        const lxt::gantry_result r = lxt::run_gantry(c);
        const golden::gantry_prediction g = golden::predict_gantry(r.setup);
        res.check(verify(c, r, g).empty(), "checker: reference run not clean");
        int caught = 0, tries = 0;
        auto mutate = [&](const char* what, auto f) {
            lxt::gantry_result m = r;
            golden::gantry_prediction gm = g;
            f(m, gm);
            ++tries;
            if (!verify(c, m, gm).empty()) ++caught;
            else res.check(false, std::string("checker missed: ") + what);
        };
        mutate("final skew off by one", [](lxt::gantry_result& m, golden::gantry_prediction&) { ++m.skew_final; });
        mutate("alarm flipped", [](lxt::gantry_result& m, golden::gantry_prediction&) { m.alarm = !m.alarm; });
        mutate("d of X2 changed", [](lxt::gantry_result& m, golden::gantry_prediction&) { ++m.homings[1][0]; });
        mutate("golden d swapped", [](lxt::gantry_result&, golden::gantry_prediction& gm) {
            std::swap(gm.homings[0][0], gm.homings[1][0]);
        });
        mutate("rack after pass 1", [](lxt::gantry_result& m, golden::gantry_prediction&) { m.rack[0] += 1; });
        mutate("home latched at sin != cos", [](lxt::gantry_result& m, golden::gantry_prediction&) { m.latch_cos[0] += 1; });
        mutate("no deskew", [](lxt::gantry_result& m, golden::gantry_prediction&) { m.skew_final = m.skew_check; });
        mutate("physical rack", [](lxt::gantry_result& m, golden::gantry_prediction& gm) {
            m.rack_final_nm = gm.rack_final_nm + 2 * gm.rack_tol_nm;
        });
        std::printf("checker: %d of %d perturbed results flagged\n", caught, tries);
    }

    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("runtime %.1f s\n", secs);
    return res.finish();
}
