// ctest-args: --seed 4 --runs 40
// ctest-args-O0: --seed 4 --runs 6
// tb_encoder_counter — encoder counter block (hls/encoder_counter.h) against its golden model
// (golden/encoder_counter.h) on every call, plus the behaviour it promises
// (docs/PSO_COUNTERS.md §3).
//
// random:    both channels, quadrature steps (random walk) or simulation (random rate up to the
//            25 MHz limit, up or down), presets next to the +-2^31 boundary so that counting wraps
//            in both directions, resets now and at the next trigger, random triggers, correction
//            periods, scales (full 32-bit range), positions, wait-for-encoder on either channel in
//            either direction with values on both sides of the wrap, short invalid configurations.
// wrap:      max + 1 -> min and min - 1 -> max, counted by quadrature steps and by the simulation,
//            both directions; wait-for-encoder reached exactly two calls after the counter passes
//            a value across the boundary (up and down); a value 2^31 or more ahead is seen behind.
// reset:     immediate reset in the request call; reset-on-trigger in the trigger call (not a
//            trigger in the request call); simulation phase restarts: first count 101 calls
//            after the reset at 1 MHz (carry in the 100th call, counted in the next).
// correction: ticks exactly every corr_period calls, the first at corr_period - 1 + 33 (the
//            sequenced product's latency); value = pos + floor(scale * cnt / 2^24 + 1/2) from the
//            counter before the sample call (33 calls before the tick) and that call's position,
//            including ties, negative values, the largest product and corr_period = 33.
// config:    source 2/3, period 0 and 32, simulation above 25 MHz: cfg_err, outputs held at zero.
// calibration: increments from start/end readings across the wrap, least squares over wrapped
//            readings, Scale = K / i and K * v / rate, signs for both directions, Q8.24.
// command:   `laserax counters` (cmd_counters) returns 0 (bit-exact, wrap seen, reset at trigger).
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "golden/calibration.h"
#include "golden/encoder_counter.h"
#include "hls/encoder_counter.h"
#include "tb/tb_util.h"
#include "tools/laserax/counters_cmd.h"

namespace {

constexpr int64_t kMax = 2147483647LL;
constexpr int64_t kMin = -2147483648LL;

struct pair_run {
    lx::encoder_counter h;
    golden::encoder_counter g;
    tbu::result* res;
    std::string tag;
    long long t = 0;
    golden::encoder_counter::out step(const golden::encoder_counter_in& in, const golden::encoder_counter_regs& r) {
        const lx::encoder_counter::out_t ho = h.step(lxt::counters_to_hls(in), lxt::counters_to_hls(r));
        const golden::encoder_counter::out go = g.step(in, r);
        const std::string m = lxt::counters_compare(ho, go);
        res->expect(m.empty(), [&] { return tag + " call " + std::to_string(t) + ": " + m; });
        ++t;
        return go;
    }
};

golden::encoder_counter_regs quad_regs() {
    golden::encoder_counter_regs r;
    r.src[0] = r.src[1] = 0;
    return r;
}

golden::encoder_counter_regs sim_regs() {  // both channels from the simulation, 1 MHz
    golden::encoder_counter_regs r;
    r.src[0] = r.src[1] = 1;
    return r;
}

golden::encoder_counter_in qin(int s0, int s1) {
    golden::encoder_counter_in in;
    in.qstep[0] = s0;
    in.qstep[1] = s1;
    return in;
}

struct coverage {
    long long wrap_up = 0, wrap_down = 0, reached_up = 0, reached_down = 0, reset_now = 0, reset_trig = 0, ticks = 0;
    long long cfg_err = 0;
};

void test_random(tbu::result& res, std::mt19937_64& rng, int runs, long long* calls, coverage* cov) {
    for (int run = 0; run < runs && res.failures < 10; ++run) {
        int64_t prev[2] = {0, 0};
        bool armed_down = false;
        pair_run p{{}, {}, &res, "random run " + std::to_string(run)};
        golden::encoder_counter_regs r;
        int dir[2] = {1, -1};
        double prob[2] = {0.3, 0.05};
        for (int c = 0; c < 2; ++c) {
            r.src[c] = static_cast<int>(rng() % 2);
            r.sim_inc[c] = rng() % 3 == 0 ? 42949673 : rng() % ((1ULL << 30) + 1);
            r.sim_down[c] = rng() % 2 == 0;
            r.scale[c] = static_cast<int64_t>(static_cast<int32_t>(static_cast<uint32_t>(rng())));
            if (rng() % 2) r.scale[c] >>= (rng() % 24);
            prob[c] = static_cast<double>(rng() % 1000) / 1000.0;
        }
        r.corr_period = rng() % 2 ? 1000 : rng() % 4 == 0 ? golden::kEncoderCorrLatency : golden::kEncoderCorrLatency + static_cast<int>(rng() % 2000);
        r.rst_on_trig = rng() % 2 == 0;
        std::uniform_real_distribution<double> u01(0, 1);
        bool ok = true;
        for (long long t = 0; t < 60000 && ok; ++t) {
            golden::encoder_counter_regs rr = r;
            golden::encoder_counter_in in;
            for (int c = 0; c < 2; ++c) {
                if (u01(rng) < prob[c]) in.qstep[c] = dir[c];
                if (rng() % 700 == 0) dir[c] = -dir[c];
                if (rng() % 9000 == 0) {  // preset next to the boundary, moving towards it
                    rr.load[c] = true;
                    rr.load_val[c] = rng() % 2 ? kMax - static_cast<int64_t>(rng() % 300) : kMin + static_cast<int64_t>(rng() % 300);
                    dir[c] = rr.load_val[c] > 0 ? 1 : -1;
                    r.sim_down[c] = rr.load_val[c] < 0;
                    rr.sim_down[c] = r.sim_down[c];
                }
                if (rng() % 15000 == 0) rr.rst_req[c] = true;
                if (rng() % 20000 == 0) r.src[c] = 1 - r.src[c];
                in.pos[c] = static_cast<int64_t>(static_cast<int32_t>(static_cast<uint32_t>(rng())));
            }
            if (rng() % 4000 == 0) in.trig = true;
            if (rng() % 30000 == 0) r.rst_on_trig = !r.rst_on_trig;
            if (rng() % 2000 == 0) {
                rr.wait_arm = true;
                rr.wait_ch = static_cast<int>(rng() % 2);
                rr.wait_down = rng() % 2 == 0;
                const int64_t base = rng() % 4 == 0 ? (rng() % 2 ? kMax : kMin) : 0;
                rr.wait_val = golden::wrap_s32(base + static_cast<int64_t>(rng() % 400) - 200);
            }
            if (rng() % 50000 == 0) rr.src[0] = 2;  // one invalid call: both models reset
            const golden::encoder_counter::out o = p.step(in, rr);
            ok = res.failures == 0;
            for (int c = 0; c < 2; ++c) {
                if (o.step[c] > 0 && prev[c] == kMax && o.cnt[c] == kMin) ++cov->wrap_up;
                if (o.step[c] < 0 && prev[c] == kMin && o.cnt[c] == kMax) ++cov->wrap_down;
                if (o.rst_done[c]) ++(rr.rst_req[c] && !rr.rst_on_trig ? cov->reset_now : cov->reset_trig);
                prev[c] = o.cnt[c];
            }
            if (o.reached) ++(armed_down ? cov->reached_down : cov->reached_up);
            if (rr.wait_arm) armed_down = rr.wait_down;
            cov->ticks += o.tick ? 1 : 0;
            cov->cfg_err += o.cfg_err ? 1 : 0;
            ++*calls;
        }
    }
}

void test_wrap(tbu::result& res) {
    // quadrature steps across max -> min and back
    {
        pair_run p{{}, {}, &res, "wrap quad"};
        golden::encoder_counter_regs r = quad_regs();
        r.load[0] = true;
        r.load_val[0] = kMax - 2;
        r.load[1] = true;
        r.load_val[1] = kMin + 2;
        p.step(qin(0, 0), r);
        r.load[0] = r.load[1] = false;
        const int64_t up[] = {kMax - 1, kMax, kMin, kMin + 1, kMin + 2};
        const int64_t down[] = {kMin + 1, kMin, kMax, kMax - 1, kMax - 2};
        bool ok = true;
        for (int k = 0; k < 5; ++k) {
            const golden::encoder_counter::out o = p.step(qin(1, -1), r);
            ok = ok && o.cnt[0] == up[k] && o.cnt[1] == down[k];
        }
        for (int k = 0; k < 5; ++k) {
            const golden::encoder_counter::out o = p.step(qin(-1, 1), r);
            ok = ok && o.cnt[0] == down[k] && o.cnt[1] == up[k];
        }
        res.check(ok, "quadrature counting across the wrap boundary");
    }
    // simulation across the boundary, both directions (0.25 count per call: a count every 4 calls)
    {
        pair_run p{{}, {}, &res, "wrap sim"};
        golden::encoder_counter_regs r = sim_regs();
        r.sim_inc[0] = r.sim_inc[1] = 1ULL << 30;
        r.sim_down[1] = true;
        r.load[0] = true;
        r.load_val[0] = kMax - 1;
        r.load[1] = true;
        r.load_val[1] = kMin + 1;
        p.step(qin(0, 0), r);
        r.load[0] = r.load[1] = false;
        std::vector<int64_t> seq0, seq1;
        for (int t = 0; t < 16; ++t) {
            const golden::encoder_counter::out o = p.step(qin(0, 0), r);
            if (o.step[0]) seq0.push_back(o.cnt[0]);
            if (o.step[1]) seq1.push_back(o.cnt[1]);
        }
        res.check(seq0 == std::vector<int64_t>({kMax, kMin, kMin + 1, kMin + 2}),
                  "simulation up across the boundary: " + std::to_string(seq0.size()) + " counts");
        res.check(seq1 == std::vector<int64_t>({kMin, kMax, kMax - 1, kMax - 2}),
                  "simulation down across the boundary: " + std::to_string(seq1.size()) + " counts");
    }
    // wait-for-encoder across the boundary: up past max (reached at min), down past min (at max)
    for (int down = 0; down <= 1; ++down) {
        pair_run p{{}, {}, &res, down ? "wait down" : "wait up"};
        golden::encoder_counter_regs r = quad_regs();
        r.load[1] = true;
        r.load_val[1] = down ? kMin + 3 : kMax - 3;
        r.wait_arm = true;
        r.wait_ch = 1;
        r.wait_val = down ? kMin : kMax;
        r.wait_down = down != 0;
        p.step(qin(0, 0), r);
        r.load[1] = false;
        r.wait_arm = false;
        long long reached = -1;
        int64_t at = 0;
        for (int t = 1; t < 12; ++t) {
            const golden::encoder_counter::out o = p.step(qin(0, down ? -1 : 1), r);
            if (o.reached && reached < 0) {
                reached = t;
                at = o.cnt[1];
            }
        }
        // counts: 3 steps reach the value, the 4th passes it (across the boundary); reported two
        // calls later (the 6th step is in that call's counter)
        res.check(reached == 6 && at == (down ? kMax - 2 : kMin + 2),
                  std::string("wait-for-encoder across the boundary (") + (down ? "down" : "up") + "): reached at call " +
                      std::to_string(reached) + ", counter " + std::to_string(at));
    }
    // a value already passed is reached in the second call after the arm; a value 2^31 ahead is
    // 'behind'
    {
        pair_run p{{}, {}, &res, "wait levels"};
        golden::encoder_counter_regs r = quad_regs();
        r.load[0] = true;
        r.load_val[0] = 100;
        p.step(qin(0, 0), r);
        r.load[0] = false;
        r.wait_arm = true;
        r.wait_val = 50;
        p.step(qin(0, 0), r);
        r.wait_arm = false;
        const bool first = p.step(qin(0, 0), r).reached;
        res.check(!first && p.step(qin(0, 0), r).reached, "wait for a value already passed");
        r.wait_arm = true;
        r.wait_val = golden::wrap_s32(100 + kMax + 1);  // exactly 2^31 away: counts as ahead? no
        p.step(qin(0, 0), r);
        r.wait_arm = false;
        bool any = false;
        for (int t = 0; t < 10; ++t) any = any || p.step(qin(0, 0), r).reached;
        res.check(!any, "wait for a value 2^31 away reached");
    }
}

void test_reset(tbu::result& res) {
    // immediate
    {
        pair_run p{{}, {}, &res, "reset now"};
        golden::encoder_counter_regs r = sim_regs();
        golden::encoder_counter::out o;
        for (int t = 0; t < 100; ++t) o = p.step(qin(0, 0), r);
        r.rst_req[0] = true;
        o = p.step(qin(0, 0), r);
        res.check(o.rst_done[0] && o.cnt[0] == 0 && o.cnt[1] == 1 && !o.rst_done[1], "immediate reset");
    }
    // at the next trigger; a trigger in the request call does not count
    {
        pair_run p{{}, {}, &res, "reset at trigger"};
        golden::encoder_counter_regs r = sim_regs();
        r.rst_on_trig = true;
        golden::encoder_counter::out o;
        long long reset_call = -1, first_count = -1;
        bool pending_ok = true;
        for (int t = 0; t < 400; ++t) {
            golden::encoder_counter_regs rr = r;
            golden::encoder_counter_in in;
            if (t == 120) {
                rr.rst_req[0] = true;
                in.trig = true;
            }
            if (t == 170) in.trig = true;
            o = p.step(in, rr);
            if (t >= 120 && t < 170) pending_ok = pending_ok && o.rst_pending[0] && !o.rst_done[0];
            if (o.rst_done[0]) reset_call = t;
            if (reset_call >= 0 && first_count < 0 && o.step[0] != 0) first_count = t;
        }
        res.check(pending_ok && reset_call == 170 && !o.rst_pending[0],
                  "reset-on-trigger: reset at call " + std::to_string(reset_call) + ", want 170");
        // 1 MHz = 42949673 / 2^32 count per call: the 100th call after the reset carries, the
        // 101st counts
        res.check(first_count == 271, "simulation after the reset: first count at call " + std::to_string(first_count) +
                                          ", want 271");
        // counter 1 (never reset): carries in calls 99, 199, 299, 399, the last counted in call 400
        res.check(o.cnt[1] == 3 && o.cnt[0] == 2, "counter values after reset-on-trigger: " + std::to_string(o.cnt[0]) +
                                                      " / " + std::to_string(o.cnt[1]));
    }
}

void test_correction(tbu::result& res) {
    pair_run p{{}, {}, &res, "correction"};
    golden::encoder_counter_regs r = quad_regs();
    r.scale[0] = 1LL << 23;         // 0.5 bit per count: ties
    r.scale[1] = -25165824;         // -1.5
    golden::encoder_counter_in in = qin(-1, 1);
    in.pos[0] = 1000;
    in.pos[1] = -7;
    int ticks = 0;
    bool spacing_ok = true, value_ok = true;
    const int lat = golden::kEncoderCorrLatency;
    long long last_tick = -1;
    std::vector<int64_t> cnt_before[2];  // counter register before call t
    std::vector<int64_t> pos_at[2];      // position input of call t
    int64_t prev_cnt[2] = {0, 0};
    for (int t = 0; t < 5100; ++t) {
        in.pos[0] = 1000 + t / 7;
        in.pos[1] = -7 - t / 3;
        for (int c = 0; c < 2; ++c) {
            cnt_before[c].push_back(prev_cnt[c]);
            pos_at[c].push_back(in.pos[c]);
        }
        const golden::encoder_counter::out o = p.step(in, r);
        if (o.tick) {
            ++ticks;
            spacing_ok = spacing_ok && (last_tick < 0 ? t == 999 + lat : t - last_tick == 1000);
            last_tick = t;
            for (int c = 0; c < 2; ++c) {
                const int64_t num = r.scale[c] * cnt_before[c][static_cast<size_t>(t - lat)] + (1LL << 23);
                const int64_t q = num >= 0 ? num / (1LL << 24) : -((-num + (1LL << 24) - 1) / (1LL << 24));
                value_ok = value_ok && o.corr[c] == pos_at[c][static_cast<size_t>(t - lat)] + q;
            }
        }
        prev_cnt[0] = o.cnt[0];
        prev_cnt[1] = o.cnt[1];
    }
    res.check(ticks == 5 && spacing_ok, "correction ticks: " + std::to_string(ticks) + " in 5100 calls");
    res.check(value_ok, "correction value pos + round(scale * counter), sampled 33 calls before the tick");
    // largest product: scale -2^31 (-128 bits/count) times counter -2^31; shortest period (33):
    // loaded in call 0, sampled in calls 32 and 65, shown in calls 65 and 98 (a sample and a
    // tick in the same call)
    pair_run q{{}, {}, &res, "correction extreme"};
    golden::encoder_counter_regs x = quad_regs();
    x.scale[0] = kMin;
    x.scale[1] = kMax;
    x.load[0] = true;
    x.load_val[0] = kMin;
    x.load[1] = true;
    x.load_val[1] = kMin;
    x.corr_period = lat;
    golden::encoder_counter_in xi;
    xi.pos[0] = kMax;
    xi.pos[1] = kMin;
    q.step(xi, x);
    x.load[0] = x.load[1] = false;
    int xt = 0;
    bool ext_ok = true;
    golden::encoder_counter::out o;
    for (int t = 1; t < 3 * lat + 1; ++t) {
        o = q.step(xi, x);
        if (o.tick) {
            ++xt;
            ext_ok = ext_ok && (t == 2 * lat - 1 || t == 3 * lat - 1) && o.corr[0] == (1LL << 38) + kMax &&
                     o.corr[1] == kMin - (1LL << 38) + 128;
        }
    }
    res.check(xt == 2 && ext_ok, "largest correction product: " + std::to_string(o.corr[0]) + " / " +
                                     std::to_string(o.corr[1]) + ", ticks " + std::to_string(xt));
}

void test_config(tbu::result& res) {
    struct bad {
        const char* what;
        void (*set)(golden::encoder_counter_regs&);
    };
    const bad bads[] = {
        {"source 2", [](golden::encoder_counter_regs& r) { r.src[0] = 2; }},
        {"source 3", [](golden::encoder_counter_regs& r) { r.src[1] = 3; }},
        {"correction period 0", [](golden::encoder_counter_regs& r) { r.corr_period = 0; }},
        {"correction period 32", [](golden::encoder_counter_regs& r) { r.corr_period = golden::kEncoderCorrLatency - 1; }},
        {"simulation above 25 MHz", [](golden::encoder_counter_regs& r) { r.sim_inc[1] = (1ULL << 30) + 1; }},
    };
    for (const bad& b : bads) {
        pair_run p{{}, {}, &res, std::string("bad config: ") + b.what};
        golden::encoder_counter_regs r = sim_regs();
        r.sim_inc[0] = r.sim_inc[1] = 1ULL << 28;
        r.scale[0] = 1 << 24;
        b.set(r);
        bool err = true, zero = true;
        for (int t = 0; t < 2000; ++t) {
            golden::encoder_counter_in in = qin(1, 1);
            in.pos[0] = 5;
            const golden::encoder_counter::out o = p.step(in, r);
            err = err && o.cfg_err;
            zero = zero && o.cnt[0] == 0 && o.cnt[1] == 0 && o.corr[0] == 0 && !o.tick;
        }
        res.check(err && zero, std::string("bad configuration not rejected: ") + b.what);
    }
    // a fast simulation rate is legal on a channel that counts quadrature steps
    pair_run p{{}, {}, &res, "fast rate on a quadrature channel"};
    golden::encoder_counter_regs r = quad_regs();
    r.sim_inc[0] = 0xFFFFFFFFULL;
    res.check(!p.step(qin(1, 0), r).cfg_err, "simulation rate checked on a quadrature channel");
}

void test_calibration(tbu::result& res, std::mt19937_64& rng) {
    // start/end readings across the wrap: +5000 counts over 5 mm from max - 1000
    const int64_t start = kMax - 1000, end = golden::wrap_s32(kMax - 1000 + 5000);
    const golden::increment_result i1 = golden::encoder_increment(start, end, 5.0);
    res.check(i1.ok && std::fabs(i1.counts_per_mm - 1000.0) < 1e-12, "increment across the wrap");
    const golden::increment_result i2 = golden::encoder_increment(end, start, -5.0);
    res.check(i2.ok && std::fabs(i2.counts_per_mm - 1000.0) < 1e-12, "increment, travel in the negative direction");
    // many readings, wrapped, with noise: slope recovered; encoder counting down: negative slope
    for (int sign = 1; sign >= -1; sign -= 2) {
        std::vector<double> x;
        std::vector<int64_t> y;
        std::normal_distribution<double> noise(0.0, 2.0);
        for (int k = 0; k < 200; ++k) {
            const double mm = 0.05 * k;
            x.push_back(mm);
            const int64_t base = sign > 0 ? kMax - 3000 : kMin + 3000;  // both cross the boundary
            y.push_back(golden::wrap_s32(base + sign * std::llround(1234.5 * mm + noise(rng))));
        }
        const golden::linear_fit f = golden::encoder_increment_fit(x, y);
        res.check(f.ok && std::fabs(f.scale - sign * 1234.5) < 0.1,
                  "least-squares increment over wrapped readings: " + std::to_string(f.scale));
        const double scale = golden::scale_from_increment(8000.0, f.scale).scale;
        res.check((scale > 0) == (sign > 0) && std::fabs(std::fabs(scale) - 8000.0 / 1234.5) < 1e-3,
                  "Scale = K / i sign and value");
    }
    // constant speed: 1 MHz simulation for 1 ms while the workpiece moves 0.1 mm at 100 mm/s:
    // scale * counter = K * 0.1 mm
    {
        pair_run p{{}, {}, &res, "constant speed"};
        golden::encoder_counter_regs r = sim_regs();
        const double k = 10000.0, v = 100.0;
        const double scale = golden::encoder_scale_at_rate(k, v, 1e6);
        res.check(std::fabs(scale - golden::scale_from_speed(k, v).scale) < 1e-12, "scale at 1 MHz = scale_from_speed");
        bool ok = false;
        r.scale[0] = golden::encoder_scale_to_q(scale, &ok);
        r.sim_inc[0] = golden::encoder_sim_inc(1e6);
        golden::encoder_counter::out o;
        for (int t = 0; t < 100000 + golden::kEncoderCorrLatency; ++t) o = p.step(qin(0, 0), r);
        // the tick at call 100032 shows the sample of call 99999: the counter after call 99998,
        // 999 counts
        res.check(ok && o.tick && o.cnt[0] == 1000 && o.corr[0] == std::llround(scale * 999),
                  "constant-speed correction: counter " + std::to_string(o.cnt[0]) + ", corr " + std::to_string(o.corr[0]));
        res.check(std::fabs(static_cast<double>(o.corr[0]) - k * 0.1) <= scale + 0.5, "correction equals K * travel");
        bool neg_ok = false;
        res.check(golden::encoder_scale_to_q(golden::encoder_scale_at_rate(k, -v, 1e6), &neg_ok) == -r.scale[0] && neg_ok,
                  "negative speed: negative scale");
        bool big_ok = true;
        golden::encoder_scale_to_q(128.0, &big_ok);
        res.check(!big_ok, "scale 128 bits/count out of the Q8.24 range");
        res.check(golden::encoder_sim_inc(1e6) == lx::encoder_counter_cfg::SIM_INC_DEFAULT, "1 MHz rate register");
    }
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 4);
    const int runs = static_cast<int>(tbu::arg_ll(argc, argv, "--runs", 40));
    tbu::result res("tb_encoder_counter", seed);
    std::mt19937_64 rng(seed);
    long long calls = 0;
    coverage cov;
    test_random(res, rng, runs, &calls, &cov);
    std::printf("[tb_encoder_counter] random: %d runs, %lld calls compared; wraps max->min %lld, min->max %lld;\n"
                "    waits reached up %lld, down %lld; resets now %lld, at trigger %lld; correction ticks %lld; "
                "invalid-config calls %lld\n",
                runs, calls, cov.wrap_up, cov.wrap_down, cov.reached_up, cov.reached_down, cov.reset_now, cov.reset_trig,
                cov.ticks, cov.cfg_err);
    res.check(cov.wrap_up > 0 && cov.wrap_down > 0 && cov.reached_up > 0 && cov.reached_down > 0 &&
                  cov.reset_now > 0 && cov.reset_trig > 0 && cov.cfg_err > 0,
              "random runs did not cover every case");
    test_wrap(res);
    test_reset(res);
    test_correction(res);
    test_config(res);
    test_calibration(res, rng);
    const char* bd = std::getenv("LASERAX_BUILD_DIR");
    const std::string out = std::string(bd ? bd : "/tmp") + "/counters_cmd_test";
    const std::vector<std::string> args = {"counters", "--out", out, "--no-plot"};
    std::fflush(stdout);
    res.check(lxt::cmd_counters(args, 1) == 0, "laserax counters demo failed");
    return res.finish();
}
