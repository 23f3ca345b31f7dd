// ctest-args-O0: --calls 300000
// tb_pulse_multiplier — pulse_multiplier (DESIGN §4.3): hls against golden and against an __int128
// reference of the Definition written here, plus the re-base theorem checked directly.
//
// 1. Random walk of N over |N| < 2^21 with random ratio and offset updates (standing still and
//    moving, updates closer than K_REBASE so that some wait, ratios over the whole Q5.32 range,
//    offsets over the whole 64-bit register including both extremes): hls == golden == reference
//    every call; the deltas add up to comp (no count lost in a re-base); and the re-base theorem:
//    from K_REBASE + L_MUL calls after an update taken while idle, comp == floor((N*R' + OFF')/2^32)
//    of the N of L_MUL calls earlier, on every call until the next update.
// 2. Exact-range statement: long double (64-bit significand) represents N*R + OFF exactly while
//    |N*R + OFF| < 2^64; checked for |N| up to 2^26 with the largest ratio and offset.
// 3. Timing of k: an update while idle is visible in comp exactly 1 + K_REBASE + L_MUL calls later
//    (not one call earlier), for random N, R, R', OFF, OFF'.
// 4. Beyond 2^26: N preset near +-2^31 and walked across the 32-bit wrap in both directions with
//    random ratios, offsets and updates (also during the wrap); hls == reference every call.
// 5. Path independence: two different paths to the same (N, R, OFF) give the same comp.
#include <climits>
#include <random>

#include "golden/pulse_multiplier.h"
#include "hls/pulse_multiplier.h"
#include "tb/tb_util.h"

namespace {
__extension__ typedef __int128 i128;
constexpr int K = 40;  // K_REBASE, DESIGN §4.3
constexpr int L = 3;   // L_MUL
constexpr int KL = 1 + K + L;  // an update at call w is taken at w + 1 (registered compare)

int64_t floor32(i128 v) { return static_cast<int64_t>(v >> 32); }  // arithmetic: floor
int64_t wrap_bits(int64_t v, int b) {
    const uint64_t m = (uint64_t{1} << b) - 1, u = static_cast<uint64_t>(v) & m, s = uint64_t{1} << (b - 1);
    return (u & s) ? static_cast<int64_t>(u | ~m) : static_cast<int64_t>(u);
}
int64_t wrap32(int64_t n) { return wrap_bits(n, 32); }

// The Definition of DESIGN §4.3 in exact integers (a third implementation, for the checks).
struct ref_model {
    int64_t n = 0, n0 = 0, off_tgt = 0, off_old = 0;
    uint64_t r_tgt = 0, r_old = 0;
    bool reb = false;
    int since = 0;
    int64_t hist[L + 1] = {0, 0, 0, 0};
    bool started = false;  // the last call started a re-base
    void preset(int64_t pn, uint64_t r, int64_t off) {
        *this = ref_model{};
        n = pn;
        r_tgt = r;
        off_tgt = off;
        for (int64_t& h : hist) h = value();
    }
    int64_t value() const {
        const i128 v = reb ? static_cast<i128>(n0) * r_old + static_cast<i128>(n - n0) * r_tgt + off_old
                           : static_cast<i128>(n) * r_tgt + off_tgt;
        return wrap_bits(floor32(v), 38);
    }
    bool pend = false;
    void step(int s, uint64_t r, int64_t off, int64_t& comp, int64_t& delta) {
        n = wrap32(n + s);
        if (reb && ++since >= K) reb = false;
        started = false;
        if (!reb && pend) {
            reb = true, since = 0, n0 = n, r_old = r_tgt, off_old = off_tgt, r_tgt = r, off_tgt = off;
            started = true;
        }
        pend = r != r_tgt || off != off_tgt;
        const int64_t prev = hist[L];
        for (int i = L; i > 0; --i) hist[i] = hist[i - 1];
        hist[0] = value();
        comp = hist[L];
        delta = comp - prev;
    }
};

// A random offset: mostly thermal-sized (|OFF| < 2^(32+24)), sometimes anywhere, sometimes an extreme.
int64_t random_offset(std::mt19937_64& rng) {
    const uint64_t k = rng() % 10;
    if (k == 0) return INT64_MIN;
    if (k == 1) return INT64_MAX;
    if (k < 4) return static_cast<int64_t>(rng());
    return static_cast<int64_t>(rng() % (1ULL << 57)) - (1LL << 56);
}
std::string s64(int64_t v) { return std::to_string(v); }
}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 7);
    const long long calls = tbu::arg_ll(argc, argv, "--calls", 3000000);
    tbu::result res("tb_pulse_multiplier", seed);
    std::mt19937_64 rng(seed);
    const uint64_t r_max = (1ULL << 37) - 1;
    static_assert(K == lx::pulse_multiplier_cfg::K_REBASE && L == lx::pulse_multiplier_cfg::L_MUL &&
                      K == golden::pulse_multiplier::K_REBASE && L == golden::pulse_multiplier::L_MUL,
                  "the constants of DESIGN §4.3");

    // 1. random walk, hls vs golden vs reference, and the re-base theorem
    {
        lx::pulse_multiplier h;
        golden::pulse_multiplier g;
        ref_model m;
        g.reset();
        int64_t n = 0, sum_delta = 0;
        uint64_t r = 34789620252ULL;
        int64_t off = 0;
        int dir = 1;
        long long settle_at = -1, theorem_checks = 0, waits = 0;  // call from which the theorem holds
        int64_t nhist[L + 1] = {0, 0, 0, 0};
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
            for (int i = L; i > 0; --i) nhist[i] = nhist[i - 1];
            nhist[0] = n;
            const lx::pulse_multiplier::out_t ho = h.step(step, r, off);
            const golden::pulse_multiplier::out g_o = g.step(step, r, off);
            int64_t rc = 0, rd = 0;
            const bool was_reb = m.reb && m.since + 1 < K;
            m.step(step, r, off, rc, rd);
            if (m.started) settle_at = t + K + L;  // the start call + K_REBASE + L_MUL
            if (!m.started && (r != m.r_tgt || off != m.off_tgt) && was_reb) ++waits;
            sum_delta += ho.delta.to_int64();
            const bool ok = ho.comp.to_int64() == rc && ho.delta.to_int64() == rd && g_o.comp == rc &&
                            g_o.delta == rd && sum_delta == rc;
            res.expect(ok, [&] {
                return "call " + std::to_string(t) + " N=" + s64(n) + " R=" + std::to_string(r) + " OFF=" + s64(off) +
                       ": comp hls " + s64(ho.comp.to_int64()) + " golden " + s64(g_o.comp) + " ref " + s64(rc) +
                       " delta hls " + s64(ho.delta.to_int64()) + " golden " + s64(g_o.delta) + " ref " + s64(rd) +
                       " sum(delta) " + s64(sum_delta);
            });
            // the theorem: settled and the pair in force unchanged since -> pure function of N(t-L)
            const bool pending = r != m.r_tgt || off != m.off_tgt;
            if (settle_at >= 0 && t >= settle_at && !pending && !m.reb) {
                const int64_t want = floor32(static_cast<i128>(nhist[L]) * m.r_tgt + m.off_tgt);
                ++theorem_checks;
                res.expect(ho.comp.to_int64() == want, [&] {
                    return "re-base theorem at call " + std::to_string(t) + ": comp " + s64(ho.comp.to_int64()) +
                           " want floor((N R' + OFF')/2^32) = " + s64(want);
                });
            }
        }
        res.check(theorem_checks > calls / 2, "the theorem was checked on most calls (" + std::to_string(theorem_checks) + ")");
        res.check(waits > 0, "some updates arrived during a re-base and waited");
        std::printf("[tb_pulse_multiplier] walk: %lld calls, theorem checked on %lld, %lld calls with a waiting update\n",
                    calls, theorem_checks, waits);
    }
    // 2. long double exact range: |N| < 2^26 with R up to 2^37-1 keeps |N*R| < 2^63, and with
    //    |OFF| <= 2^63 the sum stays below 2^64: exact, so the golden's floor is exact.
    for (int i = 0; i < 200000; ++i) {
        const int64_t n = static_cast<int64_t>(rng() % (1ULL << 27)) - (1LL << 26);
        const uint64_t r = i < 2 ? r_max : 1 + rng() % r_max;
        const int64_t off = i < 2 ? (i == 0 ? INT64_MIN : INT64_MAX) : random_offset(rng);
        const long double p = static_cast<long double>(n) * static_cast<long double>(r) + static_cast<long double>(off);
        const i128 exact = static_cast<i128>(n) * static_cast<i128>(r) + off;
        res.check(static_cast<i128>(p) == exact, "long double not exact at N=" + std::to_string(n));
    }
    // 3. k exactly: preset (N, R, OFF), stand still, update to (R', OFF') at call w: comp changes at
    //    call w + K + L and not before (hls and golden); moving meanwhile, the theorem holds from then.
    for (int rep = 0; rep < 3000 && res.failures < 10; ++rep) {
        const int64_t n = static_cast<int64_t>(rng() % (1ULL << 27)) - (1LL << 26);
        const uint64_t r1 = 1 + rng() % r_max, r2 = 1 + rng() % r_max;
        const int64_t o1 = random_offset(rng), o2 = random_offset(rng);
        lx::pulse_multiplier h;
        golden::pulse_multiplier g;
        h.preset(n, r1, o1);
        g.preset(n, r1, o1);
        const int64_t before = floor32(static_cast<i128>(n) * r1 + o1);
        const int64_t after = floor32(static_cast<i128>(n) * r2 + o2);
        const bool moving = rep & 1;
        int64_t nn = n, nhist[L + 1] = {n, n, n, n};
        for (int t = 0; t < KL + 5; ++t) {
            const int s = moving ? 1 : 0;
            nn += s;
            for (int i = L; i > 0; --i) nhist[i] = nhist[i - 1];
            nhist[0] = nn;
            const lx::pulse_multiplier::out_t ho = h.step(s, r2, o2);
            const golden::pulse_multiplier::out go = g.step(s, r2, o2);
            res.expect(ho.comp.to_int64() == go.comp, [&] { return "k check: hls != golden at call " + std::to_string(t); });
            if (!moving && t < KL)
                res.expect(ho.comp.to_int64() == before, [&] { return "k check: comp moved before call w+K+L, call " + std::to_string(t); });
            if (!moving && t >= KL)
                res.expect(ho.comp.to_int64() == after, [&] { return "k check: comp not settled at call w+" + std::to_string(t); });
            if (moving && t >= KL)
                res.expect(ho.comp.to_int64() == floor32(static_cast<i128>(nhist[L]) * r2 + o2),
                           [&] { return "k check (moving): theorem fails at call w+" + std::to_string(t); });
        }
    }
    // 4. across the 32-bit wrap, both directions, with updates, hls vs the reference
    for (int rep = 0; rep < 400 && res.failures < 10; ++rep) {
        lx::pulse_multiplier h;
        ref_model m;
        uint64_t r = 1 + rng() % r_max;
        int64_t off = random_offset(rng);
        const int dir = (rep & 1) ? 1 : -1;
        int64_t n = dir > 0 ? (1LL << 31) - 60 : -(1LL << 31) + 60;
        h.preset(n, r, off);
        m.preset(n, r, off);
        for (int i = 0; i < 200; ++i) {
            if (rng() % 40 == 0) r = 1 + rng() % r_max;
            if (rng() % 60 == 0) off = random_offset(rng);
            const int s = (rng() % 5 == 0) ? 0 : dir;
            const lx::pulse_multiplier::out_t ho = h.step(s, r, off);
            int64_t rc = 0, rd = 0;
            m.step(s, r, off, rc, rd);
            res.expect(ho.comp.to_int64() == rc && ho.delta.to_int64() == rd, [&] {
                return "wrap: N=" + s64(m.n) + " R=" + std::to_string(r) + " comp " + s64(ho.comp.to_int64()) + " want " +
                       s64(rc) + " delta " + s64(ho.delta.to_int64()) + " want " + s64(rd);
            });
        }
    }
    // 5. path independence: up 1000 at (R1, OFF1) then (R2, OFF2), versus (R2, OFF2) first then up 1000
    for (int rep = 0; rep < 1000; ++rep) {
        const uint64_t r1 = 1 + rng() % r_max, r2 = 1 + rng() % r_max;
        const int64_t o1 = random_offset(rng), o2 = random_offset(rng);
        lx::pulse_multiplier a, b;
        lx::pulse_multiplier::out_t oa = a.step(0, r1, o1), ob = b.step(0, r2, o2);
        for (int i = 0; i < 1000; ++i) oa = a.step(1, r1, o1);
        for (int i = 0; i <= KL; ++i) oa = a.step(0, r2, o2);  // w .. w + K + L
        for (int i = 0; i < 1000; ++i) ob = b.step(1, r2, o2);
        for (int i = 0; i <= KL; ++i) ob = b.step(0, r2, o2);
        res.check(oa.comp.to_int64() == ob.comp.to_int64() && oa.comp.to_int64() == floor32(static_cast<i128>(1000) * r2 + o2),
                  "path dependence at R1=" + std::to_string(r1) + " R2=" + std::to_string(r2));
    }
    return res.finish();
}
