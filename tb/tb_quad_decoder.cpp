// tb_quad_decoder — block-level checks of quad_decoder, hls against golden on every call, plus
// direct checks of the behaviour the block promises (split from tb_blocks, issue 14).
//
// quad_decoder: random quadrature motion with glitches, illegal transitions (A and B together),
//   laser error bursts, clears and random minimum spacing: every output equal; a clean sequence
//   of k edges counts exactly k; each illegal transition raises the flag and bumps the counter.
#include <algorithm>
#include <random>

#include "golden/quad_decoder.h"
#include "hls/quad_decoder.h"
#include "tb/tb_util.h"
#include "sysmodel/sim.h"

namespace {

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

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 5);
    tbu::result res("tb_quad_decoder", seed);
    std::mt19937_64 rng(seed);
    test_quad_decoder(res, rng);
    return res.finish();
}
