// golden/encoder_counter.cpp — see encoder_counter.h (docs/PSO_COUNTERS.md §3).
#include "golden/encoder_counter.h"

#include <Eigen/Dense>
#include <cmath>

namespace golden {

namespace {
constexpr long double kQ = 4294967296.0L;  // 2^32
constexpr int64_t k2p32 = 4294967296LL;
constexpr int64_t k2p31 = 2147483648LL;
}  // namespace

int64_t wrap_s32(int64_t v) {
    int64_t m = v % k2p32;
    if (m < 0) m += k2p32;
    return m >= k2p31 ? m - k2p32 : m;
}

int64_t counter_diff(int64_t a, int64_t b) { return wrap_s32(b - a); }

bool encoder_counter::config_ok(const encoder_counter_regs& r) {
    bool ok = r.corr_period >= kEncoderCorrLatency;
    for (int c = 0; c < 2; ++c) {
        ok = ok && (r.src[c] == 0 || r.src[c] == 1);
        // simulation counting rate at most 25 MHz (0.25 count per clock)
        ok = ok && (r.src[c] != 1 || static_cast<long double>(r.sim_inc[c]) / kQ * 100e6L <= 25e6L);
    }
    return ok;
}

void encoder_counter::reset() { *this = encoder_counter{}; }

encoder_counter::out encoder_counter::step(const encoder_counter_in& in, const encoder_counter_regs& r) {
    out o;
    if (!config_ok(r)) {
        reset();
        o.cfg_err = true;
        return o;
    }
    // sample: corr_period calls after the previous sample (the first at call corr_period - 1);
    // the value is shown, with tick, kEncoderCorrLatency calls after its sample call
    if (t_ == due_) {
        o.tick = true;
        corr_[0] = pend_[0];
        corr_[1] = pend_[1];
        due_ = -1;
    }
    // (a sample while an earlier one is not yet shown is dropped: the earlier one is shown)
    if (t_ - last_tick_ >= r.corr_period) {
        last_tick_ = t_;
        if (due_ < 0) {
            due_ = t_ + kEncoderCorrLatency;
            for (int c = 0; c < 2; ++c) {
                const long double prod = static_cast<long double>(r.scale[c]) * static_cast<long double>(wrap_s32(u_[c]));
                pend_[c] = in.pos[c] + static_cast<int64_t>(floorl(prod / 16777216.0L + 0.5L));  // round half up
            }
        }
    }
    ++t_;
    // wait: reported two calls after the counter passes the value. The judgement of this call
    // is about the counter as it was after call t-2 against the value latched before call t-1
    // (none if an arm came in call t-1): judged_ holds it, computed in the previous call.
    if (waiting_ && judged_ok_) {
        o.reached = w_down_ ? judged_diff_ < 0 : judged_diff_ > 0;
        if (o.reached) waiting_ = false;
    }
    judged_diff_ = counter_diff(w_val_, wrap_s32(u_[w_ch_]));  // counter after the previous call
    judged_ok_ = !r.wait_arm;
    for (int c = 0; c < 2; ++c) {
        // simulation: one count per integer crossed by the commanded count, in the call after
        // the crossing
        const int sim = sim_due_[c] ? (r.sim_down[c] ? -1 : 1) : 0;
        const long double before = floorl(phi_[c]);
        phi_[c] += static_cast<long double>(r.sim_inc[c]) / kQ;
        sim_due_[c] = floorl(phi_[c]) > before;
        int st = r.src[c] == 1 ? sim : in.qstep[c];
        // reset now, or at the first start trigger after the request
        const bool now = r.rst_req[c] && !r.rst_on_trig;
        const bool at_trig = pending_[c] && in.trig;
        if (at_trig) pending_[c] = false;
        if (r.rst_req[c] && r.rst_on_trig) pending_[c] = true;
        if (now || at_trig) {
            u_[c] = 0;
            phi_[c] = 0;
            sim_due_[c] = false;
            st = 0;
        } else if (r.load[c]) {
            u_[c] = r.load_val[c];
            st = 0;
        } else {
            u_[c] += st;
        }
        o.step[c] = st;
        o.rst_done[c] = now || at_trig;
        o.rst_pending[c] = pending_[c];
        o.cnt[c] = wrap_s32(u_[c]);
        o.corr[c] = corr_[c];
    }
    if (r.wait_arm) {
        waiting_ = true;
        w_ch_ = r.wait_ch ? 1 : 0;
        w_val_ = wrap_s32(r.wait_val);
        w_down_ = r.wait_down;
    }
    o.waiting = waiting_;
    return o;
}

// ---- calibration helpers --------------------------------------------------------------------

linear_fit encoder_increment_fit(const std::vector<double>& pos_mm, const std::vector<int64_t>& readings) {
    const size_t n = pos_mm.size();
    if (readings.size() != n) {
        linear_fit f;
        f.error = "position and reading counts differ";
        return f;
    }
    Eigen::VectorXd x(static_cast<Eigen::Index>(n)), y(static_cast<Eigen::Index>(n));
    int64_t unwrapped = 0;
    for (size_t k = 0; k < n; ++k) {
        if (k > 0) unwrapped += counter_diff(readings[k - 1], readings[k]);
        x(static_cast<Eigen::Index>(k)) = pos_mm[k];
        y(static_cast<Eigen::Index>(k)) = static_cast<double>(unwrapped);
    }
    return fit_scale_offset(x, y);
}

double encoder_scale_at_rate(double k_bits_per_mm, double v_mm_per_s, double rate_counts_per_s) {
    return k_bits_per_mm * v_mm_per_s / rate_counts_per_s;
}

int64_t encoder_scale_to_q(double scale, bool* ok) {
    const long double q = static_cast<long double>(scale) * 16777216.0L;
    const long double r = q < 0 ? -floorl(-q + 0.5L) : floorl(q + 0.5L);
    const bool in_range = std::isfinite(scale) && r >= -2147483648.0L && r <= 2147483647.0L;
    if (ok) *ok = in_range;
    if (!in_range) return 0;
    return static_cast<int64_t>(r);
}

uint64_t encoder_sim_inc(double counts_per_s, double clock_hz) {
    const long double inc = static_cast<long double>(counts_per_s) / static_cast<long double>(clock_hz) * kQ;
    return static_cast<uint64_t>(floorl(inc + 0.5L));
}

}  // namespace golden
