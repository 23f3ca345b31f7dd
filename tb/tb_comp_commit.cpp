// tb_comp_commit — atomic updates of the wide compensation registers over the bus (DESIGN 4.7,
// comp_sync / comp_commit; docs/REGISTERS.md).
//
// A host writes 32-bit words, one per clock here (a fast bus: the worst case for a torn value).
// The axis moves at constant speed about 10 000 raw counts from its zero while new ratio and
// comp_offset values arrive whose high words differ from the old ones, so a half-written ratio is
// off by about one unit (10 000 output counts at this position).
//   * framed: the word sequence of lxt::compensation_writes (comp_sync = 1, ratio and comp_offset
//     words, comp_commit pulse), replayed word by word into a register image that drives both
//     models (hls and golden, compared on every call by lxt::dual_axis);
//   * reference: the same final values written atomically (whole struct) in the commit call;
//   * unframed (negative control): the same words without comp_sync / comp_commit, against a
//     second reference that switches atomically in the call of the last unframed word (so the
//     two differ only by the half-written values in between).
// Checks: every output and tap of the framed run equals the reference run on every call (the
// half-written values never reach the multiplier); the unframed run differs from its reference
// in every round (so the comparison can fail, and the hazard is real); with comp_sync = 1, a ratio register of
// 0 is a configuration error even without a commit, and the held pair survives the safe state.
// Random rounds (seeded): new values anywhere in the register ranges that keep the position
// within the output width, update at random times while moving in either direction.
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "tb/tb_util.h"
#include "host/regmap.h"
#include "sysmodel/sim.h"

namespace {

namespace rm = lxt::regmap;

struct run {
    lxt::reg_image img;
    lxt::dual_axis ax;
    explicit run(const lxt::axis_settings& s) : ax(s) {}
};

lxt::axis_settings settings_of(const lxt::reg_image& img) { return lxt::settings_from(img); }

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 41);
    const long long rounds = tbu::arg_ll(argc, argv, "--rounds", 60);
    tbu::result res("tb_comp_commit", seed);
    std::mt19937_64 rng(seed);
    auto uni = [&](long long lo, long long hi) { return std::uniform_int_distribution<long long>(lo, hi)(rng); };

    long long unframed_differs = 0, framed_calls = 0;
    for (long long round = 0; round < rounds && res.failures < 10; ++round) {
        // start: ratio just below a multiple of 2^32, the new one just above (high word changes)
        const uint64_t hi = static_cast<uint64_t>(uni(2, 15));
        const uint64_t r1 = (hi << 32) - static_cast<uint64_t>(uni(1, 1 << 20));
        const uint64_t r2 = (hi << 32) + static_cast<uint64_t>(uni(0, 1 << 20));
        const int64_t o1 = uni(-(1LL << 40), 1LL << 40);
        const int64_t o2 = o1 + (round % 3 == 0 ? 0 : uni(-(1LL << 36), 1LL << 36)) + (round % 2 ? (1LL << 32) : -(1LL << 32));
        const bool up = round % 2 == 0;

        lxt::reg_image base;
        base.set(rm::idx::ratio, static_cast<int64_t>(r1));
        base.set(rm::idx::comp_offset, o1);
        base.set(rm::idx::pace_m, 2);
        base.set(rm::idx::backlog_thr, 1 << 30);
        base.set(rm::idx::glitch_n, 1);
        lxt::axis_settings s0 = settings_of(base);
        run framed(s0), ref(s0), unframed(s0), ref2(s0);
        framed.img = ref.img = unframed.img = ref2.img = base;

        // the target values and the two word sequences
        lxt::reg_image target = base;
        target.set(rm::idx::ratio, static_cast<int64_t>(r2));
        target.set(rm::idx::comp_offset, o2);
        const std::vector<lxt::reg_write> seq_framed = lxt::compensation_writes(target);
        const std::vector<lxt::reg_write> seq_plain = lxt::writes_for(target, {rm::idx::ratio, rm::idx::comp_offset});
        // the framed sequence must be: comp_sync, the words, comp_commit 1, comp_commit 0
        res.check(seq_framed.size() >= 4 && seq_framed.front().name == "comp_sync" &&
                      seq_framed[seq_framed.size() - 2].name == "comp_commit" && seq_framed.back().value == 0,
                  "compensation_writes is not framed by comp_sync / comp_commit");

        // raw count N walks from 10000 (or -10000) one count every 5 calls
        int64_t n = up ? 10000 : -10000;
        const long long t_start = uni(200, 600);
        const long long calls = t_start + 400;
        long long commit_call = -1;
        bool differs = false;
        for (long long t = 0; t < calls; ++t) {
            // bus: one word per call from t_start; the reference switches at the commit call
            const long long k = t - t_start;
            if (k >= 0 && k < static_cast<long long>(seq_framed.size())) {
                const lxt::reg_write& w = seq_framed[static_cast<size_t>(k)];
                std::string err;
                res.check(framed.img.write_word(w.offset, w.value, &err), "framed write: " + err);
                if (w.name == "comp_commit" && w.value == 1) commit_call = t;
            }
            if (k >= 0 && k < static_cast<long long>(seq_plain.size())) {
                const lxt::reg_write& w = seq_plain[static_cast<size_t>(k)];
                std::string err;
                res.check(unframed.img.write_word(w.offset, w.value, &err), "plain write: " + err);
            }
            if (t == commit_call) ref.img = target;  // whole registers at once, comp_sync 0
            if (k == static_cast<long long>(seq_plain.size()) - 1) ref2.img = target;
            for (run* r : {&framed, &ref, &unframed, &ref2}) r->ax.set(settings_of(r->img));

            if (t % 5 == 0) n += up ? 1 : -1;
            lx::axis_pins p;
            lxt::quad_pins(n, p.a, p.b);
            for (run* r : {&framed, &ref, &unframed, &ref2}) {
                const std::string m = r->ax.step(p);
                res.expect(m.empty(), [&] { return "round " + std::to_string(round) + " call " + std::to_string(t) + ": " + m; });
            }
            const std::string d = lxt::compare(framed.ax.hls(), ref.ax.gold());
            res.expect(d.empty(), [&] {
                return "round " + std::to_string(round) + " call " + std::to_string(t) +
                       ": framed update differs from the atomic reference: " + d;
            });
            ++framed_calls;
            if (!lxt::compare(unframed.ax.hls(), ref2.ax.gold()).empty()) differs = true;
        }
        res.check(commit_call > 0, "no commit in the framed sequence");
        res.check(framed.ax.gold().comp_pos == ref.ax.gold().comp_pos, "final positions differ");
        if (differs) ++unframed_differs;
    }
    // negative control: without the framing, the half-written ratio moves the outputs in every round
    res.check(unframed_differs == rounds, "the unframed update matched the reference in " +
                                              std::to_string(rounds - unframed_differs) + " of " +
                                              std::to_string(rounds) + " rounds (the check cannot fail?)");

    // comp_sync = 1: the register value 0 is a configuration error at once; the held pair
    // survives the safe state and is used again when the register is valid (not committed)
    {
        lxt::axis_settings s;
        s.comp_sync = true;
        s.ratio = 3ULL << 32;
        s.comp_commit = true;
        lxt::dual_axis ax(s);
        lx::axis_pins p;
        res.check(ax.step(p).empty() && !ax.gold().cfg_err, "commit of a valid ratio (power-up call)");
        res.check(ax.step(p).empty() && !ax.gold().cfg_err, "commit of a valid ratio");
        s.comp_commit = false;
        s.ratio = 0;
        ax.set(s);
        // register stage (DESIGN 4.7): presented in this call, in force in the next one
        res.check(ax.step(p).empty() && !ax.gold().cfg_err && !ax.hls().cfg_err,
                  "ratio register 0 with comp_sync: cfg_err in the call it is presented (no register stage?)");
        res.check(ax.step(p).empty() && ax.gold().cfg_err && ax.hls().cfg_err, "ratio register 0 with comp_sync: no cfg_err");
        s.ratio = 5ULL << 32;  // valid register, not committed: the held 3.0 is in force
        ax.set(s);
        int64_t nn = 0;
        for (int t = 0; t < 400; ++t) {
            if (t % 4 == 0 && t < 350) ++nn;  // then stand still: comp catches up
            lxt::quad_pins(nn, p.a, p.b);
            res.expect(ax.step(p).empty(), [&] { return "held-pair run, call " + std::to_string(t); });
        }
        res.check(ax.gold().comp_pos == ax.gold().raw_count * 3 && ax.gold().raw_count > 50,
                  "after the safe state the held ratio 3.0 must be in force: comp " + std::to_string(ax.gold().comp_pos) +
                      ", raw " + std::to_string(ax.gold().raw_count));
    }
    std::printf("  %lld rounds, %lld calls of the framed run compared with the atomic reference; the unframed run differs in %lld rounds\n",
                rounds, framed_calls, unframed_differs);
    return res.finish();
}
