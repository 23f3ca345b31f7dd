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

    // ---- encoder_counter (columns: lxt::vec_layout, every port): channel 0 from a quadrature
    //      step stream crossing the +2^31 wrap, channel 1 simulated at 1 MHz (up, then down),
    //      reset on trigger, waits on channel 0 (up, then down, both across the wrap),
    //      correction ticks every 1000 calls, then every 33 calls (the period lowered live),
    //      50 calls with an invalid source
    vec_table enc{"encoder_counter", vec_layout("encoder_counter"), {}};
    {
        lx::encoder_counter h;
        golden::encoder_counter g;
        g.reset();
        int dir = 1;
        for (long long t = 0; t < calls; ++t) {
            golden::encoder_counter_regs gr;
            const bool load0 = t == 3;
            const int64_t load_val0 = 2147483647LL - 3000;
            const int qstep = (t % 7 == 0) ? dir : 0;
            if (t % 25000 == 24999) dir = -dir;
            const bool trig = t % 9000 == 8999;
            const bool rst_req1 = t == calls / 3 || t == calls * 2 / 3;
            const bool rst_on_trig = t < calls / 2;
            // (40000 calls: the first wait is reached up across the wrap in call 24522, the
            // second down across the wrap back in call 29702)
            const bool wait_arm = t == 100 || t == calls * 5 / 8;
            const int64_t wait_val = t < calls * 5 / 8 ? -2147483647LL + 500 : 2147483647LL - 100;
            const bool wait_down = t >= calls * 5 / 8;
            const int64_t scale0 = 3 << 23, scale1 = -(1 << 24);
            gr.src[0] = (t >= calls * 3 / 4 && t < calls * 3 / 4 + 50) ? 2 : 0;
            gr.src[1] = 1;
            gr.sim_down[1] = (t / 40000) % 2 == 1;
            gr.scale[0] = scale0;
            gr.scale[1] = scale1;
            gr.rst_req[1] = rst_req1;
            gr.load[0] = load0;
            gr.load_val[0] = load_val0;
            gr.rst_on_trig = rst_on_trig;
            gr.corr_period = t >= calls * 5 / 6 ? golden::kEncoderCorrLatency : 1000;
            gr.wait_arm = wait_arm;
            gr.wait_ch = 0;
            gr.wait_val = wait_val;
            gr.wait_down = wait_down;
            golden::encoder_counter_in gi;
            gi.qstep[0] = qstep;
            gi.trig = trig;
            gi.pos[0] = 1000 + t / 10;
            gi.pos[1] = -5000;
            lx::encoder_counter_regs hr;
            lx::encoder_counter_in hi{};
            for (int c = 0; c < 2; ++c) {
                hr.src[c] = gr.src[c];
                hr.sim_inc[c] = gr.sim_inc[c];
                hr.sim_down[c] = gr.sim_down[c];
                hr.scale[c] = gr.scale[c];
                hr.rst_req[c] = gr.rst_req[c];
                hr.load[c] = gr.load[c];
                hr.load_val[c] = gr.load_val[c];
                hi.qstep[c] = gi.qstep[c];
                hi.pos[c] = gi.pos[c];
            }
            hr.rst_on_trig = gr.rst_on_trig;
            hr.corr_period = gr.corr_period;
            hr.wait_arm = gr.wait_arm;
            hr.wait_ch = gr.wait_ch != 0;
            hr.wait_val = gr.wait_val;
            hr.wait_down = gr.wait_down;
            hi.trig = gi.trig;
            const lx::encoder_counter::out_t ho = h.step(hi, hr);
            const golden::encoder_counter::out go = g.step(gi, gr);
            bool same = ho.tick == go.tick && ho.waiting == go.waiting && ho.reached == go.reached &&
                        ho.cfg_err == go.cfg_err;
            for (int c = 0; c < 2; ++c)
                same = same && ho.cnt[c].to_int64() == go.cnt[c] && ho.step[c].to_int64() == go.step[c] &&
                       ho.rst_done[c] == go.rst_done[c] && ho.rst_pending[c] == go.rst_pending[c] &&
                       ho.corr[c].to_int64() == go.corr[c];
            if (!same) {
                if (err) *err = "encoder_counter: hls/golden mismatch at call " + std::to_string(t);
                return false;
            }
            enc.rows.push_back({gi.qstep[0], gi.qstep[1], gi.trig, gi.pos[0], gi.pos[1], gr.src[0], gr.src[1],
                                static_cast<int64_t>(gr.sim_inc[0]), static_cast<int64_t>(gr.sim_inc[1]), gr.sim_down[0],
                                gr.sim_down[1], gr.scale[0], gr.scale[1], gr.rst_req[0], gr.rst_req[1], gr.load[0],
                                gr.load[1], gr.load_val[0], gr.load_val[1], gr.rst_on_trig, gr.corr_period, gr.wait_arm,
                                gr.wait_ch, gr.wait_val, gr.wait_down, go.cnt[0], go.cnt[1], go.step[0], go.step[1],
                                go.rst_done[0], go.rst_done[1], go.rst_pending[0], go.rst_pending[1], go.corr[0],
                                go.corr[1], go.tick, go.waiting, go.reached, go.cfg_err});
        }
    }
    tables.push_back(pso);
    tables.push_back(enc);
    return true;
}

}  // namespace lxt
