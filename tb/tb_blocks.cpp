// tb_blocks — block-level checks of input_filter, quad_decoder and output_pacer, hls against
// golden on every call, plus direct checks of the behaviour each block promises.
//
// input_filter: every filter length 0..12 with random pins that hold for random times (many
//   shorter than N): outputs equal; no pulse shorter than max(N,1) calls ever reaches the output;
//   the latency of a clean edge is exactly max(N,1) + 1 calls.
// quad_decoder: random quadrature motion with glitches, illegal transitions (A and B together),
//   laser error bursts, clears and random minimum spacing: every output equal; a clean sequence
//   of k edges counts exactly k; each illegal transition raises the flag and bumps the counter.
// output_pacer: random deltas including huge jumps, random M and threshold: every output equal;
//   consecutive counts are >= max(M, 2) calls apart; paced + backlog (taps, two calls late) ==
//   sum of the deltas up to two calls earlier; ovs == |backlog of four calls earlier| > thr;
//   drains fully; every fifth run with jumps up to 2^37 and thresholds over all 32 bits.
#include <random>

#include "golden/input_filter.h"
#include "golden/output_pacer.h"
#include "golden/quad_decoder.h"
#include "hls/input_filter.h"
#include "hls/output_pacer.h"
#include "hls/quad_decoder.h"
#include "tb/tb_util.h"
#include "sysmodel/sim.h"

namespace {

void test_input_filter(tbu::result& res, std::mt19937_64& rng) {
    for (int n = 0; n <= 12; ++n) {
        lx::input_filter<8> h;
        golden::input_filter g;
        g.reset();
        bool pin = false;
        long hold = 0;
        bool last_out = false;
        long last_change = -1000;
        for (long t = 0; t < 200000 && res.failures < 10; ++t) {
            if (hold-- <= 0) {
                pin = !pin;
                hold = static_cast<long>(rng() % static_cast<unsigned>(3 * (n + 1)));
            }
            const lx::input_filter<8>::out_t ho = h.step(pin, n);
            const golden::input_filter::out go = g.step(pin, n);
            res.expect(ho.f == go.f && ho.valid == go.valid && ho.glitch == go.glitch, [&] {
                return "input_filter N=" + std::to_string(n) + " call " + std::to_string(t) + ": f/valid hls " +
                       std::to_string(ho.f) + "/" + std::to_string(ho.valid) + " golden " + std::to_string(go.f) + "/" +
                       std::to_string(go.valid);
            });
            // an output level, once valid, lasts at least max(N,1) calls
            if (ho.valid && ho.f != last_out) {
                const long len = t - last_change;
                res.expect(last_change < 0 || len >= (n < 1 ? 1 : n), [&] {
                    return "input_filter N=" + std::to_string(n) + ": output pulse of " + std::to_string(len) + " calls";
                });
                last_change = t;
                last_out = ho.f;
            }
        }
        // latency of a clean edge
        lx::input_filter<8> h2;
        long lat = -1;
        for (long t = 0; t < 100; ++t) {
            const bool p = t >= 10;
            const lx::input_filter<8>::out_t o = h2.step(p, n);
            if (o.f && lat < 0) lat = t - 10;
        }
        const long want = (n < 1 ? 1 : n) + 1;
        res.check(lat == want, "input_filter N=" + std::to_string(n) + ": latency " + std::to_string(lat) + " want " +
                                   std::to_string(want));
        // a pulse one call shorter than N never passes
        if (n >= 2) {
            lx::input_filter<8> h3;
            bool passed = false;
            for (long t = 0; t < 100; ++t) {
                const bool p = t >= 10 && t < 10 + n - 1;
                if (h3.step(p, n).f) passed = true;
            }
            res.check(!passed, "input_filter N=" + std::to_string(n) + ": pulse of N-1 calls passed");
        }
    }
    // N written while running (DESIGN 4.1: the pass decision of call t uses N of call t-1): random
    // lengths 0..12 changed every few calls, hls against golden on every call
    {
        lx::input_filter<8> h;
        golden::input_filter g;
        g.reset();
        bool pin = false;
        long hold = 0, keep = 0;
        int n = 3;
        for (long t = 0; t < 200000 && res.failures < 10; ++t) {
            if (hold-- <= 0) {
                pin = !pin;
                hold = static_cast<long>(rng() % 30u);
            }
            if (keep-- <= 0) {
                n = static_cast<int>(rng() % 13u);
                keep = static_cast<long>(rng() % 8u);
            }
            const lx::input_filter<8>::out_t ho = h.step(pin, n);
            const golden::input_filter::out go = g.step(pin, n);
            res.expect(ho.f == go.f && ho.valid == go.valid && ho.glitch == go.glitch, [&] {
                return "input_filter, N changing: call " + std::to_string(t) + " N " + std::to_string(n) + ": f/valid/glitch hls " +
                       std::to_string(ho.f) + "/" + std::to_string(ho.valid) + "/" + std::to_string(ho.glitch) + " golden " +
                       std::to_string(go.f) + "/" + std::to_string(go.valid) + "/" + std::to_string(go.glitch);
            });
        }
    }
    // directed: N = 10, the pin rises at call 10 (x differs from call 12 on: run 4 at call 15); N
    // written to 3 at call 15 is used from call 16, so the output rises at call 16, not 15
    {
        lx::input_filter<8> h;
        golden::input_filter g;
        g.reset();
        long rise_h = -1, rise_g = -1;
        for (long t = 0; t < 40; ++t) {
            const int n = t >= 15 ? 3 : 10;
            if (h.step(t >= 10, n).f && rise_h < 0) rise_h = t;
            if (g.step(t >= 10, n).f && rise_g < 0) rise_g = t;
        }
        res.check(rise_h == 16 && rise_g == 16, "input_filter: N written at call 15 must act at call 16: output rises at " +
                                                    std::to_string(rise_h) + " (hls), " + std::to_string(rise_g) + " (golden)");
    }
}

void test_quad_decoder(tbu::result& res, std::mt19937_64& rng) {
    for (int rep = 0; rep < 40 && res.failures < 10; ++rep) {
        lx::quad_decoder h;
        golden::quad_decoder g;
        g.reset();
        const int glitch = static_cast<int>(rng() % 5);
        const int min_sp = static_cast<int>(rng() % 20);
        int64_t n = 0;
        int glitch_left = 0, glitch_pin = 0, lerr_left = 0;
        long spacing = 1 + static_cast<long>(rng() % 30), wait = 0;
        int dir = 1;
        for (long t = 0; t < 100000; ++t) {
            if (wait-- <= 0) {
                n += dir;
                wait = spacing;
                if (rng() % 200 == 0) dir = -dir;
                if (rng() % 100 == 0) spacing = 1 + static_cast<long>(rng() % 30);
            }
            if (rng() % 5000 == 0) n += 2;  // illegal
            if (glitch_left == 0 && rng() % 300 == 0) {
                glitch_left = 1 + static_cast<int>(rng() % 4);
                glitch_pin = static_cast<int>(rng() % 2);
            }
            if (lerr_left == 0 && rng() % 20000 == 0) lerr_left = 1 + static_cast<int>(rng() % 50);
            bool a, b;
            lxt::quad_pins(n, a, b);
            if (glitch_left > 0) {
                if (glitch_pin) a = !a; else b = !b;
                --glitch_left;
            }
            const bool lerr = lerr_left > 0;
            if (lerr_left > 0) --lerr_left;
            const bool clear = rng() % 3000 == 0;
            const lx::quad_decoder::out_t ho = h.step(a, b, lerr, glitch, min_sp, clear);
            const golden::quad_decoder::out go = g.step(a, b, lerr, glitch, min_sp, clear);
            const bool same = ho.step == go.step && ho.raw_count == go.raw_count && ho.illegal == go.illegal &&
                              ho.ovs == go.ovs && ho.err_cnt.to_int() == go.err_cnt && ho.illegal_st == go.illegal_st &&
                              ho.ovs_st == go.ovs_st && ho.lerr == go.lerr && ho.lerr_alarm == go.lerr_alarm &&
                              ho.glitch_st == go.glitch_st;
            if (!res.expect(same, [&] {
                    return "quad_decoder rep " + std::to_string(rep) + " call " + std::to_string(t) + ": step " +
                           std::to_string(ho.step.to_int()) + "/" + std::to_string(go.step) + " raw " +
                           std::to_string(ho.raw_count.to_int64()) + "/" + std::to_string(go.raw_count) + " illegal " +
                           std::to_string(ho.illegal) + "/" + std::to_string(go.illegal) + " ovs " +
                           std::to_string(ho.ovs) + "/" + std::to_string(go.ovs) + " err_cnt " +
                           std::to_string(ho.err_cnt.to_int()) + "/" + std::to_string(go.err_cnt) + " lerr " +
                           std::to_string(ho.lerr) + "/" + std::to_string(go.lerr) + " (hls/golden)";
                }))
                break;
        }
    }
    // clean sequences: k edges count k, forward and backward, every glitch length
    for (int glitch = 0; glitch <= 6; ++glitch) {
        for (int dir = 1; dir >= -1; dir -= 2) {
            lx::quad_decoder h;
            int64_t n = 0;
            long long illegal = 0;
            for (long t = 0; t < 20000; ++t) {
                if (t > 20 && t % (glitch + 3) == 0 && t < 15000) n += dir;
                bool a, b;
                lxt::quad_pins(n, a, b);
                const lx::quad_decoder::out_t o = h.step(a, b, false, glitch, 0, false);
                illegal += o.illegal ? 1 : 0;
            }
            const lx::quad_decoder::out_t o = h.step(false, false, false, glitch, 0, false);
            (void)o;
            res.check(illegal == 0, "clean sequence flagged illegal");
            bool a, b;
            lxt::quad_pins(n, a, b);
            const lx::quad_decoder::out_t f = h.step(a, b, false, glitch, 0, false);
            res.check(f.raw_count.to_int64() == n, "clean sequence, glitch " + std::to_string(glitch) + ": counted " +
                                                       std::to_string(f.raw_count.to_int64()) + " of " + std::to_string(n));
        }
    }
    // every illegal transition is flagged and counted (saturating at 255)
    {
        lx::quad_decoder h;
        for (int k = 0; k < 300; ++k) {
            for (int t = 0; t < 6; ++t) h.step(false, false, false, 0, 0, false);
            lx::quad_decoder::out_t o{};
            bool flagged = false;
            for (int t = 0; t < 6; ++t) {
                o = h.step(true, true, false, 0, 0, false);
                flagged = flagged || o.illegal;
            }
            res.check(flagged && o.illegal_st && o.err_cnt.to_int() == std::min(2 * k + 1, 255),
                      "illegal transition " + std::to_string(k) + " not flagged/counted (err_cnt " +
                          std::to_string(o.err_cnt.to_int()) + ")");
            for (int t = 0; t < 6; ++t) o = h.step(false, false, false, 0, 0, false);
        }
    }
}

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
        long last_emit = -1000000;
        for (long t = 0; t < 60000; ++t) {
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
            const lx::output_pacer::out_t ho = h.step(delta - add, add, m, thr, clear);
            const golden::output_pacer::out go = g.step(delta, m, thr, clear);
            const bool same = ho.pstep == go.pstep && ho.paced == go.paced && ho.backlog == go.backlog &&
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
            if (ho.pstep != 0) {
                res.expect(t - last_emit >= (m < 2 ? 2 : m), [&] { return "pacer emitted counts closer than max(M, 2)"; });
                last_emit = t;
            }
            // the taps paced and backlog are two calls late (DESIGN 4.4)
            res.expect(ho.paced.to_int64() + ho.backlog.to_int64() == sum_2,
                       [&] { return "pacer lost counts at call " + std::to_string(t); });
        }
        // after motion stops the backlog drains at one count per M calls, exactly
        lx::output_pacer::out_t o = h.step(0, 0, m, thr, false);
        const int64_t left = o.backlog.to_int64() < 0 ? -o.backlog.to_int64() : o.backlog.to_int64();
        const int64_t limit = left * (m < 2 ? 2 : m) + m + 4;  // + the two calls of tap latency
        int64_t k = 0;
        while (o.backlog != 0 && k < limit) {
            o = h.step(0, 0, m, thr, false);
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
        const lx::output_pacer::out_t ho = h.step(delta, add, 2, 1000, false);
        const golden::output_pacer::out go = g.step(delta + add, 2, 1000, false);
        res.expect(ho.pstep == go.pstep && ho.paced == go.paced && ho.backlog == go.backlog,
                   [&] { return "output_pacer carry +2: hls != golden at call " + std::to_string(t); });
        if (ho.pstep != 0) ++emitted;
    }
    res.check(emitted == 1, "output_pacer carry +2: exactly one count is emitted (the one owed)");
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 5);
    tbu::result res("tb_blocks", seed);
    std::mt19937_64 rng(seed);
    test_input_filter(res, rng);
    test_quad_decoder(res, rng);
    test_output_pacer_carry2(res);  // directed first: its message is not crowded out by the random run's
    test_output_pacer(res, rng);
    return res.finish();
}
