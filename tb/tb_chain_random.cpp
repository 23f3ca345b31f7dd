// ctest-args: --cycles 10000000
// ctest-args-O0: --cycles 300000
// tb_chain_random — long seeded random run of the whole single-axis chain, hls against golden.
//
// Stimulus (pin level, one call per clock): a fringe index that moves with random speeds, stops
// and reversals; short glitches on A or B (below and above the glitch filter length); illegal
// transitions (A and B flip together); laser error bursts; random ratio and comp_offset updates,
// including large ones while moving; random pacer M and backlog thresholds; switch crossings, rehome and clear
// pulses; occasional period/preset changes and invalid configurations.
// Checks on every call:
//   * every output and every block tap of hls equals the golden model exactly, and the
//     position-integrity invariant holds (lxt::dual_axis: controller decode of sin/cos and A/B
//     == golden out_pos, comp == floor((N*R + OFF) / 2^32) by a 128-bit reference,
//     paced + backlog == comp + corr of three calls earlier);
//   * the decoder's raw count equals the true fringe count except across flagged events: the
//     testbench reads the flags at quiet points, re-synchronises after a flagged event and clears
//     the flags like a host would; a count lost with no flag raised fails the test.
#include <cstdio>
#include <random>

#include "tb/tb_util.h"
#include "tools/common/sim.h"

namespace {

const int kPresets[5] = {256, 320, 512, 640, 1280};

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 20261121);
    const long long cycles = tbu::arg_ll(argc, argv, "--cycles", 10000000);
    tbu::result res("tb_chain_random", seed);
    std::mt19937_64 rng(seed);
    auto uni = [&](long long lo, long long hi) {
        return std::uniform_int_distribution<long long>(lo, hi)(rng);
    };

    lxt::axis_settings s;
    s.glitch_n = 2;
    s.sw_debounce = 8;
    s.pace_m = 2;
    s.backlog_thr = 64;
    s.min_spacing = 8;
    lxt::dual_axis ax(s);

    // true fringe position and stimulus state
    int64_t n = 0;
    long long move_left = 0, idle_left = 200;
    int dirn = 1;
    long long spacing = 20, until_next_edge = 0;
    int glitch_pin = -1;
    long long glitch_left = 0;
    long long lerr_left = 0;
    const int64_t sw_edge = 3000;  // switch closes for n >= sw_edge

    bool dirty = true;  // a flagged event since the last raw-count sync
    int64_t raw_offset = 0;
    long long quiet = 0;
    long long mismatches = 0;
    bool want_clear = false;
    long long integrity_checks = 0, resyncs = 0;  // the testbench acts like a host: after reading flags, clear them

    for (long long t = 0; t < cycles; ++t) {
        lxt::axis_settings ns = ax.settings();
        ns.rehome = false;
        ns.clear = false;
        // ---- register activity
        const long long r = uni(0, 199999);
        if (r < 20) {
            ns.ratio = static_cast<uint64_t>(static_cast<long long>(lxt::ratio_for(632.991, 1.000271, 78.125)) +
                                             uni(-20000000, 20000000));  // +-600 ppm
        } else if (r < 22) {
            ns.ratio = static_cast<uint64_t>(uni(1LL << 32, (1LL << 36) - 1));  // ratio 1..16
        } else if (r < 24) {
            // thermal origin term: up to +-2^16 counts, sometimes anywhere in the register
            ns.comp_offset = uni(0, 9) == 0 ? static_cast<int64_t>(rng()) : uni(-(1LL << 48), 1LL << 48);
        } else if (r < 27) {
            ns.pace_m = uni(2, 6);
            ns.backlog_thr = static_cast<uint64_t>(uni(8, 5000));
        } else if (r < 28 || want_clear) {
            ns.clear = true;
            want_clear = false;
        } else if (r < 30) {
            ns.rehome = true;
        } else if (r < 31) {
            const int p = kPresets[uni(0, 4)];
            ns.period = ns.tbl_period = p;
            ns.mark_len = p / 4 + uni(0, 3 * p / 4);
        } else if (r < 32) {
            // min_spacing above the longest glitch (5 calls): every passing glitch is an
            // overspeed (DESIGN 4.2, count integrity)
            ns.glitch_n = uni(0, 4);
            ns.min_spacing = uni(6, 30);
        } else if (r < 33) {
            ns.tbl_period = ns.period + 8;  // invalid for a while
        } else if (r < 40 && ns.tbl_period != ns.period) {
            ns.tbl_period = ns.period;
        }
        ax.set(ns);

        // ---- motion of the true fringe index
        int64_t n_before = n;
        if (idle_left > 0) {
            --idle_left;
        } else if (move_left > 0) {
            if (until_next_edge-- <= 0) {
                n += dirn;
                --move_left;
                until_next_edge = spacing;
            }
        } else {
            const long long k = uni(0, 9);
            if (k < 3) {
                idle_left = uni(50, 3000);
            } else {
                dirn = uni(0, 1) ? 1 : -1;
                if (n > sw_edge + 4000) dirn = -1;
                if (n < -4000) dirn = 1;
                move_left = uni(1, 3000);
                spacing = uni(0, 9) < 2 ? uni(1, 3) : uni(4, 120);  // sometimes overspeed
            }
        }
        // illegal: both pins flip (never in the same call as a real edge: three transitions
        // inside one clock alias to one and no sampled decoder can see them, DESIGN 4.2)
        if (n == n_before && uni(0, 99999) < 3) n += 2 * (uni(0, 1) ? 1 : -1);
        if (uni(0, 99999) < 20 && glitch_left == 0) {
            glitch_pin = static_cast<int>(uni(0, 1));
            glitch_left = uni(1, 5);
        }
        if (uni(0, 999999) < 5 && lerr_left == 0) lerr_left = uni(1, 400);

        lx::axis_pins p;
        lxt::quad_pins(n, p.a, p.b);
        const bool glitching = glitch_left > 0;
        if (glitching) {
            if (glitch_pin == 0) p.a = !p.a; else p.b = !p.b;
            --glitch_left;
        }
        p.lerr = lerr_left > 0;
        if (lerr_left > 0) --lerr_left;
        p.sw = n >= sw_edge;

        // ---- both models, every output and tap
        const std::string m = ax.step(p);
        if (!res.expect(m.empty(), [&] { return "cycle " + std::to_string(t) + ": " + m; }) && ++mismatches > 5) break;
        const golden::axis_out& g = ax.gold();

        // ---- raw count integrity: no count lost without a flag
        if (g.cfg_err || g.illegal_st || g.lerr_alarm || g.glitch_st || g.ovs_edge_st || p.lerr) dirty = true;
        quiet = (n == n_before && !glitching && !p.lerr) ? quiet + 1 : 0;
        if (quiet == 40) {
            if (dirty) {
                raw_offset = n - g.raw_count;
                dirty = false;
                want_clear = true;
                ++resyncs;
            } else {
                ++integrity_checks;
                res.expect(n - g.raw_count == raw_offset, [&] { return std::string("cycle " + std::to_string(t) + ": raw count " + std::to_string(g.raw_count) +
                              " lost counts without a flag (true " + std::to_string(n) + ", offset " +
                              std::to_string(raw_offset) + ")"); });
            }
        }
        if ((t & ((1 << 22) - 1)) == 0 && t > 0) std::printf("  %lld calls...\n", t);
    }
    std::printf("  raw-count integrity checked at %lld quiet points, %lld re-syncs after flagged events\n",
                integrity_checks, resyncs);
    std::printf("  calls %llu, final raw %lld comp %lld out %lld stage %d\n",
                static_cast<unsigned long long>(ax.calls()), static_cast<long long>(ax.gold().raw_count),
                static_cast<long long>(ax.gold().comp_pos), static_cast<long long>(ax.gold().out_pos),
                ax.gold().stage);
    return res.finish();
}
