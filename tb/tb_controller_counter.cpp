// tb_controller_counter — the controller-side quadrature counter model (tb/controller_counter.h)
// against the pacing rule of host/pacing.h (issue 36, docs/CONTROLLER.md).
//
// (a) Synthetic quadrature streams made here (bursts of counts at exactly S clocks in both
//     directions, immediate direction reversals, idle stretches, an index pulse one quadrature
//     state wide at A = B = 1), fed to the model over many start phases and several clock ratios
//     (each controller input of the docs table, its clock nominal, 900 ppm slow and 700 / 400 ppm
//     fast, with and without a 1 ns metastable aperture, plus four non-integer ratios). With
//     S = the rule's pace_m: every count seen (each +1 and -1, none lost, no quadrature error),
//     the final count right, the index latched at the right count on every pass. With S = the
//     rule's pace_m - 1: counts lost for some phase in every case (printed).
// (b) A two-line change is a quadrature error (filter off and on), and the count stays.
// (c) host pacing: the reference values of issue 36 (a hostmot2 counter: 61, 31, 7), the table
//     values derived by hand from the rule, the output speed, invalid inputs.
// ctest-args: --seed 36
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "host/pacing.h"
#include "tb/controller_counter.h"
#include "tb/tb_util.h"

namespace {

constexpr int kIndexPos = 6;  // position of the index state (6 mod 4 = 2: A = B = 1)

int pins_of(int64_t pos, bool z) {
    const int q = static_cast<int>(((pos % 4) + 4) % 4);  // 0: 00, 1: 10, 2: 11, 3: 01 (A, B)
    const int a = (q == 1 || q == 2) ? 1 : 0, b = (q == 2 || q == 3) ? 1 : 0;
    return a | (b << 1) | (z ? 4 : 0);
}

struct stream {
    std::vector<uint8_t> pins;  // per clock: bit 0 A, 1 B, 2 Z
    int64_t final_pos = 0;
    uint64_t counts = 0;                   // output counts emitted (+1 and -1)
    uint64_t reversals = 0;
    std::vector<int64_t> z_rise, z_fall;   // position at each clock where Z rises / falls
};

// Counts exactly S clocks apart in bursts, reversals right after a count (the reversed line
// level lasts one state, S clocks), idle stretches, the walk kept around the index position.
stream make_stream(int s, long tail, std::mt19937_64& rng) {
    stream st;
    int64_t pos = 0;
    auto hold = [&](long n) {
        for (long i = 0; i < n; ++i) st.pins.push_back(static_cast<uint8_t>(pins_of(pos, pos == kIndexPos)));
    };
    auto count = [&](int dir) {
        const bool z0 = pos == kIndexPos;
        pos += dir;
        ++st.counts;
        const bool z1 = pos == kIndexPos;
        if (z1 && !z0) st.z_rise.push_back(pos);
        if (z0 && !z1) st.z_fall.push_back(pos);
        hold(s);  // the change clock and S - 1 more: the next count is S clocks later
    };
    hold(s + static_cast<long>(rng() % static_cast<uint64_t>(3 * s)));
    int dir = 1;
    while (st.counts < 400 || (st.z_rise.size() < 8 && st.counts < 4000)) {
        if (pos > kIndexPos + 9) dir = -1;  // the walk stays around the index
        if (pos < kIndexPos - 9) dir = 1;
        const int len = 1 + static_cast<int>(rng() % 10);
        for (int i = 0; i < len; ++i) count(dir);
        const int what = static_cast<int>(rng() % 4);
        if (what <= 1) {  // immediate reversal: the next count S clocks after the last one
            dir = -dir;
            ++st.reversals;
        } else {
            hold(1 + static_cast<long>(rng() % static_cast<uint64_t>(4 * s)));  // idle
            if (what == 3) {
                dir = -dir;
                ++st.reversals;
            }
        }
    }
    hold(tail);
    st.final_pos = pos;
    return st;
}

struct input_case {
    const char* name;
    double ctl_mhz;
    int sample_div;
    int filter_n;
    bool in_table;  // a row of docs/CONTROLLER.md
};

struct variant {
    double ppm;       // controller clock error: negative = slower = longer sample period
    double aperture;  // ns
};

struct tally {
    long runs = 0;
    long bad_runs = 0;       // runs with a lost count, a count error, a quadrature error or a wrong index
    uint64_t lost = 0;       // counts not seen, over all runs
    uint64_t qerr = 0;
    long index_wrong = 0;    // latches missing, extra or at the wrong count
    std::string first;       // the first bad run: phase, ratio, what
};

// Runs the stream through four counters (index on rising / falling, ungated / gated at A = B = 1)
// at one phase and ratio; adds to t. check_exact_index: ap = 0, every latch value is checked;
// else (metastable edges: Z and A/B may resolve a sample apart) only the gated rising edge.
void run_one(const stream& st, const input_case& c, const variant& v, double phase, uint64_t seed, tally& t) {
    const bool exact = v.aperture == 0;
    uint64_t lost = 0, qerr = 0;
    long wrong = 0;
    std::string what;
    for (int k = 0; k < 4; ++k) {
        lxtb::controller_cfg cfg;
        cfg.ctl_clock_mhz = c.ctl_mhz * (1.0 + v.ppm * 1e-6);
        cfg.sample_div = c.sample_div;
        cfg.filter_n = c.filter_n;
        cfg.phase_ns = phase;
        cfg.aperture_ns = v.aperture;
        cfg.seed = seed + static_cast<uint64_t>(k);
        cfg.index_rising = (k & 1) == 0;
        cfg.index_gate = k >= 2;
        lxtb::controller_counter m(cfg);
        for (uint8_t p : st.pins) m.clock((p & 1) != 0, (p & 2) != 0, (p & 4) != 0);
        const std::vector<int64_t>& want = cfg.index_rising ? st.z_rise : st.z_fall;
        const bool check_values = exact || (cfg.index_rising && cfg.index_gate);
        if (k == 0) {
            lost = st.counts > m.steps() ? st.counts - m.steps() : 0;
            qerr = m.quad_errors();
            if (m.steps() != st.counts || m.count() != st.final_pos || qerr != 0)
                what += " counts " + std::to_string(m.steps()) + " of " + std::to_string(st.counts) + ", final " +
                        std::to_string(m.count()) + " for " + std::to_string(st.final_pos) + ", quadrature errors " +
                        std::to_string(qerr) + ";";
        }
        const bool ok_index = m.index_counts().size() == want.size() && (!check_values || m.index_counts() == want);
        if (!ok_index) {
            ++wrong;
            std::string got;
            for (size_t i = 0; i < m.index_counts().size() && i < 6; ++i) got += " " + std::to_string(m.index_counts()[i]);
            what += std::string(" index ") + (cfg.index_rising ? "rising" : "falling") + (cfg.index_gate ? " gated" : "") +
                    ": " + std::to_string(m.index_counts().size()) + " latches for " + std::to_string(want.size()) +
                    " (first:" + got + ");";
        }
    }
    ++t.runs;
    t.lost += lost;
    t.qerr += qerr;
    t.index_wrong += wrong;
    if (!what.empty()) {
        ++t.bad_runs;
        if (t.first.empty()) {
            char b[200];
            std::snprintf(b, sizeof b, "phase %.4f ns, controller %.6f MHz / %d (%+.0f ppm), aperture %.1f ns, seed %llu:",
                          phase, c.ctl_mhz * (1.0 + v.ppm * 1e-6), c.sample_div, v.ppm, v.aperture,
                          static_cast<unsigned long long>(seed));
            t.first = b + what;
        }
    }
}

void test_model_against_rule(tbu::result& res, uint64_t seed) {
    const input_case cases[] = {
        {"hostmot2 defaults (50 MHz / 2, 15 samples)", 50.0, 2, 15, true},
        {"hostmot2 sampling at 50 MHz, 15 samples", 50.0, 1, 15, true},
        {"hostmot2 filter off (3 samples at 50 MHz)", 50.0, 1, 3, true},
        {"50 MHz, filter off", 50.0, 1, 0, true},
        {"50 MHz, 4 samples", 50.0, 1, 4, true},
        {"50 MHz, 8 samples", 50.0, 1, 8, true},
        {"100 MHz, filter off", 100.0, 1, 0, true},
        {"100 MHz, 4 samples", 100.0, 1, 4, true},
        {"100 MHz, 8 samples", 100.0, 1, 8, true},
        {"40 MHz, 5 samples", 40.0, 1, 5, false},
        {"33.333 MHz, 7 samples", 100.0 / 3.0, 1, 7, false},
        {"60 MHz / 3, 2 samples", 60.0, 3, 2, false},
        // N T_s = 599.7 ns = 59.97 clocks: without the margins the rule would give 60, which
        // loses counts when the controller runs 900 ppm slow; with them 61
        {"25.0125 MHz, 15 samples (59.97 clocks)", 25.0125, 1, 15, false},
    };
    const variant variants[] = {{-900.0, 1.0}, {0.0, 1.0}, {700.0, 0.0}, {-400.0, 0.0}, {0.0, 0.0}};
    const int kPhases = 32;
    std::mt19937_64 rng(seed);
    long total_runs = 0;
    for (const input_case& c : cases) {
        const double t_s = 1000.0 * c.sample_div / c.ctl_mhz;
        const lxt::pacing_result rule = lxt::min_safe_pace_m(c.ctl_mhz / c.sample_div, c.filter_n);
        if (!res.check(rule.ok, std::string("rule for ") + c.name + ": " + rule.error)) continue;
        const int n = c.filter_n < 1 ? 1 : c.filter_n;
        const long tail = static_cast<long>(std::ceil((n + 3) * t_s * 1.01 / 10.0)) + 20;
        for (int below = 0; below < 2; ++below) {
            const int s = rule.pace_m - below;
            const stream st = make_stream(s, tail, rng);
            tally t;
            for (const variant& v : variants)
                for (int j = 0; j < kPhases; ++j) {
                    const double phase = t_s * j / kPhases;
                    run_one(st, c, v, phase, seed * 1000003u + static_cast<uint64_t>(j), t);
                }
            total_runs += t.runs;
            std::printf("  %-44s S = %2d (%s): %ld runs (%d phases x %zu ratios), %zu counts, %llu reversals, %zu index "
                        "passes each; bad runs %ld, counts lost %llu, quadrature errors %llu, wrong index %ld\n",
                        c.name, s, below ? "rule - 1" : "rule", t.runs, kPhases, sizeof variants / sizeof variants[0],
                        static_cast<size_t>(st.counts), static_cast<unsigned long long>(st.reversals), st.z_rise.size(),
                        t.bad_runs, static_cast<unsigned long long>(t.lost), static_cast<unsigned long long>(t.qerr),
                        t.index_wrong);
            if (below == 0) {
                res.check(t.bad_runs == 0, std::string(c.name) + ": S = pace_m of the rule (" + std::to_string(s) +
                                               ") loses: " + t.first);
                res.check(st.z_rise.size() >= 5 && st.reversals >= 20, std::string(c.name) + ": stream too tame");
            } else {
                if (t.lost > 0) std::printf("    failing case: %s\n", t.first.c_str());
                res.check(t.lost > 0, std::string(c.name) + ": S = pace_m - 1 = " + std::to_string(s) +
                                          " lost no count for any phase: the rule has too much margin");
            }
        }
    }
    std::printf("  model: %ld runs of 4 counters each\n", total_runs);
}

// (b) both lines in one change: a quadrature error, the count stays.
void test_quad_error(tbu::result& res) {
    for (int n : {0, 4}) {
        for (double phase : {0.0, 3.3, 17.9}) {
            lxtb::controller_cfg cfg;
            cfg.ctl_clock_mhz = 47.3;
            cfg.filter_n = n;
            cfg.phase_ns = phase;
            lxtb::controller_counter m(cfg);
            auto hold = [&](bool a, bool b, int clocks) {
                for (int i = 0; i < clocks; ++i) m.clock(a, b, false);
            };
            hold(false, false, 50);
            hold(true, false, 50);   // +1
            hold(false, true, 50);   // 10 -> 01: both lines
            const std::string ctx = "filter " + std::to_string(n) + ", phase " + std::to_string(phase);
            res.check(m.quad_errors() == 1, ctx + ": quadrature errors " + std::to_string(m.quad_errors()) + ", want 1");
            res.check(m.count() == 1, ctx + ": count " + std::to_string(m.count()) + ", want 1 (kept)");
            hold(false, false, 50);  // 01 -> 00: +1 from the state the decoder now holds
            res.check(m.count() == 2 && m.quad_errors() == 1,
                      ctx + ": after 01 -> 00: count " + std::to_string(m.count()) + ", want 2");
            hold(true, true, 50);    // 00 -> 11: both lines again
            res.check(m.count() == 2 && m.quad_errors() == 2,
                      ctx + ": after 00 -> 11: count " + std::to_string(m.count()) + " errors " +
                          std::to_string(m.quad_errors()) + ", want 2 and 2");
        }
    }
    // a legal sequence with no error, both directions
    lxtb::controller_cfg cfg;
    cfg.ctl_clock_mhz = 61.7;
    cfg.filter_n = 3;
    lxtb::controller_counter m(cfg);
    const int seq[] = {0, 1, 3, 2, 0, 2, 3, 1, 0, 1};  // A | B << 1: 00 10 11 01 00 01 11 10 00 10
    for (int q : seq)
        for (int i = 0; i < 40; ++i) m.clock((q & 1) != 0, (q & 2) != 0, false);
    res.check(m.count() == 1 && m.steps() == 9 && m.quad_errors() == 0,
              "legal sequence: count " + std::to_string(m.count()) + " steps " + std::to_string(m.steps()) +
                  ", want 1 and 9, no error");
}

// (c) the host calculation: values worked out by hand from the rule
//     pace_m = smallest M with M * 10 ns > N * T_s * 1.001 + 1 ns (N = 0 counts as 1).
void test_host(tbu::result& res) {
    struct row {
        double mhz;
        long long n;
        int want;
    };
    const row rows[] = {
        {25.0, 15, 61},  // issue 36: hostmot2, LinuxCNC defaults (measured: 61)
        {50.0, 15, 31},  // issue 36: sample rate = the card clock (measured: 31)
        {50.0, 3, 7},    // issue 36: filter "off" = 3 samples at 50 MHz (measured: 7)
        {50.0, 0, 3},    // 20 ns + margin -> 3
        {50.0, 1, 3},    // 1 = off as well
        {50.0, 4, 9},    {50.0, 8, 17}, {100.0, 0, 2}, {100.0, 4, 5}, {100.0, 8, 9},
        {400.0, 1, 2},   // a fast sampler: the register minimum
        {40.0, 5, 13},   // 125 ns * 1.001 + 1 = 126.1 ns -> 13
        {25.0, 16000, 64065},  // 640 000 ns * 1.001 + 1 = 640 641 ns -> 64 065
    };
    for (const row& r : rows) {
        const lxt::pacing_result p = lxt::min_safe_pace_m(r.mhz, r.n);
        res.check(p.ok && p.pace_m == r.want, "min_safe_pace_m(" + std::to_string(r.mhz) + ", " + std::to_string(r.n) +
                                                  ") = " + std::to_string(p.pace_m) + " (" + p.error + "), want " +
                                                  std::to_string(r.want));
    }
    // our clock other than 100 MHz: 50 MHz (20 ns): 25 MHz, 15 samples: 601 ns -> 31
    const lxt::pacing_result p50 = lxt::min_safe_pace_m(25.0, 15, 50.0);
    res.check(p50.ok && p50.pace_m == 31, "min_safe_pace_m(25, 15, clock 50) = " + std::to_string(p50.pace_m) + ", want 31");
    // speed: one count of 78.125 nm per M clocks of 10 ns
    const lxt::pacing_speed s61 = lxt::max_speed_for_pace_m(61);
    res.check(s61.ok && std::fabs(s61.counts_per_s - 1e8 / 61) < 1e-3 && std::fabs(s61.mm_per_s - 7812.5 / 61) < 1e-9,
              "speed at 61: " + std::to_string(s61.mm_per_s) + " mm/s, want 128.0738");
    const lxt::pacing_speed s4 = lxt::max_speed_for_pace_m(4);
    res.check(s4.ok && std::fabs(s4.mm_per_s - 1953.125) < 1e-9, "speed at 4: " + std::to_string(s4.mm_per_s));
    const lxt::pacing_result p61 = lxt::min_safe_pace_m(25.0, 15);
    res.check(std::fabs(p61.max_mm_per_s - 7812.5 / 61) < 1e-9, "min_safe_pace_m's speed " + std::to_string(p61.max_mm_per_s));
    // invalid inputs: an error, never a crash
    const double nan = std::nan(""), inf = HUGE_VAL;
    const double bad_mhz[] = {0.0, -25.0, nan, inf, -inf};
    for (double b : bad_mhz) {
        const lxt::pacing_result p = lxt::min_safe_pace_m(b, 15);
        res.check(!p.ok && !p.error.empty(), "sample MHz " + std::to_string(b) + " accepted");
        const lxt::pacing_result q = lxt::min_safe_pace_m(25.0, 15, b);
        res.check(!q.ok && !q.error.empty(), "clock MHz " + std::to_string(b) + " accepted");
        const lxt::pacing_speed sp = lxt::max_speed_for_pace_m(10, b);
        res.check(!sp.ok && !sp.error.empty(), "speed: clock MHz " + std::to_string(b) + " accepted");
    }
    const lxt::pacing_result neg = lxt::min_safe_pace_m(25.0, -1);
    res.check(!neg.ok && !neg.error.empty(), "filter -1 accepted");
    const lxt::pacing_result longf = lxt::min_safe_pace_m(25.0, 16400);  // 65 666 clocks
    res.check(!longf.ok && longf.error.find("65535") != std::string::npos, "filter 16400 at 25 MHz: " + longf.error);
    const lxt::pacing_result huge = lxt::min_safe_pace_m(1e-300, 1000000000000LL);
    res.check(!huge.ok && !huge.error.empty(), "an absurdly long filter accepted");
    for (long long m : {-1LL, 0LL, 1LL, 65536LL}) {
        const lxt::pacing_speed sp = lxt::max_speed_for_pace_m(m);
        res.check(!sp.ok && !sp.error.empty(), "speed for pace_m " + std::to_string(m) + " accepted");
    }
    res.check(lxt::max_speed_for_pace_m(65535).ok && lxt::max_speed_for_pace_m(2).ok, "pace_m 2 / 65535 refused");
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 36);
    tbu::result res("tb_controller_counter", seed);
    test_host(res);
    test_quad_error(res);
    test_model_against_rule(res, seed);
    return res.finish();
}
