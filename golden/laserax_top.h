// golden/laserax_top.h — golden model of the whole top, DESIGN.md 4.7 (laserax_top),
// including the configuration check (cfg_ok) and the safe state.
//
// Pipeline rule (DESIGN 2, 4.7): one call = one clock edge; a block at call t consumes the
// outputs its upstream returned at call t-1 (kept in members, all zero at reset).
//   swf.step(sw)                      (switch input_filter, length sw_debounce)
//   dec.step(a, b, lerr)              (glitch_n, min_spacing, clear of this call)
//   mul.step(dec_q.step)
//   emap.step(mul_q.comp, rep_q.homed) (map registers of this call; docs/ERROR_MAP.md §8)
//   pac.step(mul_q.delta + emap_q.delta) (pace_m, backlog_thr, clear of this call)
//   rep.step(pac_q.pstep, swf_q.f, swf_q.valid, rehome of this call, unhome = dec_q.lerr)
//   dds.step(rep_q.ostep)
// sin/cos: the DDS outputs of this call; qa, qb (quadrature of out_pos mod 4), qz and ref_mark
// (= rephase mark) from the rephase outputs of call t-3. While !config_ok every block and every
// inter-block register is reset in each call and the outputs are the safe state.
#pragma once
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
    int64_t pace_m = 4;
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
    error_map_regs emap;  // map_en, bank_sel, geometries, table write port; reset: disabled
};

struct axis_pins {
    bool a = false, b = false, sw = false, lerr = false;
};

struct axis_out {
    int64_t sin, cos;
    bool ref_mark, qa, qb, qz;
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
    // inter-block registers: outputs of the previous call (zero at reset)
    input_filter::out swf_q_{};
    quad_decoder::out dec_q_{};
    pulse_multiplier::out mul_q_{};
    output_pacer::out pac_q_{};
    error_map::out emap_q_{};
    rephase::out rep_q_{};   // rephase output of call t-1
    struct rep_tap {         // the rephase outputs qa, qb, qz and ref_mark use (DESIGN 4.7)
        int64_t out_pos = 0;
        bool mark = false;
    };
    rep_tap rep_q2_{};  // of call t-2
    rep_tap rep_q3_{};  // of call t-3
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
