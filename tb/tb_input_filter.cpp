// tb_input_filter — block-level checks of input_filter, hls against golden on every call, plus
// direct checks of the behaviour the block promises (split from tb_blocks, issue 14).
//
// input_filter: every filter length 0..12 with random pins that hold for random times (many
//   shorter than N): outputs equal; no pulse shorter than max(N,1) calls ever reaches the output;
//   the latency of a clean edge is exactly max(N,1) + 1 calls; N written while running acts from
//   the next call.
#include <random>

#include "golden/input_filter.h"
#include "hls/input_filter.h"
#include "tb/tb_util.h"

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

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 5);
    tbu::result res("tb_input_filter", seed);
    std::mt19937_64 rng(seed);
    test_input_filter(res, rng);
    return res.finish();
}
