// ctest-args: --seed 11 --runs 40 --calls 100000
// ctest-args-O0: --seed 11 --runs 6 --calls 20000
// tb_error_map — error mapping block (hls/error_map.h) against its golden model
// (golden/error_map.h), every output on every call, plus the behaviour the block promises
// (docs/ERROR_MAP.md).
//
// random:     seeded motion (random speeds up to 4 points per call, both directions, reversals,
//             dwells, jumps) over and beyond both table ends; random geometries (k 4..20, n 2..1024,
//             origin anywhere in +-2^30); random tables (smooth walks with large slopes, full-range
//             noise, alternating extremes, small sinusoids, constants); homing and enable toggles;
//             reloads of the inactive bank one word per call during motion, followed by a flip
//             (some to an invalid geometry). Bit-exact against golden on every call; invariants:
//             sum of delta == corr, corr == 0 unless active, corr equals a direct integer formula
//             written here (which also checks the end values held outside the table).
// exhaustive: k = 4, n = 8: every position from 40 counts before the table to 40 beyond it, up
//             and down, several tables (noise, extremes, exact half ties, ramp), several origins.
// directed:   a flip never mixes banks (constant tables of different value, frac != 0); writes
//             to the inactive bank never change the output; every invalid geometry gives cfg_err
//             and corr 0 (delta brings it back once), and recovery; latency is L_MAP = 50 calls
//             from a sample call (one in S_MAP = 32; the outputs hold in between). Every call of
//             every part is also checked against the direct formula of the last published sample.
#include <cstdio>
#include <deque>
#include <random>
#include <string>
#include <vector>

#include "golden/error_map.h"
#include "hls/error_map.h"
#include "tb/tb_util.h"

namespace {

constexpr int kDepth = 1024;  // ERROR_MAP.md §2
constexpr int kPeriod = 32;   // ERROR_MAP.md §6: one sample call in kPeriod (the first after reset)
constexpr int kLat = 50;      // sample call t -> outputs of calls t + kLat - 1 .. (held until the next)
constexpr int kNMax = 2047;   // largest value of the 11-bit n_points register
static_assert(kDepth == lx::error_map_cfg::TBL_DEPTH && kDepth == golden::error_map::kDepth, "depth");
static_assert(kLat == lx::error_map_cfg::L_MAP && kLat == golden::error_map::kLat, "latency");
static_assert(kPeriod == lx::error_map_cfg::S_MAP && kPeriod == golden::error_map::kPeriod, "period");
static_assert(kNMax == (1 << lx::error_map_cfg::W_N) - 1, "n_points register width");
constexpr int32_t kWordMin = -(1 << 23);
constexpr int32_t kWordMax = (1 << 23) - 1;

int64_t floordiv(int64_t a, int64_t b) {  // b > 0
    const int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

struct geom {
    int64_t origin = 0;
    int k = 10;
    int n = kDepth;
    bool ok() const { return k >= 4 && k <= 20 && n >= 2 && n <= kDepth; }
};

// Direct formula, written independently of both models: convex combination of the two points in
// integers, round floor(x + 1/2); positions outside the table take the end point.
int64_t direct_corr(const std::vector<int32_t>& t, const geom& g, int64_t x) {
    const int64_t s = int64_t{1} << g.k;
    const int64_t span = int64_t{g.n - 1} * s;
    int64_t r = x - g.origin;
    if (r < 0) r = 0;
    if (r > span) r = span;
    const int64_t i = r / s;
    const int64_t f = r - i * s;
    const int64_t a = t[static_cast<size_t>(i)];
    const int64_t b = f == 0 ? a : t[static_cast<size_t>(i + 1)];
    const int64_t num = a * (s - f) + b * f;  // |num| < 2^43
    return floordiv(num + s * 128, s * 256);
}

struct host_regs {
    bool map_en = true;
    bool bank_sel = false;
    geom g[2];
    bool we = false;
    int addr = 0;
    int32_t data = 0;
};

// What the outputs must be once a sample call's result is published, from that call's inputs
// (the tables before its write).
struct expect_t {
    bool active = false;
    bool cfg_err = false;
    int64_t corr = 0;
    int where = 0;  // -1 below the table, 0 inside, +1 beyond
};

expect_t expected(const std::vector<int32_t>* shadow, int64_t p, bool homed, const host_regs& r) {
    expect_t e;
    const int b = r.bank_sel ? 1 : 0;
    const geom& g = r.g[b];
    e.cfg_err = r.map_en && !g.ok();
    e.active = r.map_en && homed && g.ok();
    if (e.active) {
        e.corr = direct_corr(shadow[b], g, p);
        const int64_t span = int64_t{g.n - 1} << g.k;
        e.where = p < g.origin ? -1 : (p - g.origin > span ? 1 : 0);
    }
    return e;
}

void check_expect(tbu::result& res, const expect_t& e, const lx::error_map::out_t& o, const char* where, long t) {
    res.expect(o.active == e.active && o.cfg_err == e.cfg_err && o.corr.to_int64() == e.corr &&
                   o.clamped == (e.active && e.where != 0) && o.in_range == (e.active && e.where == 0),
               [&] {
                   return std::string(where) + " call " + std::to_string(t) + ": corr " +
                          std::to_string(o.corr.to_int64()) + " want " + std::to_string(e.corr) + " (active " +
                          std::to_string(o.active) + "/" + std::to_string(e.active) + ", cfg_err " +
                          std::to_string(o.cfg_err) + "/" + std::to_string(e.cfg_err) + ", where " +
                          std::to_string(e.where) + ")";
               });
}

// One hls model and one golden model driven with the same inputs; compares every output with
// golden and with the published expectation of the sample schedule (ERROR_MAP.md §4, §6): the
// inputs of the calls n * kPeriod after construction, each published kLat - 1 calls later (two
// samples are in flight: kLat - 1 > kPeriod).
struct dut {
    struct pending_t {
        long at;      // call index at which it becomes cur
        expect_t e;   // the sample's expectation
        int64_t p;    // the sample's position
    };
    lx::error_map h;
    golden::error_map g;
    std::vector<int32_t> shadow[2];  // the tables as the test believes them to be
    int64_t sum_delta = 0;
    long calls = 0;             // calls since construction
    expect_t cur;               // what the outputs must be now
    std::deque<pending_t> pend;  // samples taken, not yet published, oldest first
    int64_t sample_p = 0;        // position of the sample call whose result is published

    dut() {
        shadow[0].assign(kDepth, 0);
        shadow[1].assign(kDepth, 0);
    }

    lx::error_map::out_t step(tbu::result& res, int64_t p, bool homed, const host_regs& r, const char* where,
                              long t) {
        lx::error_map_regs hr;
        golden::error_map_regs gr;
        hr.map_en = gr.map_en = r.map_en;
        hr.bank_sel = gr.bank_sel = r.bank_sel;
        for (int b = 0; b < 2; ++b) {
            hr.geom[b].origin = r.g[b].origin;
            hr.geom[b].spacing_log2 = r.g[b].k;
            hr.geom[b].n_points = r.g[b].n;
            gr.geom[b].origin = r.g[b].origin;
            gr.geom[b].spacing_log2 = r.g[b].k;
            gr.geom[b].n_points = r.g[b].n;
        }
        hr.we = gr.we = r.we;
        hr.addr = r.addr;
        gr.addr = r.addr;
        hr.data = r.data;
        gr.data = r.data;
        if (calls % kPeriod == 0)  // a sample call: expectation from the tables before its write
            pend.push_back(pending_t{calls + kLat - 1, expected(shadow, p, homed, r), p});
        const lx::error_map::out_t ho = h.step(p, homed, hr);
        const golden::error_map::out go = g.step(p, homed, gr);
        if (r.we) shadow[r.bank_sel ? 0 : 1][static_cast<size_t>(r.addr)] = r.data;
        if (!pend.empty() && calls == pend.front().at) {
            cur = pend.front().e;
            sample_p = pend.front().p;
            pend.pop_front();
        }
        check_expect(res, cur, ho, where, t);
#ifndef __SYNTHESIS__  // (the RAM flags: C simulation only)
        res.expect(h.ram_violations() == 0, [&] {
            return std::string(where) + " call " + std::to_string(t) + ": RAM port violations " +
                   std::to_string(h.ram_violations());
        });
#endif
        ++calls;
        sum_delta += ho.delta.to_int64();
        res.expect(ho.corr.to_int64() == go.corr && ho.delta.to_int64() == go.delta && ho.active == go.active &&
                       ho.in_range == go.in_range && ho.clamped == go.clamped && ho.cfg_err == go.cfg_err,
                   [&] {
                       return std::string(where) + " call " + std::to_string(t) + ": hls/golden corr " +
                              std::to_string(ho.corr.to_int64()) + "/" + std::to_string(go.corr) + " delta " +
                              std::to_string(ho.delta.to_int64()) + "/" + std::to_string(go.delta) + " act " +
                              std::to_string(ho.active) + "/" + std::to_string(go.active) + " inr " +
                              std::to_string(ho.in_range) + "/" + std::to_string(go.in_range) + " clamp " +
                              std::to_string(ho.clamped) + "/" + std::to_string(go.clamped) + " cfg_err " +
                              std::to_string(ho.cfg_err) + "/" + std::to_string(go.cfg_err);
                   });
        res.expect(sum_delta == ho.corr.to_int64(), [&] {
            return std::string(where) + " call " + std::to_string(t) + ": sum of delta " + std::to_string(sum_delta) +
                   " != corr " + std::to_string(ho.corr.to_int64());
        });
        return ho;
    }
};

int32_t clamp_word(int64_t v) { return static_cast<int32_t>(v < kWordMin ? kWordMin : (v > kWordMax ? kWordMax : v)); }

std::vector<int32_t> random_table(std::mt19937_64& rng, int n, int* kind_out) {
    std::vector<int32_t> t(static_cast<size_t>(n));
    const int kind = static_cast<int>(rng() % 5);
    *kind_out = kind;
    auto urange = [&](int64_t lo, int64_t hi) { return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1)); };
    if (kind == 0) {  // smooth walk, slope up to 2^(4..20) per point
        const int64_t slope = int64_t{1} << urange(4, 20);
        int64_t v = urange(kWordMin / 2, kWordMax / 2);
        for (auto& w : t) {
            v += urange(-slope, slope);
            w = clamp_word(v);
            v = w;
        }
    } else if (kind == 1) {  // full-range noise: largest slopes, sign change almost every point
        for (auto& w : t) w = static_cast<int32_t>(urange(kWordMin, kWordMax));
    } else if (kind == 2) {  // alternating extremes
        const bool start = (rng() & 1) != 0;
        for (size_t i = 0; i < t.size(); ++i) t[i] = ((i & 1) != 0) == start ? kWordMax : kWordMin;
    } else if (kind == 3) {  // small periodic error (a few um), integer triangle-ish shape
        const int64_t amp = urange(1, 200 * 256);
        const int64_t per = urange(2, 64);
        const int64_t off = urange(-1000 * 256, 1000 * 256);
        for (size_t i = 0; i < t.size(); ++i) {
            const int64_t ph = static_cast<int64_t>(i) % per;
            const int64_t tri = 4 * ph < 2 * per ? 4 * ph - per : 3 * per - 4 * ph;  // -per..per
            t[i] = clamp_word(off + amp * tri / per + urange(-255, 255));
        }
    } else {
        const int32_t c = static_cast<int32_t>(urange(kWordMin, kWordMax));
        for (auto& w : t) w = c;
    }
    return t;
}

geom random_geom(std::mt19937_64& rng, bool allow_bad) {
    geom g;
    const int r = static_cast<int>(rng() % 8);
    g.k = r < 5 ? 4 + static_cast<int>(rng() % 5) : 4 + static_cast<int>(rng() % 17);  // mostly short spacing
    const int nr = static_cast<int>(rng() % 4);
    g.n = nr == 0 ? 2 + static_cast<int>(rng() % 8) : (nr == 1 ? kDepth : 2 + static_cast<int>(rng() % (kDepth - 1)));
    g.origin = static_cast<int64_t>(rng() % (uint64_t{1} << 31)) - (int64_t{1} << 30);
    if (allow_bad && rng() % 8 == 0) {
        const int b = static_cast<int>(rng() % 4);
        if (b == 0) g.k = static_cast<int>(rng() % 4);
        if (b == 1) g.k = 21 + static_cast<int>(rng() % 11);
        if (b == 2) g.n = static_cast<int>(rng() % 2);
        if (b == 3) g.n = kDepth + 1 + static_cast<int>(rng() % (kNMax - kDepth));
    }
    return g;
}

struct coverage {
    long calls = 0, active = 0, inside = 0, below = 0, beyond = 0, inactive = 0, cfg_err = 0, flips = 0,
         writes = 0, reversals = 0, bad_flips = 0, home_toggles = 0, en_toggles = 0;
    long kinds[5] = {0, 0, 0, 0, 0};
    int64_t max_abs_delta = 0;
};

void test_random(tbu::result& res, std::mt19937_64& rng, int runs, long calls, coverage& cov) {
    for (int run = 0; run < runs && res.failures < 10; ++run) {
        dut d;
        host_regs r;
        r.map_en = true;
        bool homed = rng() % 2 == 0;
        // bank 0 is active with the all-zero power-up table and a random geometry
        r.g[0] = random_geom(rng, false);
        r.g[1] = random_geom(rng, false);
        const geom* ag = &r.g[0];
        int64_t p = ag->origin + static_cast<int64_t>(rng() % 1000);
        int64_t v = 1;
        // host reload state machine
        std::vector<int32_t> next_tbl;
        int load_pos = -1;  // < 0: idle
        long idle = static_cast<long>(rng() % 2000);
        for (long t = 0; t < calls && res.failures < 10; ++t) {
            // --- host: reload of the inactive bank, one word per call, then the flip
            r.we = false;
            if (load_pos < 0 && idle-- <= 0) {
                int kind = 0;
                const geom ng = random_geom(rng, true);
                r.g[r.bank_sel ? 0 : 1] = ng;  // inactive bank's geometry: free to change
                next_tbl = random_table(rng, ng.n >= 2 && ng.n <= kDepth ? ng.n : kDepth, &kind);
                ++cov.kinds[kind];
                load_pos = 0;
            }
            if (load_pos >= 0) {
                if (load_pos < static_cast<int>(next_tbl.size())) {
                    if (rng() % 4 != 0) {  // not every call
                        r.we = true;
                        r.addr = load_pos;
                        r.data = next_tbl[static_cast<size_t>(load_pos)];
                        ++load_pos;
                        ++cov.writes;
                    }
                } else if (rng() % 16 == 0) {
                    r.bank_sel = !r.bank_sel;  // flip: takes effect in this call
                    ++cov.flips;
                    if (!r.g[r.bank_sel ? 1 : 0].ok()) ++cov.bad_flips;
                    load_pos = -1;
                    idle = static_cast<long>(rng() % 6000);
                    if (rng() % 3 != 0) {  // restart motion near the new table
                        const geom& g = r.g[r.bank_sel ? 1 : 0];
                        p = g.origin - 50 + static_cast<int64_t>(rng() % 100);
                    }
                }
            }
            if (rng() % 4000 == 0) { homed = !homed; ++cov.home_toggles; }
            if (rng() % 7000 == 0) { r.map_en = !r.map_en; ++cov.en_toggles; }
            if (!r.map_en && rng() % 500 == 0) { r.map_en = true; ++cov.en_toggles; }
            if (!homed && rng() % 400 == 0) { homed = true; ++cov.home_toggles; }

            // --- motion over the active table and beyond both ends
            ag = &r.g[r.bank_sel ? 1 : 0];
            const int ks = ag->k >= 4 && ag->k <= 20 ? ag->k : 10;
            const int ns = ag->n >= 2 && ag->n <= kDepth ? ag->n : 16;
            const int64_t s = int64_t{1} << ks;
            const int64_t span = int64_t{ns - 1} * s;
            const int64_t lo = ag->origin - span / 8 - 2 * s, hi = ag->origin + span + span / 8 + 2 * s;
            if ((p < lo - 4 * s || p > hi + 4 * s) && rng() % 64 == 0)  // far away (new table): come back
                p = lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
            if (rng() % 300 == 0) {
                const int sel = static_cast<int>(rng() % 6);
                const int64_t vmax = sel == 0 ? 1 : sel == 1 ? 3 : sel == 2 ? s / 8 + 1 : sel == 3 ? s : sel == 4 ? 4 * s : 0;
                const int64_t nv = vmax == 0 ? 0 : static_cast<int64_t>(rng() % static_cast<uint64_t>(2 * vmax + 1)) - vmax;
                if ((nv < 0) != (v < 0)) ++cov.reversals;
                v = nv;
            }
            if (rng() % 20000 == 0) p = lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));  // jump
            p += v;
            if (p > hi && v >= 0) { v = -(v == 0 ? 1 : v); ++cov.reversals; }
            if (p < lo && v <= 0) { v = (v == 0 ? 1 : -v); ++cov.reversals; }

            const bool published = !d.pend.empty() && d.calls == d.pend.front().at;
            const lx::error_map::out_t o = d.step(res, p, homed, r, "random", t);
            const expect_t& pub = d.cur;  // checked against o by d.step
            ++cov.calls;
            if (o.active) ++cov.active; else ++cov.inactive;
            if (o.cfg_err) ++cov.cfg_err;
            if (o.in_range) ++cov.inside;
            if (published && pub.active && pub.where < 0) ++cov.below;
            if (published && pub.active && pub.where > 0) ++cov.beyond;
            const int64_t ad = o.delta.to_int64() < 0 ? -o.delta.to_int64() : o.delta.to_int64();
            if (ad > cov.max_abs_delta) cov.max_abs_delta = ad;
        }
    }
}

// Loads table t into the inactive bank with geometry g and flips to it (one write per call; p
// held at `park`; only the hls/golden comparison runs during the load). bank_sel is flipped for
// the caller's next call.
void load_and_flip(tbu::result& res, dut& d, host_regs& r, const std::vector<int32_t>& t, const geom& g, int64_t park,
                   bool homed) {
    const int ib = r.bank_sel ? 0 : 1;
    r.g[ib] = g;
    for (size_t a = 0; a < t.size(); ++a) {
        r.we = true;
        r.addr = static_cast<int>(a);
        r.data = t[a];
        d.step(res, park, homed, r, "load", static_cast<long>(a));
    }
    r.we = false;
    r.bank_sel = !r.bank_sel;
}

void test_exhaustive(tbu::result& res, std::mt19937_64& rng, long& points) {
    const geom base{0, 4, 8};
    std::vector<std::vector<int32_t>> tables;
    std::vector<int32_t> t(8);
    for (auto& w : t) w = static_cast<int32_t>(static_cast<int64_t>(rng() % (uint64_t{1} << 24)) + kWordMin);
    tables.push_back(t);
    for (size_t i = 0; i < 8; ++i) t[i] = (i & 1) ? kWordMax : kWordMin;
    tables.push_back(t);
    // exact half ties: values x.5 at the points and halfway between points (e.g. 128 -> 0.5)
    const int32_t ties[8] = {128, 384, -128, -384, 640, -640, 0, 1};
    for (size_t i = 0; i < 8; ++i) t[i] = ties[i];
    tables.push_back(t);
    for (size_t i = 0; i < 8; ++i) t[i] = static_cast<int32_t>(i) * 37 * 256 / 3 - 200;
    tables.push_back(t);
    const int64_t origins[3] = {0, -1000003, (int64_t{1} << 36) - 200};
    for (const auto& tb : tables) {
        for (int64_t org : origins) {
            dut d;
            host_regs r;
            geom g = base;
            g.origin = org;
            r.g[0] = g;
            load_and_flip(res, d, r, tb, g, org, true);
            const int64_t span = 7 * 16;
            long t_call = 0;
            for (int dir = 1; dir >= -1; dir -= 2) {
                for (int64_t j = 0; j <= span + 80; ++j) {
                    const int64_t x = dir > 0 ? org - 40 + j : org + span + 40 - j;
                    // hold x until a sample call has taken it and its result is published
                    while (d.calls % kPeriod != 0) d.step(res, x, true, r, "exhaustive", t_call++);
                    for (int c = 0; c < kLat; ++c) d.step(res, x, true, r, "exhaustive", t_call++);
                    res.expect(d.sample_p == x && d.cur.active, [&] {
                        return "exhaustive: position " + std::to_string(x) + " not sampled";
                    });
                    ++points;
                }
            }
        }
    }
}

void test_directed(tbu::result& res) {
    // 1. flip never mixes banks: bank 0 all A, bank 1 all B, positions with frac != 0
    {
        dut d;
        host_regs r;
        const geom g{1000, 6, 64};
        r.g[0] = g;
        const int32_t A = 100 * 256 + 17, B = -250 * 256 + 3;
        load_and_flip(res, d, r, std::vector<int32_t>(64, A), g, 0, true);   // now bank 1 = A
        load_and_flip(res, d, r, std::vector<int32_t>(64, B), g, 0, true);   // now bank 0 = B
        // now bank 0 (B) is active and bank 1 holds A; flip every 5 calls while moving. Each
        // published value is that of the bank selected in its sample call.
        const int64_t wantA = floordiv(A + 128, 256), wantB = floordiv(B + 128, 256);
        std::deque<std::pair<long, bool>> samples;  // (publication call, bank_sel of the sample)
        int seenA = 0, seenB = 0;
        for (long t = 0; t < 4000; ++t) {
            if (t % 5 == 0) r.bank_sel = !r.bank_sel;
            const int64_t x = 1000 + 3 + 7 * t % 4000;
            if (d.calls % kPeriod == 0) samples.emplace_back(d.calls + kLat - 1, r.bank_sel);
            const bool pub = !samples.empty() && d.calls == samples.front().first;
            const bool sample_sel = pub && samples.front().second;
            if (pub) samples.pop_front();
            const lx::error_map::out_t o = d.step(res, x, true, r, "flip", t);
            if (pub) {
                const int64_t want = sample_sel ? wantA : wantB;  // bank 1 holds A
                (sample_sel ? seenA : seenB)++;
                res.expect(o.corr.to_int64() == want, [&] {
                    return "flip call " + std::to_string(t) + ": corr " + std::to_string(o.corr.to_int64()) +
                           " want " + std::to_string(want);
                });
            }
        }
        res.check(seenA > 10 && seenB > 10, "flip: both banks must be published");
    }
    // 2. writes to the inactive bank never change the output; latency is kLat calls from a sample
    {
        dut d;
        host_regs r;
        const geom g{-5000, 8, 100};
        r.g[0] = g;
        std::vector<int32_t> t(100);
        for (size_t i = 0; i < t.size(); ++i) t[i] = static_cast<int32_t>(i * i) * 300 - 700000;
        load_and_flip(res, d, r, t, g, -100000, false);  // not homed while loading
        const int64_t x = -5000 + 37 * 256 + 77;
        const int64_t want = direct_corr(t, g, x);
        while (d.calls % kPeriod != 0) d.step(res, x, false, r, "align", d.calls);
        // homed rises in a sample call (c = 0) with p = x: corr appears in call kLat - 1, not before
        for (int c = 0; c < kLat - 1; ++c) {
            const lx::error_map::out_t o0 = d.step(res, x, true, r, "latency", c);
            res.check(o0.corr.to_int64() == 0 && !o0.active,
                      "latency: corr appeared in call " + std::to_string(c) + " after the sample");
        }
        const lx::error_map::out_t o1 = d.step(res, x, true, r, "latency", kLat - 1);
        res.check(o1.corr.to_int64() == want && o1.delta.to_int64() == want && o1.active,
                  "latency: corr " + std::to_string(o1.corr.to_int64()) + " want " + std::to_string(want) +
                      " kLat - 1 calls after the sample");
        for (int a = 0; a < kDepth; ++a) {
            r.we = true;
            r.addr = a;
            r.data = (a & 1) ? kWordMax : kWordMin;
            const lx::error_map::out_t o = d.step(res, x, true, r, "inactive-write", a);
            if (!res.check(o.corr.to_int64() == want && o.delta.to_int64() == 0,
                           "write to the inactive bank changed the output at addr " + std::to_string(a)))
                break;
        }
        r.we = false;
    }
    // 3. a flip while samples are in flight, then at once a reload of the released bank: every
    //    sample taken before the flip still publishes the old table (the write port's delay,
    //    W_DLY = 24 calls, outlasts the reads of the samples in flight; a shorter one mixes)
    for (int flip_at = 1; flip_at < kPeriod; flip_at += 3) {
        dut d;
        host_regs r;
        const geom g{0, 5, 40};
        r.g[0] = g;
        const int32_t A = 700 * 256 + 11, B = -900 * 256 + 5;
        load_and_flip(res, d, r, std::vector<int32_t>(40, A), g, 0, true);  // active: A
        r.g[r.bank_sel ? 0 : 1] = g;
        const int64_t x = 13 * 32 + 9;  // inside, frac != 0
        while (d.calls % kPeriod != 0) d.step(res, x, true, r, "reload-align", d.calls);
        for (int c = 0; c < kPeriod + kLat; ++c) d.step(res, x, true, r, "reload-settle", c);
        while (d.calls % kPeriod != 0) d.step(res, x, true, r, "reload-align", d.calls);
        const long sample = d.calls;  // a sample call on table A
        for (int c = 0; c < flip_at; ++c) d.step(res, x, true, r, "reload-pre", c);
        r.bank_sel = !r.bank_sel;  // flip: the A bank is released, written at once with B
        for (int a = 0; a < 40; ++a) {
            r.we = true;
            r.addr = a;
            r.data = B;
            d.step(res, x, true, r, "reload-write", a);
        }
        r.we = false;
        while (d.calls < sample + kLat - 1) d.step(res, x, true, r, "reload-wait", d.calls);
        const lx::error_map::out_t o = d.step(res, x, true, r, "reload-pub", d.calls);
        res.check(o.corr.to_int64() == floordiv(A + 128, 256),
                  "reload after a flip in call " + std::to_string(flip_at) + " of the period: the sample of call " +
                      std::to_string(sample) + " published " + std::to_string(o.corr.to_int64()) +
                      " instead of table A's value");
    }
    // 4. invalid geometries: cfg_err, corr 0 (one delta back), recovery; none when disabled
    {
        const geom bad[] = {{0, 0, 16}, {0, 3, 16}, {0, 21, 16}, {0, 31, 16}, {0, 8, 0},
                            {0, 8, 1},  {0, 8, kDepth + 1}, {0, 8, kNMax}, {0, 2, 1500}};
        for (const geom& b : bad) {
            dut d;
            host_regs r;
            const geom g{0, 8, 16};
            r.g[0] = g;
            const int32_t v = 5000 * 256;
            load_and_flip(res, d, r, std::vector<int32_t>(16, v), g, 0, true);
            for (int t = 0; t < kPeriod + kLat; ++t) d.step(res, 300, true, r, "cfg", t);
            while (d.calls % kPeriod != 0) d.step(res, 300, true, r, "align", d.calls);
            const int cur = r.bank_sel ? 1 : 0;
            const std::string name = "invalid k=" + std::to_string(b.k) + " n=" + std::to_string(b.n);
            r.g[cur] = b;
            // the bad geometry enters in a sample call (c = 0); the output of call kLat - 1 is its
            for (int c = 0; c < kLat - 1; ++c) {
                const lx::error_map::out_t q = d.step(res, 300, true, r, "cfg", c);
                res.check(!q.cfg_err && q.corr.to_int64() == 5000, name + ": cfg_err / corr change too early");
            }
            const lx::error_map::out_t o = d.step(res, 300, true, r, "cfg", kLat - 1);
            res.check(o.cfg_err && !o.active && o.corr.to_int64() == 0 && o.delta.to_int64() == -5000,
                      name + ": no cfg_err / corr not 0 / delta not -5000 (delta " +
                          std::to_string(o.delta.to_int64()) + ")");
            for (int c = kLat; c < kLat + 3 * kPeriod; ++c) {
                const lx::error_map::out_t q = d.step(res, 300 + c, true, r, "cfg", c);
                res.check(q.cfg_err && q.corr.to_int64() == 0 && q.delta.to_int64() == 0, name + ": not held at 0");
            }
            r.map_en = false;  // disabled: no error flag
            while (d.calls % kPeriod != 0) d.step(res, 300, true, r, "align", d.calls);
            lx::error_map::out_t q;
            for (int c = 0; c < kLat; ++c) q = d.step(res, 300, true, r, "cfg-off", c);
            res.check(!q.cfg_err && q.corr.to_int64() == 0, name + ": cfg_err while disabled");
            r.map_en = true;
            r.g[cur] = g;  // recovery
            while (d.calls % kPeriod != 0) d.step(res, 300, true, r, "align", d.calls);
            lx::error_map::out_t w;
            for (int c = 0; c < kLat; ++c) w = d.step(res, 300, true, r, "cfg-rec", c);
            res.check(!w.cfg_err && w.corr.to_int64() == 5000 && w.delta.to_int64() == 5000, name + ": no recovery");
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 11);
    const int runs = static_cast<int>(tbu::arg_ll(argc, argv, "--runs", 40));
    const long calls = static_cast<long>(tbu::arg_ll(argc, argv, "--calls", 100000));
    tbu::result res("tb_error_map", seed);
    std::mt19937_64 rng(seed);

    test_directed(res);
    long points = 0;
    test_exhaustive(res, rng, points);
    coverage cov;
    test_random(res, rng, runs, calls, cov);

    std::printf("[tb_error_map] exhaustive: %ld positions (k=4, n=8, 4 tables x 3 origins, both directions)\n",
                points);
    std::printf("[tb_error_map] random: %ld calls, active %ld (inside %ld, below %ld, beyond %ld), inactive %ld, "
                "cfg_err %ld\n",
                cov.calls, cov.active, cov.inside, cov.below, cov.beyond, cov.inactive, cov.cfg_err);
    std::printf("[tb_error_map] random: %ld flips (%ld to an invalid geometry), %ld table writes, %ld reversals, "
                "%ld homing / %ld enable toggles, max |delta| %lld, table kinds %ld/%ld/%ld/%ld/%ld\n",
                cov.flips, cov.bad_flips, cov.writes, cov.reversals, cov.home_toggles, cov.en_toggles,
                static_cast<long long>(cov.max_abs_delta), cov.kinds[0], cov.kinds[1], cov.kinds[2], cov.kinds[3],
                cov.kinds[4]);
    // coverage must be real, not vacuous
    res.check(cov.below > 0 && cov.beyond > 0 && cov.inside > 0 && cov.flips > 0 && cov.bad_flips > 0 &&
                  cov.cfg_err > 0 && cov.home_toggles > 0 && cov.en_toggles > 0,
              "random coverage incomplete");
    return res.finish();
}
