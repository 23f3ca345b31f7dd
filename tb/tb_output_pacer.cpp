// tb_output_pacer — block-level checks of output_pacer, hls against golden on every call, plus
// direct checks of the behaviour the block promises (split from tb_blocks, issue 14).
//
// output_pacer: random deltas including huge jumps, random M and threshold: every output equal;
//   consecutive events (counts and slots) are >= max(M, 2) calls apart, a count emitted while
//   `wide` is followed by a slot before the next count, and a slot comes only then; paced + backlog (taps, two calls late) ==
//   sum of the deltas up to two calls earlier; ovs == |backlog of four calls earlier| > thr;
//   drains fully; every fifth run with jumps up to 2^37 and thresholds over all 32 bits; a
//   directed carry of +2 from the lower half.
#include <random>

#include "golden/output_pacer.h"
#include "hls/output_pacer.h"
#include "tb/tb_util.h"

namespace {

void test_output_pacer(tbu::result& res, std::mt19937_64& rng) {
    for (int rep = 0; rep < 50 && res.failures < 10; ++rep) {
        lx::output_pacer h;
        golden::output_pacer g;
        g.reset();
        // M = 1 is outside the legal range; the block still keeps two counts apart (DESIGN 4.4)
        const int m = rep % 10 == 9 ? 1 : 2 + static_cast<int>(rng() % 7);
        // every fifth run: jumps up to +-2^37 (taken back by the next jump, so the backlog
        // drains) and a threshold anywhere in 32 bits (the split halves of the hardware form)
        const bool big = rep % 5 == 3;
        const uint64_t thr = big ? (rng() % 2 ? rng() % 0x100000000ull : rng() % 0x300000ull) : 1 + rng() % 300;
        int64_t pending_jump = 0;
        int64_t bl_hist[2] = {0, 0};  // backlog tap of calls t-1, t-2 (0 before the first call)
        int64_t sum = 0;
        int64_t sum_1 = 0, sum_2 = 0;  // sum of the deltas up to one / two calls earlier
        long last_event = -1000000;
        bool wide = false, owed = false;
        for (long t = 0; t < 60000; ++t) {
            // rephase's window: on and off in stretches (off for the drain below)
            if (rng() % 700 == 0) wide = !wide;
            if (t >= 50000) wide = false;
            int64_t delta = 0;
            if (t < 50000) {
                const uint64_t k = rng() % 1000;
                if (k < 100) delta = static_cast<int64_t>(rng() % 17) - 8;
                else if (k == 100 && !big) delta = static_cast<int64_t>(rng() % 4001) - 2000;  // ratio jump
                else if (k == 100 && pending_jump != 0) {
                    delta = -pending_jump;
                    pending_jump = 0;
                } else if (k == 100) {
                    const int sh = static_cast<int>(rng() % 38);
                    delta = static_cast<int64_t>(rng() % (uint64_t(1) << sh)) * (rng() % 2 ? 1 : -1);
                    pending_jump = delta;
                }
            }
            if (t == 49999 && pending_jump != 0) {  // take the last jump back: the backlog drains
                delta -= pending_jump;
                pending_jump = 0;
            }
            sum_2 = sum_1;
            sum_1 = sum;
            sum += delta;
            const bool clear = rng() % 5000 == 0;
            // the hls block takes the delta as two addends (multiplier + error map, DESIGN 4.4):
            // split it, the second one anywhere in its 18 bits (corners included) or zero
            int64_t add = 0;
            switch (rng() % 8) {
            case 0: add = static_cast<int64_t>(rng() % (1u << 18)) - (1 << 17); break;
            case 1: add = static_cast<int64_t>(rng() % 65) - 32; break;
            case 2: add = rng() % 2 ? -(1 << 17) : (1 << 17) - 1; break;
            default: break;
            }
            const lx::output_pacer::out_t ho = h.step(delta - add, add, m, thr, clear, wide);
            const golden::output_pacer::out go = g.step(delta, m, thr, clear, wide);
            const bool same = ho.pstep == go.pstep && ho.slot == go.slot && ho.paced == go.paced && ho.backlog == go.backlog &&
                              ho.ovs == go.ovs && ho.ovs_st == go.ovs_st;
            if (!res.expect(same, [&] {
                    return "output_pacer rep " + std::to_string(rep) + " call " + std::to_string(t) + ": pstep " +
                           std::to_string(ho.pstep.to_int()) + "/" + std::to_string(go.pstep) + " backlog " +
                           std::to_string(ho.backlog.to_int64()) + "/" + std::to_string(go.backlog) + " (hls/golden)";
                }))
                break;
            // ovs compares the backlog of four calls earlier (the tap of two calls earlier) with
            // the threshold of the previous call (constant here; 0 > thr is never true at t = 0)
            {
                const int64_t b4 = bl_hist[1];
                const uint64_t mag = b4 < 0 ? uint64_t(-b4) : uint64_t(b4);
                res.expect(ho.ovs == (mag > thr), [&] { return "pacer ovs at call " + std::to_string(t); });
            }
            bl_hist[1] = bl_hist[0];
            bl_hist[0] = ho.backlog.to_int64();
            if (ho.pstep != 0 || ho.slot) {
                res.expect(t - last_event >= (m < 2 ? 2 : m),
                           [&] { return "pacer events closer than max(M, 2) at call " + std::to_string(t); });
                last_event = t;
            }
            res.expect(!(ho.pstep != 0 && ho.slot), [&] { return "pacer: a slot with a count"; });
            res.expect(!(ho.pstep != 0 && owed), [&] { return "pacer: a count while its slot is owed, call " + std::to_string(t); });
            res.expect(!ho.slot || owed, [&] { return "pacer: a slot nobody is owed, call " + std::to_string(t); });
            if (ho.pstep != 0) owed = wide;
            if (ho.slot) owed = false;
            // the taps paced and backlog are two calls late (DESIGN 4.4)
            res.expect(ho.paced.to_int64() + ho.backlog.to_int64() == sum_2,
                       [&] { return "pacer lost counts at call " + std::to_string(t); });
        }
        // after motion stops the backlog drains at one count per M calls, exactly
        lx::output_pacer::out_t o = h.step(0, 0, m, thr, false, false);
        const int64_t left = o.backlog.to_int64() < 0 ? -o.backlog.to_int64() : o.backlog.to_int64();
        const int64_t limit = left * (m < 2 ? 2 : m) + m + 4;  // + the two calls of tap latency
        int64_t k = 0;
        while (o.backlog != 0 && k < limit) {
            o = h.step(0, 0, m, thr, false, false);
            ++k;
        }
        res.check(o.backlog == 0 && o.paced.to_int64() == sum, "pacer did not drain within |backlog|*M calls");
    }
}

// Directed: the lower half carries +2 into the upper half (only the second addend makes that
// possible) and leaves X = 0 with hi = -2, lo = 0: the zero test must see B = 0 (no count). The
// random deltas above almost never reach this state. With M = 2 from reset: call 0 B = 2^20 - 1;
// call 1 emits +1 (e_prev = 1 after it); call 2 adds delta = -2^20 - 2^17 + 3 and add = 2^17 - 1,
// so T = lo + delta_lo + add - e_prev = 2^21 exactly and hi' = 0 + (-2) + 0; B = 0 from then on.
void test_output_pacer_carry2(tbu::result& res) {
    lx::output_pacer h;
    golden::output_pacer g;
    g.reset();
    const int64_t d[3] = {(int64_t(1) << 20) - 1, 0, -(int64_t(1) << 20) - (int64_t(1) << 17) + 3};
    const int64_t a[3] = {0, 0, (int64_t(1) << 17) - 1};
    int emitted = 0;  // counts of either sign (a wrong +1 taken back by a -1 still counts twice)
    for (int t = 0; t < 12; ++t) {
        const int64_t delta = t < 3 ? d[t] : 0, add = t < 3 ? a[t] : 0;
        const lx::output_pacer::out_t ho = h.step(delta, add, 2, 1000, false, false);
        const golden::output_pacer::out go = g.step(delta + add, 2, 1000, false, false);
        res.expect(ho.pstep == go.pstep && ho.paced == go.paced && ho.backlog == go.backlog,
                   [&] { return "output_pacer carry +2: hls != golden at call " + std::to_string(t); });
        if (ho.pstep != 0) ++emitted;
    }
    res.check(emitted == 1, "output_pacer carry +2: exactly one count is emitted (the one owed)");
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 5);
    tbu::result res("tb_output_pacer", seed);
    std::mt19937_64 rng(seed);
    test_output_pacer_carry2(res);  // directed first: its message is not crowded out by the random run's
    test_output_pacer(res, rng);
    return res.finish();
}
