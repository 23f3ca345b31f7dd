#include "sysmodel/homing.h"

#include <cmath>
#include <deque>
#include <random>

namespace lxt {

homing_result run_homing(const homing_params& p, const std::function<void(const trace_row&)>& sink) {
    homing_result r;
    r.lambda_nm = kVacuumWavelengthNm / p.air_index;
    r.ratio = p.ratio != 0 ? p.ratio : ratio_for(kVacuumWavelengthNm, p.air_index, kOutputCountNm);
    const double period_nm = p.period * kOutputCountNm;

    std::mt19937_64 rng(p.seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    // Power-up: somewhere 10 um plus up to one period before the switch, at a random fringe phase.
    r.switch_edge_nm = 0.0;
    r.start_nm = -p.dir * (10000.0 + u01(rng) * period_nm);
    const double frac0 = u01(rng);
    axis_motion motion(r.start_nm, r.lambda_nm, frac0);
    const double speed = p.speed_mm_s * 1e6 / p.clock_hz;  // nm per clock
    motion.add(r.switch_edge_nm + p.dir * (2.0 * period_nm + 5000.0), speed);
    if (p.return_pass) motion.add(r.switch_edge_nm - p.dir * 5000.0, speed);
    ref_switch sw;
    sw.edge_nm = r.switch_edge_nm;
    sw.dir = p.dir;
    sw.bounce_nm = p.bounce_nm;

    axis_settings s;
    s.period = s.tbl_period = p.period;
    s.mark_len = p.period / 4;
    s.ratio = r.ratio;
    s.comp_offset = p.comp_offset;
    s.glitch_n = p.glitch_n;
    s.sw_debounce = p.sw_debounce;
    s.pace_m = p.pace_m;
    s.pin_cfg = p.pin_cfg;
    dual_axis ax(s);

    const char* names[4] = {"A", "B", "Z", "C"};
    for (const char* n : names) {
        homing_event e;
        e.name = n;
        r.events.push_back(e);
    }
    std::deque<lx::axis_out> hist;
    int prev_stage = 1;
    long long settle = 0;
    bool z_seen_out = false;
    for (long long t = 0; p.max_cycles == 0 || t < p.max_cycles; ++t) {
        motion.tick();
        lx::axis_pins pins;
        quad_pins(motion.raw_count(), pins.a, pins.b);
        pins.sw = sw.level(motion.x_nm(), rng);
        const std::string m = ax.step(pins);
        if (!m.empty() && r.mismatch.empty()) r.mismatch = "cycle " + std::to_string(t) + ": " + m;
        const lx::axis_out& h = ax.hls();
        if (sink) sink(trace_row{t, motion.x_nm(), pins.a, pins.b, pins.sw, pins.lerr, h});

        const int64_t real = h.out_pos.to_int64() - h.adj.to_int64();  // rephase's paced position
        auto mark_event = [&](int i) {
            homing_event& e = r.events[static_cast<size_t>(i)];
            if (e.cycle >= 0) return;
            e.cycle = t;
            e.true_nm = motion.x_nm();
            e.paced = real;
            e.out_pos = h.out_pos.to_int64();
        };
        if (prev_stage == 1 && h.stage == 2) mark_event(0);
        if (prev_stage == 2 && h.stage == 3) {
            mark_event(1);
            r.d = h.d.to_int64();
        }
        if (h.homed && h.ostep == 0) {
            if (real == h.z_pos.to_int64()) mark_event(2);
            if (real == h.c_pos.to_int64()) mark_event(3);
        }
        prev_stage = h.stage.to_int();
        hist.push_back(h);
        if (hist.size() > 3) hist.pop_front();
        if (!z_seen_out && hist.size() == 3) {
            const lx::axis_out& r2 = hist[0];
            if (r2.homed && r2.ostep == 0 && r2.out_pos - r2.adj == r2.z_pos && r2.adj == h.adj) {
                z_seen_out = true;
                r.sin_at_z = h.sin.to_int64();
                r.cos_at_z = h.cos.to_int64();
                r.mark_at_z = h.ref_mark;
            }
        }
        settle = (motion.done() && h.backlog == 0 && h.ostep == 0) ? settle + 1 : 0;
        r.cycles = t + 1;
        if (settle > 200) break;
    }
    return r;
}

}  // namespace lxt
