// tb_dds_sincos — dds_sincos: every phase of every legal period, hls against golden.
//
// For every period P = 8, 16, ..., 4096 (all 512 of them, presets included) the table is
// generated and loaded, and the phase is walked once round forwards and once backwards; every
// sin/cos code must equal the golden model (long double sin/cos, round half away). Done with the
// default amplitude (32767) for every P, and with a random legal amplitude for 18-bit and 12-bit
// DACs, then a short walk with stops (the held paths). Also checked directly: sin == cos > 0 at
// P/8, (0, amp) at phase 0, |code| <= amp.
#include <random>

#include "golden/dds_sincos.h"
#include "hls/dds_sincos.h"
#include "tb/tb_util.h"
#include "host/dds_table.h"

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 11);
    tbu::result res("tb_dds_sincos", seed);
    std::mt19937_64 rng(seed);
    long phases = 0;
    for (int pass = 0; pass < 3; ++pass) {
        for (int P = 8; P <= 4096 && res.failures < 10; P += 8) {
            int amp = 32767;
            if (pass == 1) amp = 1 + static_cast<int>(rng() % ((1u << 17) - 1));  // 18-bit DAC
            if (pass == 2) amp = 1 + static_cast<int>(rng() % ((1u << 11) - 1));  // 12-bit DAC
            lx::dds_sincos h;
            const std::vector<uint32_t> tbl = lxt::dds_table(P, amp);
            for (size_t k = 0; k < tbl.size(); ++k) h.load(static_cast<unsigned>(k), tbl[k]);
            golden::dds_sincos g;
            g.reset();
            for (int dir = 1; dir >= -1; dir -= 2) {
                // dir +1: phases 0,1,...,P-1,0 ; dir -1 continues from there: 1,0,P-1,... (the codes
                // follow two calls behind)
                for (int k = 0; k <= P; ++k) {
                    const lx::dds_sincos::out_t ho = h.step(dir, P, amp);
                    const golden::dds_sincos::out go = g.step(dir, P, amp);
                    ++phases;
                    const long long hs = ho.sin.to_int64(), hc = ho.cos.to_int64();
                    if (hs != go.sin || hc != go.cos) {
                        res.check(false, "P=" + std::to_string(P) + " amp=" + std::to_string(amp) + " call " +
                                             std::to_string(k) + " dir " + std::to_string(dir) + ": sin/cos hls " +
                                             std::to_string(hs) + "/" + std::to_string(hc) + " golden " +
                                             std::to_string(go.sin) + "/" + std::to_string(go.cos));
                        break;
                    }
                    res.check(hs <= amp && hs >= -amp && hc <= amp && hc >= -amp, "code beyond amplitude");
                    // two stages (DESIGN 4.6): the codes of call k belong to the phase before call
                    // k - 1, i.e. phase k - 1 on the forward walk; call 0 shows the reset codes
                    if (dir == 1 && k == P / 8 + 1)
                        res.check(hs == hc && hs > 0, "P=" + std::to_string(P) + ": sin != cos at P/8 (" +
                                                          std::to_string(hs) + " vs " + std::to_string(hc) + ")");
                    if (dir == 1 && k == 1)
                        res.check(hs == 0 && hc == amp, "P=" + std::to_string(P) + ": phase 0 is not (0, amp)");
                    if (dir == 1 && k == 0)
                        res.check(hs == 0 && hc == 0, "P=" + std::to_string(P) + ": the first call after reset is not 0/0");
                }
            }
            // then a walk with stops (ostep 0 in three calls of four): the held read stage and the
            // held output registers, against golden in every call
            for (int k = 0; k < 96 && res.failures < 10; ++k) {
                const int st = (rng() % 4 != 0) ? 0 : ((rng() & 1) != 0 ? 1 : -1);
                const lx::dds_sincos::out_t ho = h.step(st, P, amp);
                const golden::dds_sincos::out go = g.step(st, P, amp);
                ++phases;
                res.check(ho.sin.to_int64() == go.sin && ho.cos.to_int64() == go.cos,
                          "P=" + std::to_string(P) + " amp=" + std::to_string(amp) + " walk with stops, call " +
                              std::to_string(k) + ": sin/cos hls " + std::to_string(ho.sin.to_int64()) + "/" +
                              std::to_string(ho.cos.to_int64()) + " golden " + std::to_string(go.sin) + "/" +
                              std::to_string(go.cos));
            }
#ifndef __SYNTHESIS__  // (the RAM flags: C simulation only)
            res.check(h.ram_violations() == 0, "P=" + std::to_string(P) + ": RAM port violations " +
                                                   std::to_string(h.ram_violations()));
#endif
        }
    }
    std::printf("  %ld phases compared\n", phases);
    return res.finish();
}
