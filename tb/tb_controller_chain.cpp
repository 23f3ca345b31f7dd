// ctest-args-types: --seeds 1
// tb_controller_chain — the chain's digital outputs through a controller-side counter (issue 36).
//
// Homing runs of the whole chain (sysmodel run_homing: golden and hls compared on every call,
// the qa/qb spacing checked on every call) drive a controller's quadrature counter
// (tb/controller_counter.h: its own clock at a non-integer ratio to ours, a sample-rate enable,
// an N-sample integrating filter, a 4x decoder, an index latch) through qa/qb/qz, with pace_m
// the smallest the pacing rule allows for that controller input (host/pacing.h,
// docs/CONTROLLER.md). Every run crosses the referencing window (Stage 2, where the extra counts
// of rephase are paid out) and the homing count. For each controller input and both homing
// directions:
//   * the counter sees every output count: after the run (pins held for the filter to settle)
//     its count equals out_pos of the last pins (the pins of call t are out_pos of call t - 3),
//     with no quadrature error;
//   * the index (qz: one quadrature state at Z, in the A/B state of DESIGN 4.7's ab_rot rule) is
//     crossed in the homing direction and back: latches on its rising edge, ungated and gated at
//     the index state, latch Z both times; on its falling edge Z + 1 moving up, Z - 1 moving
//     down; gated at another A/B state, never; at ab_rot 0 and 2 (the first seed);
//   * the safe state is not silent: q_oe falls with the safe-state pins (hiz_alarm, reset) and
//     the controller's line-fault detection fires; with hiz_alarm = 0 it does not.
// And the failing case: the same run with pace_m at a third of the rule loses counts (the count does
// not match), so the check can fail. Seeds vary the power-up position and the controller's phase.
#include <cstdio>
#include <string>
#include <vector>

#include "host/pacing.h"
#include "sysmodel/homing.h"
#include "tb/controller_counter.h"
#include "tb/tb_util.h"

namespace {

struct ctl_input {
    const char* name;
    double clock_mhz;  // the controller's clock
    int sample_div;
    int filter_n;
};

// three controller inputs of docs/CONTROLLER.md's table, at clocks slightly off nominal
const ctl_input kInputs[] = {
    {"hostmot2 defaults (25 MHz sampling, 15 samples)", 49.997, 2, 15},
    {"counter at 50 MHz, 4-sample filter", 50.003, 1, 4},
    {"counter at 100 MHz, no filter", 99.991, 1, 0},
};

// the index latches each run drives beside the counter of the count check: the index as the
// controller's rules see it (docs/CONTROLLER.md, "Index latching")
enum latch_kind { RISE, FALL, GATED_RISE, GATED_FALL, GATED_WRONG, N_LATCH };
const char* const kLatchName[N_LATCH] = {"rising edge", "falling edge", "gated rising edge",
                                         "gated falling edge", "gated at the wrong A/B state"};

struct run_out {
    bool ran = false;
    std::string mismatch;
    int64_t want = 0, got = 0;
    uint64_t qerr = 0;
    size_t qz_rises = 0;                 // index pulses at our pins
    int64_t z_out = 0;                   // the home point Z in output counts (z_pos + adj, homed)
    int64_t base = 0;                    // out_pos at the pins of the counters' first call
    int index_ab = -1;                   // quadrature index (0..3) of the pins while qz is high
    std::vector<int64_t> latch[N_LATCH]; // each latch counter's latched counts
};

run_out one_run(const ctl_input& in, int pace_m, int dir, uint64_t seed, int ab_rot) {
    lxt::homing_params p;
    p.dir = dir;
    p.seed = seed;
    p.pace_m = pace_m;
    p.pin_cfg = 8 | (ab_rot << 1);
    p.return_pass = true;  // Z crossed in the homing direction, then back the other way
    // above the 128 mm/s that pace_m 61 allows: with the hostmot2 input the pacer runs at its
    // full rate, in bursts of counts exactly M (2M in the window) clocks apart
    p.speed_mm_s = 150.0;
    lxtb::controller_cfg c;
    c.ctl_clock_mhz = in.clock_mhz;
    c.sample_div = in.sample_div;
    c.filter_n = in.filter_n;
    c.phase_ns = 0.37 + static_cast<double>(seed % 97) * 0.113;
    c.aperture_ns = 1.0;
    c.seed = seed;
    c.prime = true;
    lxtb::controller_counter ctl(c);
    // the latches: without the metastable aperture for the ungated and the falling ones (Z and
    // A/B change at the same clock edge; an aperture can resolve them a sample apart, one count
    // off: docs/CONTROLLER.md), with it for the gated rising edge, which is exact in every case.
    // The gate state is that of the index state at our pins, the ab_rot rule of DESIGN 4.7:
    // (P/8 + ab_rot) mod 4 (P = 256: (0, 0) at ab_rot 0, (1, 1) at ab_rot 2)
    const int gate_i = (p.period / 8 + ab_rot) % 4;
    const bool ga = gate_i == 1 || gate_i == 2, gb = gate_i == 2 || gate_i == 3;
    std::vector<lxtb::controller_counter> latches;
    for (int k = 0; k < N_LATCH; ++k) {
        lxtb::controller_cfg lc = c;
        lc.aperture_ns = k == GATED_RISE ? 1.0 : 0.0;
        lc.index_rising = k == RISE || k == GATED_RISE || k == GATED_WRONG;
        lc.index_gate = k >= GATED_RISE;
        lc.gate_a = k == GATED_WRONG ? !ga : ga;
        lc.gate_b = k == GATED_WRONG ? !gb : gb;
        latches.emplace_back(lc);
    }
    run_out r;
    int64_t hist[3] = {0, 0, 0};  // out_pos of calls t-1 .. t-3
    bool last_a = false, last_b = false, last_z = false;
    bool z_prev = false;
    long long calls = 0;
    const lxt::homing_result h = lxt::run_homing(p, [&](const lxt::trace_row& row) {
        const lx::axis_out& o = row.out;
        // the counters start at call 4 (the power-up call shows the reset pins, the first running
        // calls the levels of ab_rot at out_pos 0), primed on the pins there
        if (calls == 4) r.base = hist[2];
        if (calls >= 4) {
            ctl.clock(o.qa, o.qb, o.qz);
            for (lxtb::controller_counter& l : latches) l.clock(o.qa, o.qb, o.qz);
        }
        ++calls;
        if (o.qz) {
            const int qi = o.qa ? (o.qb ? 2 : 1) : (o.qb ? 3 : 0);
            if (r.index_ab < 0) r.index_ab = qi;
            if (r.index_ab != qi) r.index_ab = 4;  // qz high over more than one state
        }
        if (o.qz && !z_prev) ++r.qz_rises;
        z_prev = o.qz;
        last_a = o.qa;
        last_b = o.qb;
        last_z = o.qz;
        if (o.homed) r.z_out = o.z_pos.to_int64() + o.adj.to_int64();
        r.want = hist[2];
        hist[2] = hist[1];
        hist[1] = hist[0];
        hist[0] = o.out_pos.to_int64();
    });
    for (int k = 0; k < 20000; ++k) {  // the filters settle
        ctl.clock(last_a, last_b, last_z);
        for (lxtb::controller_counter& l : latches) l.clock(last_a, last_b, last_z);
    }
    r.ran = h.events.size() == 4 && h.events[3].cycle >= 0;
    r.mismatch = h.mismatch;
    r.got = ctl.count() + r.base;
    r.qerr = ctl.quad_errors();
    for (int k = 0; k < N_LATCH; ++k)
        for (int64_t v : latches[static_cast<size_t>(k)].index_counts()) r.latch[k].push_back(v + r.base);
    return r;
}

std::string list(const std::vector<int64_t>& v) {
    std::string s = "{";
    for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
    return s + "}";
}

// The safe state at the pins: an invalid register (pace_m = 1) while running. With hiz_alarm
// (the reset value) q_oe falls in the call whose pins drop to the safe levels, so a controller
// watching its lines sees the alarm; with hiz_alarm = 0 it stays high.
void safe_state_at_pins(tbu::result& res) {
    for (const bool hiz : {true, false}) {
        lxt::axis_settings s;
        s.pin_cfg = hiz ? 8 : 0;
        lxt::dual_axis ax(s);
        lxtb::controller_cfg c;
        c.prime = true;
        lxtb::controller_counter ctl(c);
        bool oe_low_in_safe = true, oe_high_running = true, any_safe = false;
        int64_t n = 0;
        for (long long t = 0; t < 3000; ++t) {
            if (t == 2000) {
                lxt::axis_settings bad = ax.settings();
                bad.pace_m = 1;
                ax.set(bad);
            }
            if (t % 7 == 0 && t < 1900) ++n;  // some motion first
            lx::axis_pins pins;
            lxt::quad_pins(n, pins.a, pins.b);
            const std::string m = ax.step(pins);
            res.check(m.empty(), "safe state at the pins: " + m);
            const lx::axis_out& o = ax.hls();
            if (o.cfg_err) {
                any_safe = true;
                if (o.q_oe != !hiz) oe_low_in_safe = false;
            } else if (t > 0 && !o.alarm && !o.q_oe) {
                oe_high_running = false;
            }
            if (t >= 4) ctl.clock(o.qa, o.qb, o.qz, o.q_oe);
        }
        const std::string ctx = std::string("safe state, hiz_alarm ") + (hiz ? "1" : "0");
        res.check(any_safe, ctx + ": pace_m = 1 did not reach the safe state");
        res.check(oe_low_in_safe, ctx + ": q_oe in the safe-state calls is not " + (hiz ? "0" : "1"));
        res.check(oe_high_running, ctx + ": q_oe low in a running call without an alarm");
        res.check(ctl.line_fault() == hiz, ctx + ": the controller's line-fault detection " +
                                               (ctl.line_fault() ? "fired" : "did not fire"));
        std::printf("  %s: q_oe %d in the safe state, controller line fault %d\n", ctx.c_str(), hiz ? 0 : 1,
                    ctl.line_fault() ? 1 : 0);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed0 = tbu::seed_from(argc, argv, 7);
    const long long seeds = tbu::arg_ll(argc, argv, "--seeds", 2);
    tbu::result res("tb_controller_chain", seed0);
    for (const ctl_input& in : kInputs) {
        const double sample_mhz = in.clock_mhz / in.sample_div;
        const lxt::pacing_result rule = lxt::min_safe_pace_m(sample_mhz, in.filter_n);
        if (!res.check(rule.ok, std::string("pacing rule for ") + in.name + ": " + rule.error)) continue;
        for (long long k = 0; k < seeds; ++k) {
            for (int dir : {1, -1}) {
                for (int ab_rot : {0, 2}) {
                    if (ab_rot != 0 && k != 0) continue;  // the rotation at the first seed
                    const uint64_t seed = seed0 + static_cast<uint64_t>(k);
                    const run_out r = one_run(in, rule.pace_m, dir, seed, ab_rot);
                    const std::string ctx = std::string(in.name) + ", pace_m " + std::to_string(rule.pace_m) +
                                            ", dir " + std::to_string(dir) + ", ab_rot " + std::to_string(ab_rot) +
                                            ", seed " + std::to_string(seed);
                    res.check(r.ran, ctx + ": the homing run did not reach C");
                    res.check(r.mismatch.empty(), ctx + ": " + r.mismatch);
                    res.check(r.got == r.want && r.qerr == 0,
                              ctx + ": the controller counted " + std::to_string(r.got) + ", out_pos " +
                                  std::to_string(r.want) + ", quadrature errors " + std::to_string(r.qerr));
                    // the index at our pins: one pulse per crossing of Z (homing direction, then
                    // back), one quadrature state wide, in the state DESIGN 4.7 names
                    const int want_ab = (256 / 8 + ab_rot) % 4;
                    res.check(r.qz_rises == 2 && r.index_ab == want_ab,
                              ctx + ": qz rose " + std::to_string(r.qz_rises) + " times (want 2), A/B state index " +
                                  std::to_string(r.index_ab) + " while high (want " + std::to_string(want_ab) + ")");
                    // every latch: rising edges at Z from both sides, falling edges one count past
                    // it in the direction of travel, none gated at the wrong state
                    const std::vector<int64_t> want[N_LATCH] = {
                        {r.z_out, r.z_out}, {r.z_out + dir, r.z_out - dir}, {r.z_out, r.z_out},
                        {r.z_out + dir, r.z_out - dir}, {}};
                    for (int l = 0; l < N_LATCH; ++l)
                        res.check(r.latch[l] == want[l], ctx + ": " + kLatchName[l] + " latched " + list(r.latch[l]) +
                                                             ", want " + list(want[l]));
                    std::printf("  %s: %lld counts, 0 lost, Z at %lld: rising %s, falling %s, gated rising %s, "
                                "gated falling %s, wrong gate %zu latches\n",
                                ctx.c_str(), static_cast<long long>(r.got), static_cast<long long>(r.z_out),
                                list(r.latch[RISE]).c_str(), list(r.latch[FALL]).c_str(),
                                list(r.latch[GATED_RISE]).c_str(), list(r.latch[GATED_FALL]).c_str(),
                                r.latch[GATED_WRONG].size());
                }
            }
        }
        // below the rule: the counter loses counts (the filter swallows levels that are too short:
        // at a third of the rule, a line's level in a burst, two counts, is shorter than the filter)
        const int low = rule.pace_m / 3 < 2 ? 0 : rule.pace_m / 3;
        if (low >= 2) {
            const run_out r = one_run(in, low, 1, seed0, 0);
            res.check(r.mismatch.empty(), std::string(in.name) + " below the rule: " + r.mismatch);
            res.check(r.got != r.want, std::string(in.name) + ": at pace_m " + std::to_string(low) +
                                           " (below the rule's " + std::to_string(rule.pace_m) +
                                           ") the controller still counted every count");
            std::printf("  %s, pace_m %d (below the rule): counted %lld of out_pos %lld, %llu quadrature errors\n",
                        in.name, low, static_cast<long long>(r.got), static_cast<long long>(r.want),
                        static_cast<unsigned long long>(r.qerr));
        }
    }
    safe_state_at_pins(res);
    return res.finish();
}
