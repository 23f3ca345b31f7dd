// golden/laserax_top.cpp — see laserax_top.h (DESIGN.md 4.7).
#include "golden/laserax_top.h"

#include <algorithm>
#include <utility>

namespace golden {

namespace {

// DESIGN 4.7, digital pins: qa/qb of (out_pos + ab_rot) mod 4 (true modulo), 0->(0,0), 1->(1,0),
// 2->(1,1), 3->(0,1); qz the index or, with qz_window, the mark; q_oe = !(hiz_alarm && alarm)
// (o.alarm already formed)
void pin_levels(axis_out& o, int64_t out_pos, bool mark, bool index, int64_t pin_cfg) {
    const bool qz_window = (pin_cfg & 1) != 0;
    const int64_t ab_rot = (pin_cfg >> 1) & 3;
    const bool hiz_alarm = (pin_cfg & 8) != 0;
    const int64_t qi = (((out_pos + ab_rot) % 4) + 4) % 4;
    o.qa = qi == 1 || qi == 2;
    o.qb = qi == 2 || qi == 3;
    o.qz = qz_window ? mark : index;
    o.ref_mark = mark;
    o.q_oe = !(hiz_alarm && o.alarm);
}

}  // namespace

bool config_ok(const axis_regs& r) {
    const int64_t P = r.period;
    // Reading: only the conditions listed in DESIGN 4.7 are checked; register values are taken
    // as given (no truncation to the register widths of section 5; callers keep them in range).
    return P >= 8 && P <= 4096 && P % 8 == 0 &&                            //
           r.ratio != 0 &&                                                 //
           r.pace_m >= 2 &&                                                //
           r.dac_width >= 12 && r.dac_width <= 18 &&                       //
           r.amplitude >= 1 && r.amplitude <= (int64_t{1} << (r.dac_width - 1)) - 1 &&  //
           r.tbl_period == P &&                                            //
           !r.tbl_we &&                                                    //
           r.mark_len >= P / 4 && r.mark_len <= P &&                       //
           r.min_spacing > std::max<int64_t>(r.glitch_n, 1);  // count integrity (DESIGN 4.2)
}

void laserax_top::reset() {
    const int64_t keep = last_period_;  // the period memory is not part of the chain's reset
    const bool keep_run = was_running_;
    const uint64_t keep_ratio = ratio_held_;  // held registers: register file, not chain state
    const int64_t keep_offset = offset_held_;
    error_map keep_map = std::move(emap_);  // the map tables are RAM, not reset
    const axis_regs keep_regs = in_force_;  // the register stage is not chain state
    const bool keep_tbl_we = prev_tbl_we_;
    const bool keep_powered = powered_;
    dds_sincos keep_dds = std::move(dds_);  // keeps its memo of the codes (a pure function)
    *this = laserax_top{};
    in_force_ = keep_regs;
    prev_tbl_we_ = keep_tbl_we;
    powered_ = keep_powered;
    emap_ = std::move(keep_map);
    emap_.reset();
    dds_ = std::move(keep_dds);
    dds_.reset();
    last_period_ = keep;
    was_running_ = keep_run;
    ratio_held_ = keep_ratio;
    offset_held_ = keep_offset;
}

axis_out laserax_top::step(const axis_pins& pins, const axis_regs& presented) {
    // DESIGN 4.7 register stage: this call runs on the registers presented in the previous call
    // (in_force_, read in place); the registers presented now are in force from the next call
    const axis_out o = run(pins);
    prev_tbl_we_ = in_force_.tbl_we;  // 0 after the power-up call (no registers in force)
    in_force_ = presented;
    return o;
}

axis_out laserax_top::run(const axis_pins& pins) {
    axis_out o{};
    const axis_regs& regs = in_force_;  // reset() keeps it (the register stage is not chain state)
    if (!powered_) {  // power-up call: no registers in force, every block in reset, outputs 0
        powered_ = true;
        reset();
        o.stage = 1;
        o.q_oe = true;  // no alarm (cfg_err = 0 in the power-up call)
        return o;
    }
    // DESIGN 4.7: ratio and comp_offset in force are loaded in every call without comp_sync,
    // else only in a call with comp_commit
    if (!regs.comp_sync || regs.comp_commit) {
        ratio_held_ = regs.ratio;
        offset_held_ = regs.comp_offset;
    }
    // DESIGN 4.7: a change of the period register between two running calls is a
    // reconfiguration: the call in which the new value appears is a safe-state call.
    const bool period_changed = was_running_ && regs.period != last_period_;
    // DESIGN 4.6 / 4.7: the call after a table write is a safe-state call too
    const bool running = config_ok(regs) && !prev_tbl_we_ && ratio_held_ != 0 && !period_changed;
    last_period_ = regs.period;
    was_running_ = running;
    if (!running) {
        // safe state: every block and every kept block output (including the t-3 outputs of
        // qa/qb/qz/ref_mark) held in reset; outputs and taps zero, cfg_err = alarm = 1, stage 1.
        reset();
        o.cfg_err = true;
        o.alarm = true;
        o.stage = 1;
        pin_levels(o, 0, false, false, regs.pin_cfg);
        return o;
    }

    // DESIGN 4.7, connections: every block input that is another block's output is that output
    // of call t - L (connection_latency); pins and registers are this call's
    const input_filter::out swf_o = swf_.step(pins.sw, regs.sw_debounce);
    const quad_decoder::out dec_o =
        dec_.step(pins.a, pins.b, pins.lerr, regs.glitch_n, regs.min_spacing, regs.clear);
    const pulse_multiplier::out mul_o = mul_.step(dec_past_.at(L::MUL_STEP).step, ratio_held_, offset_held_);
    // error map (docs/ERROR_MAP.md §8): the uncorrected comp and the homed status; its delta joins
    // the multiplier delta at the pacer input
    const error_map::out emap_o = emap_.step(mul_past_.at(L::MAP_P).comp, rep_past_.at(L::MAP_HOMED).homed, regs.emap);
    const output_pacer::out pac_o = pac_.step(mul_past_.at(L::PAC_DELTA).delta + emap_past_.at(L::PAC_DELTA).delta,
                                              regs.pace_m, regs.backlog_thr, regs.clear,
                                              rep_past_.at(L::PAC_WIDE).stage == 2);
    const input_filter::out& sw_in = swf_past_.at(L::REP_SW);
    const rephase::out rep_o = rep_.step(pac_past_.at(L::REP_PSTEP).pstep, pac_past_.at(L::REP_PSTEP).slot, sw_in.f, sw_in.valid, regs.rehome,
                                         dec_past_.at(L::REP_UNHOME).lerr, regs.period, regs.mark_len);
    const dds_sincos::out dds_o = dds_.step(rep_past_.at(L::DDS_OSTEP).ostep, regs.period, regs.amplitude);

    // DAC range guard (DESIGN 4.7): codes clamped to +-(2^(dac_width-1) - 1); a clamp sets the
    // sticky dac_clip_st (clear acts first, an event in the same call wins)
    const int64_t dac_hi = (int64_t{1} << (regs.dac_width - 1)) - 1;
    bool clip = false;
    const auto clamp = [&](int64_t v) {
        if (v > dac_hi || v < -dac_hi) clip = true;
        return std::min(std::max(v, -dac_hi), dac_hi);
    };
    o.sin = clamp(dds_o.sin);
    o.cos = clamp(dds_o.cos);
    if (regs.clear) dac_clip_st_ = false;
    if (clip) dac_clip_st_ = true;
    o.dac_clip_st = dac_clip_st_;

    // digital outputs from the rephase output of call t - 3: index = out_pos mod 4 (true modulo),
    // 0->(0,0), 1->(1,0), 2->(1,1), 3->(0,1)
    const rephase::out& rep_quad = rep_past_.at(L::OUT_QUAD);

    o.cfg_err = false;
    o.stage = rep_o.stage;
    o.homed = rep_o.homed;
    o.lerr_alarm = dec_o.lerr_alarm;
    o.illegal_st = dec_o.illegal_st;
    o.err_cnt = dec_o.err_cnt;
    o.ovs_edge_st = dec_o.ovs_st;
    o.ovs_backlog_st = pac_o.ovs_st;
    o.glitch_st = dec_o.glitch_st;
    o.map_cfg_err = emap_o.cfg_err;
    o.alarm = o.lerr_alarm || o.illegal_st || o.ovs_edge_st || o.ovs_backlog_st || o.cfg_err || o.map_cfg_err ||
              o.dac_clip_st;
    // the index of rephase has one call more latency than its mark (DESIGN 4.5 step 5), so
    // qz's index is the rephase index of call t - 2 (the index test of call t - 3)
    pin_levels(o, rep_quad.out_pos, rep_quad.mark, rep_past_.at(L::OUT_QUAD - 1).index, regs.pin_cfg);

    o.raw_count = dec_o.raw_count;
    o.step = dec_o.step;
    o.comp_pos = mul_o.comp;
    o.delta = mul_o.delta;
    o.backlog = pac_o.backlog;
    o.pstep = pac_o.pstep;
    o.paced_pos = pac_o.paced;
    o.ostep = rep_o.ostep;
    o.out_pos = rep_o.out_pos;
    o.adj = rep_o.adj;
    o.a_pos = rep_o.a;
    o.b_pos = rep_o.b;
    o.c_pos = rep_o.c;
    o.z_pos = rep_o.z;
    o.d = rep_o.d;
    o.rep_mark = rep_o.mark;
    o.corr = emap_o.corr;
    o.map_delta = emap_o.delta;

    // this call's block outputs join the kept ones
    swf_past_.push(swf_o);
    dec_past_.push(dec_o);
    mul_past_.push(mul_o);
    emap_past_.push(emap_o);
    pac_past_.push(pac_o);
    rep_past_.push(rep_o);
    return o;
}

}  // namespace golden
