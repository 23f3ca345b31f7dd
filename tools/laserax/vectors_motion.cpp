// vectors_motion.cpp — golden vectors of the motion-synchronised blocks (pso, encoder_counter),
// written by `laserax vectors` next to the single-axis files (format: docs/VECTORS.md).
#include <cmath>
#include <random>

#include "golden/encoder_counter.h"
#include "golden/pso.h"
#include "hls/encoder_counter.h"
#include "hls/pso.h"
#include "tools/laserax/pso_cmd.h"
#include "tools/laserax/vectors.h"

namespace lxt {

bool build_motion_vectors(uint64_t seed, long long calls, std::vector<vec_table>& tables, std::string* err) {
    std::mt19937_64 rng(seed ^ 0x5a5aULL);

    // ---- pso (columns: lxt::vec_layout("pso"), every port). Four parts of the run:
    //      1 (0 .. 40 %)  2D path of random straight segments with reversals (K 16), window on
    //                     x in [-200, 200] in its second half, live distance and width changes
    //                     (overlaps), a clear every 20000 calls;
    //      2 (40 .. 60 %) 3D path, K 8, array mode: 8 entries (4..40 counts) written while
    //                     disabled, the run wraps; the window on z;
    //      3 (60 .. 80 %) part-speed: a rate profile up to 30 MHz (clamped, rate_over), laser
    //                     minimum period 100 (spacing_err, freq_err), window on the pulse count;
    //      4 (80 .. 100 %) 2D again (K 4), with enable toggles and one-call invalid
    //                     configurations (K 0, distance below 4 counts, window low > high)
    vec_table pso{"pso", vec_layout("pso"), {}};
    {
        lx::pso h;
        golden::pso g;
        g.reset();
        int64_t pos[3] = {0, 0, 0};
        double acc[3] = {0, 0, 0}, vel[3] = {0, 0, 0};
        long long seg_left = 0;
        const long long p2 = calls * 2 / 5, p3 = calls * 3 / 5, p4 = calls * 4 / 5;
        for (long long t = 0; t < calls; ++t) {
            const int part = t < p2 ? 1 : t < p3 ? 2 : t < p4 ? 3 : 4;
            const bool three_d = part == 2;
            if (seg_left-- <= 0) {
                const double ang = static_cast<double>(rng() % 6283) / 1000.0;
                const double el = three_d ? static_cast<double>(rng() % 3141) / 1000.0 - 1.5707 : 0.0;
                const double speed = 0.05 + static_cast<double>(rng() % 900) / 1000.0;  // counts per call
                vel[0] = speed * std::cos(ang) * std::cos(el);
                vel[1] = speed * std::sin(ang) * std::cos(el);
                vel[2] = speed * std::sin(el);
                seg_left = 200 + static_cast<long long>(rng() % 3000);
            }
            golden::pso_regs gr;
            golden::pso_in gi;
            gr.enable = t >= 5;
            gr.win_src = 0;
            gr.win_low = -200;
            gr.win_high = 200;
            gr.clear = t % 20000 == 19999;
            if (part == 1) {
                gr.axis_mask = 3;
                gr.win_en = t >= p2 / 2;
                gr.fire_dist = (t < p2 / 3 ? 128ULL : 37ULL) << 32;  // live change
                gr.pulse_w = t < p2 / 4 ? 10 : 60;                   // overlaps later
            } else if (part == 2) {
                // entries written in the first calls of the part (enable low), then an array run
                const long long k = t - p2;
                gr.enable = k >= 12;
                gr.axis_mask = 7;
                gr.win_k = 8;
                gr.arr_en = true;
                gr.arr_len = 8;
                gr.arr_wrap = true;
                if (k < 8) {
                    gr.arr_we = true;
                    gr.arr_addr = static_cast<int>(k);
                    gr.arr_data = (4ULL + static_cast<uint64_t>(rng() % 37)) * (1ULL << 32) + (rng() & 0xffffffffULL);
                }
                gr.pulse_w = 4;
                gr.win_en = true;
                gr.win_src = 2;
                gr.win_low = -300;
                gr.win_high = 300;
            } else if (part == 3) {
                const long long k = t - p3;
                gr.enable = k >= 2;
                gr.part_speed = true;
                gr.fire_dist = (k < (p4 - p3) / 2 ? 20ULL : 5ULL) << 32;
                gr.pulse_w = 2;
                gr.min_period = 100;
                gr.win_en = true;
                gr.win_src = 3;
                gr.win_low = 100;
                gr.win_high = 2000;
                // rate profile: a ramp from 0 to 30 MHz and back, period 4000 calls
                const long long ph = k % 4000;
                const double mhz = 30.0 * static_cast<double>(ph < 2000 ? ph : 4000 - ph) / 2000.0;
                gi.ps_inc = static_cast<uint64_t>(mhz / 100.0 * 4294967296.0);
            } else {
                const long long k = t - p4;
                gr.axis_mask = 3;
                gr.win_k = 4;
                gr.fire_dist = (9ULL << 32) + 0x80000000ULL;
                gr.pulse_w = 3;
                gr.enable = k % 1500 >= 3;
                if (k % 2500 == 1000) gr.win_k = 0;
                if (k % 2500 == 1700) gr.fire_dist = (1ULL << 32);
                if (k % 2500 == 2200) {
                    gr.win_en = true;
                    gr.win_low = 5;
                    gr.win_high = 4;
                }
            }
            for (int a = 0; a < 3; ++a) {
                if (part == 3 || (a == 2 && !three_d)) {
                    gi.step[a] = 0;
                    continue;
                }
                acc[a] += vel[a];
                int st = 0;
                if (acc[a] >= 1.0) st = 1;
                if (acc[a] <= -1.0) st = -1;
                acc[a] -= st;
                pos[a] += st;
                gi.step[a] = st;
            }
            for (int a = 0; a < 3; ++a) gi.pos[a] = pos[a];
            const lx::pso::out_t ho = h.step(pso_to_hls(gi), pso_to_hls(gr));
            const golden::pso::out go = g.step(gi, gr);
            const std::string m = pso_compare(ho, go);
            if (!m.empty()) {
                if (err) *err = "pso: hls/golden mismatch at call " + std::to_string(t) + ": " + m;
                return false;
            }
            pso.rows.push_back(pso_vec_row(gi, gr, go));
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
