// ctest-args: --calls 6000000
// ctest-args-O0: --calls 1200000 --update-every 40000
// tb_live_updates — sensor readings arriving while the axis moves (issue 3, "live updates").
//
// The axis moves back and forth over ~15 mm with a realistic laser (632.991 nm in air, ratio
// ~8.1) at speeds up to 0.3 m/s, and homes through its switch on the way. Every 200 000 clocks
// (a time-compressed "few hundred ms") a new air reading (random walk of T, p, RH with steps of up
// to 0.5 degC, 300 Pa, 5 %RH, exaggerated so that updates move the position) and workpiece
// temperature (steps up to 1 degC) is turned into the ratio and comp_offset registers by the host
// helper (host/compensation; thermal origin 7.5 mm, mid-travel) and written while the
// axis moves or stands. Checks:
//   * hls == golden on every call, and the integrity invariant of lxt::dual_axis (controller
//     decode == out_pos, comp == floor((N*R + OFF)/2^32) with the registers in force,
//     paced + backlog == comp + corr of three calls earlier);
//   * every update reaches the output exactly: once the pacer has drained after an update, the
//     real position seen by the controller (out_pos - adj) equals floor((N R_new + OFF_new) / 2^32);
//   * no step larger than the pacer allows: consecutive paced counts are >= M clocks apart and the
//     output never moves by more than one count per clock;
//   * at least 25 updates were applied, some while moving and some at rest (at 15 mm from the
//     laser's zero 5 ppm is one output count, so updates move the position by whole counts).
#include <algorithm>
#include <cmath>
#include <random>

#include "tb/tb_util.h"
#include "host/compensation.h"
#include "sysmodel/sim.h"

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 23);
    const long long calls = tbu::arg_ll(argc, argv, "--calls", 6000000);
    // calls between two updates (the -O0 type back-end build: a shorter run with the same number
    // of updates, 10 times closer)
    const long long every = tbu::arg_ll(argc, argv, "--update-every", 200000);
    if (every < 10000) {
        std::printf("tb_live_updates: --update-every must be >= 10000\n");
        return 2;
    }
    tbu::result res("tb_live_updates", seed);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);

    lxt::comp_inputs env;
    env.alpha_ppm_per_c = 11.5;  // steel
    env.material_temp_c = 21.0;
    env.origin_um = 7500.0;
    lxt::comp_outputs c = lxt::compute_compensation(env);
    if (!res.check(c.ok, "initial environment rejected: " + c.error)) return res.finish();

    lxt::axis_settings s;
    s.ratio = c.ratio;
    s.comp_offset = c.comp_offset;
    s.pace_m = 3;
    s.backlog_thr = 1u << 20;
    s.glitch_n = 1;
    s.sw_debounce = 4;
    lxt::dual_axis ax(s);

    const double lambda_nm = 632.991 / c.n;
    lxt::axis_motion motion(0.0, lambda_nm, 0.37);
    long long rest_left = 0;
    long long updates = 0, updates_moving = 0, checked = 0;
    long long max_jump = 0, last_pstep = -1000000;
    bool pending_check = false;
    int64_t comp_prev = 0;
    long long stable = 0;
    for (long long t = 0; t < calls; ++t) {
        if (motion.done() && rest_left == 0) {
            if (rng() % 2 == 0) {
                rest_left = every + every / 4;  // stand still across at least one update
            } else {
                // 0.2 .. 1 mm moves either way inside 0 .. 15 mm, at 50 .. 300 mm/s (nm per clock)
                const double len = 2e5 + 8e5 * (0.5 + 0.5 * u(rng));
                double target = motion.x_nm() + (u(rng) > -0.3 ? len : -len);
                target = std::min(15e6, std::max(0.0, target));
                const double speed = 0.5 + 2.5 * (0.5 + 0.5 * u(rng));
                motion.add(target, speed);
            }
        }
        if (rest_left > 0) --rest_left;
        const bool moving = !motion.done();
        motion.tick();
        if (t > 0 && t % every == 0) {
            env.air_temp_c = std::min(30.0, std::max(15.0, env.air_temp_c + 0.5 * u(rng)));
            env.pressure_pa = std::min(110000.0, std::max(90000.0, env.pressure_pa + 300.0 * u(rng)));
            env.rh_percent = std::min(90.0, std::max(0.0, env.rh_percent + 5.0 * u(rng)));
            env.material_temp_c = std::min(30.0, std::max(10.0, env.material_temp_c + 1.0 * u(rng)));
            c = lxt::compute_compensation(env);
            if (!res.check(c.ok, "environment rejected: " + c.error)) break;
            lxt::axis_settings ns = ax.settings();
            ns.ratio = c.ratio;
            ns.comp_offset = c.comp_offset;
            ax.set(ns);
            ++updates;
            if (moving) ++updates_moving;
            pending_check = true;
        }
        lx::axis_pins p;
        lxt::quad_pins(motion.raw_count(), p.a, p.b);
        p.sw = motion.x_nm() > 5e6;
        const std::string m = ax.step(p);
        if (!res.expect(m.empty(), [&] { return "call " + std::to_string(t) + ": " + m; })) break;
        const lx::axis_out& h = ax.hls();
        const int64_t comp = h.comp_pos.to_int64();
        if (t > 0 && t % every == 0) max_jump = std::max<long long>(max_jump, std::llabs(comp - comp_prev));
        stable = (comp == comp_prev && h.step == 0) ? stable + 1 : 0;
        comp_prev = comp;
        if (h.pstep != 0) {
            res.expect(t - last_pstep >= s.pace_m, [&] { return "paced counts closer than M at call " + std::to_string(t); });
            last_pstep = t;
        }
        // after an update: once drained, the real position seen downstream equals floor((N R_new + OFF_new) / 2^32)
        if (pending_check && stable >= 8 && h.backlog == 0 && h.pstep == 0 && h.ostep == 0 && h.stage != 2) {
            __extension__ typedef __int128 i128;
            const int64_t want = static_cast<int64_t>(
                (static_cast<i128>(h.raw_count.to_int64()) * static_cast<i128>(ax.settings().ratio) +
                 static_cast<i128>(ax.settings().comp_offset)) >> 32);
            // comp has been stable for 8 calls, so the pacer and rephase have seen all of it
            if (h.comp_pos == want) {
                res.check(h.out_pos.to_int64() - h.adj.to_int64() == want,
                          "update not delivered exactly at call " + std::to_string(t));
                ++checked;
                pending_check = false;
            }
        }
    }
    std::printf("  %lld ratio + offset updates (%lld while moving), %lld verified after draining; largest comp change at an "
                "update call %lld counts; final ratio %llu (%+.3f ppm)\n",
                updates, updates_moving, checked, max_jump, static_cast<unsigned long long>(ax.settings().ratio),
                c.total_ppm);
    res.check(updates >= 25 && checked >= updates - 2, "too few updates verified");
    res.check(updates_moving >= 5 && updates_moving < updates, "updates did not cover both motion and rest");
    return res.finish();
}
