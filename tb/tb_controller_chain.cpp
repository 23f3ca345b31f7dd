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
//   * it latches the index on the rising edge of qz at the count of the qz rise at our pins.
// And the failing case: the same run with pace_m at a third of the rule loses counts (the count does
// not match), so the check can fail. Seeds vary the power-up position and the controller's phase.
#include <cstdio>
#include <string>

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

struct run_out {
    bool ran = false;
    std::string mismatch;
    int64_t want = 0, got = 0;
    uint64_t qerr = 0;
    size_t index_events = 0;
    int64_t index_got = 0, index_want = 0;
    bool index_seen = false;
};

run_out one_run(const ctl_input& in, int pace_m, int dir, uint64_t seed) {
    lxt::homing_params p;
    p.dir = dir;
    p.seed = seed;
    p.pace_m = pace_m;
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
    lxtb::controller_counter ctl(c);
    run_out r;
    int64_t hist[3] = {0, 0, 0};  // out_pos of calls t-1 .. t-3
    bool last_a = false, last_b = false, last_z = false;
    bool z_prev = false;
    const lxt::homing_result h = lxt::run_homing(p, [&](const lxt::trace_row& row) {
        const lx::axis_out& o = row.out;
        ctl.clock(o.qa, o.qb, o.qz);
        if (o.qz && !z_prev && !r.index_seen) {
            r.index_seen = true;
            r.index_want = hist[2];  // the pins of this call: out_pos of call t - 3
        }
        z_prev = o.qz;
        last_a = o.qa;
        last_b = o.qb;
        last_z = o.qz;
        r.want = hist[2];
        hist[2] = hist[1];
        hist[1] = hist[0];
        hist[0] = o.out_pos.to_int64();
    });
    for (int k = 0; k < 20000; ++k) ctl.clock(last_a, last_b, last_z);  // the filter settles
    r.ran = h.events.size() == 4 && h.events[3].cycle >= 0;
    r.mismatch = h.mismatch;
    r.got = ctl.count();
    r.qerr = ctl.quad_errors();
    r.index_events = ctl.index_counts().size();
    if (!ctl.index_counts().empty()) r.index_got = ctl.index_counts()[0];
    return r;
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
                const uint64_t seed = seed0 + static_cast<uint64_t>(k);
                const run_out r = one_run(in, rule.pace_m, dir, seed);
                const std::string ctx = std::string(in.name) + ", pace_m " + std::to_string(rule.pace_m) + ", dir " +
                                        std::to_string(dir) + ", seed " + std::to_string(seed);
                res.check(r.ran, ctx + ": the homing run did not reach C");
                res.check(r.mismatch.empty(), ctx + ": " + r.mismatch);
                res.check(r.got == r.want && r.qerr == 0,
                          ctx + ": the controller counted " + std::to_string(r.got) + ", out_pos " +
                              std::to_string(r.want) + ", quadrature errors " + std::to_string(r.qerr));
                res.check(r.index_seen && r.index_events >= 1 && r.index_got == r.index_want,
                          ctx + ": index latched at " + std::to_string(r.index_got) + ", qz rose at out_pos " +
                              std::to_string(r.index_want) + " (" + std::to_string(r.index_events) + " latches)");
                std::printf("  %s: %lld counts, 0 lost, index at %lld\n", ctx.c_str(), static_cast<long long>(r.got),
                            static_cast<long long>(r.index_got));
            }
        }
        // below the rule: the counter loses counts (the filter swallows levels that are too short:
        // at a third of the rule, a line's level in a burst, two counts, is shorter than the filter)
        const int low = rule.pace_m / 3 < 2 ? 0 : rule.pace_m / 3;
        if (low >= 2) {
            const run_out r = one_run(in, low, 1, seed0);
            res.check(r.mismatch.empty(), std::string(in.name) + " below the rule: " + r.mismatch);
            res.check(r.got != r.want, std::string(in.name) + ": at pace_m " + std::to_string(low) +
                                           " (below the rule's " + std::to_string(rule.pace_m) +
                                           ") the controller still counted every count");
            std::printf("  %s, pace_m %d (below the rule): counted %lld of out_pos %lld, %llu quadrature errors\n",
                        in.name, low, static_cast<long long>(r.got), static_cast<long long>(r.want),
                        static_cast<unsigned long long>(r.qerr));
        }
    }
    return res.finish();
}
