// tb_dac_guard — the DAC range guard of DESIGN §4.7: sin/cos never leave
// +-(2^(dac_width-1) - 1), whatever the table in use holds, and a clamp sets the sticky
// dac_clip_st, which is part of alarm.
//
// 1. The case of issue 12: from reset, write only dac_width = 12 and amplitude = 2047 (the
//    configuration check passes; the table in use still holds the P = 256 / 32767 words). The
//    expected codes are computed here from the table definition (rha(32767 sin(2 pi k / 256)),
//    independent of the hls table RAM) and clamped to +-2047: every code must match, the flag
//    must rise with the first code above 2047 and stay, alarm with it; clear drops it, the next
//    clamp sets it again (event wins in the same call).
// 2. Consistent tables (lxt::dds_table loaded into the RAM) at every dac_width 12..18 with the
//    largest amplitude, several periods: hls equals golden on every output (lxt::compare) over
//    several turns in both directions, and dac_clip_st never rises.
#include <cmath>
#include <cstdio>
#include <string>

#include "golden/laserax_top.h"
#include "hls/laserax_top.h"
#include "tb/tb_util.h"
#include "host/dds_table.h"
#include "host/regmap_table.h"
#include "sysmodel/sim.h"

namespace {

// quadrature pins of raw count n (DESIGN §4.2)
lx::axis_pins pins_at(long long n) {
    lx::axis_pins p;
    const unsigned q = static_cast<unsigned>(n & 3);
    p.a = q == 1 || q == 2;
    p.b = q == 2 || q == 3;
    return p;
}

golden::axis_pins gpins(const lx::axis_pins& p) {
    golden::axis_pins g;
    g.a = p.a;
    g.b = p.b;
    g.sw = p.sw;
    g.lerr = p.lerr;
    return g;
}

long long rha(double v) { return v >= 0 ? static_cast<long long>(std::floor(v + 0.5)) : -static_cast<long long>(std::floor(-v + 0.5)); }

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 12);
    tbu::result res("tb_dac_guard", seed);

    // ---- 1. dac_width 12 / amplitude 2047 over the power-up table --------------------------------
    {
        lx::laserax_top core;
        lx::axis_regs r{};
        r.dac_width = 12;
        r.amplitude = 2047;
        res.check(lx::axis_config_ok(r), "dac_width 12 / amplitude 2047 passes the configuration check");
        const long long hi = 2047;
        long long n = 0, clamps = 0, first_clip = -1, calls = 0;
        bool seen_flag = false;
        // the codes of call t belong to the DDS phase before call t-1 (two DDS stages, DESIGN
        // 4.6), which is the sum of the rephase osteps of calls <= t-3 (the dds steps with the
        // ostep of the previous call)
        long long ph_acc = 0, ostep_prev = 0, ostep_prev2 = 0;
        for (int t = 0; t < 60000; ++t) {
            if (t % 7 == 0 && t < 50000) ++n;  // forward motion
            r.clear = (t == 52000);
            const lx::axis_out o = core.step(pins_at(n), r);
            ++calls;
            const long long s = o.sin.to_int64(), c = o.cos.to_int64();
            res.expect(s >= -hi && s <= hi && c >= -hi && c <= hi,
                       [&] { return "call " + std::to_string(t) + ": code outside +-2047: " + std::to_string(s) + "/" + std::to_string(c); });
            // expected codes from the definition of the power-up table, clamped
            const long long ph = ((ph_acc % 256) + 256) % 256;
            const double w = 2.0 * 3.14159265358979323846 * double(ph) / 256.0;
            // table words rha(32767 sin(2 pi k / 256)); at the quarter points the word P/4 is the
            // amplitude register itself (DESIGN §4.6), i.e. +-2047
            long long es = rha(32767.0 * std::sin(w)), ec = rha(32767.0 * std::cos(w));
            if (ph % 64 == 0) {
                es = ph == 64 ? 2047 : (ph == 192 ? -2047 : 0);
                ec = ph == 0 ? 2047 : (ph == 128 ? -2047 : 0);
            }
            const bool clip_now = es > hi || es < -hi || ec > hi || ec < -hi;
            es = es > hi ? hi : (es < -hi ? -hi : es);
            ec = ec > hi ? hi : (ec < -hi ? -hi : ec);
            if (t > 20) {  // after the chain's start-up (sin/cos 0 before the first DDS read)
                res.expect(s == es && c == ec, [&] {
                    return "call " + std::to_string(t) + " ph " + std::to_string(ph) + ": codes " + std::to_string(s) + "/" +
                           std::to_string(c) + ", expected " + std::to_string(es) + "/" + std::to_string(ec);
                });
                if (clip_now) {
                    ++clamps;
                    if (first_clip < 0) first_clip = t;
                    res.expect(o.dac_clip_st && o.alarm,
                               [&] { return "call " + std::to_string(t) + ": clamped code without dac_clip_st / alarm"; });
                }
            }
            if (o.dac_clip_st) seen_flag = true;
            if (t == 52000) {
                // clear in a call whose codes clamp (cos = 32767 at ph 0 when stopped there or
                // any clamped phase): the event wins
                res.check(o.dac_clip_st == clip_now, "clear in a clamping call: the event wins");
            }
            ph_acc += ostep_prev2;
            ostep_prev2 = ostep_prev;
            ostep_prev = o.ostep.to_int64();
        }
        res.check(seen_flag && clamps > 1000, "the stale 16-bit table is clamped and flagged (" +
                                                  std::to_string(clamps) + " clamped calls, first at call " +
                                                  std::to_string(first_clip) + ")");
        std::printf("  dac_width 12 / amplitude 2047 over the power-up table: %lld calls, %lld clamped, first at %lld\n",
                    calls, clamps, first_clip);
    }

    // ---- 1b. clear at a non-clamping phase drops the flag ----------------------------------------
    {
        lx::laserax_top core;
        lx::axis_regs r{};
        r.dac_width = 12;
        r.amplitude = 2047;
        // stopped off a quarter point (raw count 4, about 32 output counts): one of sin / cos is a
        // table word >= 23170 in every call, so the flag is set in every running call after the
        // first read, also in the calls with clear (the event wins).
        bool always = true;
        for (int t = 0; t < 2000; ++t) {
            r.clear = (t % 100) == 50;
            const lx::axis_out o = core.step(pins_at(t < 40 ? t / 8 : 4), r);
            if (t > 60 && !o.dac_clip_st && always) {
                always = false;
                std::printf("  1b: no flag at call %d: sin %lld cos %lld cfg_err %d\n", t, (long long)o.sin.to_int64(),
                            (long long)o.cos.to_int64(), int(o.cfg_err));
            }
        }
        res.check(always, "over the 32767 table at dac_width 12 every running call clamps: flag set in every call, "
                          "also in calls with clear");
    }

    // ---- 2. consistent tables: no clamp, hls == golden -------------------------------------------
    {
        long long compared = 0;
        const int periods[] = {8, 256, 640, 4096};
        for (int dw = 12; dw <= 18; ++dw) {
            for (int P : periods) {
                const int amp = (1 << (dw - 1)) - 1;
                std::string err;
                const std::vector<uint32_t> words = lxt::dds_table(P, amp, &err);
                res.check(err.empty() && words.size() == size_t(P / 4), "dds_table " + std::to_string(P) + ": " + err);
                lx::laserax_top core;
                golden::laserax_top gold;
                for (size_t k = 0; k < words.size(); ++k)
                    core.dds().load(lx::tbl_addr_t(k), lx::tbl_word_t(words[k]));
                golden::axis_regs g{};
                g.period = P;
                g.tbl_period = P;
                g.mark_len = P;
                g.dac_width = dw;
                g.amplitude = amp;
                const lx::axis_regs h = lxt::to_hls(g);
                long long n = 0;
                bool clipped = false, differ = false;
                const int steps = 3 * P / 8 + 64;  // > 1.5 turns of output counts each way
                for (int t = 0; t < 8 * steps + 200; ++t) {
                    if (t % 3 == 0) n += (t < 4 * steps) ? 1 : -1;
                    const lx::axis_pins p = pins_at(n);
                    const lx::axis_out o = core.step(p, h);
                    const golden::axis_out go = gold.step(gpins(p), g);
                    const std::string d = lxt::compare(o, go);
                    if (!d.empty() && !differ) {
                        differ = true;
                        res.check(false, "dw " + std::to_string(dw) + " P " + std::to_string(P) + " call " +
                                             std::to_string(t) + ": hls != golden: " + d);
                    }
                    if (o.dac_clip_st) clipped = true;
                    ++compared;
                }
                res.check(!clipped, "consistent table dw " + std::to_string(dw) + " P " + std::to_string(P) +
                                        ": dac_clip_st never rises");
            }
        }
        std::printf("  consistent tables: %lld calls compared with golden, no clamp\n", compared);
    }
    return res.finish();
}
