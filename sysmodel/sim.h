// sim.h — testbench and tool support shared by tb/ and tools/: register settings for both
// models, table loading, output comparison, a physical motion model that drives the pins, and a
// controller-side decoder of the sin/cos and A/B outputs.
//
// Nothing here is a model of the IP: it stands outside both hls/ and golden/ and talks to each in
// its own types.
#ifndef LASERAX_TOOLS_SIM_H
#define LASERAX_TOOLS_SIM_H

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "golden/laserax_top.h"
#include "hls/laserax_top.h"
#include "host/regmap_table.h"
#include "sysmodel/regmap_models.h"

namespace lxt {

// Physical constants of the default set-up (DESIGN §1).
constexpr double kVacuumWavelengthNm = 632.991;
constexpr double kAirIndexDefault = 1.000271;
constexpr double kOutputCountNm = 78.125;  // 20 um / 256
constexpr double kClockHz = 100e6;        // model clock for time axes and speeds

// One register set in plain integers: the host settings struct lxt::axis_settings (generated from
// the register map, host/regmap_table.h: the member names and reset values of the hls s_axilite
// block, docs/REGISTERS.md); converted to the model structs by to_hls() and to_golden()
// (sysmodel/regmap_models.h).

// Ratio register for one raw count = vacuum wavelength / air index, output count in nm.
uint64_t ratio_for(double vacuum_nm, double air_index, double count_nm);

// Writes the quarter-wave table for (period, amplitude) into the core's table RAM (host driver).
void load_table(lx::laserax_top& core, int period, int amplitude);

// Compares every output and tap; returns "" or a message naming the first differing signal.
std::string compare(const lx::axis_out& h, const golden::axis_out& g);

// The quadrature levels (A, B) for raw count index n (forward = A leads B).
inline void quad_pins(int64_t n, bool& a, bool& b) {
    const int i = static_cast<int>(((n % 4) + 4) % 4);
    a = i == 1 || i == 2;
    b = i == 2 || i == 3;
}

// Physical axis: position in nm, moved by a list of constant-velocity segments. Produces the
// laser's raw count (floor((x - x0)/lambda + frac0)) and the reference switch level.
struct motion_segment {
    double target_nm;
    double speed_nm_per_cycle;  // > 0
};

class axis_motion {
public:
    axis_motion(double start_nm, double lambda_nm, double fringe_frac0);
    void add(double target_nm, double speed_nm_per_cycle) { segs_.push_back({target_nm, speed_nm_per_cycle}); }
    // Advances one clock; returns false when every segment is done (the axis then stands still).
    bool tick();
    double x_nm() const { return x_; }
    int64_t raw_count() const;
    bool done() const { return seg_ >= segs_.size(); }

private:
    std::vector<motion_segment> segs_;
    size_t seg_ = 0;
    double x_, x0_, lambda_, frac0_;
};

// Reference switch: a cam that closes for x >= edge_nm (dir +1) or x <= edge_nm (dir -1), with
// optional contact bounce: within bounce_nm past the edge the level is random.
struct ref_switch {
    double edge_nm = 0;
    int dir = 1;
    double bounce_nm = 0;
    bool level(double x_nm, std::mt19937_64& rng) const;
};

// Controller-side decoder: what a controller's interpolator reconstructs from the outputs.
// sin/cos -> phase index round(atan2 * P / 2pi), unwrapped by period counting; A/B -> 4x count.
class controller_decoder {
public:
    void reset(int period, int64_t start_pos);
    // Feeds one call's outputs; returns false if a sin/cos step of more than one count (or an
    // illegal A/B transition) was seen.
    bool feed(int64_t sin_code, int64_t cos_code, bool qa, bool qb);
    // The sin/cos amplitude crossed the decodable limit (amp * 2pi / P >= 8 codes per count) in
    // either direction: the sin/cos interpolator re-acquires at the next feed(), taking the
    // position from the A/B count as a controller does when the analogue signal comes back.
    void reacquire_sincos() { sc_primed_ = false; }
    int64_t sincos_pos() const { return pos_sc_; }
    int64_t quad_pos() const { return pos_q_; }

private:
    int period_ = 256;
    int64_t pos_sc_ = 0, pos_q_ = 0;
    int last_ph_ = 0;
    int last_q_ = 0;
    bool primed_ = false;
    bool sc_primed_ = true;
    // memo of the last atan2 phase (a pure function of sin, cos, period)
    bool ph_memo_ok_ = false;
    int64_t memo_sin_ = 0, memo_cos_ = 0;
    int memo_period_ = 0;
    int memo_ph_ = 0;
};

// Convenience: both models, the same settings, stepped together and compared. Every call also
// checks the position-integrity invariant from the outside:
//   * the controller decoder (atan2 of the hls sin/cos, and the hls A/B) reconstructs exactly the
//     golden out_pos of the call the outputs belong to (three calls back), never stepping by more
//     than one count (sin/cos decoding is skipped when amp * 2pi / P < 8 codes per count);
//   * golden paced + backlog == golden comp_pos + corr of three calls earlier (the pacer loses
//     nothing; its paced and backlog taps are two calls late, DESIGN 4.4; corr is the error-map
//     correction, 0 while the map is disabled);
//   * golden comp_pos == floor((N * R + OFF) / 2^32) with N the raw count of call t - 1 - L_MUL
//     (128-bit), on every call once the pair (R, OFF) in force has been unchanged for
//     2 * K_REBASE + L_MUL calls since its last change or the last restart (DESIGN 4.3: an update
//     is taken at once or, during a re-base, at most K_REBASE calls later, and settles K_REBASE +
//     L_MUL calls after it is taken);
// so once the pacer has drained, what a controller decodes equals the compensated position plus
// the error-map correction plus the rephase adjustment, exactly.
class dual_axis {
public:
    explicit dual_axis(const axis_settings& s);
    void set(const axis_settings& s);  // new register values (table reloaded if P/amp changed)
    // Steps both models; returns "" or the mismatch text.
    std::string step(const lx::axis_pins& p);
    // One error-map table word for the next step() of both models (the write port writes the bank
    // not selected by bank_sel in that call); the write enable is cleared after that call.
    void write_map(int addr, int32_t data);
    // the hls outputs of the last step(): the core's output register file (laserax_top::out())
    const lx::axis_out& hls() const { return core_.out(); }
    const golden::axis_out& gold() const { return g_; }
    lx::laserax_top& core() { return core_; }
    const axis_settings& settings() const { return s_; }
    uint64_t calls() const { return calls_; }
    uint64_t writes() const { return writes_; }  // register writes to the core (set() with changed settings)

private:
    axis_settings s_;
    lx::axis_regs hr_;
    golden::axis_regs gr_;
    lx::laserax_top core_;
    golden::laserax_top gold_;
    golden::axis_out g_{};
    uint64_t calls_ = 0;
    uint64_t writes_ = 0;
    // integrity state
    controller_decoder dec_;
    // the outputs of call t belong to the rephase out_pos of call t-3 (DESIGN 4.7: dds 3 stages)
    static constexpr int kOutLag = 3;
    int64_t out_hist_[kOutLag] = {};  // golden out_pos of calls t-1 .. t-kOutLag
    int hist_n_ = 0;
    bool prev_cfg_err_ = true;
    int64_t cc_hist_[3] = {0, 0, 0};  // golden comp_pos + corr of calls t-1, t-2, t-3
    static constexpr int L_MUL = golden::pulse_multiplier::L_MUL;
    int64_t raw_hist_[L_MUL + 1] = {};  // golden raw_count of calls t-1 .. t-1-L_MUL
    long long settled_ = 0;             // calls since the pair in force last changed (or restart)
    bool prev_use_sc_ = false;          // sin/cos decoded on the previous call
    // pin spacing (DESIGN 4.4, 4.5): two changes of the qa/qb state are at least max(M, 2) calls
    // apart in every stage, M the least pace_m in force from 8 calls before the first change on
    // (the count reaches the pins 4 calls after the pacer decides it)
    bool q_have_ = false;               // a running call's qa/qb seen since the last restart
    bool q_changed_ = false;            // a change seen since then
    bool q_a_ = false, q_b_ = false;    // qa/qb of the previous call
    uint64_t q_last_ = 0;               // call of the last change
    int64_t m_min_ = 0;                 // least pace_m (as a gap) since 8 calls before it
    int64_t m_ring_[8] = {};            // the gaps of the last 8 running calls (0: none yet)
    unsigned m_pos_ = 0;                // next slot of the ring
    std::string pin_spacing(bool qa, bool qb);
    // register stage (DESIGN 4.7): the settings presented in a call are in force in the next one
    axis_settings f_{};          // settings in force in the current call (presented in the previous)
    bool have_f_ = false;        // false in the power-up call (no settings in force)
    bool f_stale_ = true;        // s_ changed since f_ = s_ (the copy is made only then)
    bool table_pending_ = false;  // DDS table to reload after the call in which P / amp were presented
    // ratio / comp_offset in force (DESIGN 4.7: loaded every call without comp_sync, else on comp_commit)
    uint64_t eff_ratio_ = golden::default_ratio();
    int64_t eff_offset_ = 0;
    std::string integrity();
};

}  // namespace lxt

#endif
