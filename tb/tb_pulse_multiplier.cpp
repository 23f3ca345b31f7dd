// tb_pulse_multiplier — pulse_multiplier: hls against golden and against a 128-bit reference.
//
// 1. Random walk of N over |N| < 2^21 with random ratio and offset updates (standing still and
//    moving, ratios over the whole Q5.32 range, offsets over the whole 64-bit register including
//    both extremes): hls == golden == floor((N*R + OFF)/2^32) every call, and the deltas add up
//    to the position (no count lost in a re-base).
// 2. Exact-range statement: long double (64-bit significand) represents N*R + OFF exactly while
//    |N*R + OFF| < 2^64; checked here for |N| up to 2^26 with the largest ratio and offset.
// 3. Beyond: N preset near +-2^31 and walked across the 32-bit wrap in both directions with
//    random ratios and offsets; hls == 128-bit reference every call.
// 4. Path independence: two different paths to the same (N, R, OFF) give the same comp.
#include <climits>
#include <random>

#include "golden/pulse_multiplier.h"
#include "hls/pulse_multiplier.h"
#include "tb/tb_util.h"

namespace {
__extension__ typedef __int128 i128;

int64_t ref_comp(int64_t n, uint64_t r, int64_t off) {
    return static_cast<int64_t>((static_cast<i128>(n) * static_cast<i128>(r) + off) >> 32);  // arithmetic: floor
}
// A random offset: mostly thermal-sized (|OFF| < 2^(32+24)), sometimes anywhere, sometimes an extreme.
int64_t random_offset(std::mt19937_64& rng) {
    const uint64_t k = rng() % 10;
    if (k == 0) return INT64_MIN;
    if (k == 1) return INT64_MAX;
    if (k < 4) return static_cast<int64_t>(rng());
    return static_cast<int64_t>(rng() % (1ULL << 57)) - (1LL << 56);
}
int64_t wrap32(int64_t n) { return static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(n))); }
}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 7);
    const long long calls = tbu::arg_ll(argc, argv, "--calls", 3000000);
    tbu::result res("tb_pulse_multiplier", seed);
    std::mt19937_64 rng(seed);
    const uint64_t r_max = (1ULL << 37) - 1;

    // 1. random walk, hls vs golden vs reference
    {
        lx::pulse_multiplier h;
        golden::pulse_multiplier g;
        g.reset();
        int64_t n = 0, sum_delta = 0;
        uint64_t r = 34789620252ULL;
        int64_t off = 0;
        int dir = 1;
        for (long long t = 0; t < calls && res.failures < 10; ++t) {
            const uint64_t k = rng() % 100000;
            if (k < 30) r = 1 + rng() % r_max;                                  // anywhere
            else if (k < 300) r = r + (rng() % 2001) - 1000;                    // small trims
            if (k >= 300 && k < 330) off = random_offset(rng);
            else if (k >= 330 && k < 600 && off > -(1LL << 62) && off < (1LL << 62))
                off += static_cast<int64_t>(rng() % 2000001) - 1000000;  // trims (no overflow)
            if ((off > (1LL << 62) || off < -(1LL << 62)) && k % 7 == 0) off = 0;  // leave the extremes
            if (k % 997 == 0) dir = -dir;
            int step = static_cast<int>(rng() % 3) - 1;
            if (rng() % 4 != 0) step = dir;
            if (n + step > (1 << 21) || n + step < -(1 << 21)) step = -step;
            n += step;
            const lx::pulse_multiplier::out_t ho = h.step(step, r, off);
            const golden::pulse_multiplier::out g_o = g.step(step, r, off);
            sum_delta += ho.delta.to_int64();
            const int64_t want = ref_comp(n, r, off);
            if (ho.comp.to_int64() != want || g_o.comp != want || ho.delta.to_int64() != g_o.delta ||
                sum_delta != want) {
                res.check(false, "call " + std::to_string(t) + " N=" + std::to_string(n) + " R=" + std::to_string(r) +
                                     " OFF=" + std::to_string(off) + ": comp hls " + std::to_string(ho.comp.to_int64()) + " golden " +
                                     std::to_string(g_o.comp) + " ref " + std::to_string(want) + " sum(delta) " +
                                     std::to_string(sum_delta));
            } else {
                res.check(true, "");
            }
        }
    }
    // 2. long double exact range: |N| < 2^26 with R up to 2^37-1 keeps |N*R| < 2^63, and with
    //    |OFF| <= 2^63 the sum stays below 2^64: exact, so the golden's floor is exact.
    {
        golden::pulse_multiplier g;
        for (int i = 0; i < 200000; ++i) {
            const int64_t n = static_cast<int64_t>(rng() % (1ULL << 27)) - (1LL << 26);
            const uint64_t r = i < 2 ? r_max : 1 + rng() % r_max;
            const int64_t off = i < 2 ? (i == 0 ? INT64_MIN : INT64_MAX) : random_offset(rng);
            const long double p = static_cast<long double>(n) * static_cast<long double>(r) + static_cast<long double>(off);
            const i128 exact = static_cast<i128>(n) * static_cast<i128>(r) + off;
            res.check(static_cast<i128>(p) == exact, "long double not exact at N=" + std::to_string(n));
        }
        // the golden model itself at the edge of that range (one call from N = 0 per check)
        for (int i = 0; i < 20000; ++i) {
            g.reset();
            const uint64_t r = 1 + rng() % r_max;
            const int64_t off = random_offset(rng);
            const int st = (i & 1) ? 1 : -1;
            res.check(g.step(st, r, off).comp == ref_comp(st, r, off), "golden single step, OFF=" + std::to_string(off));
        }
    }
    // 3. across the 32-bit wrap, both directions, hls vs 128-bit reference
    for (int rep = 0; rep < 200 && res.failures < 10; ++rep) {
        lx::pulse_multiplier h;
        const uint64_t r = 1 + rng() % r_max;
        const int64_t off = random_offset(rng);
        const int dir = (rep & 1) ? 1 : -1;
        int64_t n = dir > 0 ? (1LL << 31) - 50 : -(1LL << 31) + 50;
        h.preset(n, r, off);
        int64_t comp_prev = ref_comp(n, r, off);
        for (int i = 0; i < 100; ++i) {
            n = wrap32(n + dir);
            const lx::pulse_multiplier::out_t ho = h.step(dir, r, off);
            const int64_t want = ref_comp(n, r, off);
            res.check(ho.comp.to_int64() == want && ho.delta.to_int64() == want - comp_prev,
                      "wrap: N=" + std::to_string(n) + " R=" + std::to_string(r) + " comp " +
                          std::to_string(ho.comp.to_int64()) + " want " + std::to_string(want));
            comp_prev = want;
        }
    }
    // 4. path independence: up 1000 at (R1, OFF1) then (R2, OFF2), versus (R2, OFF2) first then up 1000
    for (int rep = 0; rep < 1000; ++rep) {
        const uint64_t r1 = 1 + rng() % r_max, r2 = 1 + rng() % r_max;
        const int64_t o1 = random_offset(rng), o2 = random_offset(rng);
        lx::pulse_multiplier a, b;
        lx::pulse_multiplier::out_t oa{}, ob{};
        for (int i = 0; i < 1000; ++i) oa = a.step(1, r1, o1);
        oa = a.step(0, r2, o2);
        ob = b.step(0, r2, o2);
        for (int i = 0; i < 1000; ++i) ob = b.step(1, r2, o2);
        res.check(oa.comp.to_int64() == ob.comp.to_int64() && oa.comp.to_int64() == ref_comp(1000, r2, o2),
                  "path dependence at R1=" + std::to_string(r1) + " R2=" + std::to_string(r2));
    }
    return res.finish();
}
