// ctest-args: --cycles 4000000
// ctest-args-O0: --cycles 200000
// tb_chain_error_map — the whole single-axis chain with the error map enabled (docs/ERROR_MAP.md
// §8), hls against golden.
//
// Scenario (pin level, one call per clock): the axis homes with the map disabled; a random table
// (smooth walks, noise, extreme points) is loaded into the inactive bank through the register
// port, one word per call, while the axis moves; then map_en and a bank flip. From there on:
// random moves with reversals and dwells, reloads of the inactive bank followed by flips while
// moving, new geometries (the map is indexed by comp, origin in comp coordinates), short windows
// of an invalid geometry (map_cfg_err), map_en toggles, occasional rehome. Sensor updates all the
// way through: every 5000..40000 calls new air and workpiece readings (15..30 degC, 90..110 kPa,
// 0..90 %RH, alpha 0..25 ppm/degC at 10..30 degC, origin within +-50 mm) become a new ratio and
// comp_offset (lxt::compute_compensation, as the host would write them), while moving or not, so
// the combined datapath (ratio, offset, interpolated map) is compared with the golden model.
// Checks:
//   * every call: every output and tap of hls equals golden (lxt::dual_axis, which also checks
//     paced + backlog (taps) == comp + corr of three calls earlier and that the controller decodes out_pos);
//   * corr == 0 while the map is disabled or the axis not homed; map_cfg_err never puts the chain
//     in the safe state (cfg_err stays 0, the axis stays homed) and raises alarm;
//   * after each dwell, once the pacer has drained: the position a controller decodes from the
//     hls sin/cos and A/B equals comp + corr + adj (rephase adjustment), exactly.
#include <cstdio>
#include <random>
#include <vector>

#include "tb/tb_util.h"
#include "host/compensation.h"
#include "sysmodel/sim.h"

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 8);
    const long long cycles = tbu::arg_ll(argc, argv, "--cycles", 1500000);
    tbu::result res("tb_chain_error_map", seed);
    std::mt19937_64 rng(seed);
    auto uni = [&](long long lo, long long hi) { return std::uniform_int_distribution<long long>(lo, hi)(rng); };

    lxt::axis_settings s;
    s.glitch_n = 1;
    s.sw_debounce = 4;
    s.pace_m = 2;
    s.backlog_thr = 1u << 30;  // large corrections must not raise the backlog alarm here
    s.min_spacing = 2;
    lxt::dual_axis ax(s);
    lxt::controller_decoder dec;
    dec.reset(static_cast<int>(s.period), 0);

    const int64_t sw_edge = 300;  // switch closes for n >= sw_edge
    int64_t n = 0;
    int dirn = 1;
    long long move_left = 2000, idle_left = 0, spacing = 6, until_next = 0;

    // table load in progress: words for the inactive bank, then a flip (and maybe map_en)
    std::vector<int32_t> load;
    size_t load_pos = 0;
    lxt::axis_settings::emap_t::geom_t load_geom;
    auto new_table = [&](int npts) {
        std::vector<int32_t> t(static_cast<size_t>(npts));
        const int kind = static_cast<int>(uni(0, 3));
        int64_t v = uni(-20000, 20000);
        for (int i = 0; i < npts; ++i) {
            if (kind == 0) v += uni(-3000, 3000);                       // smooth walk
            else if (kind == 1) v = uni(-40000, 40000);                 // noise (+-156 counts)
            else if (kind == 2) v = (i % 2) ? 51200 : -51200;           // alternating +-200 counts
            else v = (i % 7 == 3) ? uni(-(1 << 23), (1 << 23) - 1) : uni(-600, 600);  // rare extremes
            if (v > (1 << 23) - 1) v = (1 << 23) - 1;
            if (v < -(1 << 23)) v = -(1 << 23);
            t[static_cast<size_t>(i)] = static_cast<int32_t>(v);
        }
        return t;
    };
    auto new_geom = [&]() {
        lxt::axis_settings::emap_t::geom_t gm;
        gm.spacing_log2 = static_cast<int>(uni(4, 10));
        gm.n_points = static_cast<int>(uni(2, 400));
        // comp ranges over about -9000 .. 33000 output counts here; the table sometimes covers
        // only part of it (clamped ends)
        gm.origin = uni(-12000, 8000);
        return gm;
    };
    auto start_load = [&]() {
        load_geom = new_geom();
        load = new_table(static_cast<int>(load_geom.n_points));
        load_pos = 0;
    };

    long long next_sensor = 100, sensor_updates = 0;
    auto urand = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };

    bool homed_once = false, map_started = false;
    long long flips = 0, drained_checks = 0, corr_rows = 0, cfg_err_rows = 0, mismatches = 0;
    long long bad_geom_left = 0;
    lxt::axis_settings::emap_t::geom_t saved_geom;
    long long drain_wait = 0;

    for (long long t = 0; t < cycles; ++t) {
        lxt::axis_settings ns = ax.settings();
        ns.rehome = false;
        ns.clear = false;
        const int inactive = ns.emap.bank_sel ? 0 : 1;
        const int active = 1 - inactive;
        bool write = false;
        int waddr = 0;
        int32_t wdata = 0;

        if (homed_once && load_pos >= load.size() && bad_geom_left == 0 && uni(0, 19999) < 3) start_load();
        if (load_pos < load.size()) {
            write = true;
            waddr = static_cast<int>(load_pos);
            wdata = load[load_pos];
            ++load_pos;
            if (load_pos == load.size()) {
                ns.emap.geom[inactive] = load_geom;  // geometry of the bank just loaded
            }
        } else if (homed_once && !load.empty() && ns.emap.geom[inactive].n_points == load_geom.n_points &&
                   ns.emap.geom[inactive].origin == load_geom.origin && bad_geom_left == 0) {
            // loaded and idle: flip now (while moving or not)
            ns.emap.bank_sel = !ns.emap.bank_sel;
            ns.emap.map_en = true;
            map_started = true;
            load.clear();
            ++flips;
        }
        if (map_started && bad_geom_left == 0 && load_pos >= load.size() && uni(0, 99999) < 4) {
            saved_geom = ns.emap.geom[active];
            bad_geom_left = uni(1, 200);
            if (uni(0, 1)) ns.emap.geom[active].n_points = static_cast<int>(uni(0, 1));
            else ns.emap.geom[active].spacing_log2 = static_cast<int>(uni(0, 1) ? uni(0, 3) : uni(21, 31));
        } else if (bad_geom_left > 0 && --bad_geom_left == 0) {
            ns.emap.geom[active] = saved_geom;
        }
        if (map_started && uni(0, 199999) < 2) ns.emap.map_en = !ns.emap.map_en;
        if (map_started && uni(0, 299999) < 1) ns.rehome = true;
        if (t == next_sensor) {
            next_sensor = t + uni(5000, 40000);
            lxt::comp_inputs ci;
            ci.air_temp_c = urand(15.0, 30.0);
            ci.pressure_pa = urand(90e3, 110e3);
            ci.rh_percent = urand(0.0, 90.0);
            ci.alpha_ppm_per_c = urand(0.0, 25.0);
            ci.material_temp_c = urand(10.0, 30.0);
            ci.origin_um = urand(-50000.0, 50000.0);
            const lxt::comp_outputs co = lxt::compute_compensation(ci);
            if (res.check(co.ok, "compute_compensation: " + co.error)) {
                ns.ratio = co.ratio;
                ns.comp_offset = co.comp_offset;
                ++sensor_updates;
            }
        }
        ax.set(ns);
        if (write) ax.write_map(waddr, wdata);

        // ---- motion
        if (idle_left > 0) {
            --idle_left;
        } else if (move_left > 0) {
            if (until_next-- <= 0) {
                n += dirn;
                --move_left;
                until_next = spacing;
            }
        } else if (uni(0, 2) == 0) {
            idle_left = uni(2000, 40000);
            drain_wait = 0;
        } else {
            dirn = uni(0, 1) ? 1 : -1;
            if (n > 4000) dirn = -1;
            if (n < -1000) dirn = 1;
            move_left = uni(1, 1500);
            spacing = uni(2, 40);
        }
        if (!homed_once && n > sw_edge + 400) {  // homing pass: come back over the switch
            dirn = -1;
            move_left = 600;
        }
        lx::axis_pins p;
        lxt::quad_pins(n, p.a, p.b);
        p.sw = n >= sw_edge;

        const std::string m = ax.step(p);
        if (!res.expect(m.empty(), [&] { return "cycle " + std::to_string(t) + ": " + m; }) && ++mismatches > 5) break;
        const golden::axis_out& g = ax.gold();
        const lx::axis_out& h = ax.hls();
        if (t > 0) dec.feed(h.sin.to_int64(), h.cos.to_int64(), h.qa, h.qb);  // as lxt::dual_axis

        if (g.homed && !homed_once) {
            homed_once = true;
            start_load();
        }
        res.check(!g.cfg_err, "the map must never put the chain in the safe state");
        if (!homed_once) res.expect(g.corr == 0, [&] { return "cycle " + std::to_string(t) + ": corr before homing"; });
        if (g.corr != 0) ++corr_rows;
        if (g.map_cfg_err) {
            ++cfg_err_rows;
            res.expect(g.alarm && g.corr == 0, [&] { return "cycle " + std::to_string(t) + ": map_cfg_err without alarm or with corr"; });
        }

        // ---- drained: controller position == comp + corr + adj
        // (the map publishes a sample's correction up to 58 calls after the position settles: a
        // new map_delta restarts the wait)
        if (idle_left > 0 && g.backlog == 0 && g.pstep == 0 && g.ostep == 0 && g.map_delta == 0) {
            if (++drain_wait == 8) {
                ++drained_checks;
                const int64_t want = g.comp_pos + g.corr + g.adj;
                res.expect(dec.quad_pos() == want && dec.sincos_pos() == want && g.out_pos == want, [&] {
                    return "cycle " + std::to_string(t) + ": drained, controller decodes " + std::to_string(dec.quad_pos()) +
                           " (A/B) " + std::to_string(dec.sincos_pos()) + " (sin/cos), out_pos " +
                           std::to_string(g.out_pos) + ", expected comp + corr + adj = " + std::to_string(want);
                });
            }
        } else {
            drain_wait = 0;
        }
        if ((t & ((1 << 20) - 1)) == 0 && t > 0) std::printf("  %lld calls...\n", t);
    }
    res.check(homed_once, "the axis never homed");
    res.check(flips >= 5, "fewer than 5 bank flips: " + std::to_string(flips));
    // (the scenario is random in its timing: a run of 200000 calls, the -O0 build's, has 2-29
    // drained dwells over seeds 1-9 (issue 36's slower referencing window moved them), so a
    // short run must see one, the full run ten)
    const long long min_drained = cycles >= 1000000 ? 10 : 1;
    res.check(drained_checks >= min_drained, "fewer than " + std::to_string(min_drained) +
                                                 " drained checks: " + std::to_string(drained_checks));
    res.check(corr_rows >= cycles / 10, "corr was non-zero in only " + std::to_string(corr_rows) + " calls");
    res.check(cfg_err_rows > 0, "no map_cfg_err window");
    res.check(sensor_updates >= cycles / 40000, "too few sensor updates: " + std::to_string(sensor_updates));
    std::printf("  %lld flips, %lld drained checks, corr != 0 in %lld calls, map_cfg_err in %lld calls, %lld sensor updates\n",
                flips, drained_checks, corr_rows, cfg_err_rows, sensor_updates);
    return res.finish();
}
