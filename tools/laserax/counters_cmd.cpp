// counters_cmd.cpp — `laserax counters` and the encoder counter test support, see counters_cmd.h.
#include "tools/laserax/counters_cmd.h"

#include "tools/laserax/cli_util.h"

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "golden/calibration.h"
#include "golden/quad_decoder.h"
#include "hls/quad_decoder.h"
#include "sysmodel/sim.h"

namespace lxt {

lx::encoder_counter_regs counters_to_hls(const golden::encoder_counter_regs& r) {
    lx::encoder_counter_regs h;
    for (int c = 0; c < 2; ++c) {
        h.src[c] = r.src[c];
        h.sim_inc[c] = r.sim_inc[c];
        h.sim_down[c] = r.sim_down[c];
        h.scale[c] = r.scale[c];
        h.rst_req[c] = r.rst_req[c];
        h.load[c] = r.load[c];
        h.load_val[c] = r.load_val[c];
    }
    h.rst_on_trig = r.rst_on_trig;
    h.corr_period = r.corr_period;
    h.wait_arm = r.wait_arm;
    h.wait_ch = r.wait_ch != 0;
    h.wait_val = r.wait_val;
    h.wait_down = r.wait_down;
    return h;
}

lx::encoder_counter_in counters_to_hls(const golden::encoder_counter_in& in) {
    lx::encoder_counter_in h;
    for (int c = 0; c < 2; ++c) {
        h.qstep[c] = in.qstep[c];
        h.pos[c] = in.pos[c];
    }
    h.trig = in.trig;
    return h;
}

std::string counters_compare(const lx::encoder_counter::out_t& h, const golden::encoder_counter::out& g) {
    std::ostringstream m;
    auto i = [&](const std::string& n, long long hv, long long gv) {
        if (hv != gv && m.tellp() == 0) m << n << " hls " << hv << " golden " << gv;
    };
    i("cfg_err", h.cfg_err, g.cfg_err);
    for (int c = 0; c < 2; ++c) {
        const std::string s = std::to_string(c);
        i("cnt" + s, h.cnt[c].to_int64(), g.cnt[c]);
        i("step" + s, h.step[c].to_int(), g.step[c]);
        i("rst_done" + s, h.rst_done[c], g.rst_done[c]);
        i("rst_pending" + s, h.rst_pending[c], g.rst_pending[c]);
        i("corr" + s, h.corr[c].to_int64(), g.corr[c]);
    }
    i("tick", h.tick, g.tick);
    i("waiting", h.waiting, g.waiting);
    i("reached", h.reached, g.reached);
    return m.str();
}

const char* const kCountersUsage =
    "usage: laserax counters [options]\n"
    "  --out DIR            output folder (default out)\n"
    "  --rate-hz F          encoder simulation counting rate of counter 0, (0, 5e7] (default 1e6)\n"
    "  --k-bits-mm K        calibration factor K, bits per mm, (0, 1e9] (default 10000)\n"
    "  --v-mm-s V           workpiece speed for the constant-speed scale of counter 0, (0, 1e5] (default 100)\n"
    "  --enc-counts-mm I    counts per mm of the quadrature encoder on counter 1, (0, 1e9] (default 1000)\n"
    "  --enc-speed C        quadrature encoder speed, counts per clock, (0, 0.2] (default 0.05)\n"
    "  --wait N             wait-for-encoder: counter 0 oversteps N after its reset, a 32-bit signed\n"
    "                       counter value -2147483648..2147483647 (default 500)\n"
    "  --calls N            clocks to simulate, 1000..100000000 (default 150000 = 1.5 ms)\n"
    "  --no-plot            do not call scripts/plot_pso.py\n";

namespace {


}  // namespace

int cmd_counters(const std::vector<std::string>& args, size_t first) {
    std::string out = "out";
    double rate = 1e6, kbits = 10000, vmm = 100, enc_cpm = 1000, enc_speed = 0.05, wait_n = 500, calls_d = 150000;
    bool plot = true;
    cli cl("laserax counters", args, first, kCountersUsage);
    long long wait_i = 500, calls_i = 150000;
    while (cl.next()) {
        if (cl.is("--no-plot")) plot = false;
        else if (cl.is("--out")) cl.get_text(&out);
        else if (cl.is("--rate-hz")) cl.get_real(0.0, 5e7, &rate, true, false);
        else if (cl.is("--k-bits-mm")) cl.get_real(0.0, 1e9, &kbits, true, false);
        else if (cl.is("--v-mm-s")) cl.get_real(0.0, 1e5, &vmm, true, false);
        else if (cl.is("--enc-counts-mm")) cl.get_real(0.0, 1e9, &enc_cpm, true, false);
        else if (cl.is("--enc-speed")) cl.get_real(0.0, 0.2, &enc_speed, true, false);
        else if (cl.is("--wait")) cl.get_int(-2147483647LL - 1, 2147483647LL, &wait_i);
        else if (cl.is("--calls")) cl.get_int(1000, 100000000, &calls_i);
        else cl.unknown();
    }
    if (cl.failed()) return cl.status();
    wait_n = static_cast<double>(wait_i);
    calls_d = static_cast<double>(calls_i);
    const long long calls = static_cast<long long>(calls_d);
    if (!make_dirs(out, "laserax counters")) return 2;
    const std::string trace_path = out + "/counters_trace.csv";
    FILE* tr = std::fopen(trace_path.c_str(), "w");
    if (!tr) {
        std::fprintf(stderr, "laserax counters: cannot write %s\n", trace_path.c_str());
        return 2;
    }

    // Scale factors (RTC5 linear movements): counter 0 by the constant-speed form, counter 1 from a
    // calibration run (start/end readings across the wrap and a least-squares fit).
    const double scale0 = golden::encoder_scale_at_rate(kbits, vmm, rate);
    const int64_t wrap_preset = 2147483647LL - static_cast<int64_t>(0.3 * enc_speed * calls_d);
    golden::encoder_counter_regs regs;
    regs.src[0] = 1;
    regs.sim_inc[0] = golden::encoder_sim_inc(rate);
    regs.src[1] = 0;
    bool ok0 = false, ok1 = false;
    regs.scale[0] = golden::encoder_scale_to_q(scale0, &ok0);
    regs.corr_period = 1000;
    const golden::encoder_counter_in idle;

    lx::encoder_counter hls;
    golden::encoder_counter gold;
    lx::quad_decoder qd_h;
    golden::quad_decoder qd_g;
    qd_g.reset();
    std::string mismatch;
    std::fprintf(tr, "# laserax counters: counter 0 simulation %.0f Hz, counter 1 quadrature %.3f counts/clock\n", rate,
                 enc_speed);
    std::fprintf(tr, "cycle,cnt0,cnt1,corr0,corr1,tick,waiting,reached,rst_pending0,rst_done0,event\n");
    long long rows = 0;
    const long long t_req = calls / 8, t_trig = calls / 6, t_cal0 = calls / 10, t_cal1 = calls - calls / 10;
    long long t_reset = -1, t_reached = -1, t_wrap = -1;
    int64_t cnt_at_reach = 0, cal_start = 0, cal_end = 0;
    std::vector<double> fit_x;
    std::vector<int64_t> fit_y;
    double enc_phase = 0;
    int64_t enc_n = 0;
    int prev_qstep = 0;
    lx::encoder_counter::out_t h{};
    int64_t prev_cnt1 = 0;
    bool scale1_set = false;
    for (long long t = 0; t < calls; ++t) {
        golden::encoder_counter_regs r = regs;
        golden::encoder_counter_in in = idle;
        std::string event;
        if (t == 0) {
            r.load[1] = true;
            r.load_val[1] = wrap_preset;
            event = "preset counter 1";
        }
        if (t == t_cal1 + 1) {  // the correction of counter 1 starts from zero (like set_fly_x)
            r.rst_req[1] = true;
            event = "counter 1 reset, correction starts";
        }
        if (t == t_req) {
            r.rst_req[0] = true;
            r.rst_on_trig = true;
            event = "reset request (at next trigger)";
        }
        if (t == t_trig) {
            in.trig = true;
            event = "start trigger";
        }
        if (t == t_trig + 1) {
            r.wait_arm = true;
            r.wait_ch = 0;
            r.wait_val = static_cast<int64_t>(wait_n);
            event = "wait armed";
            regs.rst_on_trig = false;  // later resets act immediately
        }
        if (t == t_req) regs.rst_on_trig = true;
        // counter 1: a quadrature encoder moving at constant speed, through the quad decoder
        enc_phase += enc_speed;
        while (enc_phase >= 1.0) {
            enc_phase -= 1.0;
            ++enc_n;
        }
        bool pa, pb;
        quad_pins(enc_n, pa, pb);
        const lx::quad_decoder::out_t qh = qd_h.step(pa, pb, false, 2, 0, false);
        const golden::quad_decoder::out qg = qd_g.step(pa, pb, false, 2, 0, false);
        if (mismatch.empty() && qh.step.to_int() != qg.step)
            mismatch = "quad decoder step differs at call " + std::to_string(t);
        in.qstep[1] = prev_qstep;  // one register stage between the decoder and the counter
        prev_qstep = qh.step.to_int();
        in.pos[0] = 1000;
        in.pos[1] = -2000;
        h = hls.step(counters_to_hls(in), counters_to_hls(r));
        const golden::encoder_counter::out g = gold.step(in, r);
        if (mismatch.empty()) {
            const std::string m = counters_compare(h, g);
            if (!m.empty()) mismatch = "call " + std::to_string(t) + ": " + m;
        }
        const int64_t c1 = h.cnt[1].to_int64();
        if (t > 0 && t_wrap < 0 && prev_cnt1 == 2147483647LL && c1 == -2147483648LL) {
            t_wrap = t;
            event = "counter 1 wraps +2^31-1 -> -2^31";
        }
        prev_cnt1 = c1;
        if (h.rst_done[0]) {
            t_reset = t;
            event = "counter 0 reset";
        }
        if (h.reached) {
            t_reached = t;
            cnt_at_reach = h.cnt[0].to_int64();
            event = "wait reached";
        }
        // calibration of counter 1: readings every 10 us during a 'calibration move'
        if (t == t_cal0) cal_start = c1;
        if (t >= t_cal0 && t <= t_cal1 && (t - t_cal0) % 1000 == 0) {
            fit_x.push_back(static_cast<double>(t - t_cal0) * enc_speed / enc_cpm);  // mm travelled
            fit_y.push_back(c1);
        }
        if (t == t_cal1) {
            cal_end = c1;
            const double dist_mm = static_cast<double>(t - t_cal0) * enc_speed / enc_cpm;
            const double inc = golden::encoder_increment(cal_start, cal_end, dist_mm).counts_per_mm;
            regs.scale[1] = golden::encoder_scale_to_q(golden::scale_from_increment(kbits, inc).scale, &ok1);
            scale1_set = true;
            event = "counter 1 scale set from calibration";
        }
        if (h.tick || !event.empty()) {
            std::fprintf(tr, "%lld,%lld,%lld,%lld,%lld,%d,%d,%d,%d,%d,%s\n", t, static_cast<long long>(h.cnt[0].to_int64()),
                         static_cast<long long>(c1), static_cast<long long>(h.corr[0].to_int64()),
                         static_cast<long long>(h.corr[1].to_int64()), h.tick ? 1 : 0, h.waiting ? 1 : 0,
                         h.reached ? 1 : 0, h.rst_pending[0] ? 1 : 0, h.rst_done[0] ? 1 : 0, event.c_str());
            ++rows;
        }
    }
    std::fclose(tr);

    const double dist_mm = static_cast<double>(t_cal1 - t_cal0) * enc_speed / enc_cpm;
    const double inc_se = golden::encoder_increment(cal_start, cal_end, dist_mm).counts_per_mm;
    const golden::linear_fit fit = golden::encoder_increment_fit(fit_x, fit_y);
    std::printf("laserax counters: %lld clocks (%.3f ms at 100 MHz), correction every 1000 clocks (10 us)\n", calls,
                static_cast<double>(calls) * 1e-5);
    std::printf("  counter 0: encoder simulation %.0f counts/s (rate register %llu, Q0.32 = %.9f counts/clock)\n", rate,
                static_cast<unsigned long long>(regs.sim_inc[0]), static_cast<double>(regs.sim_inc[0]) / 4294967296.0);
    std::printf("  counter 1: quadrature encoder %.3f counts/clock via quad_decoder, preset to %lld\n\n", enc_speed,
                static_cast<long long>(wrap_preset));
    std::printf("  %-36s %12s  %s\n", "event", "clock", "value");
    std::printf("  %-36s %12lld\n", "reset request (mode: at trigger)", t_req);
    std::printf("  %-36s %12lld  %s\n", "start trigger", t_trig,
                t_reset == t_trig ? "counter 0 reset in this clock" : "counter 0 NOT reset at the trigger");
    std::printf("  %-36s %12lld  counter 0 > %.0f: %lld\n", "wait-for-encoder reached", t_reached, wait_n,
                static_cast<long long>(cnt_at_reach));
    std::printf("  %-36s %12lld  2147483647 -> -2147483648\n", "counter 1 wrap", t_wrap);
    std::printf("  %-36s %12s  %lld / %lld\n", "final counters 0 / 1", "", static_cast<long long>(h.cnt[0].to_int64()),
                static_cast<long long>(h.cnt[1].to_int64()));
    std::printf("  %-36s %12s  %lld / %lld bits\n", "last correction outputs 0 / 1", "",
                static_cast<long long>(h.corr[0].to_int64()), static_cast<long long>(h.corr[1].to_int64()));
    std::printf("\n  calibration (K = %.1f bits/mm)\n", kbits);
    std::printf("    counter 0, constant speed: Scale = K * v / rate = %.1f * %.3f / %.0f = %.9f bits/count (Q8.24 %lld%s)\n",
                kbits, vmm, rate, scale0, static_cast<long long>(regs.scale[0]), ok0 ? "" : ", OUT OF RANGE");
    std::printf("    counter 1, start/end readings %lld -> %lld over %.6f mm: i = %.4f counts/mm (true %.1f)\n",
                static_cast<long long>(cal_start), static_cast<long long>(cal_end), dist_mm, inc_se, enc_cpm);
    if (fit.ok)
        std::printf("    counter 1, least squares over %ld readings: i = %.4f +- %.4f counts/mm, rms %.3f counts\n", fit.n,
                    fit.scale, fit.scale_se, fit.rms_residual);
    std::printf("    counter 1: Scale = K / i = %.9f bits/count (Q8.24 %lld%s)%s\n",
                golden::scale_from_increment(kbits, inc_se).scale, static_cast<long long>(regs.scale[1]), ok1 ? "" : ", OUT OF RANGE",
                scale1_set ? "" : " (not set)");
    std::printf("  hls vs golden: %s\n", mismatch.empty() ? "bit-exact on every clock" : mismatch.c_str());
    std::printf("  wrote %s (%lld rows)\n", trace_path.c_str(), rows);
    if (plot) {
        const std::string py = "/usr/bin/python3";
        struct stat st;
        if (stat(py.c_str(), &st) == 0) {
            const std::string c = py + " scripts/plot_pso.py counters " + trace_path + " " + out + "/counters.png";
            std::fflush(stdout);
            if (std::system(c.c_str()) == 0) std::printf("  wrote %s/counters.png\n", out.c_str());
            else std::printf("  plot skipped (scripts/plot_pso.py failed; needs matplotlib: run `make deps`)\n");
        } else {
            std::printf("  plot skipped: /usr/bin/python3 not found\n");
        }
    }
    const bool ok = mismatch.empty() && t_reset == t_trig && t_reached >= 0 && t_wrap >= 0;
    return ok ? 0 : 1;
}

}  // namespace lxt
