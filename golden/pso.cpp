// golden/pso.cpp — see pso.h (docs/PSO_COUNTERS.md §2).
#include "golden/pso.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace golden {

namespace {

constexpr long double kQ = 4294967296.0L;  // 2^32

long double counts(uint64_t q32) { return static_cast<long double>(q32) / kQ; }

int sgn(int64_t v) { return (v > 0) - (v < 0); }

}  // namespace

pso::pso() : ram_(kArrDepth, 0), ram_m2_(kArrDepth, 0), ram_m3_(kArrDepth, 0), ram_g3_(kArrDepth, 0) { reset(); }

uint64_t pso::inc_max() { return static_cast<uint64_t>(floorl(kPulseHzMax * kQ / kClockHz)); }

uint64_t pso::chord_q32(int64_t s) {
    // sqrt in long double, rounded to nearest, then made exact: r is the nearest integer to
    // sqrt(s) * 2^32 iff (2r - 1)^2 <= 4 s 2^64 < (2r + 1)^2 (no ties: the value is an integer or
    // irrational).
    __extension__ typedef unsigned __int128 u128;
    uint64_t r = static_cast<uint64_t>(llroundl(sqrtl(static_cast<long double>(s)) * kQ));
    const u128 x4 = static_cast<u128>(s) << 66;
    for (int guard = 0; guard < 4; ++guard) {
        const u128 lo = r == 0 ? 0 : static_cast<u128>(2 * r - 1) * (2 * r - 1);
        const u128 hi = static_cast<u128>(2 * r + 1) * (2 * r + 1);
        if (x4 < lo) --r;
        else if (x4 >= hi) ++r;
        else break;
    }
    return r;
}

bool pso::config_ok(const pso_regs& r) const {
    const bool k_ok = r.win_k >= 1 && r.win_k <= kMaxK;
    const bool axes_ok = r.part_speed || (r.axis_mask & 7u) != 0;
    bool thr_ok;
    if (r.arr_en) {
        thr_ok = r.arr_len >= 1 && r.arr_len <= kArrDepth;
        for (int j = 0; thr_ok && j < r.arr_len; ++j) thr_ok = counts(ram_[static_cast<size_t>(j)]) >= kMinDist;
    } else {
        thr_ok = counts(r.fire_dist) >= kMinDist;
    }
    const bool src_ok = (r.win_src >= 0 && r.win_src <= 2) || (r.win_src == 3 && r.part_speed);
    const bool win_ok = !r.win_en || (r.win_low <= r.win_high && src_ok);
    return k_ok && axes_ok && thr_ok && win_ok && r.pulse_w >= 1;
}

void pso::reset_run() {
    running_ = false;
    ps_ = arr_en_ = arr_wrap_ = false;
    mask_ = 0;
    arr_len_ = 1;
    t_ = 0;
    for (int i = 0; i < kAxes; ++i) p_[i] = s_[i] = 0;
    closed_ = phi_ = fired_ = frozen_ = thr_ = 0;
    for (int k = 0; k < kFireLat; ++k) {
        est_hist_[k] = 0;
        inwin_hist_[k] = false;
    }
    fd_m1_ = fd_m2_ = fd_m3_ = 0;
    sp_pending_ = false;
    ps_count_ = 0;
    idx_ = 0;
    done_ = false;
    fired_last_ = false;
    have_emit_ = false;
    last_emit_ = 0;
    last_w_ = 0;
}

void pso::reset() {
    reset_run();
    fire_cnt_ = 0;
    ovl_cnt_ = 0;
    overlap_st_ = rate_over_st_ = spacing_st_ = freq_st_ = false;
}

pso::out pso::step(const pso_in& in, const pso_regs& presented) {
    // register stage: this call works with the values presented in the previous call
    const pso_regs r = force_;
    force_ = presented;
    // the RAM as it stood after call t-3 (a fire of this call takes the next threshold from it)
    ram_g3_ = ram_m3_;
    ram_m3_ = ram_m2_;  // the RAM after call t-2: "after call n-3" of the next call
    ram_m2_ = ram_;     // the RAM after the previous call
    if (r.arr_we) ram_[static_cast<size_t>(r.arr_addr) % kArrDepth] = r.arr_data;
    out o;
    if (!config_ok(r)) {
        reset();
        o.cfg_err = true;
        return o;
    }
    if (r.clear) {
        overlap_st_ = rate_over_st_ = spacing_st_ = freq_st_ = false;
        ovl_cnt_ = 0;
    }
    if (!r.enable) reset_run();
    if (r.enable) {
        if (!running_) {
            running_ = true;
            ps_ = r.part_speed;
            mask_ = r.axis_mask & 7u;
            arr_en_ = r.arr_en;
            arr_len_ = r.arr_len;
            arr_wrap_ = r.arr_wrap;
        }
        const int64_t t = t_;
        // the start of the run takes the first threshold: fire_dist of this call, or entry 0 as
        // the RAM stands after this call's write
        if (t == 0) thr_ = arr_en_ ? counts(ram_[0]) : counts(r.fire_dist);
        const long double est_old = est_hist_[kFireLat - 1];  // est(t - 7)

        // ---- fire on the estimate of call t - 7 ----
        const bool was_done = done_;
        // (no fire in the call after a fire: with every threshold >= kMinDist > 2 sqrt3 the
        // estimate cannot reach two thresholds in two calls, so this never acts on a legal
        // configuration; it defines the block when a run's latched array holds an entry below
        // kMinDist, docs/PSO_COUNTERS.md §2.7)
        o.fire = t >= kFireLat && !done_ && !fired_last_ && est_old - fired_ >= thr_;
        fired_last_ = o.fire;
        if (o.fire) {
            fired_ += thr_;
            if (arr_en_) {
                if (idx_ + 1 >= arr_len_) {
                    if (arr_wrap_) idx_ = 0;
                    else done_ = true;
                } else {
                    ++idx_;
                }
            }
            if (done_) {
                frozen_ = est_old - fired_;
            } else {
                // the threshold of the next fire, taken at this fire: fire_dist of call t-3, or
                // the entry of the next index as the RAM stood after call t-3
                thr_ = arr_en_ ? counts(ram_g3_[static_cast<size_t>(idx_)]) : counts(fd_m3_);
            }
        }
        o.dist = was_done ? frozen_ : est_old - fired_;
        o.in_win = inwin_hist_[kFireLat - 1];
        o.emit = o.fire && o.in_win;
        const bool pulse_before = have_emit_ && (t - 1) - last_emit_ < last_w_;
        if (o.emit) {
            o.overlap = pulse_before;
            o.freq_err = r.min_period != 0 && have_emit_ && t - last_emit_ < r.min_period;
            have_emit_ = true;
            last_emit_ = t;
            last_w_ = r.pulse_w;
            ++fire_cnt_;
        }
        o.pulse = have_emit_ && t - last_emit_ < last_w_;
        if (o.overlap) {
            overlap_st_ = true;
            if (ovl_cnt_ < 65535) ++ovl_cnt_;
        }
        if (o.freq_err) freq_st_ = true;
        // the threshold of the next fire as it stands after this call's fire (spacing sample)
        const long double thr_now = thr_;

        // ---- this call's motion ----
        long double est;
        if (ps_) {
            const uint64_t inc = in.ps_inc;
            o.rate_over = inc > inc_max();
            const uint64_t inc_eff = o.rate_over ? inc_max() : inc;
            const long double before = floorl(phi_);
            phi_ += counts(inc_eff);
            o.ps_pulse = floorl(phi_) > before;
            if (o.ps_pulse) ++ps_count_;
            if (t % kSpLat == 0) {  // sample call: the result of the previous sample, a new sample
                o.spacing_err = t >= kSpLat && sp_pending_;
                sp_pending_ = r.min_period != 0 && thr_now < counts(inc_eff) * static_cast<long double>(r.min_period);
            }
            est = floorl(phi_);
        } else {
            int d[kAxes];
            bool rev = false;
            for (int i = 0; i < kAxes; ++i) {
                d[i] = ((mask_ >> i) & 1u) ? in.step[i] : 0;
                const int64_t open = p_[i] - s_[i];
                if (d[i] != 0 && open != 0 && sgn(d[i]) != sgn(open)) rev = true;
            }
            auto close_window = [&]() {
                int64_t s2 = 0;
                for (int i = 0; i < kAxes; ++i) s2 += (p_[i] - s_[i]) * (p_[i] - s_[i]);
                closed_ += counts(chord_q32(s2));
                for (int i = 0; i < kAxes; ++i) s_[i] = p_[i];
            };
            if (rev) close_window();  // at the position before the reversing step
            int64_t span = 0;
            for (int i = 0; i < kAxes; ++i) {
                p_[i] += d[i];
                span = std::max<int64_t>(span, std::llabs(p_[i] - s_[i]));
            }
            if (span >= r.win_k) close_window();
            int64_t s2 = 0;
            for (int i = 0; i < kAxes; ++i) s2 += (p_[i] - s_[i]) * (p_[i] - s_[i]);
            est = closed_ + counts(chord_q32(s2));
        }
        if (o.rate_over) rate_over_st_ = true;
        if (o.spacing_err) spacing_st_ = true;
        bool inwin = true;
        if (r.win_en) {
            const int64_t wp = r.win_src == 3 ? ps_count_ : in.pos[r.win_src];
            inwin = r.win_low <= wp && wp <= r.win_high;
        }
        for (int k = kFireLat - 1; k > 0; --k) {
            est_hist_[k] = est_hist_[k - 1];
            inwin_hist_[k] = inwin_hist_[k - 1];
        }
        est_hist_[0] = est;
        inwin_hist_[0] = inwin;
        fd_m3_ = fd_m2_;
        fd_m2_ = fd_m1_;
        fd_m1_ = r.fire_dist;
        ++t_;
    }
    o.idx = idx_;
    o.arr_done = done_;
    o.fire_cnt = fire_cnt_;
    o.overlap_cnt = ovl_cnt_;
    o.overlap_st = overlap_st_;
    o.rate_over_st = rate_over_st_;
    o.spacing_st = spacing_st_;
    o.freq_st = freq_st_;
    o.ps_count = ps_count_;
    return o;
}

// ---- helpers --------------------------------------------------------------------------------

double pso_max_feed(double counts_per_unit, double pulse_hz) { return pulse_hz / counts_per_unit; }

double pso_min_spacing(double feed_units_per_s, double laser_hz) { return feed_units_per_s / laser_hz; }

double pso_vector_speed(double vx, double vy, double vz) { return std::sqrt(vx * vx + vy * vy + vz * vz); }

uint64_t pso_rate_increment(double counts_per_unit, double feed_units_per_s, bool* over, double clock_hz) {
    const long double rate = static_cast<long double>(counts_per_unit) * static_cast<long double>(feed_units_per_s);
    const long double inc = rate / static_cast<long double>(clock_hz) * kQ;
    if (over) *over = rate > 24e6L;
    if (inc <= 0) return 0;
    if (inc >= kQ) return static_cast<uint64_t>(kQ) - 1;  // register is Q0.32
    return static_cast<uint64_t>(llroundl(inc));
}

int pso_min_period_clocks(double laser_hz, double clock_hz) {
    if (laser_hz <= 0) return 0;
    return static_cast<int>(std::ceil(clock_hz / laser_hz - 1e-9));
}

uint64_t pso_dist_q32(long double c) { return static_cast<uint64_t>(llroundl(c * kQ)); }

std::vector<uint64_t> pso_array_from_positions(const std::vector<long double>& positions) {
    std::vector<uint64_t> out;
    uint64_t prev = 0;
    for (long double p : positions) {
        const uint64_t q = pso_dist_q32(p);
        out.push_back(q - prev);
        prev = q;
    }
    return out;
}

}  // namespace golden
