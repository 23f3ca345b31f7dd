// vectors_motion.cpp — golden vectors of the motion-synchronised blocks (pso, encoder_counter),
// written by `laserax vectors` next to the single-axis files (format: docs/VECTORS.md).
#include <cmath>
#include <random>

#include "golden/encoder_counter.h"
#include "golden/pso.h"
#include "hls/encoder_counter.h"
#include "hls/pso.h"
#include "tools/common/vectors.h"

namespace lxt {

namespace {

vec_column vin(const char* n, int bits, bool s = false) { return vec_column{n, bits, s, true}; }
vec_column vout(const char* n, int bits, bool s = false) { return vec_column{n, bits, s, false}; }

}  // namespace

bool build_motion_vectors(uint64_t seed, long long calls, std::vector<vec_table>& tables, std::string* err) {
    using PC = lx::pso_cfg;
    using EC = lx::encoder_counter_cfg;
    const int WP = lx::axis_widths::W_POS;
    std::mt19937_64 rng(seed ^ 0x5a5aULL);

    // ---- pso: a 2D path of random straight segments with reversals, window on part of it
    vec_table pso{"pso",
                  {vin("step0", 2, true), vin("step1", 2, true), vin("step2", 2, true), vin("pos0", WP, true),
                   vin("pos1", WP, true), vin("pos2", WP, true), vin("enable", 1), vin("fire_dist", PC::W_DIST),
                   vin("pulse_w", PC::W_PW), vin("win_en", 1), vin("win_low", WP, true), vin("win_high", WP, true),
                   vin("clear", 1), vout("fire", 1), vout("emit", 1), vout("pulse", 1), vout("in_win", 1),
                   vout("dist", PC::W_REM, true), vout("fire_cnt", PC::W_FCNT), vout("overlap_cnt", PC::W_OVL),
                   vout("overlap_st", 1), vout("cfg_err", 1)},
                  {}};
    {
        lx::pso h;
        golden::pso g;
        g.reset();
        lx::pso_regs hr;
        golden::pso_regs gr;
        int64_t pos[3] = {0, 0, 0};
        double acc[2] = {0, 0}, vel[2] = {0, 0};
        long long seg_left = 0;
        for (long long t = 0; t < calls; ++t) {
            if (seg_left-- <= 0) {
                const double ang = static_cast<double>(rng() % 6283) / 1000.0;
                const double speed = 0.05 + static_cast<double>(rng() % 900) / 1000.0;  // counts per call
                vel[0] = speed * std::cos(ang);
                vel[1] = speed * std::sin(ang);
                seg_left = 200 + static_cast<long long>(rng() % 3000);
            }
            const bool enable = t >= 5;
            const bool win_en = t >= calls / 2;
            const uint64_t fire_dist = (t < calls / 3 ? 128ULL : 37ULL) << 32;  // live change
            const int pulse_w = t < calls / 4 ? 10 : 60;                        // overlaps later
            const bool clear = t % 20000 == 19999;
            lx::pso_in hi{};
            golden::pso_in gi;
            for (int a = 0; a < 2; ++a) {
                acc[a] += vel[a];
                int st = 0;
                if (acc[a] >= 1.0) st = 1;
                if (acc[a] <= -1.0) st = -1;
                acc[a] -= st;
                pos[a] += st;
                hi.step[a] = st;
                gi.step[a] = st;
            }
            hi.step[2] = 0;
            for (int a = 0; a < 3; ++a) {
                hi.pos[a] = pos[a];
                gi.pos[a] = pos[a];
            }
            hi.ps_inc = 0;
            gi.ps_inc = 0;
            hr.enable = gr.enable = enable;
            hr.fire_dist = fire_dist;
            gr.fire_dist = fire_dist;
            hr.pulse_w = pulse_w;
            gr.pulse_w = pulse_w;
            hr.win_en = gr.win_en = win_en;
            hr.win_src = 0;
            gr.win_src = 0;
            hr.win_low = -200;
            gr.win_low = -200;
            hr.win_high = 200;
            gr.win_high = 200;
            hr.clear = gr.clear = clear;
            const lx::pso::out_t ho = h.step(hi, hr);
            const golden::pso::out go = g.step(gi, gr);
            const int64_t gdist = static_cast<int64_t>(go.dist * 4294967296.0L);
            if (ho.fire != go.fire || ho.emit != go.emit || ho.pulse != go.pulse || ho.in_win != go.in_win ||
                ho.dist.to_int64() != gdist || ho.fire_cnt.to_uint64() != go.fire_cnt ||
                ho.overlap_cnt.to_int64() != go.overlap_cnt || ho.overlap_st != go.overlap_st ||
                ho.cfg_err != go.cfg_err) {
                if (err) *err = "pso: hls/golden mismatch at call " + std::to_string(t);
                return false;
            }
            pso.rows.push_back({hi.step[0].to_int64(), hi.step[1].to_int64(), 0, pos[0], pos[1], pos[2], enable,
                                static_cast<int64_t>(fire_dist), pulse_w, win_en, -200, 200, clear, go.fire, go.emit,
                                go.pulse, go.in_win, gdist, static_cast<int64_t>(go.fire_cnt), go.overlap_cnt,
                                go.overlap_st, go.cfg_err});
        }
    }

    // ---- encoder_counter: channel 0 from a quadrature step stream crossing the +2^31 wrap,
    //      channel 1 simulated at 1 MHz, reset on trigger, a wait on channel 0, correction ticks
    vec_table enc{"encoder_counter",
                  {vin("qstep0", 2, true), vin("trig", 1), vin("pos0", EC::W_POSIN, true), vin("pos1", EC::W_POSIN, true),
                   vin("src1", 2), vin("sim_down1", 1), vin("scale0", EC::W_SCALE, true), vin("scale1", EC::W_SCALE, true),
                   vin("rst_req1", 1), vin("load0", 1), vin("load_val0", EC::W_CNT, true), vin("rst_on_trig", 1),
                   vin("wait_arm", 1), vin("wait_val", EC::W_CNT, true), vin("wait_down", 1),
                   vout("cnt0", EC::W_CNT, true), vout("cnt1", EC::W_CNT, true), vout("corr0", EC::W_CORR, true),
                   vout("corr1", EC::W_CORR, true), vout("tick", 1), vout("waiting", 1), vout("reached", 1),
                   vout("rst_pending1", 1), vout("cfg_err", 1)},
                  {}};
    {
        lx::encoder_counter h;
        golden::encoder_counter g;
        g.reset();
        int dir = 1;
        for (long long t = 0; t < calls; ++t) {
            lx::encoder_counter_regs hr;
            golden::encoder_counter_regs gr;
            const bool load0 = t == 3;
            const int64_t load_val0 = 2147483647LL - 3000;
            const int qstep = (t % 7 == 0) ? dir : 0;
            if (t % 25000 == 24999) dir = -dir;
            const bool trig = t % 9000 == 8999;
            const bool rst_req1 = t == calls / 3 || t == calls * 2 / 3;
            const bool rst_on_trig = t < calls / 2;
            const bool wait_arm = t == 100 || t == calls / 2;
            const int64_t wait_val = t < calls / 2 ? -2147483647LL + 500 : 2147483647LL - 2500;
            const bool wait_down = t >= calls / 2;
            const int64_t scale0 = 3 << 23, scale1 = -(1 << 24);
            hr.src[1] = 1;
            gr.src[1] = 1;
            hr.sim_down[1] = gr.sim_down[1] = (t / 40000) % 2 == 1;
            hr.scale[0] = scale0;
            gr.scale[0] = scale0;
            hr.scale[1] = scale1;
            gr.scale[1] = scale1;
            hr.rst_req[1] = gr.rst_req[1] = rst_req1;
            hr.load[0] = gr.load[0] = load0;
            hr.load_val[0] = load_val0;
            gr.load_val[0] = load_val0;
            hr.rst_on_trig = gr.rst_on_trig = rst_on_trig;
            hr.wait_arm = gr.wait_arm = wait_arm;
            hr.wait_ch = false;
            gr.wait_ch = 0;
            hr.wait_val = wait_val;
            gr.wait_val = wait_val;
            hr.wait_down = gr.wait_down = wait_down;
            lx::encoder_counter_in hi{};
            golden::encoder_counter_in gi;
            hi.qstep[0] = qstep;
            hi.qstep[1] = 0;
            gi.qstep[0] = qstep;
            hi.trig = gi.trig = trig;
            const int64_t pos0 = 1000 + t / 10, pos1 = -5000;
            hi.pos[0] = pos0;
            hi.pos[1] = pos1;
            gi.pos[0] = pos0;
            gi.pos[1] = pos1;
            const lx::encoder_counter::out_t ho = h.step(hi, hr);
            const golden::encoder_counter::out go = g.step(gi, gr);
            if (ho.cnt[0].to_int64() != go.cnt[0] || ho.cnt[1].to_int64() != go.cnt[1] ||
                ho.corr[0].to_int64() != go.corr[0] || ho.corr[1].to_int64() != go.corr[1] || ho.tick != go.tick ||
                ho.waiting != go.waiting || ho.reached != go.reached || ho.rst_pending[1] != go.rst_pending[1] ||
                ho.cfg_err != go.cfg_err) {
                if (err) *err = "encoder_counter: hls/golden mismatch at call " + std::to_string(t);
                return false;
            }
            enc.rows.push_back({qstep, trig, pos0, pos1, 1, gr.sim_down[1], scale0, scale1, rst_req1, load0, load_val0,
                                rst_on_trig, wait_arm, wait_val, wait_down, go.cnt[0], go.cnt[1], go.corr[0], go.corr[1],
                                go.tick, go.waiting, go.reached, go.rst_pending[1], go.cfg_err});
        }
    }
    tables.push_back(pso);
    tables.push_back(enc);
    return true;
}

}  // namespace lxt
