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
// Before the random run, a directed case (restart_edge below) replays the sequence the 10^9 soak
// found at seed 1000000007, call 244585403, with a negative control.
// --trace-from T prints the pins, the registers, the flags and the bookkeeping of calls T..T+2999.
#include <cstdio>
#include <random>

#include "tb/tb_util.h"
#include "sysmodel/sim.h"

namespace {

const int kPresets[5] = {256, 320, 512, 640, 1280};

// Raw-count integrity bookkeeping: the testbench as a host with an independent reference, the
// true fringe index n. At a quiet point (kQuiet calls in a row with n unchanged, no glitch on the
// pins, the laser error pin low and the chain running) the decoder has counted every edge it is
// going to count, so n - raw_count is the same at every quiet point unless a flag was raised in
// between; after a flagged event the next quiet point re-synchronises (and asks for a clear).
//
// A safe-state call (cfg_err) ends the quiet window like a pin event: its raw count is the reset
// value 0 and counts nothing, and the restarted decoder takes its reference from the pins of the
// first running call (DESIGN 4.1: the filter's first output is pin(0) of the first call after
// reset; 4.7: the counts that arrive while the configuration is invalid are not counted, flagged
// by cfg_err). An edge between the last safe-state call and the first running call is one of
// those counts, so the re-sync must come from a window of running calls after that reference.
class raw_integrity {
public:
    static constexpr long long kQuiet = 40;  // above the decoder latency (max(glitch_n,1) + 1 <= 5)

    // One call: n the true index after the call, n_moved whether it changed in this call,
    // glitching / lerr_pin the pin disturbances of this call, g the golden outputs of this call.
    // Returns "" or the text of a count lost without a flag.
    std::string observe(long long t, int64_t n, bool n_moved, bool glitching, bool lerr_pin,
                        const golden::axis_out& g) {
        if (g.cfg_err || g.illegal_st || g.lerr_alarm || g.glitch_st || g.ovs_edge_st || lerr_pin) dirty_ = true;
        quiet_ = (!n_moved && !glitching && !lerr_pin && !g.cfg_err) ? quiet_ + 1 : 0;
        if (quiet_ != kQuiet) return "";
        if (dirty_) {
            offset_ = n - g.raw_count;
            dirty_ = false;
            want_clear_ = true;
            ++resyncs_;
            return "";
        }
        ++checks_;
        if (n - g.raw_count == offset_) return "";
        return "cycle " + std::to_string(t) + ": raw count " + std::to_string(g.raw_count) +
               " lost counts without a flag (true " + std::to_string(n) + ", offset " + std::to_string(offset_) + ")";
    }
    // The host's clear after a re-sync (presented by the caller in the next call it can).
    bool take_clear() {
        const bool c = want_clear_;
        want_clear_ = false;
        return c;
    }
    bool dirty() const { return dirty_; }
    long long quiet() const { return quiet_; }
    int64_t offset() const { return offset_; }
    long long checks() const { return checks_; }
    long long resyncs() const { return resyncs_; }

private:
    bool dirty_ = true;  // a flagged event since the last sync (power-up: no sync yet)
    int64_t offset_ = 0;
    long long quiet_ = 0;
    bool want_clear_ = false;
    long long checks_ = 0, resyncs_ = 0;
};

// Directed regression for the soak failure at seed 1000000007 (call 244585403): the settings of
// that moment (P = 512, glitch_n = 0, min_spacing = 26), the axis moving backwards one edge every
// 41 calls; tbl_period != period makes the configuration invalid for several edges (quiet points
// fall inside the safe state) and is restored so that the last safe-state call is a quiet point and
// the axis moves in the first running call. That edge is not counted (DESIGN 4.1 / 4.7) and the
// bookkeeping must not take the safe state's raw count 0 as a reference for it.
// phantom: negative control, the true index moves once more after the restart while the pins stay
// (a count lost without a flag): the bookkeeping must report it at the next quiet point.
void restart_edge(tbu::result& res, bool phantom) {
    const std::string tag = phantom ? "restart_edge (phantom count): " : "restart_edge: ";
    lxt::axis_settings s;
    s.period = s.tbl_period = 512;
    s.mark_len = 200;
    s.glitch_n = 0;
    s.min_spacing = 26;
    s.sw_debounce = 8;
    s.pace_m = 2;
    s.backlog_thr = 64;
    lxt::dual_axis ax(s);
    raw_integrity ri;

    const long long kSpace = 41;                       // calls between edges (the soak's spacing 40)
    const long long t_move = 300, kEdges = 24;         // edges at t_move + kSpace * k, k < kEdges
    const long long t_bad = t_move + 3 * kSpace + 20;  // tbl_period = P + 8 presented here
    const long long t_good = t_move + 10 * kSpace + 40;  // P presented here: the last safe-state call
    const long long k_phantom = 15;                    // after the first re-sync following the restart
    const long long t_end = t_move + kEdges * kSpace + 300;

    int64_t n = 1735, pin_n = n;
    int64_t n_first_running = 0;  // n in the first running call after the restart
    long long last_edge = -1;
    long long losses = 0, first_loss = -1, safe_calls = 0;
    bool quiet_at_last_safe = false, moved_at_first_running = false;
    for (long long t = 0; t < t_end; ++t) {
        lxt::axis_settings ns = ax.settings();
        ns.clear = ri.take_clear();
        if (t == t_bad) ns.tbl_period = ns.period + 8;
        if (t == t_good) ns.tbl_period = ns.period;
        ax.set(ns);

        const bool edge = t >= t_move && (t - t_move) % kSpace == 0 && (t - t_move) / kSpace < kEdges;
        if (edge) {
            --n;
            last_edge = t;
            if (!(phantom && (t - t_move) / kSpace == k_phantom)) --pin_n;
        }
        lx::axis_pins p;
        lxt::quad_pins(pin_n, p.a, p.b);
        const std::string m = ax.step(p);
        res.expect(m.empty(), [&] { return tag + "cycle " + std::to_string(t) + ": " + m; });
        const golden::axis_out& g = ax.gold();

        // register stage (DESIGN 4.7): presented in call c, in force (and checked) in call c + 1
        const bool want_safe = t > t_bad && t <= t_good;
        res.expect(g.cfg_err == want_safe, [&] { return tag + "cycle " + std::to_string(t) + ": cfg_err " +
                                                        std::to_string(g.cfg_err); });
        if (g.cfg_err) ++safe_calls;
        const std::string loss = ri.observe(t, n, edge, false, false, g);
        if (!loss.empty() && losses++ == 0) first_loss = t;
        if (t == t_good) quiet_at_last_safe = t - last_edge == raw_integrity::kQuiet;
        if (t == t_good + 1) {
            moved_at_first_running = edge;
            n_first_running = n;
        }
    }
    // the stimulus hits the sequence (else this case tests nothing): the last safe-state call ends
    // a window of kQuiet calls without an edge, the first running call has one
    res.check(safe_calls > 3 * kSpace && moved_at_first_running && quiet_at_last_safe,
              tag + "stimulus misses the sequence (safe calls " + std::to_string(safe_calls) + ")");
    if (!phantom) {
        res.check(losses == 0, tag + std::to_string(losses) + " quiet points report a lost count, first at cycle " +
                                   std::to_string(first_loss));
        // the restarted count's reference is the pins of the first running call: every later edge counts
        res.check(ax.gold().raw_count == n - n_first_running,
                  tag + "raw count " + std::to_string(ax.gold().raw_count) + ", want " +
                      std::to_string(n - n_first_running) + " (edges after the first running call)");
    } else {
        const long long t_want = t_move + k_phantom * kSpace + raw_integrity::kQuiet;
        res.check(losses > 0 && first_loss == t_want, tag + "the lost count is reported first at cycle " +
                                                          std::to_string(first_loss) + ", want " + std::to_string(t_want));
    }
    std::printf("  %s%lld safe-state calls, %lld quiet-point checks, %lld re-syncs, %lld reported losses\n",
                tag.c_str(), safe_calls, ri.checks(), ri.resyncs(), losses);
}

// Directed case for tick's fast path (hls/laserax_top.h): clear and rehome held at 1 for many
// calls with the registers otherwise unchanged (the random run below presents them as one-call
// pulses only). While clear is held, single-call glitches on A set glitch_st, which every held
// call clears again; while rehome is held, the axis goes back below the switch and across it, so
// the capture takes the window (stage 2) and the held rehome leaves it in the next call. Every
// output and tap of hls against golden in every call; the stimulus must hit both sequences.
void held_levels(tbu::result& res) {
    const std::string tag = "held_levels: ";
    lxt::axis_settings s;
    s.glitch_n = 2;
    s.min_spacing = 8;
    s.sw_debounce = 8;
    s.pace_m = 2;
    lxt::dual_axis ax(s);
    const int64_t sw_edge = 100;  // switch closed for n >= sw_edge
    const long long kSpace = 20;  // calls between edges while moving
    // forward to n = 300 (homes), rehome held in [t_r0, t_r1) while the axis goes back to n = 60
    // and forward to n = 200, clear held in [t_c0, t_c1) with a glitch on A every 60 calls
    const long long t_r0 = 7000, t_r1 = 15000, t_c0 = 16000, t_c1 = 18000, t_end = 19000;
    int64_t n = 0;
    long long glitch_set = 0, glitch_cleared = 0, windows_left = 0, mismatches = 0;
    bool homed_before = false;
    for (long long t = 0; t < t_end && mismatches < 5; ++t) {
        lxt::axis_settings ns = ax.settings();
        ns.rehome = t >= t_r0 && t < t_r1;
        ns.clear = t >= t_c0 && t < t_c1;
        ax.set(ns);
        if (t % kSpace == 0) {
            if (t < t_r0) {
                if (n < 300) ++n;
            } else if (t < t_r0 + 250 * kSpace) {
                if (n > 60) --n;
            } else if (n < 200) {
                ++n;
            }
        }
        lx::axis_pins p;
        lxt::quad_pins(n, p.a, p.b);
        const bool glitch = t >= t_c0 + 10 && t < t_c1 - 10 && (t - t_c0) % 60 == 0;
        if (glitch) p.a = !p.a;
        p.sw = n >= sw_edge;
        const std::string m = ax.step(p);
        if (!res.expect(m.empty(), [&] { return tag + "cycle " + std::to_string(t) + ": " + m; })) ++mismatches;
        const golden::axis_out& g = ax.gold();
        if (t == t_r0) homed_before = g.homed;
        // (the register stage: a level presented in call t is in force from call t + 1)
        if (t > t_r0 + 1 && t < t_r1 && g.stage == 2) ++windows_left;
        if (t > t_c0 + 1 && t < t_c1 && g.glitch_st) ++glitch_set;
        if (t > t_c0 + 1 && t < t_c1 && !g.glitch_st && glitch_set > 0) ++glitch_cleared;
    }
    res.check(homed_before && windows_left > 0 && glitch_set > 0 && glitch_cleared > 0,
              tag + "stimulus misses the sequences (homed before rehome " + std::to_string(homed_before) +
                  ", stage-2 calls under rehome " + std::to_string(windows_left) + ", glitch_st set / cleared calls under clear " +
                  std::to_string(glitch_set) + " / " + std::to_string(glitch_cleared) + ")");
    std::printf("  %sstage-2 calls under a held rehome %lld, glitch_st set / cleared under a held clear %lld / %lld\n",
                tag.c_str(), windows_left, glitch_set, glitch_cleared);
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 20261121);
    const long long cycles = tbu::arg_ll(argc, argv, "--cycles", 10000000);
    const long long trace_from = tbu::arg_ll(argc, argv, "--trace-from", -1);
    tbu::result res("tb_chain_random", seed);
    restart_edge(res, false);
    restart_edge(res, true);
    held_levels(res);
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

    raw_integrity ri;  // the testbench acts like a host: after reading flags, clear them
    long long mismatches = 0;
    bool want_clear = false;

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
        const long long checks_before = ri.checks();
        const std::string loss = ri.observe(t, n, n != n_before, glitching, p.lerr, g);
        if (!loss.empty() || ri.checks() != checks_before) res.check(loss.empty(), loss);
        if (ri.take_clear()) want_clear = true;
        if (trace_from >= 0 && t >= trace_from && t < trace_from + 3000) {
            const lxt::axis_settings& ps = ax.settings();  // presented in this call, in force in the next
            std::printf("T %lld n=%lld ab=%d%d lerr=%d gl=%d | P=%lld tP=%lld gn=%lld ms=%lld clr=%d reh=%d | cfg=%d "
                        "raw=%lld st=%d il=%d la=%d gs=%d ovs=%d | dirty=%d q=%lld off=%lld\n",
                        t, static_cast<long long>(n), p.a, p.b, p.lerr, glitching, static_cast<long long>(ps.period),
                        static_cast<long long>(ps.tbl_period), static_cast<long long>(ps.glitch_n),
                        static_cast<long long>(ps.min_spacing), ps.clear, ps.rehome, g.cfg_err,
                        static_cast<long long>(g.raw_count), g.step, g.illegal_st, g.lerr_alarm, g.glitch_st,
                        g.ovs_edge_st, ri.dirty(), ri.quiet(), static_cast<long long>(ri.offset()));
        }
        if ((t & ((1 << 22) - 1)) == 0 && t > 0) std::printf("  %lld calls...\n", t);
    }
    std::printf("  raw-count integrity checked at %lld quiet points, %lld re-syncs after flagged events\n",
                ri.checks(), ri.resyncs());
    std::printf("  calls %llu, final raw %lld comp %lld out %lld stage %d\n",
                static_cast<unsigned long long>(ax.calls()), static_cast<long long>(ax.gold().raw_count),
                static_cast<long long>(ax.gold().comp_pos), static_cast<long long>(ax.gold().out_pos),
                ax.gold().stage);
    // tick's fast path (the path the bench measures) runs in every call after one without a
    // register write: most calls here, as the registers change rarely (lxt::dual_axis::set writes
    // only changed settings)
    std::printf("  register writes %llu (the other calls run tick's fast path)\n",
                static_cast<unsigned long long>(ax.writes()));
    res.check(ax.writes() * 4 < ax.calls(), "register writes in " + std::to_string(ax.writes()) + " of " +
                                                std::to_string(ax.calls()) + " calls: the fast path is hardly run");
    return res.finish();
}
