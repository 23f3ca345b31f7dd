// gantry.cpp — see gantry.h and docs/GANTRY.md.
#include "sysmodel/gantry.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include "hls/laserax_top.h"
#include "sysmodel/sim.h"

namespace lxt {

namespace {

constexpr double kTwoPi = 6.283185307179586;

int64_t floor_div(int64_t a, int64_t b) {
    int64_t q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
    return q;
}

int iabs(int v) { return v < 0 ? -v : v; }

// ---- setpoint generator: velocity and acceleration limited move to a target ---------------------
struct trajectory {
    double s = 0, v = 0, target = 0, vmax = 0.25, amax = 1.0 / 1024;
    bool active = false;

    void start(double from, double vel, double to, double vm, double am) {
        s = from;
        v = vel;
        target = to;
        vmax = vm;
        amax = am;
        active = true;
    }
    void retarget(double to) {
        target = to;
        active = true;
    }
    void step() {
        if (!active) {
            v = 0;
            return;
        }
        const double dist = target - s;
        if (std::fabs(dist) < 1e-9) {
            s = target;
            v = 0;
            active = false;
            return;
        }
        const double dir = dist > 0 ? 1.0 : -1.0;
        const double vd = dir * std::min(vmax, std::sqrt(2.0 * amax * std::fabs(dist)));
        v += std::max(-amax, std::min(amax, vd - v));
        if (v * dir >= std::fabs(dist)) v = dist;  // lands on the target in this call
        s += v;
    }
};

// ---- controller model ---------------------------------------------------------------------------
// Inputs per call: the sin/cos codes and reference mark of each axis (what arrives at the
// controller's encoder inputs) and the compensators' alarm status bit. Outputs: a velocity command
// per drive (counts per call) and the rehome/clear register writes.
struct axis_feedback {
    int64_t sin = 0, cos = 0;
    bool mark = false, alarm = false;
};

struct axis_command {
    double v = 0;
    bool rehome = false, clear = false;
};

enum step_id {
    st_powerup = 0,
    st_clear,
    st_lock,
    st_search1,
    st_clear1,
    st_backoff,
    st_search2,
    st_clear2,
    st_park,
    st_check,
    st_deskew,
    st_done,
    st_fail,
    st_count
};

const char* const kStepNames[st_count] = {"power-up",    "clear",          "lock",
                                          "X1 search",   "X1 clearance",   "back off",
                                          "X2 search",   "X2 clearance",   "park (X1 master)",
                                          "skew check",  "deskew (X2)",    "done",
                                          "failed"};

class gantry_controller {
public:
    explicit gantry_controller(const gantry_config& c) : c_(c) {
        limit_ = c.skew_limit < 0 ? c.period : c.skew_limit;
        const int ad = iabs(c.switch_offset);
        const int p = c.period;
        search_len_ = 4 * p + 4 * ad + 64;
        clearance_ = p + ad + p / 8;
        backoff_ = p + p / 4 + p + ad + p / 8 + 4;
        for (int i = 0; i < 2; ++i) ip_[i].reset(c.period, c.resolution);
    }

    int step_id() const { return st_; }
    bool finished() const { return st_ == st_done || st_ == st_fail; }
    bool failed() const { return st_ == st_fail; }
    const std::string& error() const { return error_; }
    bool homed(int i) const { return homed_[i]; }
    int64_t measured(int i) const { return ip_[i].counts(); }
    int64_t ctrl(int i) const { return homed_[i] ? ip_[i].counts() - home_[i] : ip_[i].counts(); }
    double setpoint(int i) const { return sp_[i]; }
    bool skew_alarm() const { return skew_alarm_; }
    bool checked() const { return checked_; }
    int64_t skew_check() const { return skew_check_; }
    int64_t latch_sin(int i) const { return latch_sin_[i]; }
    int64_t latch_cos(int i) const { return latch_cos_[i]; }
    bool latch_mark(int i) const { return latch_mark_[i]; }
    // A settled step asks for a table row (kind, name); cleared by take_row().
    int row_kind() const { return row_kind_; }
    const std::string& row_name() const { return row_name_; }
    void take_row() { row_kind_ = -1; }

    // Interpolators: every call, also while the machine powers up.
    void sense(const axis_feedback fb[2]) {
        for (int i = 0; i < 2; ++i) {
            fb_[i] = fb[i];
            if (!ip_[i].feed(fb[i].sin, fb[i].cos) && st_ != st_fail) fail("X" + std::to_string(i + 1) + ": sin/cos phase jumped by more than a quarter period");
        }
    }

    // Sequence and position loops, once the lasers are ready.
    void step(axis_command cmd[2]) {
        for (int i = 0; i < 2; ++i) {
            cmd[i] = axis_command{};
            cmd[i].rehome = hold_rehome_[i];
        }
        if (st_ == st_powerup) enter(st_clear, cmd);
        switch (st_) {
            case st_clear:
                if (--timer_ <= 0) {
                    if (fb_[0].alarm || fb_[1].alarm) {
                        fail("compensator alarm still set after clear");
                        break;
                    }
                    enter(st_lock, cmd);
                }
                break;
            case st_search1:
            case st_search2: {
                const int k = st_ == st_search1 ? 0 : 1;
                if (ip_[k].crossed() && fb_[k].mark) {
                    // home: reference mark active and the phase at P/8 (sin == cos > 0)
                    home_[k] = ip_[k].to_counts(ip_[k].crossing());
                    homed_[k] = true;
                    latch_sin_[k] = fb_[k].sin;
                    latch_cos_[k] = fb_[k].cos;
                    latch_mark_[k] = fb_[k].mark;
                    tr_[k].retarget(static_cast<double>(home_[k] + clearance_));
                    st_ = k == 0 ? st_clear1 : st_clear2;
                } else if (!tr_[k].active) {
                    fail("X" + std::to_string(k + 1) + ": no home (reference mark with sin == cos) found");
                }
                break;
            }
            case st_clear1:
            case st_clear2: {
                const int k = st_ == st_clear1 ? 0 : 1;
                if (!tr_[k].active && settled()) {
                    request_row(k == 0 ? gantry_row::x1_homed : gantry_row::x2_homed,
                                k == 0 ? "X1 homed (master), X2 tracking" : "X2 homed (master), X1 tracking");
                    enter(k == 0 ? st_backoff : st_park, cmd);
                }
                break;
            }
            case st_lock:
            case st_backoff:
            case st_park:
            case st_deskew:
                if (settled()) {
                    if (st_ == st_lock) {
                        request_row(gantry_row::lock, "lasers ready, axes locked");
                        enter(st_search1, cmd);
                    } else if (st_ == st_backoff) {
                        request_row(gantry_row::backoff, "backed off behind the switches");
                        hold_rehome_[0] = hold_rehome_[1] = false;
                        cmd[0].rehome = cmd[1].rehome = false;
                        enter(st_search2, cmd);
                    } else if (st_ == st_park) {
                        request_row(gantry_row::park, "X1 master again, at its home");
                        enter(st_check, cmd);
                    } else {
                        request_row(gantry_row::deskewed, "deskewed (X2 moved alone)");
                        st_ = st_done;
                    }
                }
                break;
            case st_check:
                // (the row of the park step is recorded in this call; the check row in the next)
                if (row_kind_ < 0) {
                    checked_ = true;
                    skew_check_ = ctrl(0) - ctrl(1);
                    skew_alarm_ = std::llabs(skew_check_ - c_.offset) > limit_;
                    request_row(gantry_row::check, skew_alarm_ ? "skew check: ALARM, outside the limit" : "skew check: within the limit");
                    if (skew_alarm_) st_ = st_done;
                    else enter(st_deskew, cmd);
                }
                break;
            default:
                break;
        }
        servo(cmd);
    }

    void fail(const std::string& why) {
        if (st_ != st_fail) error_ = why;
        st_ = st_fail;
    }

private:
    enum mode_t { m_hold, m_traj, m_follow };

    void request_row(int kind, const std::string& name) {
        row_kind_ = kind;
        row_name_ = name;
    }

    // The setpoint in use now (the position loop's reference), as an integer hold value.
    void hold_here(int i) {
        mode_[i] = m_hold;
        hold_[i] = std::round(sp_[i]);
        tr_[i].active = false;
    }
    void move(int i, double target, double vmax) {
        const double from = mode_[i] == m_traj ? tr_[i].s : sp_[i];
        const double vel = mode_[i] == m_traj ? tr_[i].v : 0.0;
        mode_[i] = m_traj;
        tr_[i].start(from, vel, target, vmax, c_.a_max);
    }
    void follow(int slave, int master) {
        mode_[slave] = m_follow;
        master_[slave] = master;
        base_self_[slave] = static_cast<int64_t>(std::llround(sp_[slave]));
        base_master_[slave] = ip_[master].counts();
        tr_[slave].active = false;
    }

    void enter(int st, axis_command cmd[2]) {
        st_ = st;
        settle_count_ = 0;
        switch (st) {
            case st_clear:
                cmd[0].clear = cmd[1].clear = true;
                timer_ = 32;
                break;
            case st_lock:
                servo_on_ = true;
                for (int i = 0; i < 2; ++i) {
                    sp_[i] = static_cast<double>(ip_[i].counts());
                    hold_here(i);
                }
                break;
            case st_search1:
            case st_search2: {
                const int k = st == st_search1 ? 0 : 1, o = 1 - k;
                // arm the compensators for this homing pass (rehome register pulses)
                cmd[k].rehome = true;
                if (c_.arm == golden::gantry_arm::both) cmd[o].rehome = true;
                if (c_.arm == golden::gantry_arm::hold && !homed_[o]) {
                    hold_rehome_[o] = true;
                    cmd[o].rehome = true;
                }
                move(k, sp_[k] + static_cast<double>(search_len_), c_.v_home);
                follow(o, k);
                break;
            }
            case st_backoff:  // pass 1's master (X1) leads the locked move back
                move(0, static_cast<double>(home_[0] - backoff_), c_.v_max);
                follow(1, 0);
                break;
            case st_park:  // X1 master again: to its home, X2 tracking
                move(0, static_cast<double>(home_[0]), c_.v_max);
                follow(1, 0);
                break;
            case st_deskew:  // X1 holds, X2 alone until ctrl1 - ctrl2 == offset
                hold_here(0);
                move(1, static_cast<double>(home_[1] + ctrl(0) - c_.offset), c_.v_max);
                break;
            default:
                break;
        }
    }

    bool settled() const { return settle_count_ >= c_.settle_calls; }

    void servo(axis_command cmd[2]) {
        double ff[2] = {0, 0};
        // own references first (trajectories, holds), then the tracking axes
        for (int pass = 0; pass < 2; ++pass) {
            for (int i = 0; i < 2; ++i) {
                if ((mode_[i] == m_follow) != (pass == 1)) continue;
                if (mode_[i] == m_hold) {
                    sp_[i] = hold_[i];
                } else if (mode_[i] == m_traj) {
                    tr_[i].step();
                    sp_[i] = tr_[i].s;
                    ff[i] = tr_[i].v;
                } else {
                    const int m = master_[i];
                    sp_[i] = static_cast<double>(base_self_[i] + (ip_[m].counts() - base_master_[i]));
                    ff[i] = ff[m];
                }
            }
        }
        bool still = true;
        for (int i = 0; i < 2; ++i) {
            if (!servo_on_) {  // before the lock the drives are not under laser feedback
                cmd[i].v = 0;
                continue;
            }
            const double e = sp_[i] - static_cast<double>(ip_[i].counts());
            double v = ff[i] + c_.kv * e;
            v = std::max(-c_.v_drive, std::min(c_.v_drive, v));
            cmd[i].v = v;
            if ((mode_[i] == m_traj && tr_[i].active) || std::fabs(e) > 1e-9 || ff[i] != 0.0) still = false;
        }
        settle_count_ = still ? settle_count_ + 1 : 0;
    }

    gantry_config c_;
    int limit_ = 0;
    int64_t search_len_ = 0, clearance_ = 0, backoff_ = 0;
    sincos_interpolator ip_[2];
    axis_feedback fb_[2];
    int st_ = st_powerup;
    std::string error_;
    int timer_ = 0;
    int settle_count_ = 0;
    bool homed_[2] = {false, false};
    int64_t home_[2] = {0, 0};
    bool hold_rehome_[2] = {false, false};
    mode_t mode_[2] = {m_hold, m_hold};
    double sp_[2] = {0, 0}, hold_[2] = {0, 0};
    trajectory tr_[2];
    int master_[2] = {0, 0};
    int64_t base_self_[2] = {0, 0}, base_master_[2] = {0, 0};
    int64_t latch_sin_[2] = {0, 0}, latch_cos_[2] = {0, 0};
    bool latch_mark_[2] = {false, false};
    bool servo_on_ = false;
    bool checked_ = false, skew_alarm_ = false;
    int64_t skew_check_ = 0;
    int row_kind_ = -1;
    std::string row_name_;
};

}  // namespace

// ---- interpolator ------------------------------------------------------------------------------

void sincos_interpolator::reset(int period, int resolution) {
    period_ = period;
    res_ = resolution;
    primed_ = crossed_ = false;
    u_ = 0;
    units_ = crossing_ = 0;
}

bool sincos_interpolator::feed(int64_t sin_code, int64_t cos_code) {
    crossed_ = false;
    if (sin_code == 0 && cos_code == 0) return true;  // no signal
    const double ang = std::atan2(static_cast<double>(sin_code), static_cast<double>(cos_code));
    long u = std::lround(ang / kTwoPi * res_);
    u %= res_;
    if (u < 0) u += res_;
    const int ui = static_cast<int>(u);
    if (!primed_) {
        primed_ = true;
        u_ = ui;
        units_ = ui;
        return true;
    }
    int du = ui - u_;
    if (du >= res_ / 2) du -= res_;
    if (du < -res_ / 2) du += res_;
    const bool ok = du <= res_ / 4 && du >= -res_ / 4;
    const int h = res_ / 8;  // phase P/8: sin == cos > 0
    if (du > 0 && u_ < h && ui >= h) {
        crossed_ = true;
        crossing_ = units_ + du - (ui - h);
    }
    units_ += du;
    u_ = ui;
    return ok;
}

int64_t sincos_interpolator::to_counts(int64_t units) const {
    return floor_div(2 * units * period_ + res_, 2 * static_cast<int64_t>(res_));
}

// ---- set-up ------------------------------------------------------------------------------------

std::string gantry_check(const gantry_config& c) {
    if (c.period < 8 || c.period > 4096 || c.period % 8 != 0) return "period must be 8..4096 and a multiple of 8";
    if (c.resolution < c.period || c.resolution % 8 != 0)
        return "resolution must be a multiple of 8 and at least the period (the controller must resolve one output count)";
    if (!(c.compliance > 0.0 && c.compliance <= 1.0)) return "compliance must be in (0, 1]";
    for (int i = 0; i < 2; ++i)
        if (c.phase[i] < 0 || c.phase[i] >= c.period) return "power-up phases must be 0..P-1";
    if (iabs(c.switch_offset) > 4 * c.period) return "switch offset must be within +-4P";
    if (!(c.v_home > 0 && c.v_home <= 1.0 / 16)) return "homing speed must be in (0, 1/16] counts per call";
    if (!(c.v_max > 0 && c.v_max <= 0.4) || !(c.a_max > 0) || !(c.kv > 0 && c.kv <= 0.05) || !(c.v_drive > 0 && c.v_drive < 0.5))
        return "motion parameters out of range";
    if (c.amplitude < 1000 || c.amplitude > 32767) return "amplitude must be 1000..32767";
    return "";
}

golden::gantry_setup gantry_setup_for(const gantry_config& c) {
    golden::gantry_setup g;
    const int p = c.period;
    const double cnt = kOutputCountNm;
    const int ad = iabs(c.switch_offset);
    g.period = p;
    g.count_nm = cnt;
    g.ratio = 1.0;
    g.conventional = c.conventional;
    g.arm = c.arm;
    g.switch_nm[0] = 1.0e6;  // 1 mm: X1's switch
    g.switch_nm[1] = g.switch_nm[0] + c.switch_offset * cnt;
    // The switch edge lies 3/4 into a laser count: the compensator's switch path is 3 clocks
    // faster than its count path, so at the homing speeds used the edge is always seen in the
    // count it lies in (A is then a function of the geometry alone).
    const int k = (p / 4 + 7 + ad + p - 1) / p;
    for (int i = 0; i < 2; ++i) {
        g.grid_nm[i] = g.switch_nm[i] - 0.75 * cnt;
        // laser ready in the middle of a count, K periods + phase behind the switch's count:
        // A = K*P + phase, so the output phase at A is the power-up phase
        g.origin_nm[i] = g.grid_nm[i] + (0.5 - static_cast<double>(k * p + c.phase[i])) * cnt;
        g.enc_home_nm[i] = g.grid_nm[i] + (1.25 * p + 0.5) * cnt;
    }
    g.start_nm = std::min(g.switch_nm[0], g.switch_nm[1]) - (p / 4 + 4.5) * cnt;
    g.offset = c.offset;
    g.skew_limit = c.skew_limit < 0 ? p : c.skew_limit;
    return g;
}

const char* gantry_step_name(int step) { return step >= 0 && step < st_count ? kStepNames[step] : "?"; }

const char* gantry_arm_name(golden::gantry_arm a) {
    switch (a) {
        case golden::gantry_arm::own: return "own";
        case golden::gantry_arm::both: return "both";
        case golden::gantry_arm::hold: return "hold";
    }
    return "?";
}

bool gantry_parse_arm(const std::string& s, golden::gantry_arm* a) {
    if (s == "own") *a = golden::gantry_arm::own;
    else if (s == "both") *a = golden::gantry_arm::both;
    else if (s == "hold") *a = golden::gantry_arm::hold;
    else return false;
    return true;
}

// ---- the system --------------------------------------------------------------------------------

gantry_result run_gantry(const gantry_config& c, const std::function<void(const gantry_trace_row&)>& sink) {
    gantry_result res;
    res.error = gantry_check(c);
    if (!res.error.empty()) return res;
    const golden::gantry_setup g = gantry_setup_for(c);
    res.setup = g;
    const int p = c.period;
    const double cnt = kOutputCountNm;
    const double lam = cnt * g.ratio;
    const bool laser = !c.conventional;
    const double home_nm[2] = {laser ? g.grid_nm[0] + 1.25 * p * lam : g.enc_home_nm[0],
                               laser ? g.grid_nm[1] + 1.25 * p * lam : g.enc_home_nm[1]};

    // the two compensators (heap: each holds its table RAM image)
    std::unique_ptr<lx::laserax_top> core[2] = {std::make_unique<lx::laserax_top>(), std::make_unique<lx::laserax_top>()};
    axis_settings s;
    s.period = s.tbl_period = p;
    s.mark_len = p / 4;
    s.ratio = 1ULL << 32;  // one raw count = one output count (the laser grid is one count)
    s.glitch_n = 0;
    s.sw_debounce = 0;
    s.pace_m = 2;
    s.amplitude = c.amplitude;
    const lx::axis_regs regs = to_hls(s);
    for (int i = 0; i < 2; ++i) load_table(*core[i], p, c.amplitude);

    gantry_controller ctl(c);
    axis_command cmd[2];
    axis_feedback fb[2];
    lx::axis_out out[2];
    bool ready[2] = {false, false};

    // power-up: the square gantry stands at the first laser's ready point, then is positioned on
    // its motor encoders to the second one and to the start position; each laser becomes ready
    // (stops signalling a laser error) while the gantry stands at its ready point
    const int first = g.origin_nm[0] <= g.origin_nm[1] ? 0 : 1;
    const double pu_stops[3] = {g.origin_nm[first], g.origin_nm[1 - first], g.start_nm};
    int pu_state = 0, pu_timer = 0;
    double u[2] = {pu_stops[0], pu_stops[0]};
    double x[2] = {u[0], u[1]};

    const long long max_calls = c.max_calls > 0 ? c.max_calls : 700LL * p + 400LL * iabs(c.switch_offset) + 60000;
    int prev_stage[2] = {1, 1};
    int prev_step = -1;
    int64_t lock_dp = 0;
    bool locked = false;
    long long t = 0;
    for (; t < max_calls && !ctl.finished(); ++t) {
        // 1. mechanics
        if (pu_state < 5) {
            const double tgt = pu_stops[pu_state == 0 ? 0 : (pu_state <= 2 ? 1 : 2)];
            if (pu_state == 1 || pu_state == 3) {
                const double stepnm = c.v_max * cnt;
                const double dxm = tgt - u[0];
                u[0] = u[1] = std::fabs(dxm) <= stepnm ? tgt : u[0] + (dxm > 0 ? stepnm : -stepnm);
                if (u[0] == tgt) {
                    ++pu_state;
                    pu_timer = 0;
                }
            } else {
                ++pu_timer;
                if (pu_timer == 32 && pu_state == 0) ready[first] = true;
                if (pu_timer == 32 && pu_state == 2) ready[1 - first] = true;
                if (pu_timer == 64) {
                    ++pu_state;
                    pu_timer = 0;
                    if (pu_state == 1 && pu_stops[1] == pu_stops[0]) pu_state = 2;
                }
            }
        } else {
            for (int i = 0; i < 2; ++i) u[i] += cmd[i].v * cnt;
        }
        const double mean = 0.5 * (u[0] + u[1]), diff = u[0] - u[1];
        x[0] = mean + 0.5 * c.compliance * diff;
        x[1] = mean - 0.5 * c.compliance * diff;

        // 2. feedback: compensators (laser quadrature + switch) or conventional encoders
        bool sw[2];
        for (int i = 0; i < 2; ++i) {
            sw[i] = x[i] >= g.switch_nm[i];
            if (laser) {
                lx::axis_pins pins;
                quad_pins(static_cast<int64_t>(std::floor((x[i] - g.grid_nm[i]) / lam)), pins.a, pins.b);
                pins.sw = sw[i];
                pins.lerr = !ready[i];
                lx::axis_regs r = regs;
                r.rehome = cmd[i].rehome;
                r.clear = cmd[i].clear;
                out[i] = core[i]->step(pins, r);
                fb[i].sin = out[i].sin.to_int64();
                fb[i].cos = out[i].cos.to_int64();
                fb[i].mark = out[i].ref_mark;
                fb[i].alarm = out[i].alarm;
            } else {
                const double ph = (x[i] - g.enc_home_nm[i]) / cnt + p / 8.0;
                const double ang = kTwoPi * ph / p;
                fb[i].sin = std::lround(c.amplitude * std::sin(ang));
                fb[i].cos = std::lround(c.amplitude * std::cos(ang));
                fb[i].mark = std::fabs(x[i] - g.enc_home_nm[i]) <= (p / 8.0) * cnt;
                fb[i].alarm = false;
            }
        }

        // 3. controller
        ctl.sense(fb);
        if (pu_state >= 5) ctl.step(cmd);

        // 4. records (taps and physics: for the report and the tests only)
        int stage[2] = {0, 0};
        int64_t real_count[2];
        for (int i = 0; i < 2; ++i) {
            if (laser) {
                stage[i] = out[i].stage.to_int();
                real_count[i] = out[i].out_pos.to_int64() - out[i].adj.to_int64();
                if (prev_stage[i] == 1 && stage[i] == 2) ++res.rises[i];
                if (prev_stage[i] == 2 && stage[i] == 3) {
                    if (res.homings[i].empty()) {
                        res.a[i] = out[i].a_pos.to_int64();
                        res.z[i] = out[i].z_pos.to_int64();
                    }
                    res.homings[i].push_back(out[i].d.to_int64());
                }
                prev_stage[i] = stage[i];
            } else {
                real_count[i] = static_cast<int64_t>(std::floor((x[i] - g.grid_nm[i]) / cnt));
            }
        }
        const double rack = (x[0] - x[1]) / cnt;
        if (locked) res.max_rack = std::max(res.max_rack, std::fabs(rack));
        if (ctl.row_kind() >= 0) {
            gantry_row row;
            row.kind = ctl.row_kind();
            row.name = ctl.row_name();
            row.cycle = t;
            for (int i = 0; i < 2; ++i) {
                row.ctrl[i] = ctl.ctrl(i);
                row.homed[i] = ctl.homed(i);
                row.real[i] = (x[i] - home_nm[i]) / cnt;
                row.stage[i] = stage[i];
                row.real_count[i] = real_count[i];
            }
            row.rack = rack;
            row.skew_valid = row.homed[0] && row.homed[1];
            row.skew = row.ctrl[0] - row.ctrl[1];
            row.alarm = row.kind == gantry_row::check && ctl.skew_alarm();
            if (row.kind == gantry_row::lock) {
                locked = true;
                lock_dp = real_count[0] - real_count[1];
            }
            if (row.kind == gantry_row::x1_homed) res.rack[0] = real_count[0] - real_count[1] - lock_dp;
            if (row.kind == gantry_row::x2_homed) res.rack[1] = real_count[0] - real_count[1] - lock_dp;
            if (row.kind == gantry_row::check) res.rack[2] = real_count[0] - real_count[1] - lock_dp;
            res.rows.push_back(row);
            ctl.take_row();
        }
        if (sink && (t % c.trace_every == 0 || ctl.step_id() != prev_step)) {
            gantry_trace_row tr;
            tr.cycle = t;
            tr.step = ctl.step_id();
            for (int i = 0; i < 2; ++i) {
                tr.x_nm[i] = x[i];
                tr.setpoint[i] = ctl.setpoint(i);
                tr.ctrl[i] = ctl.ctrl(i);
                tr.homed[i] = ctl.homed(i);
                tr.stage[i] = stage[i];
                tr.mark[i] = fb[i].mark;
                tr.sw[i] = sw[i];
                tr.sin[i] = fb[i].sin;
                tr.cos[i] = fb[i].cos;
                if (laser && out[i].alarm) tr.alarm = true;
            }
            tr.rack = rack;
            tr.skew_valid = tr.homed[0] && tr.homed[1];
            tr.skew = tr.ctrl[0] - tr.ctrl[1];
            if (ctl.checked() && ctl.skew_alarm()) tr.alarm = true;
            sink(tr);
        }
        prev_step = ctl.step_id();
    }
    res.calls = t;
    if (!ctl.finished()) ctl.fail("sequence did not finish within " + std::to_string(max_calls) + " calls");
    for (int i = 0; i < 2; ++i) {
        res.latch_sin[i] = ctl.latch_sin(i);
        res.latch_cos[i] = ctl.latch_cos(i);
        res.latch_mark[i] = ctl.latch_mark(i);
    }
    res.checked = ctl.checked();
    res.skew_check = ctl.skew_check();
    res.skew_error = ctl.skew_check() - c.offset;
    res.alarm = ctl.skew_alarm();
    res.skew_final = ctl.ctrl(0) - ctl.ctrl(1);
    res.rack_final_nm = x[0] - x[1];
    res.drive_rack_final_nm = u[0] - u[1];
    res.both_referenced = ctl.homed(0) && ctl.homed(1) && (!laser || (prev_stage[0] == 3 && prev_stage[1] == 3));
    res.ok = !ctl.failed();
    res.error = ctl.error();
    return res;
}

}  // namespace lxt
