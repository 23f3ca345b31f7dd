// tb_invalid_config — invalid configurations are rejected with a flag and a defined safe state.
//
// * Every period 0..4200 and every dac_width 0..31, with the matching table period: the config
//   check of hls and of golden agree with the rule written here (8..4096, multiple of 8; 12..18).
// * Each single bad register (period, ratio 0, pace_m < 2, dac_width, amplitude 0 or above the
//   width's maximum, tbl_period != period, mark_len outside P/4..P), applied while the axis is
//   moving: cfg_err = 1, alarm = 1, sin = cos = 0, no mark, no A/B/Z, stage 1, hls == golden;
//   after the register is restored the chain restarts from reset and tracks again.
// * A period change while running costs exactly one safe-state call (and power-up none).
// * A DDS table write presented while running holds the safe state in the call in which it is in
//   force and in the next one, then the chain runs again (DESIGN 4.6, 4.7), in hls and golden.
#include <functional>

#include "tb/tb_util.h"
#include "sysmodel/sim.h"

int main(int argc, char** argv) {
    tbu::result res("tb_invalid_config", tbu::seed_from(argc, argv, 0));

    for (int p = 0; p <= 4200; ++p) {
        lxt::axis_settings s;
        s.period = s.tbl_period = p;
        s.mark_len = p / 4;
        const bool want = p >= 8 && p <= 4096 && p % 8 == 0;
        const bool h = lx::axis_config_ok(lxt::to_hls(s));
        const bool g = golden::config_ok(lxt::to_golden(s));
        res.expect(h == want && g == want, [&] { return "period " + std::to_string(p) + ": hls " + std::to_string(h) +
                                                         " golden " + std::to_string(g) + " want " + std::to_string(want); });
    }
    for (int w = 0; w < 32; ++w) {
        lxt::axis_settings s;
        s.dac_width = w;
        s.amplitude = 2047;  // legal for every width 12..18
        const bool want = w >= 12 && w <= 18;
        res.check(lx::axis_config_ok(lxt::to_hls(s)) == want && golden::config_ok(lxt::to_golden(s)) == want,
                  "dac_width " + std::to_string(w));
        if (want) {
            s.amplitude = (1 << (w - 1)) - 1;
            res.check(lx::axis_config_ok(lxt::to_hls(s)) && golden::config_ok(lxt::to_golden(s)), "max amplitude rejected");
            s.amplitude = 1 << (w - 1);
            res.check(!lx::axis_config_ok(lxt::to_hls(s)) && !golden::config_ok(lxt::to_golden(s)),
                      "amplitude above the width accepted, width " + std::to_string(w));
        }
    }

    struct bad {
        const char* name;
        std::function<void(lxt::axis_settings&)> apply;
    };
    const bad cases[] = {
        {"period 0", [](lxt::axis_settings& s) { s.period = 0; }},
        {"period 260 (not /8)", [](lxt::axis_settings& s) { s.period = s.tbl_period = 260; }},
        {"period 4104", [](lxt::axis_settings& s) { s.period = s.tbl_period = 4104; }},
        {"ratio 0", [](lxt::axis_settings& s) { s.ratio = 0; }},
        {"pace_m 0", [](lxt::axis_settings& s) { s.pace_m = 0; }},
        {"pace_m 1", [](lxt::axis_settings& s) { s.pace_m = 1; }},
        {"dac_width 11", [](lxt::axis_settings& s) { s.dac_width = 11; }},
        {"dac_width 19", [](lxt::axis_settings& s) { s.dac_width = 19; }},
        {"amplitude 0", [](lxt::axis_settings& s) { s.amplitude = 0; }},
        {"amplitude 32768 at 16 bits", [](lxt::axis_settings& s) { s.amplitude = 32768; }},
        {"tbl_period != period", [](lxt::axis_settings& s) { s.tbl_period = 320; }},
        {"mark_len < P/4", [](lxt::axis_settings& s) { s.mark_len = 63; }},
        {"mark_len > P", [](lxt::axis_settings& s) { s.mark_len = 257; }},
    };
    for (const bad& b : cases) {
        lxt::axis_settings good;
        good.glitch_n = 0;
        good.sw_debounce = 0;
        lxt::dual_axis ax(good);
        int64_t n = 0;
        auto run = [&](int calls, const char* phase) {
            for (int t = 0; t < calls; ++t) {
                if (t % 5 == 0) ++n;
                lx::axis_pins p;
                lxt::quad_pins(n, p.a, p.b);
                p.sw = n > 150;
                const std::string m = ax.step(p);
                res.expect(m.empty(), [&] { return std::string(b.name) + " (" + phase + "): " + m; });
            }
        };
        run(2000, "valid");
        lxt::axis_settings s = good;
        b.apply(s);
        ax.set(s);
        run(500, "invalid");
        const lx::axis_out& h = ax.hls();
        res.check(h.cfg_err && h.alarm && h.sin == 0 && h.cos == 0 && !h.ref_mark && !h.qa && !h.qb && !h.qz &&
                      h.stage == 1 && !h.homed,
                  std::string(b.name) + ": outputs not in the safe state");
        ax.set(good);
        run(3000, "restored");
        res.check(!ax.hls().cfg_err && ax.hls().raw_count > 0 && ax.hls().raw_count < 700 &&
                      (ax.hls().cos != 0 || ax.hls().sin != 0),
                  std::string(b.name) + ": chain did not restart after the register was restored");
    }
    {  // a period change while running costs exactly one safe-state call, then the chain restarts
        lxt::axis_settings s;
        s.glitch_n = 0;
        lxt::dual_axis ax(s);
        int64_t n = 0;
        int safe_calls = 0;
        for (int t = 0; t < 4000; ++t) {
            if (t == 2000) {
                lxt::axis_settings s2 = s;
                s2.period = s2.tbl_period = 320;
                s2.mark_len = 80;
                ax.set(s2);
            }
            if (t % 5 == 0) ++n;
            lx::axis_pins p;
            lxt::quad_pins(n, p.a, p.b);
            const std::string m = ax.step(p);
            res.expect(m.empty(), [&] { return "period change: " + m; });
            if (ax.hls().cfg_err) ++safe_calls;
            // register stage (DESIGN 4.7): the period presented in call 2000 is in force in 2001
            if (t == 2000) res.check(!ax.hls().cfg_err, "period change: safe state before the period is in force");
            if (t == 2001) res.check(ax.hls().cfg_err && ax.hls().raw_count == 0, "period change: no safe-state call");
            if (t == 2002) res.check(!ax.hls().cfg_err, "period change: more than one safe-state call");
        }
        res.check(safe_calls == 1, "period change: " + std::to_string(safe_calls) + " safe-state calls (power-up must cost none)");
    }
    {  // a table write: safe state in the call it is in force and in the next one (DESIGN 4.6)
        lxt::axis_settings s;
        s.glitch_n = 0;
        lx::axis_regs hr = lxt::to_hls(s);
        golden::axis_regs gr = lxt::to_golden(s);
        lx::laserax_top core;
        golden::laserax_top gold;
        gold.reset();
        int safe_h = 0, safe_g = 0;
        for (int t = 0; t < 200; ++t) {
            const bool we = t == 100;  // presented in call 100, in force in call 101
            hr.tbl_we = gr.tbl_we = we;
            hr.tbl_addr = 0;   // T[0] = 0 for every table: the write leaves the table as it is
            hr.tbl_data = 0;
            lx::axis_pins hp;
            golden::axis_pins gp;
            const lx::axis_out h = core.step(hp, hr);
            const golden::axis_out g = gold.step(gp, gr);
            if (t >= 99 && t <= 103) {
                const bool want = t == 101 || t == 102;
                res.expect(h.cfg_err == want && g.cfg_err == want, [&] {
                    return "table write: call " + std::to_string(t) + " cfg_err hls " + std::to_string(h.cfg_err) +
                           " golden " + std::to_string(g.cfg_err) + ", want " + std::to_string(want);
                });
            }
            if (t > 1) {
                safe_h += h.cfg_err;
                safe_g += g.cfg_err;
            }
        }
        res.check(safe_h == 2 && safe_g == 2, "table write: " + std::to_string(safe_h) + " / " + std::to_string(safe_g) +
                                                  " safe-state calls (hls / golden), want 2");
    }
    return res.finish();
}
