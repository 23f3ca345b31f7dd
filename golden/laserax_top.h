// golden/laserax_top.h — golden model of the whole top, DESIGN.md 4.7 (laserax_top),
// including the configuration check (cfg_ok) and the safe state.
//
// Written from the connection table of DESIGN 4.7: an input of a block in call t is another
// block's output of call t - L (or a pin / register of call t). The model keeps each block's
// outputs of its last calls (`past`, zero after a reset of the chain) and reads them at the
// latencies of that table (`connection_latency`, one constant per row), so the order in which the
// blocks are stepped within a call does not matter. sin/cos: the DDS outputs of this call through
// the DAC range guard. While the configuration check fails every block and every kept output is
// reset in each call and the outputs are the safe state.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "golden/dds_sincos.h"
#include "golden/error_map.h"
#include "golden/input_filter.h"
#include "golden/output_pacer.h"
#include "golden/pulse_multiplier.h"
#include "golden/quad_decoder.h"
#include "golden/rephase.h"

namespace golden {

// Default ratio register (DESIGN 5): rha(632.991 / 1.000271 / 78.125 * 2^32), evaluated in
// long double left to right = 34789620252 (exact value 34789620251.7897, not near a tie).
inline uint64_t default_ratio() {
    return static_cast<uint64_t>(std::llround(632.991L / 1.000271L / 78.125L * 4294967296.0L));
}

struct axis_regs {
    int64_t period = 256;
    uint64_t ratio = default_ratio();
    int64_t comp_offset = 0;  // Q32.32 output counts added to N * R (thermal origin, K168)
    bool comp_sync = false;   // 1: ratio / comp_offset take effect only in a comp_commit call
    bool comp_commit = false; // pulse (DESIGN 4.7)
    int64_t glitch_n = 2;
    int64_t sw_debounce = 16;
    int64_t min_spacing = 8;
    int64_t pace_m = 61;
    uint64_t backlog_thr = 4096;
    int64_t mark_len = 64;
    int64_t dac_width = 16;
    int64_t amplitude = 32767;
    int64_t tbl_period = 256;
    // DDS table write enable: the golden chain has no table RAM (its sin/cos are computed), but a
    // call with tbl_we = 1 is in the safe state (DESIGN 4.6, 4.7)
    bool tbl_we = false;
    bool rehome = false;
    bool clear = false;
    // digital pins (DESIGN 4.7): bit 0 qz_window, bits 2:1 ab_rot, bit 3 hiz_alarm
    int64_t pin_cfg = 8;
    error_map_regs emap;  // map_en, bank_sel, geometries, table write port; reset: disabled
};

struct axis_pins {
    bool a = false, b = false, sw = false, lerr = false;
};

struct axis_out {
    int64_t sin, cos;
    bool ref_mark, qa, qb, qz;
    bool q_oe;  // A/B/Z driver enable: !(hiz_alarm && alarm)
    bool cfg_err;
    int stage;
    bool homed, lerr_alarm, illegal_st;
    int err_cnt;
    bool ovs_edge_st, ovs_backlog_st, glitch_st, alarm;
    bool dac_clip_st;  // sticky: a sin/cos code outside +-(2^(dac_width-1) - 1) was clamped
    /* taps = the registered outputs of each block at this call */
    int64_t raw_count;
    int step;
    int64_t comp_pos, delta, backlog;
    int pstep;
    int64_t paced_pos;
    int ostep;
    int64_t out_pos, adj, a_pos, b_pos, c_pos, z_pos, d;
    bool rep_mark;
    bool map_cfg_err;
    int64_t corr, map_delta;
};

// DESIGN 4.7: 8 <= P <= 4096, P % 8 == 0, ratio != 0, 2 <= pace_m, 12 <= dac_width <= 18,
// 1 <= amplitude <= 2^(dac_width-1) - 1, tbl_period == P, P/4 <= mark_len <= P, tbl_we == 0,
// min_spacing > max(glitch_n, 1) (count integrity, DESIGN 4.2). (The chain also holds the safe
// state in the call after one with tbl_we = 1: that needs the previous call, see laserax_top.)
bool config_ok(const axis_regs& r);

// DESIGN 4.7, connections: the latency L, in calls, of every block input (and top output) that is
// another block's output. Input in call t = that output of call t - L.
struct connection_latency {
    static constexpr int MUL_STEP = 1;    // pulse_multiplier step      <- quad_decoder step
    static constexpr int MAP_P = 1;       // error_map p                <- pulse_multiplier comp
    static constexpr int MAP_HOMED = 1;   // error_map homed            <- rephase homed
    static constexpr int PAC_DELTA = 1;   // output_pacer delta (both)  <- pulse_multiplier delta, error_map delta
    static constexpr int PAC_WIDE = 1;    // output_pacer wide          <- rephase stage == 2
    static constexpr int REP_PSTEP = 1;   // rephase pstep, slot        <- output_pacer pstep, slot
    static constexpr int REP_SW = 1;      // rephase sw, sw_valid       <- switch filter f, valid
    static constexpr int REP_UNHOME = 1;  // rephase unhome             <- quad_decoder lerr
    static constexpr int DDS_OSTEP = 1;   // dds_sincos ostep           <- rephase ostep
    static constexpr int OUT_QUAD = 3;    // top qa, qb, qz, ref_mark   <- rephase out_pos, mark
};

// The outputs of one block in its last N calls: at(d) is the output of call t - d (d = 1..N) while
// call t runs; all zero after construction (a reset of the chain). push() ends a call.
template <class T, int N>
class past {
    static_assert(N >= 1, "a kept output is at least one call old");

public:
    const T& at(int d) const { return v_[static_cast<size_t>(d - 1)]; }
    void push(const T& x) {
        for (int d = N - 1; d > 0; --d) v_[static_cast<size_t>(d)] = v_[static_cast<size_t>(d - 1)];
        v_[0] = x;
    }

private:
    std::array<T, N> v_{};  // v_[d - 1]: the output of call t - d
};

class laserax_top {
public:
    void reset();
    axis_out step(const axis_pins& pins, const axis_regs& regs);

private:
    axis_out run(const axis_pins& pins);  // one call on the registers in force (in_force_)
    input_filter swf_;
    quad_decoder dec_;
    pulse_multiplier mul_;
    output_pacer pac_;
    rephase rep_;
    dds_sincos dds_;
    error_map emap_;  // its tables survive reset(); only the pipeline is reset
    // the blocks' outputs of the last calls, as deep as the longest latency that reads them
    using L = connection_latency;
    past<input_filter::out, L::REP_SW> swf_past_;
    past<quad_decoder::out, std::max(L::MUL_STEP, L::REP_UNHOME)> dec_past_;
    past<pulse_multiplier::out, std::max(L::MAP_P, L::PAC_DELTA)> mul_past_;
    past<error_map::out, L::PAC_DELTA> emap_past_;
    past<output_pacer::out, L::REP_PSTEP> pac_past_;
    past<rephase::out, std::max({L::MAP_HOMED, L::PAC_WIDE, L::DDS_OSTEP, L::OUT_QUAD})> rep_past_;
    int64_t last_period_ = 0;    // period register of the previous call
    uint64_t ratio_held_ = default_ratio();  // ratio in force (DESIGN 4.7, comp_sync / comp_commit)
    int64_t offset_held_ = 0;                // comp_offset in force
    bool was_running_ = false;   // the previous call ran with a valid configuration
    bool dac_clip_st_ = false;   // DAC range guard (DESIGN 4.7), reset with the chain
    // DESIGN 4.7 register stage: the registers presented in a call are in force in the next one;
    // the first call after power-up has none in force (power-up call). Not part of reset().
    axis_regs in_force_{};
    bool prev_tbl_we_ = false;   // tbl_we in force in the previous call (DESIGN 4.6, 4.7)
    bool powered_ = false;
};

}  // namespace golden
