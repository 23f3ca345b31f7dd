// ctest-args: --clocks 10000000
// ctest-args-types: --clocks 2000000
// tb_fault_injection — pin-level fault injection into the quad decoder (hls and golden in
// lockstep), with its own position reference: the true fringe index the testbench moves.
//
// The reference is not a model: the testbench moves an integer position (legal speeds: edge
// spacing >= max(min_spacing, glitch filter length), stops, reversals), drives A/B from it
// (quadrature index 0..3 -> (A,B) = 00, 10, 11, 01), and XORs faults onto the pins. After each
// fault and a settling time it compares the decoder's raw count with the reference delayed by the
// decoder latency (max(glitch_n,1) + 1 calls). A change of that difference is a position loss;
// it is *flagged* when a sticky flag (illegal_st, ovs_st (= ovs_edge_st), lerr_alarm, glitch_st)
// rose since the previous check, else *silent*. The flags are then cleared as a host would.
//
// Fault kinds (one at a time, spaced by clean motion):
//   short_glitch   XOR pulse on A or B shorter than the filter (1 .. max(N,1)-1 calls)
//   pass_glitch    XOR pulse on A or B the filter passes, max(N,1) .. 2*min_spacing-1 calls
//                  (the class DESIGN §4.2 covers), often with a real edge of the other line inside
//   long_pulse     XOR pulse of 2*min_spacing .. 2*min_spacing+2N+16 calls: outside the covered
//                  class (indistinguishable from legal motion); counted, never asserted
//   illegal        A and B flipped together for max(N,1) .. 4N+8 calls (two illegal transitions)
//   illegal_alias  an `illegal` fault whose both ends fall in the clock of a real edge: each end
//                  is then a single-line edge in the other direction; outside the class, counted
//   overrate       a burst of 2..40 real edges spaced below min_spacing (down to 1 call)
//   lerr_pulse     laser error line high for 1 .. 4N+40 calls while the axis keeps moving
//   reversal       a real direction change at the current speed (no fault; must never lose)
// Settings: the reset values of lx::axis_regs (asserted: 0 silent losses), legal corners and
// random legal pairs (min_spacing > max(glitch_n, 1), DESIGN §4.2; asserted: 0 silent losses),
// and, as a negative control, the pre-issue-12 reset (glitch_n 2, min_spacing 0, now a
// configuration error): there the test asserts that silent losses DO occur, so it can fail.
// Also checked: hls and golden decoder outputs equal on every call; axis_config_ok (hls) and
// golden::config_ok accept exactly the pairs with min_spacing > max(glitch_n, 1) (exhaustive over
// glitch_n 0..255 x min_spacing 0..65535).
// Options: --clocks N (total faulted clocks over all settings), --seed S.
#include <cinttypes>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "golden/laserax_top.h"
#include "golden/quad_decoder.h"
#include "hls/laserax_top.h"
#include "hls/quad_decoder.h"
#include "tb/tb_util.h"

namespace {

enum kind { SHORT, PASS, LONG, ILLEGAL, ALIAS, OVERRATE, LERR, REVERSAL, NKIND };
const char* const kKindName[NKIND] = {"short_glitch", "pass_glitch", "long_pulse", "illegal",
                                      "illegal_alias", "overrate",   "lerr_pulse", "reversal"};
bool uncovered(int k) { return k == LONG || k == ALIAS; }

struct stats {
    long long faults[NKIND] = {};
    long long losses[NKIND] = {};          // checks where the position error changed
    long long flagged_alarm[NKIND] = {};   // ... and illegal_st / ovs_st / lerr_alarm rose
    long long flagged_glitch[NKIND] = {};  // ... and only glitch_st rose
    long long silent[NKIND] = {};          // ... and no flag rose
    long long silent_counts[NKIND] = {};   // |error change| summed over silent losses
    long long flag_no_loss[NKIND] = {};    // a flag rose, no loss
    long long clocks = 0;
    void add(const stats& o) {
        for (int k = 0; k < NKIND; ++k) {
            faults[k] += o.faults[k];
            losses[k] += o.losses[k];
            flagged_alarm[k] += o.flagged_alarm[k];
            flagged_glitch[k] += o.flagged_glitch[k];
            silent[k] += o.silent[k];
            silent_counts[k] += o.silent_counts[k];
            flag_no_loss[k] += o.flag_no_loss[k];
        }
        clocks += o.clocks;
    }
    long long silent_covered() const {  // every kind but long_pulse
        long long s = 0;
        for (int k = 0; k < NKIND; ++k)
            if (!uncovered(k)) s += silent[k];
        return s;
    }
};

void print_stats(const char* title, const stats& s) {
    std::printf("  %s: %lld faulted clocks\n", title, s.clocks);
    std::printf("    %-13s %10s %9s %13s %14s %8s %13s %12s\n", "kind", "faults", "losses", "flagged_alarm",
                "flagged_glitch", "silent", "silent_counts", "flag_no_loss");
    for (int k = 0; k < NKIND; ++k)
        std::printf("    %-13s %10lld %9lld %13lld %14lld %8lld %13lld %12lld\n", kKindName[k], s.faults[k],
                    s.losses[k], s.flagged_alarm[k], s.flagged_glitch[k], s.silent[k], s.silent_counts[k],
                    s.flag_no_loss[k]);
}

// One run of `clocks` calls at one (glitch_n, min_spacing) setting.
class run {
public:
    run(int glitch_n, int min_spacing, uint64_t seed, tbu::result& res)
        : n_(glitch_n), m_(min_spacing), rng_(seed), res_(res) {}

    stats go(long long clocks) {
        const int nf = n_ < 1 ? 1 : n_;
        lat_ = nf + 1;
        s_lo_ = m_ > nf ? m_ : nf;  // legal real edge spacing
        // the covered glitch class: pulses up to 2*min_spacing - 1 (for min_spacing <= N, the
        // band the legal condition guarantees: up to 2N + 1)
        const int m_eff = m_ > nf ? m_ : nf + 1;
        pass_hi_ = 2 * m_eff - 1;
        settle_ = 4 * nf + 2 * s_lo_ * 2 + 64;
        hist_.assign(1024, 0);
        // warm-up: idle until the filters are valid and the history is filled
        for (int i = 0; i < 600; ++i) clock(false, false, false);
        base_err_ = err();
        read_and_clear();
        while (st_.clocks < clocks) {
            clean_motion(uni(20, 300));
            int k = static_cast<int>(uni(0, NKIND - 1));
            if (k == ALIAS) continue;  // assigned by inject(ILLEGAL)
            k = inject(k);
            if (k < 0) continue;
            ++st_.faults[k];
            clean_motion(settle_);
            evaluate(k);
        }
        return st_;
    }

private:
    long long uni(long long lo, long long hi) { return std::uniform_int_distribution<long long>(lo, hi)(rng_); }

    // One call: pins from the reference position XOR the fault masks.
    void clock(bool xa, bool xb, bool lerr) {
        // motion
        ++since_edge_;
        edge_now_ = false;
        if (dir_ != 0 && since_edge_ >= spacing_) {
            pos_ += dir_;
            since_edge_ = 0;
            edge_now_ = true;
        }
        const unsigned q = static_cast<unsigned>(pos_ & 3);
        const bool a = (q == 1 || q == 2) != xa;
        const bool b = (q == 2 || q == 3) != xb;
        const bool clr = clear_next_;
        clear_next_ = false;
        const lx::quad_decoder::out_t h =
            hdec_.step(a, b, lerr, lx::quad_decoder_cfg::glitch_t(n_), lx::quad_decoder_cfg::spacing_t(m_), clr);
        const golden::quad_decoder::out g = gdec_.step(a, b, lerr, n_, m_, clr);
        const bool same = int(h.step) == g.step && int64_t(int32_t(h.raw_count)) == g.raw_count &&
                          h.illegal == g.illegal && h.ovs == g.ovs && int(h.err_cnt) == g.err_cnt &&
                          h.illegal_st == g.illegal_st && h.ovs_st == g.ovs_st && h.lerr == g.lerr &&
                          h.lerr_alarm == g.lerr_alarm && h.glitch_st == g.glitch_st;
        res_.expect(same, [&] {
            return "hls != golden decoder at clock " + std::to_string(st_.clocks) + " (glitch_n " + std::to_string(n_) +
                   ", min_spacing " + std::to_string(m_) + ")";
        });
        out_ = h;
        if (debug_) {
            char buf[160];
            std::snprintf(buf, sizeof buf, "  t=%lld pos=%lld a=%d b=%d lerr=%d step=%d raw=%d ill=%d ovs=%d gl=%d\n",
                          st_.clocks, (long long)pos_, a, b, lerr, int(h.step), int(int32_t(h.raw_count)),
                          h.illegal_st, h.ovs_st, h.glitch_st);
            trace_[static_cast<size_t>(st_.clocks % 200)] = buf;
        }
        hist_[static_cast<size_t>(st_.clocks & 1023)] = pos_;
        ++st_.clocks;
    }

    // raw count minus the reference of lat_ calls ago (32-bit wrap)
    int64_t err() const {
        const int64_t ref = hist_[static_cast<size_t>((st_.clocks - 1 - lat_) & 1023)];
        return int64_t(int32_t(uint32_t(int64_t(int32_t(out_.raw_count)) - ref)));
    }

    // legal motion: random speed (spacing >= s_lo_), stops, no direction change here
    void clean_motion(long long calls) {
        for (long long i = 0; i < calls; ++i) {
            if (uni(0, 199) == 0) set_speed(static_cast<int>(uni(-1, 1)), static_cast<int>(uni(s_lo_, 8 * s_lo_ + 8)));
            clock(false, false, false);
        }
    }
    void set_speed(int dir, int spacing) {
        // the next edge comes no earlier than `spacing` calls after the previous one
        if (dir != 0 && dir_ != 0 && dir != dir_) dir = dir_;  // reversals are their own kind
        dir_ = dir;
        spacing_ = spacing;
    }

    // Returns the kind injected (ILLEGAL may become ALIAS), or -1 if none.
    int inject(int k) {
        const int nf = n_ < 1 ? 1 : n_;
        switch (k) {
        case SHORT: {
            if (nf <= 1) return -1;  // the filter passes every pulse
            const long long len = uni(1, nf - 1);
            const bool on_a = uni(0, 1) != 0;
            for (long long i = 0; i < len; ++i) clock(on_a, !on_a, false);
            return k;
        }
        case PASS:
        case LONG: {
            const long long lo = k == PASS ? nf : pass_hi_ + 1;
            const long long hi = k == PASS ? pass_hi_ : pass_hi_ + 2 * nf + 16;
            const long long len = uni(lo, hi);
            const bool on_a = uni(0, 1) != 0;
            // moving at the slowest legal spacing that puts a real edge inside the pulse half of
            // the time
            if (dir_ == 0 && uni(0, 1) != 0) set_speed(uni(0, 1) ? 1 : -1, s_lo_);
            for (long long i = 0; i < len; ++i) clock(on_a, !on_a, false);
            return k;
        }
        case ILLEGAL: {
            // both lines flip together; when both ends fall in the clock of a real edge, each end
            // is a single-line edge in the other direction (no sampled decoder can tell): alias
            const long long len = uni(nf, 4 * nf + 8);
            bool start_edge = false;
            for (long long i = 0; i < len; ++i) {
                clock(true, true, false);
                if (i == 0) start_edge = edge_now_;
            }
            clock(false, false, false);
            return start_edge && edge_now_ ? ALIAS : ILLEGAL;
        }
        case OVERRATE: {
            if (s_lo_ <= 1) return -1;
            const int saved_dir = dir_ == 0 ? 1 : dir_, saved_sp = spacing_;
            dir_ = saved_dir;
            spacing_ = static_cast<int>(uni(1, s_lo_ - 1));
            const long long edges = uni(2, 40);
            for (long long i = 0; i < edges * spacing_; ++i) clock(false, false, false);
            spacing_ = saved_sp < s_lo_ ? s_lo_ : saved_sp;
            return k;
        }
        case LERR: {
            const long long len = uni(1, 4 * nf + 40);
            if (dir_ == 0) set_speed(uni(0, 1) ? 1 : -1, static_cast<int>(uni(s_lo_, 4 * s_lo_)));
            for (long long i = 0; i < len; ++i) clock(false, false, true);
            return k;
        }
        case REVERSAL: {
            if (dir_ == 0) {
                dir_ = uni(0, 1) ? 1 : -1;
                spacing_ = static_cast<int>(uni(s_lo_, 2 * s_lo_));
                for (long long i = 0; i < 4 * spacing_; ++i) clock(false, false, false);
            }
            dir_ = -dir_;  // the next edge still comes >= spacing_ after the previous one
            for (long long i = 0; i < 4 * spacing_; ++i) clock(false, false, false);
            return k;
        }
        default:
            return -1;
        }
    }

    // flags that rose since the last check; then a clear pulse in the next call
    void read_and_clear() {
        alarm_ = out_.illegal_st || out_.ovs_st || out_.lerr_alarm;
        glitch_ = out_.glitch_st;
        clear_next_ = true;
    }

    void evaluate(int k) {
        // quiet point: no fault pending, the reference of lat_ calls ago is aligned
        const int64_t e = err();
        read_and_clear();
        const int64_t d = e - base_err_;
        base_err_ = e;
        if (d != 0) {
            ++st_.losses[k];
            if (alarm_) {
                ++st_.flagged_alarm[k];
            } else if (glitch_) {
                ++st_.flagged_glitch[k];
            } else {
                ++st_.silent[k];
                st_.silent_counts[k] += d < 0 ? -d : d;
                if (debug_ && dumped_ < 6 && !uncovered(k)) {
                    ++dumped_;
                    std::printf("silent %s at t=%lld d=%lld N=%d m=%d\n", kKindName[k], st_.clocks, (long long)d, n_, m_);
                    for (long long t = st_.clocks - 200; t < st_.clocks; ++t) std::printf("%s", trace_[static_cast<size_t>(t % 200)].c_str());
                }
            }
        } else if (alarm_ || glitch_) {
            ++st_.flag_no_loss[k];
        }
    }

    const int n_, m_;
    std::mt19937_64 rng_;
    tbu::result& res_;
    lx::quad_decoder hdec_;
    golden::quad_decoder gdec_;
    lx::quad_decoder::out_t out_{};
    stats st_;
    std::vector<int64_t> hist_;
    int lat_ = 0, s_lo_ = 1, pass_hi_ = 1;
    long long settle_ = 0;
    int64_t pos_ = 0;
    int dir_ = 0, spacing_ = 1;
    long long since_edge_ = 0;
    int64_t base_err_ = 0;
    bool clear_next_ = false, alarm_ = false, glitch_ = false, edge_now_ = false;
    bool debug_ = std::getenv("FI_DEBUG") != nullptr;
    int dumped_ = 0;
    std::string trace_[200];
};

long long sum(const long long (&v)[NKIND]) {
    long long s = 0;
    for (long long x : v) s += x;
    return s;
}

bool legal(int glitch_n, int min_spacing) { return min_spacing > (glitch_n < 1 ? 1 : glitch_n); }

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 20261123);
    const long long clocks = tbu::arg_ll(argc, argv, "--clocks", 10000000);
    tbu::result res("tb_fault_injection", seed);
    std::mt19937_64 rng(seed);

    // 1. The configuration check covers the integrity condition, exhaustively (hls and golden).
    {
        long long bad = 0;
        const lx::axis_regs base{};
        golden::axis_regs gbase{};
        for (int n = 0; n < 256; ++n) {
            for (int m = 0; m < 65536; ++m) {
                lx::axis_regs r = base;
                r.glitch_n = n;
                r.min_spacing = m;
                const bool want = legal(n, m);
                const bool h = lx::axis_config_ok(r);
                bool g = want;
                if ((m & 255) == 0 || m < 300) {  // golden is slower: every small value and a grid
                    golden::axis_regs gr = gbase;
                    gr.glitch_n = n;
                    gr.min_spacing = m;
                    g = golden::config_ok(gr);
                }
                if (h != want || g != want) {
                    ++bad;
                    res.check(false, "config check at glitch_n " + std::to_string(n) + ", min_spacing " +
                                         std::to_string(m) + ": hls " + std::to_string(h) + " golden " +
                                         std::to_string(g) + ", want " + std::to_string(want));
                }
            }
        }
        res.check(bad == 0, "config check matches min_spacing > max(glitch_n, 1) on all 2^24 pairs");
        res.check(legal(int(base.glitch_n), int(base.min_spacing)) && lx::axis_config_ok(base),
                  "the reset values pass the configuration check");
    }

    // 2. Fault injection.
    struct setting {
        const char* name;
        int n, m;
        long long clocks;
        bool control;
    };
    const lx::axis_regs reset_regs{};
    std::vector<setting> settings;
    const long long c_reset = clocks * 4 / 10;
    const long long c_ctrl = clocks / 10;
    settings.push_back({"reset values", int(reset_regs.glitch_n), int(reset_regs.min_spacing), c_reset, false});
    // legal corners: N = 0/1 with the smallest spacing, N = 2 with 3, larger N, wide spacing
    const int corners[][2] = {{0, 2}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {8, 9}, {0, 40}, {2, 64}, {16, 17}, {255, 256}};
    for (const auto& c : corners) settings.push_back({"legal corner", c[0], c[1], 0, false});
    for (int i = 0; i < 8; ++i) {
        const int n = static_cast<int>(std::uniform_int_distribution<int>(0, 12)(rng));
        const int nf = n < 1 ? 1 : n;
        const int m = static_cast<int>(std::uniform_int_distribution<int>(nf + 1, 4 * nf + 24)(rng));
        settings.push_back({"legal random", n, m, 0, false});
    }
    const long long rest = clocks - c_reset - c_ctrl;
    const long long per = rest / static_cast<long long>(settings.size() - 1);
    for (auto& s : settings)
        if (s.clocks == 0) s.clocks = per;
    settings.push_back({"control: old reset (illegal now)", 2, 0, c_ctrl, true});

    stats legal_total, ctrl_total;
    std::printf("[tb_fault_injection] %zu settings, seed %" PRIu64 "\n", settings.size(), seed);
    for (size_t i = 0; i < settings.size(); ++i) {
        const setting& s = settings[i];
        res.check(legal(s.n, s.m) != s.control, std::string("setting legality: ") + s.name);
        run r(s.n, s.m, seed * 1000003ULL + i, res);
        const stats st = r.go(s.clocks);
        const std::string title = std::string(s.name) + " (glitch_n " + std::to_string(s.n) + ", min_spacing " +
                                  std::to_string(s.m) + ")";
        if (i == 0 || s.control) print_stats(title.c_str(), st);
        else
            std::printf("  %s: %lld clocks, %lld faults, %lld losses (%lld flagged), %lld silent in the covered class, "
                        "%lld silent outside it\n",
                        title.c_str(), st.clocks,
                        sum(st.faults), sum(st.losses), sum(st.flagged_alarm) + sum(st.flagged_glitch),
                        st.silent_covered(), st.silent[LONG] + st.silent[ALIAS]);
        if (s.control) {
            ctrl_total.add(st);
            res.check(st.silent[PASS] > 0, "negative control: filter-passing glitches lose counts silently at "
                                           "min_spacing 0 (the test can see a silent loss)");
        } else {
            legal_total.add(st);
            res.expect(st.silent_covered() == 0, [&] {
                return std::to_string(st.silent_covered()) + " silent losses at " + title;
            });
            res.check(st.losses[REVERSAL] == 0, "a legal reversal never loses a count at " + title);
            res.check(st.faults[PASS] > 0 && st.faults[ILLEGAL] > 0 && st.faults[LERR] > 0,
                      "every fault kind was injected at " + title);
        }
    }
    print_stats("all legal settings", legal_total);
    std::printf("[tb_fault_injection] legal settings: %lld faulted clocks, silent losses (covered class) %lld, "
                "silent outside the class (long pulses, aliased flips) %lld; control: %lld silent losses (%lld counts)\n",
                legal_total.clocks, legal_total.silent_covered(), legal_total.silent[LONG] + legal_total.silent[ALIAS],
                ctrl_total.silent_covered(), ctrl_total.silent_counts[PASS]);
    return res.finish();
}
