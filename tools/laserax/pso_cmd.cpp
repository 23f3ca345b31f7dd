// pso_cmd.cpp — `laserax pso` and the PSO test support, see pso_cmd.h.
#include "tools/laserax/pso_cmd.h"

#include "tools/laserax/cli_util.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace lxt {

namespace {

constexpr double kNmPerCount = 78.125;
constexpr double kClock = 100e6;
constexpr double kQ32 = 4294967296.0;
constexpr double kPi = 3.14159265358979323846;

double norm3(const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

}  // namespace

// ---- path ------------------------------------------------------------------------------------

pso_path::pso_path(const double start[3]) {
    for (int i = 0; i < 3; ++i) cur_[i] = start[i];
}

void pso_path::line(const double dir[3], double len, double speed) {
    seg g{};
    g.kind = 0;
    const double n = norm3(dir);
    for (int i = 0; i < 3; ++i) {
        g.p0[i] = cur_[i];
        g.dir[i] = dir[i] / n;
    }
    g.len = len;
    g.speed = speed;
    g.t0 = t_end_;
    g.t1 = t_end_ + len / speed;
    g.s0 = s_end_;
    segs_.push_back(g);
    t_end_ = g.t1;
    s_end_ += len;
    point_in(g, len, cur_);
}

void pso_path::arc(const double u[3], const double v[3], double r, double sweep, double speed) {
    seg g{};
    g.kind = 1;
    for (int i = 0; i < 3; ++i) {
        g.p0[i] = cur_[i];
        g.u[i] = u[i];
        g.v[i] = v[i];
        g.c[i] = cur_[i] - r * u[i];
    }
    g.r = r;
    g.sweep = sweep;
    g.len = r * std::fabs(sweep);
    g.speed = speed;
    g.t0 = t_end_;
    g.t1 = t_end_ + g.len / speed;
    g.s0 = s_end_;
    segs_.push_back(g);
    t_end_ = g.t1;
    s_end_ += g.len;
    point_in(g, g.len, cur_);
}

void pso_path::dwell(double calls) {
    seg g{};
    g.kind = 2;
    for (int i = 0; i < 3; ++i) g.p0[i] = cur_[i];
    g.len = 0;
    g.speed = 0;
    g.t0 = t_end_;
    g.t1 = t_end_ + calls;
    g.s0 = s_end_;
    segs_.push_back(g);
    t_end_ = g.t1;
}

void pso_path::point_in(const seg& g, double sl, double x[3]) const {
    if (g.kind == 0) {
        for (int i = 0; i < 3; ++i) x[i] = g.p0[i] + sl * g.dir[i];
    } else if (g.kind == 1) {
        const double a = (g.sweep >= 0 ? sl : -sl) / g.r;
        const double ca = std::cos(a), sa = std::sin(a);
        for (int i = 0; i < 3; ++i) x[i] = g.c[i] + g.r * (ca * g.u[i] + sa * g.v[i]);
    } else {
        for (int i = 0; i < 3; ++i) x[i] = g.p0[i];
    }
}

void pso_path::dir_in(const seg& g, double sl, double d[3]) const {
    if (g.kind == 0) {
        for (int i = 0; i < 3; ++i) d[i] = g.dir[i];
    } else if (g.kind == 1) {
        const double sg = g.sweep >= 0 ? 1.0 : -1.0;
        const double a = sg * sl / g.r;
        for (int i = 0; i < 3; ++i) d[i] = sg * (-std::sin(a) * g.u[i] + std::cos(a) * g.v[i]);
    } else {
        for (int i = 0; i < 3; ++i) d[i] = 0;
    }
}

void pso_path::at_time(double tau, double x[3], double* s) const {
    if (segs_.empty()) {
        for (int i = 0; i < 3; ++i) x[i] = cur_[i];
        if (s) *s = 0;
        return;
    }
    // segments are sorted by time: binary search
    size_t lo = 0, hi = segs_.size() - 1;
    while (lo < hi) {
        const size_t mid = (lo + hi + 1) / 2;
        if (segs_[mid].t0 <= tau) lo = mid;
        else hi = mid - 1;
    }
    const seg& g = segs_[lo];
    const double dt = std::min(std::max(tau - g.t0, 0.0), g.t1 - g.t0);
    const double sl = g.kind == 2 ? 0.0 : std::min(dt * g.speed, g.len);
    point_in(g, sl, x);
    if (s) *s = g.s0 + sl;
}

void pso_path::at_length(double s, double x[3]) const {
    for (size_t k = 0; k < segs_.size(); ++k) {
        const seg& g = segs_[k];
        if (g.kind == 2) continue;
        if (s <= g.s0 + g.len || k + 1 == segs_.size()) {
            point_in(g, std::min(std::max(s - g.s0, 0.0), g.len), x);
            return;
        }
    }
    for (int i = 0; i < 3; ++i) x[i] = cur_[i];
}

double pso_path::speed_at(double tau) const {
    for (const seg& g : segs_)
        if (tau >= g.t0 && tau < g.t1) return g.speed;
    return 0;
}

void pso_path::end_point(double x[3]) const {
    for (int i = 0; i < 3; ++i) x[i] = cur_[i];
}

void pso_path::end_dir(double d[3]) const {
    for (size_t k = segs_.size(); k-- > 0;) {
        if (segs_[k].kind == 2) continue;
        dir_in(segs_[k], segs_[k].len, d);
        return;
    }
    d[0] = 1;
    d[1] = d[2] = 0;
}

void pso_sampler::start(const pso_path& p, const double off[3]) {
    path = &p;
    double x[3];
    p.at_time(0, x, nullptr);
    for (int i = 0; i < 3; ++i) {
        offset[i] = off[i];
        pos[i] = static_cast<int64_t>(std::floor(x[i] + off[i]));
    }
}

bool pso_sampler::advance(double tau, int step[3]) {
    double x[3];
    path->at_time(tau, x, nullptr);
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
        const int64_t p = static_cast<int64_t>(std::floor(x[i] + offset[i]));
        const int64_t d = p - pos[i];
        if (d > 1 || d < -1) ok = false;
        step[i] = static_cast<int>(std::max<int64_t>(-1, std::min<int64_t>(1, d)));
        pos[i] += step[i];
    }
    return ok;
}

// ---- conversion and comparison ----------------------------------------------------------------

namespace {

std::vector<int64_t> pso_vec_inputs(const golden::pso_in& in, const golden::pso_regs& r) {
    return {in.step[0], in.step[1], in.step[2], in.pos[0], in.pos[1], in.pos[2], static_cast<int64_t>(in.ps_inc),
            r.enable, r.part_speed, static_cast<int64_t>(r.axis_mask), r.win_k, static_cast<int64_t>(r.fire_dist),
            r.arr_en, r.arr_len, r.arr_wrap, r.arr_we, r.arr_addr, static_cast<int64_t>(r.arr_data), r.pulse_w,
            r.win_en, r.win_src, r.win_low, r.win_high, r.min_period, r.clear};
}

}  // namespace

std::vector<int64_t> pso_vec_row(const golden::pso_in& in, const golden::pso_regs& r, const golden::pso::out& o) {
    std::vector<int64_t> row = pso_vec_inputs(in, r);
    const int64_t dist = static_cast<int64_t>(o.dist * 4294967296.0L);  // exact: a multiple of 2^-32
    const std::vector<int64_t> outs = {o.fire, o.emit, o.pulse, o.in_win, dist, o.idx, o.arr_done,
                                       static_cast<int64_t>(o.fire_cnt), o.overlap_cnt, o.overlap, o.overlap_st,
                                       o.rate_over, o.rate_over_st, o.spacing_err, o.spacing_st, o.freq_err,
                                       o.freq_st, o.ps_pulse, o.ps_count, o.cfg_err};
    row.insert(row.end(), outs.begin(), outs.end());
    return row;
}

std::vector<int64_t> pso_vec_row(const golden::pso_in& in, const golden::pso_regs& r, const lx::pso::out_t& o) {
    std::vector<int64_t> row = pso_vec_inputs(in, r);
    const std::vector<int64_t> outs = {o.fire, o.emit, o.pulse, o.in_win, o.dist.to_int64(),
                                       static_cast<int64_t>(o.idx.to_uint64()), o.arr_done,
                                       static_cast<int64_t>(o.fire_cnt.to_uint64()),
                                       static_cast<int64_t>(o.overlap_cnt.to_uint64()), o.overlap, o.overlap_st,
                                       o.rate_over, o.rate_over_st, o.spacing_err, o.spacing_st, o.freq_err,
                                       o.freq_st, o.ps_pulse, o.ps_count.to_int64(), o.cfg_err};
    row.insert(row.end(), outs.begin(), outs.end());
    return row;
}

lx::pso_regs pso_to_hls(const golden::pso_regs& r) {
    lx::pso_regs h;
    h.enable = r.enable;
    h.part_speed = r.part_speed;
    h.axis_mask = r.axis_mask;
    h.win_k = r.win_k;
    h.fire_dist = r.fire_dist;
    h.arr_en = r.arr_en;
    h.arr_len = r.arr_len;
    h.arr_wrap = r.arr_wrap;
    h.arr_we = r.arr_we;
    h.arr_addr = r.arr_addr;
    h.arr_data = r.arr_data;
    h.pulse_w = r.pulse_w;
    h.win_en = r.win_en;
    h.win_src = r.win_src;
    h.win_low = r.win_low;
    h.win_high = r.win_high;
    h.min_period = r.min_period;
    h.clear = r.clear;
    return h;
}

lx::pso_in pso_to_hls(const golden::pso_in& in) {
    lx::pso_in h;
    for (int i = 0; i < 3; ++i) {
        h.step[i] = in.step[i];
        h.pos[i] = in.pos[i];
    }
    h.ps_inc = in.ps_inc;
    return h;
}

std::string pso_compare(const lx::pso::out_t& h, const golden::pso::out& g) {
    std::ostringstream m;
    auto b = [&](const char* n, bool hv, bool gv) {
        if (hv != gv && m.tellp() == 0) m << n << " hls " << hv << " golden " << gv;
    };
    auto i = [&](const char* n, long long hv, long long gv) {
        if (hv != gv && m.tellp() == 0) m << n << " hls " << hv << " golden " << gv;
    };
    b("cfg_err", h.cfg_err, g.cfg_err);
    b("fire", h.fire, g.fire);
    b("emit", h.emit, g.emit);
    b("pulse", h.pulse, g.pulse);
    b("in_win", h.in_win, g.in_win);
    const long double gd = g.dist * 4294967296.0L;
    if (static_cast<long double>(h.dist.to_int64()) != gd && m.tellp() == 0)
        m << "dist hls " << h.dist.to_int64() << " golden " << static_cast<long long>(gd) << " (2^-32 counts)";
    i("idx", static_cast<long long>(h.idx.to_uint()), g.idx);
    b("arr_done", h.arr_done, g.arr_done);
    i("fire_cnt", static_cast<long long>(h.fire_cnt.to_uint64()), g.fire_cnt);
    i("overlap_cnt", static_cast<long long>(h.overlap_cnt.to_uint64()), g.overlap_cnt);
    b("overlap", h.overlap, g.overlap);
    b("overlap_st", h.overlap_st, g.overlap_st);
    b("rate_over", h.rate_over, g.rate_over);
    b("rate_over_st", h.rate_over_st, g.rate_over_st);
    b("spacing_err", h.spacing_err, g.spacing_err);
    b("spacing_st", h.spacing_st, g.spacing_st);
    b("freq_err", h.freq_err, g.freq_err);
    b("freq_st", h.freq_st, g.freq_st);
    b("ps_pulse", h.ps_pulse, g.ps_pulse);
    i("ps_count", h.ps_count.to_int64(), g.ps_count);
    return m.str();
}

// ---- laserax pso ------------------------------------------------------------------------------

const char* const kPsoUsage =
    "usage: laserax pso [options]\n"
    "  --out DIR          output folder (default out)\n"
    "  --dist-um D        firing distance in um, [0, 1310720) (default 10)\n"
    "  --k K              tracking window register 0..31 (legal 1..16, default 16; 1 = per-clock magnitudes)\n"
    "  --pulse-w W        pulse width in clocks, 0..65535 (default 10)\n"
    "  --speed-mm-s V     path speed in mm/s, (0, 7421.875] (default 200)\n"
    "  --laser-khz F      laser pulse frequency limit, 0..1e6 (default 0 = no check)\n"
    "  --window-um LO:HI  output only while x is inside [LO, HI] um, -1e6 <= LO <= HI <= 1e6\n"
    "  --part-speed       track the commanded vector speed (pulse generator) instead of the axes\n"
    "  --cpu N            part-speed counts per mm of the virtual axes, (0, 1e9] (default 12800)\n"
    "  --feed-mm-s V      part-speed commanded feed, 0..1e5 (default: the path speed)\n"
    "  --seed S           sub-count start offset of the axes, 0..1e9 (default 1)\n"
    "  --no-plot          do not call scripts/plot_pso.py\n";

namespace {



}  // namespace

int cmd_pso(const std::vector<std::string>& args, size_t first) {
    std::string out = "out";
    double dist_um = 10, speed = 200, laser_khz = 0, cpu = 12800, feed = -1, seed = 1;
    int k = 16, pulse_w = 10;
    bool part_speed = false, plot = true, window = false;
    double win_lo = 0, win_hi = 0;
    const double speed_max = 0.95 * kClock * kNmPerCount * 1e-6;  // mm/s: < 1 count per call
    const double win_max_um = 1e6;
    cli cl("laserax pso", args, first, kPsoUsage);
    long long seed_i = 1;
    while (cl.next()) {
        if (cl.is("--part-speed")) part_speed = true;
        else if (cl.is("--no-plot")) plot = false;
        else if (cl.is("--out")) cl.get_text(&out);
        else if (cl.is("--window-um")) {
            std::string v;
            if (!cl.value(&v)) break;
            const size_t colon = v.find(':');
            if (colon == std::string::npos || !parse_double(v.substr(0, colon), &win_lo) ||
                !parse_double(v.substr(colon + 1), &win_hi)) {
                cl.error("needs LO:HI in um, not '" + v + "'");
            } else if (!(win_lo >= -win_max_um && win_lo <= win_max_um && win_hi >= -win_max_um &&
                         win_hi <= win_max_um && win_lo <= win_hi)) {
                cl.error(v + " is out of range (allowed -1e6 <= LO <= HI <= 1e6 um)");
            } else {
                window = true;
            }
        } else if (cl.is("--dist-um")) cl.get_real(0.0, 16777216.0 * kNmPerCount / 1000.0, &dist_um, false, true);
        else if (cl.is("--k")) cl.get_int(0, 31, &k);
        else if (cl.is("--pulse-w")) cl.get_int(0, 65535, &pulse_w);
        else if (cl.is("--speed-mm-s")) cl.get_real(0.0, speed_max, &speed, true, false);
        else if (cl.is("--laser-khz")) cl.get_real(0.0, 1e6, &laser_khz);
        else if (cl.is("--cpu")) cl.get_real(0.0, 1e9, &cpu, true, false);
        else if (cl.is("--feed-mm-s")) cl.get_real(0.0, 1e5, &feed);
        else if (cl.is("--seed")) {
            if (cl.get_int(0, 1000000000, &seed_i)) seed = static_cast<double>(seed_i);
        } else cl.unknown();
    }
    if (cl.failed()) return cl.status();
    if (feed < 0) feed = speed;
    // register ranges are checked by the parser above; values inside the range but illegal
    // (e.g. K = 0) are left to the block's configuration check, reported as cfg_err
    const double v_counts = speed * 1e-3 / (kNmPerCount * 1e-9) / kClock;  // counts per call

    // The demo path (counts): a line at 30 degrees, a half circle, a reversal back along a line,
    // a short dwell and a quarter circle the other way round.
    const double start[3] = {0, 0, 0};
    pso_path path(start);
    const double d30[3] = {std::cos(kPi / 6), std::sin(kPi / 6), 0};
    path.line(d30, 2000, v_counts);
    {
        const double u[3] = {std::sin(kPi / 6), -std::cos(kPi / 6), 0};  // centre to the left of travel
        const double w[3] = {d30[0], d30[1], 0};
        path.arc(u, w, 800, kPi, v_counts);
    }
    double dir[3];
    path.end_dir(dir);
    path.line(dir, 600, v_counts);
    const double back[3] = {-dir[0], -dir[1], 0};
    path.line(back, 1200, v_counts);  // reversal
    path.dwell(2000);
    {
        double e[3];
        path.end_dir(e);
        const double u[3] = {-e[1], e[0], 0};
        path.arc(u, e, 500, -kPi / 2, v_counts);
    }

    golden::pso_regs regs;
    regs.enable = true;
    regs.part_speed = part_speed;
    regs.axis_mask = 3;
    regs.win_k = k;
    regs.fire_dist = golden::pso_dist_q32(static_cast<long double>(dist_um) * 1000.0L / 78.125L);
    regs.pulse_w = pulse_w;
    regs.min_period = golden::pso_min_period_clocks(laser_khz * 1e3);
    if (window) {
        regs.win_en = true;
        regs.win_src = 0;
        regs.win_low = static_cast<int64_t>(std::floor(win_lo * 1000.0 / kNmPerCount));
        regs.win_high = static_cast<int64_t>(std::floor(win_hi * 1000.0 / kNmPerCount));
    }
    bool feed_over = false;
    const uint64_t ps_inc = golden::pso_rate_increment(cpu, feed, &feed_over);
    // With part-speed the virtual path length is feed/speed times the real one (same time).
    const double ps_scale = part_speed ? (cpu * 78.125e-6) * (feed / speed) : 1.0;

    if (!make_dirs(out, "laserax pso")) return 2;
    const std::string trace_path = out + "/pso_trace.csv", fires_path = out + "/pso_fires.csv";
    FILE* tr = std::fopen(trace_path.c_str(), "w");
    FILE* fr = std::fopen(fires_path.c_str(), "w");
    if (!tr || !fr) {
        std::fprintf(stderr, "laserax pso: cannot write %s\n", out.c_str());
        if (tr) std::fclose(tr);
        if (fr) std::fclose(fr);
        return 2;
    }
    std::fprintf(tr, "# laserax pso: dist %.4f um, K %d, pulse %d clocks, speed %.3f mm/s, mode %s\n", dist_um, k,
                 pulse_w, speed, part_speed ? "part-speed" : "tracking");
    std::fprintf(tr, "cycle,x_nm,y_nm,pos_x,pos_y,dist_counts,fire,emit,pulse,in_win,fire_cnt\n");
    std::fprintf(fr, "k,cycle,x_nm,y_nm,ideal_x_nm,ideal_y_nm,err_nm,along_nm,emitted\n");

    lx::pso hls;
    golden::pso gold;
    lx::pso_regs hregs = pso_to_hls(regs);
    pso_sampler smp;
    const double off[3] = {std::fmod(seed * 0.6180339887, 1.0), std::fmod(seed * 0.4142135624, 1.0), 0};
    smp.start(path, off);
    const long long calls = static_cast<long long>(std::ceil(path.duration())) + 50;
    std::string mismatch;
    long long fires = 0, emits = 0, rows = 0;
    double err_max = 0, err_sum = 0, err_sq = 0, along_sum = 0;
    const long double thr_counts = static_cast<long double>(regs.fire_dist) / 4294967296.0L;
    bool speed_ok = true;
    lx::pso::out_t last{};
    int prev_key[6] = {-1, -1, -1, -1, -1, -1};
    {   // the registers are presented one call before the motion: they are in force from its
        // first call (register stage, docs/PSO_COUNTERS.md §2.2)
        const golden::pso_in idle;
        const lx::pso::out_t h = hls.step(pso_to_hls(idle), hregs);
        const golden::pso::out g = gold.step(idle, regs);
        const std::string m = pso_compare(h, g);
        if (!m.empty()) mismatch = "register call: " + m;
    }
    for (long long t = 0; t < calls; ++t) {
        golden::pso_in in;
        speed_ok = smp.advance(static_cast<double>(t + 1), in.step) && speed_ok;
        for (int i = 0; i < 3; ++i) in.pos[i] = smp.pos[i];
        in.ps_inc = path.speed_at(static_cast<double>(t)) > 0 ? ps_inc : 0;
        const lx::pso::out_t h = hls.step(pso_to_hls(in), hregs);
        const golden::pso::out g = gold.step(in, regs);
        if (mismatch.empty()) {
            const std::string m = pso_compare(h, g);
            if (!m.empty()) mismatch = "call " + std::to_string(t) + ": " + m;
        }
        last = h;
        double x[3], s = 0;
        path.at_time(static_cast<double>(t + 1), x, &s);
        if (h.fire) {
            ++fires;
            // ideal: the point of the path at k * distance (virtual distance / ps_scale in part-speed)
            const double sk = static_cast<double>(thr_counts * static_cast<long double>(fires)) / ps_scale;
            double ideal[3];
            path.at_length(sk, ideal);
            const double e = std::hypot(x[0] - ideal[0], x[1] - ideal[1]) * kNmPerCount;
            const double along = (s - sk) * kNmPerCount;
            err_max = std::max(err_max, e);
            err_sum += e;
            err_sq += e * e;
            along_sum += along;
            if (h.emit) ++emits;
            std::fprintf(fr, "%lld,%lld,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%d\n", fires, t, x[0] * kNmPerCount,
                         x[1] * kNmPerCount, ideal[0] * kNmPerCount, ideal[1] * kNmPerCount, e, along, h.emit ? 1 : 0);
        }
        const int key[6] = {static_cast<int>(smp.pos[0] & 0x7fffffff), static_cast<int>(smp.pos[1] & 0x7fffffff),
                            h.fire ? 1 : 0, h.emit ? 1 : 0, h.pulse ? 1 : 0, h.in_win ? 1 : 0};
        if (!std::equal(key, key + 6, prev_key)) {
            std::copy(key, key + 6, prev_key);
            std::fprintf(tr, "%lld,%.3f,%.3f,%lld,%lld,%.6f,%d,%d,%d,%d,%llu\n", t, x[0] * kNmPerCount,
                         x[1] * kNmPerCount, static_cast<long long>(smp.pos[0]), static_cast<long long>(smp.pos[1]),
                         static_cast<double>(h.dist.to_int64()) / kQ32, h.fire ? 1 : 0, h.emit ? 1 : 0,
                         h.pulse ? 1 : 0, h.in_win ? 1 : 0, static_cast<unsigned long long>(h.fire_cnt.to_uint64()));
            ++rows;
        }
    }
    std::fclose(tr);
    std::fclose(fr);

    const double max_feed = golden::pso_max_feed(cpu);
    std::printf("laserax pso: %s mode, path %.1f um (%.0f counts: line, half circle r=800, line, reversal, dwell, "
                "quarter circle r=500) at %.1f mm/s (%.4f counts/clock)\n",
                part_speed ? "part-speed" : "tracking", path.length() * kNmPerCount / 1000.0, path.length(), speed,
                v_counts);
    std::printf("  %-34s %.4f um = %.6f counts (register 0x%llX, Q24.32)\n", "firing distance", dist_um,
                static_cast<double>(thr_counts), static_cast<unsigned long long>(regs.fire_dist));
    std::printf("  %-34s %d counts%s\n", "tracking window K", k, k == 1 ? " (per-clock step magnitudes)" : "");
    std::printf("  %-34s %d clocks (%.0f ns)\n", "pulse width", pulse_w, pulse_w * 10.0);
    if (window) std::printf("  %-34s x in [%lld, %lld] counts\n", "window", static_cast<long long>(regs.win_low),
                            static_cast<long long>(regs.win_high));
    if (part_speed || laser_khz > 0) {
        std::printf("  %-34s %.1f mm/s (24 MHz / %.0f counts per mm)\n", "max feed rate (part-speed)", max_feed, cpu);
        if (part_speed)
            std::printf("  %-34s %.3f mm/s -> %.4f counts/clock (inc %llu)%s\n", "commanded feed", feed,
                        static_cast<double>(ps_inc) / kQ32, static_cast<unsigned long long>(ps_inc),
                        feed_over ? "  ABOVE THE 24 MHz LIMIT: clamped, rate_over" : "");
        if (laser_khz > 0)
            std::printf("  %-34s %.4f um at %.3f mm/s, %.3f kHz (min period %d clocks)%s\n", "min spacing",
                        golden::pso_min_spacing(feed, laser_khz * 1e3) * 1000.0, feed, laser_khz, regs.min_period,
                        golden::pso_min_spacing(feed, laser_khz * 1e3) * 1000.0 > dist_um ? "  > firing distance!" : "");
    }
    std::printf("\n  %-34s %lld fires, %lld pulses emitted (fire_cnt %llu), overlaps %llu\n", "result", fires, emits,
                static_cast<unsigned long long>(last.fire_cnt.to_uint64()),
                static_cast<unsigned long long>(last.overlap_cnt.to_uint64()));
    if (fires > 0)
        std::printf("  %-34s max %.1f nm, mean %.1f nm, rms %.1f nm; mean along-path %.1f nm\n",
                    "firing position error vs ideal", err_max, err_sum / static_cast<double>(fires),
                    std::sqrt(err_sq / static_cast<double>(fires)), along_sum / static_cast<double>(fires));
    std::printf("  %-34s overlap %d, rate_over %d, spacing %d, laser frequency %d, cfg_err %d\n", "flags (sticky)",
                last.overlap_st ? 1 : 0, last.rate_over_st ? 1 : 0, last.spacing_st ? 1 : 0, last.freq_st ? 1 : 0,
                last.cfg_err ? 1 : 0);
    if (last.cfg_err) std::printf("  configuration rejected by the block (cfg_err): no pulses\n");
    std::printf("  %-34s %s\n", "hls vs golden", mismatch.empty() ? "bit-exact on every clock" : mismatch.c_str());
    if (!speed_ok) std::printf("  warning: an axis moved more than one count in a clock\n");
    std::printf("  wrote %s (%lld rows), %s\n", trace_path.c_str(), rows, fires_path.c_str());
    if (plot) {
        const std::string py = "/usr/bin/python3";
        struct stat st;
        if (stat(py.c_str(), &st) == 0) {
            const std::string c = py + " scripts/plot_pso.py pso " + trace_path + " " + fires_path + " " + out + "/pso.png";
            std::fflush(stdout);
            if (std::system(c.c_str()) == 0) std::printf("  wrote %s/pso.png\n", out.c_str());
            else std::printf("  plot skipped (scripts/plot_pso.py failed; needs matplotlib: run `make deps`)\n");
        } else {
            std::printf("  plot skipped: /usr/bin/python3 not found\n");
        }
    }
    return mismatch.empty() && last.cfg_err == false ? 0 : 1;
}

}  // namespace lxt
