// laserax_top.h — the single-axis chain: quad_decoder -> pulse_multiplier -> output_pacer ->
// rephase -> dds_sincos, with the error_map beside the pacer input, plus the switch debounce,
// the configuration check and the digital A/B/Z outputs (DESIGN §4.7, register map §5).
//
// One call of step() (or of tick()) is one clock. step(pins, regs) presents a register block in
// every call; the C simulation also has a register write port, write_regs(), and tick(), which
// presents the last block written and returns the outputs by reference (the interface the
// testbenches use, lxt::dual_axis; in the synthesis view, where the top calls step() only, they are
// host-side wrappers of step()). Between two blocks there is
// exactly one register stage: a block consumes the outputs its upstream block returned at the
// previous call (held in out_, the outputs of the previous call, and in the *_q members for those
// no output shows).
// qa/qb/qz/ref_mark take the rephase outputs of three calls ago so that they change in the same
// call as the sin/cos codes they belong to. Latency pin edge -> sin/cos: 12 calls (glitch_n <= 1, DESIGN 4.7).
//
// A class rather than a free function so that a testbench (or a gantry model) can instantiate
// several axes; hls/laserax_axil.cpp wraps one static instance as the synthesis top.
#ifndef LASERAX_HLS_LASERAX_TOP_H
#define LASERAX_HLS_LASERAX_TOP_H

#include "hls/axis_config.h"
#include "hls/dds_sincos.h"
#include "hls/error_map.h"
#include "hls/input_filter.h"
#include "hls/output_pacer.h"
#include "hls/pulse_multiplier.h"
#include "hls/quad_decoder.h"
#include "hls/rephase.h"

// C simulation with the own integer back end: the register stage compares the presented block with
// the one in force byte-wise (std::memcmp) to skip the reload and the configuration check when
// nothing changed (the C-simulation register write port; DESIGN §4.7). Synthesis and the vendor types take
// the plain path (reload and check every call), which computes the same.
#if !defined(__SYNTHESIS__) && !defined(LASERAX_USE_AP_TYPES) && !defined(LASERAX_USE_AC_TYPES)
#include <cstring>
namespace lx {
// Byte equality of two objects of a size that is a multiple of 8 (GCC / Clang: inline 16-byte
// compares and one 8-byte compare of an odd tail, b 16-byte aligned; std::memcmp elsewhere).
template <typename T>
inline bool same_bytes16(const T& a, const T& b) {
#if defined(__GNUC__) || defined(__clang__)
    static_assert(sizeof(T) % 8 == 0, "same_bytes16: size a multiple of 8");
    typedef signed char v16 __attribute__((vector_size(16)));
    const char* pa = reinterpret_cast<const char*>(&a);
    const v16* pb = static_cast<const v16*>(__builtin_assume_aligned(&b, 16));  // b: 16-byte aligned
    v16 eq = v16{} == v16{};  // all ones
#pragma GCC unroll 16
    for (unsigned i = 0; i < sizeof(T) / 16; ++i) {
        v16 x;
        std::memcpy(&x, pa + 16 * i, 16);
        eq &= x == pb[i];
    }
    typedef long long v2 __attribute__((vector_size(16)));
    const v2 w = reinterpret_cast<v2>(eq);
    bool tail = true;
    if (sizeof(T) % 16 != 0) {
        unsigned long long ta, tb;
        std::memcpy(&ta, pa + 16 * (sizeof(T) / 16), 8);
        std::memcpy(&tb, reinterpret_cast<const char*>(&b) + 16 * (sizeof(T) / 16), 8);
        tail = ta == tb;
    }
    return (w[0] & w[1]) == -1 && tail;
#else
    return std::memcmp(&a, &b, sizeof(T)) == 0;
#endif
}
}  // namespace lx
#define LASERAX_REGS_SAME(a, b) (::lx::same_bytes16((a), (b)))
#else
#define LASERAX_REGS_SAME(a, b) false
#endif

namespace lx {

struct laserax_top_cfg {
    static constexpr int W_DEBOUNCE = 16;  // switch debounce length register
    static constexpr int W_PIN_CFG = 4;    // pin_cfg register: qz_window, ab_rot (2), hiz_alarm
    // Reset ratio: round(632.991 nm / 1.000271 / 78.125 nm * 2^32), i.e. one raw count of a
    // HeNe wavelength in standard air, in output counts of 20 um / 256. Checked against the
    // formula by tb/tb_axis_config.
    static constexpr unsigned long long RATIO_DEFAULT = 34789620252ULL;
    static constexpr int PERIOD_DEFAULT = 256;
    static constexpr int AMP_DEFAULT = 32767;
    using debounce_t = uint<W_DEBOUNCE>;
    using pin_cfg_t = uint<W_PIN_CFG>;
    using dacw_t = uint<axis_widths::W_DACW>;
};

// s_axilite register block (docs/REGISTERS.md, from regmap/laserax_regs.csv). Reset values are
// the defaults below; they must equal the CSV's reset column (checked by tb_regmap).
struct axis_regs {
    period_t period = laserax_top_cfg::PERIOD_DEFAULT;
    ratio_t ratio = laserax_top_cfg::RATIO_DEFAULT;
    offset_t comp_offset = 0;  // Q32.32 output counts added to N * R (thermal origin, K168)
    // Commit of the wide compensation registers (DESIGN §4.7): with comp_sync = 0 ratio and
    // comp_offset act in the call they are written; with comp_sync = 1 only in a call with
    // comp_commit = 1 (a bus host writes the words, then pulses comp_commit: no torn value).
    bool comp_sync = false;
    bool comp_commit = false;
    quad_decoder_cfg::glitch_t glitch_n = 2;
    laserax_top_cfg::debounce_t sw_debounce = 16;
    quad_decoder_cfg::spacing_t min_spacing = 8;
    output_pacer_cfg::pace_t pace_m = 61;
    output_pacer_cfg::thr_t backlog_thr = 4096;
    period_t mark_len = laserax_top_cfg::PERIOD_DEFAULT / 4;
    laserax_top_cfg::dacw_t dac_width = 16;
    dds_sincos_cfg::amp_t amplitude = laserax_top_cfg::AMP_DEFAULT;
    period_t tbl_period = laserax_top_cfg::PERIOD_DEFAULT;
    bool rehome = false;
    bool clear = false;
    bool tbl_we = false;
    // digital pins (DESIGN §4.7): bit 0 qz_window, bits 2:1 ab_rot, bit 3 hiz_alarm
    laserax_top_cfg::pin_cfg_t pin_cfg = 8;
    tbl_addr_t tbl_addr = 0;
    tbl_word_t tbl_data = 0;
    // position error map (docs/ERROR_MAP.md §8): map_en, bank_sel, the two bank geometries and
    // the table write port (writes the bank not selected in the call). Reset: map disabled.
    error_map_regs emap;
};

struct axis_pins {
    bool a = false, b = false, sw = false, lerr = false;
};

struct axis_out {
    dac_t sin = 0, cos = 0;
    bool ref_mark = false, qa = false, qb = false, qz = false;
    bool q_oe = false;  // A/B/Z driver enable: !(hiz_alarm && alarm)
    // status
    bool cfg_err = false;
    rephase_cfg::stage_t stage = 0;
    bool homed = false, lerr_alarm = false, illegal_st = false;
    quad_decoder_cfg::errcnt_t err_cnt = 0;
    bool ovs_edge_st = false, ovs_backlog_st = false, glitch_st = false, alarm = false;
    bool dac_clip_st = false;  // sticky: a DDS code outside +-(2^(dac_width-1) - 1) was clamped (DAC range guard)
    // taps: registered outputs of each block at this call
    raw_t raw_count = 0;
    step_t step = 0;
    pos_t comp_pos = 0;
    delta_t delta = 0;
    backlog_t backlog = 0;
    step_t pstep = 0;
    pos_t paced_pos = 0;
    step_t ostep = 0;
    pos_t out_pos = 0, adj = 0, a_pos = 0, b_pos = 0, c_pos = 0, z_pos = 0;
    rephase_cfg::ph_t d = 0;
    bool rep_mark = false;
    // error map (docs/ERROR_MAP.md §8)
    bool map_cfg_err = false;               // map_en with an invalid geometry of the selected bank
    error_map_cfg::corr_t corr = 0;     // correction of the last sampled comp (sampled in call t-28), output counts
    error_map_cfg::cdelta_t map_delta = 0;  // corr(t) - corr(t-1), added to the pacer input
};

// The pacer's two addends mul_q_.delta and emap_q_.delta (summed inside the pacer) together stay
// in delta_t: a multiplier delta is at most one step (< 2^5) plus a re-base
// |N| * |R' - R| / 2^32 <= 2^31 * 2^37 / 2^32 = 2^36 plus an offset change
// |OFF' - OFF| / 2^32 <= 2^32, and |map delta| < 2^(W_CDELTA-1) = 2^17, so the sum stays below
// 2^36 + 2^33 < 2^(W_DELTA-1) = 2^38 (docs/DESIGN.md §4.7).
static_assert(error_map_cfg::W_CDELTA <= output_pacer_cfg::W_ADD, "the map delta must fit the pacer's second addend");

// Configuration check (DESIGN §4.7), every call, of the registers in force (the values presented
// in the previous call: the register stage; hardware makes it on the presented values, registered).
inline LX_CONSTEXPR bool axis_config_ok(const axis_regs& r) {
    const bool period_ok = r.period >= axis_widths::P_MIN && r.period <= axis_widths::P_MAX &&
                           (r.period & (axis_widths::P_STEP - 1)) == 0;
    const bool width_ok = r.dac_width >= axis_widths::W_DAC_MIN && r.dac_width <= axis_widths::W_DAC_MAX;
    bool amp_ok = false;
    if (width_ok) {
        const dds_sincos_cfg::amp_t amp_max = (dds_sincos_cfg::amp_t(1) << (r.dac_width - 1)) - 1;
        amp_ok = r.amplitude >= 1 && r.amplitude <= amp_max;
    }
    const bool mark_ok = r.mark_len >= (r.period >> 2) && r.mark_len <= r.period;
    // count integrity (DESIGN §4.2): a pulse the glitch filter passes must be caught by the edge
    // spacing check, so min_spacing > max(glitch_n, 1) (one 16-bit comparator)
    const quad_decoder_cfg::spacing_t glitch_floor =
        (r.glitch_n == 0) ? quad_decoder_cfg::spacing_t(1) : quad_decoder_cfg::spacing_t(r.glitch_n);
    const bool spacing_ok = r.min_spacing > glitch_floor;
    return period_ok && width_ok && amp_ok && mark_ok && spacing_ok && r.ratio != 0 && r.pace_m >= 2 &&
           r.tbl_period == r.period && !r.tbl_we;  // table writes only in the safe state (§4.6)
}

// Quadrature level of the position index i mod 4: 0 -> (0,0), 1 -> (1,0), 2 -> (1,1), 3 -> (0,1).
inline void quad_levels(pos_t pos, bool& qa, bool& qb) {
    const uint<2> i = pos;  // low two bits = pos mod 4 (two's complement)
    // (qa = i == 1 || i == 2, qb = i == 2 || i == 3: from the two bits, qa = i0 ^ i1, qb = i1)
    const bool i1 = (i >> 1) != 0;
    qa = ((i & 1) != 0) != i1;
    qb = i1;
}

class laserax_top {
public:
    // No constructor: every member starts at its initialiser (constant initialisation: the
    // static top of hls/laserax_axil.cpp has no first-call code; CTest hls_const_init). reset()
    // is the safe state of the chain, which leaves the register stage, the held compensation
    // registers and the RAMs (DDS table, error-map tables and write delay line) as they are.
    void reset() {
        swf_.reset();
        dec_.reset();
        mul_.reset();
        pac_.reset();
        rep_.reset();
        dds_.reset();
        emap_.reset();  // pipeline only, not the table RAM nor the write port's delay line
        // inter-block registers (0 / false): the block outputs in out_ (every axis_out member has
        // a default member initialiser), and those no output shows
        out_ = axis_out{};
        lerr_q_ = false;
        slot_q_ = false;
        dig_q1_ = dig_tap{};  // out_pos mod 4 = 0, mark = index = 0
        dig_q2_ = dig_tap{};
        dig_q3_ = dig_tap{};
    }

    // the DDS of the chain: the table write port only in the safe state (no write bypass)
    using dds_type = dds_sincos_t<false>;
    dds_type& dds() { return dds_; }
#ifndef __SYNTHESIS__
    // RAM port violations of the chain's RAMs (lx_ram.h RAM_V_* bits, C simulation): 0 always
    int ram_violations() const { return dds_.ram_violations() | emap_.ram_violations(); }
#endif

#ifndef __SYNTHESIS__
    // Register write port (C simulation; DESIGN §4.7 unchanged): `r` is the block
    // presented in every call from the next tick() on, until the next write, i.e. in force from the
    // call after that tick. Only a write reloads the registers in force and checks them; a tick
    // with no write since the previous one presents the same block again (nothing to compare).
    void write_regs(const axis_regs& r) {
        presented_ = r;
        written_ = true;
        fast_ = false;
    }
    const axis_regs& presented() const { return presented_; }

    // One clock on the presented registers (the last write_regs()). The outputs of the call are the
    // core's output register file, returned by reference (no copy): valid until the next tick(),
    // step() or reset(); out() reads them too.
    LASERAX_FLATTEN const axis_out& tick(const axis_pins& pins) {
        // fast_: no write since the previous call, which ran on the same registers without a
        // reload: run() would skip its loads and checks, tbl_we in force is 0 (it fails the check)
        // and the block in force stays in force; only the blocks run
        if (fast_) {
            blocks(pins, regs_q_);
            return out_;
        }
        clock(pins);
        // the register load and its check, only after a write (same_q_: the block in force in
        // this call stays in force in the next)
        same_q_ = !written_;
        if (written_) {
            regs_q_ = presented_;
            chk_q_ = check(regs_q_);
            written_ = false;
        }
        fast_ = same_q_ && run_q_;
        return out_;
    }
#else
    // The synthesis view: the testbenches' write port and tick() are step() on the last block
    // written (host-side wrappers; the synthesis top calls step() only).
    void write_regs(const axis_regs& r) { presented_ = r; }
    const axis_regs& presented() const { return presented_; }
    const axis_out& tick(const axis_pins& pins) {
        (void)step(pins, presented_);
        return out_;
    }
#endif
    const axis_out& out() const { return out_; }

    // One clock with the register block `presented` presented in this call (in force in the next):
    // the write port and tick(). C simulation: a block with the bytes of the presented one is not
    // written again (it presents the same values). Synthesis: the register stage of every call.
    axis_out step(const axis_pins& pins, const axis_regs& presented) {
#ifdef __SYNTHESIS__
        clock(pins);
        regs_q_ = presented;
        chk_q_ = check(regs_q_);
        same_q_ = false;
        return out_;
#else
        if (!LASERAX_REGS_SAME(presented, presented_)) write_regs(presented);
        return tick(pins);
#endif
    }

private:
    // the chain's part of a clock: runs on the registers presented in the previous call (regs_q_,
    // read in place) and on their configuration check, made (in hardware) in that call on the
    // presented values and registered (chk_q_)
    void clock(const axis_pins& pins) {
        if (powered_) {
            run(pins, regs_q_);
        } else {
            safe_out(false, axis_regs{}.pin_cfg);  // power-up call: no registers in force, every block in reset
            powered_ = true;
        }
        tblw_q_ = regs_q_.tbl_we;  // the table write in force in this call (false in the power-up call)
    }

private:
    // outputs of a call in which the chain does not run (out_ holds the inter-block registers of
    // the reset, every field 0 / false): stage 1; cfg_err and alarm set in the safe state
    // (invalid configuration), not in the power-up call
    void safe_out(bool cfg_err, laserax_top_cfg::pin_cfg_t pin_cfg) {
        out_.cfg_err = cfg_err;
        out_.alarm = cfg_err;
        out_.stage = 1;
        pin_levels(out_, dig_tap{}, pin_cfg);
    }

    // one call of the chain on the registers in force; its outputs in out_, whose block outputs
    // are the inter-block registers the blocks of the next call read
    void run(const axis_pins& pins, const axis_regs& regs) {
        // The same registers in force as in the previous call (same_q_), which ran: the loads
        // and checks below would load the values they hold and find the configuration valid
        // again (the C-simulation write port only, see LASERAX_REGS_SAME; false in synthesis).
        if (!(same_q_ && run_q_)) {
            // held compensation registers: loaded in every call without comp_sync, else on
            // comp_commit; not part of the chain reset (register file state)
            if (!regs.comp_sync || regs.comp_commit) {
                ratio_h_ = regs.ratio;
                offset_h_ = regs.comp_offset;
            }
            // A period change while running is a reconfiguration: the phase counters of the old
            // period are meaningless for the next one, so the chain restarts (one call in the safe
            // state). Coming out of reset or of an invalid configuration the blocks are already
            // reset.
            const bool period_changed = run_q_ && regs.period != period_q_;
            // (a table write in force in the previous call holds the safe state one more call,
            // DESIGN §4.6: no running call reads a word in the call of its write or the next)
            const bool ok = chk_q_.ok && !tblw_q_ && ratio_h_ != 0 && !period_changed;
            period_q_ = regs.period;
            run_q_ = ok;
            if (!ok) {
                // DDS table writes: only here (tbl_we fails axis_config_ok), presented before the
                // DDS's call in reset, which performs it after its read of T[0] (true dual port: two
                // accesses in the call)
                if (regs.tbl_we) dds_.write(regs.tbl_addr, regs.tbl_data);
                reset();  // safe state: every block held in reset
                // (the error map's write port runs on through the reset, one write per call at
                // most: a write already in its delay line lands in its own call, rtl_ref i_rst)
                emap_.step_reset_port();
                safe_out(true, regs.pin_cfg);
                return;
            }
        }
        // (cfg_err: false in every call that runs the blocks; a call of blocks() alone, tick's
        // register stage without a write, follows such a call, so it holds there)
        out_.cfg_err = false;
        blocks(pins, regs);
    }

    // the blocks of one running call on the registers in force (run() made the checks)
    void blocks(const axis_pins& pins, const axis_regs& regs) {
        // Every block reads only inter-block registers of the previous call, so the order of the
        // steps within a call is free: they run downstream first, and each inter-block register is
        // loaded right after its last reader (no block output is held across the other steps).
        axis_out& o = out_;
        const dds_sincos_out dds = dds_.step(o.ostep, regs.period, regs.amplitude);
        // DAC range guard (DESIGN §4.7): the codes never leave +-(2^(dac_width-1) - 1), whatever
        // the table in use holds; a clamp sets the sticky dac_clip_st (clear first, event wins).
        // (o.dac_clip_st is the sticky flag's register: false after reset(), which clears out_)
        if (regs.clear) o.dac_clip_st = false;
        o.sin = clamp_dac(dds.sin, chk_q_.dac_hi, chk_q_.dac_lo);
        o.cos = clamp_dac(dds.cos, chk_q_.dac_hi, chk_q_.dac_lo);
        // digital outputs from the rephase outputs of call t-3 (out_pos mod 4 and mark; the index,
        // one call later in rephase, of call t-2), shifted through two taps: pin_levels below,
        // once the alarm of the call is formed
        const dig_tap dig = dig_q3_;
        // error map: indexed by the uncorrected comp of the previous call, active only while the
        // rephase of the previous call was homed; its delta is the pacer's second addend, summed
        // in the pacer's carry-save layer, so no adder precedes the pacer (L_MAP = 50 calls of map
        // latency, a sample every 32 calls, DESIGN §4.7); the delta is stored after the pacer read
        // that of the previous call
        const error_map::out_t emap = emap_.step(o.comp_pos, o.homed, regs.emap);
        o.map_cfg_err = emap.cfg_err;
        o.corr = emap.corr;
        // the pacer's wide: rephase was in its window in the previous call (read before its step)
        const bool wide = o.stage == rephase_cfg::STAGE_WINDOW;
        const rephase::out_t rep =
            rep_.step(o.pstep, slot_q_, swf_.level(), swf_.valid(), regs.rehome, lerr_q_, regs.period, regs.mark_len);
        dig_q3_ = dig_q2_;
        dig_q2_ = dig_q1_;
        dig_q2_.index = rep.index;  // (rtl_ref: rep_idx3_q, one stage fewer than out_pos, mark)
        dig_q1_.pos = rep.out_pos;
        dig_q1_.mark = rep.mark;
        o.ostep = rep.ostep;
        o.out_pos = rep.out_pos;
        o.rep_mark = rep.mark;
        o.stage = rep.stage;
        o.homed = rep.homed;
        o.adj = rep.adj;
        o.a_pos = rep.a;
        o.b_pos = rep.b;
        o.c_pos = rep.c;
        o.z_pos = rep.z;
        o.d = rep.d;
        const output_pacer::out_t pac =
            pac_.step(o.delta, o.map_delta, regs.pace_m, regs.backlog_thr, regs.clear, wide);
        slot_q_ = pac.slot;
        o.ovs_backlog_st = pac.ovs_st;
        o.backlog = pac.backlog;
        o.pstep = pac.pstep;
        o.paced_pos = pac.paced;
        o.map_delta = emap.delta;
        const pulse_multiplier::out_t mul = mul_.step(o.step, ratio_h_, offset_h_);
        o.comp_pos = mul.comp;
        o.delta = mul.delta;
        const quad_decoder::out_t dec =
            dec_.step(pins.a, pins.b, pins.lerr, regs.glitch_n, regs.min_spacing, regs.clear);
        o.step = dec.step;
        lerr_q_ = dec.lerr;
        o.lerr_alarm = dec.lerr_alarm;
        o.illegal_st = dec.illegal_st;
        o.err_cnt = dec.err_cnt;
        o.ovs_edge_st = dec.ovs_st;
        o.glitch_st = dec.glitch_st;
        o.raw_count = dec.raw_count;
        swf_.step(pins.sw, regs.sw_debounce);  // (its outputs f, valid: the registers level(), valid())
        // alarm: every alarm flag of the call (cfg_err is false in a call that runs the blocks)
        o.alarm = o.lerr_alarm || o.illegal_st || o.ovs_edge_st || o.map_cfg_err || o.dac_clip_st || o.ovs_backlog_st;
        pin_levels(o, dig, regs.pin_cfg);
    }

private:
    input_filter<laserax_top_cfg::W_DEBOUNCE> swf_;
    quad_decoder dec_;
    pulse_multiplier mul_;
    output_pacer pac_;
    rephase rep_;
    dds_type dds_;
    error_map emap_;
    // the outputs of the call: every block output in it is also the inter-block register that
    // the blocks of the next call read (decoder step, multiplier comp / delta, pacer pstep, map
    // delta, rephase ostep / out_pos / mark / homed)
    axis_out out_{};
    bool lerr_q_ = false;  // decoder lerr (the rephase's unhome), not an output
    bool slot_q_ = false;  // pacer slot (the rephase's slot), not an output
    // the rephase outputs behind the digital pins: out_pos mod 4, mark, index
    struct dig_tap {
        uint<2> pos = 0;
        bool mark = false, index = false;
    };
    // the digital pins of a call (DESIGN §4.7): qa/qb of (pos + ab_rot) mod 4, qz the index or
    // (qz_window) the mark, ref_mark the mark, q_oe = !(hiz_alarm && alarm) (o.alarm formed)
    static void pin_levels(axis_out& o, const dig_tap& d, laserax_top_cfg::pin_cfg_t pin_cfg) {
        const uint<2> rot = pin_cfg >> 1;
        quad_levels(pos_t(uint<2>(d.pos + rot)), o.qa, o.qb);
        o.qz = (pin_cfg & 1) != 0 ? d.mark : d.index;
        o.ref_mark = d.mark;
        o.q_oe = !((pin_cfg & 8) != 0 && o.alarm);
    }
    // of the rephase outputs in out_ (call t-1), and of calls t-2, t-3
    dig_tap dig_q1_, dig_q2_, dig_q3_;
    period_t period_q_ = 0;  // period register of the previous call
    ratio_t ratio_h_ = laserax_top_cfg::RATIO_DEFAULT;  // ratio in force (held, see comp_sync)
    offset_t offset_h_ = 0;                           // comp_offset in force
    bool run_q_ = false;     // the previous call ran with a valid configuration
    alignas(16) axis_regs regs_q_ = axis_regs{};  // registers presented in the previous call (in force now)
    // configuration check of regs_q_ (registered with it) and the DAC code limit of its dac_width
    struct reg_check {
        bool ok = false;
        dac_t dac_hi = 0;
        dac_t dac_lo = 0;  // -dac_hi
    };
    reg_check chk_q_ = check(axis_regs{});
    bool powered_ = false;            // false until the power-up call
    bool tblw_q_ = false;             // tbl_we in force in the previous call (DESIGN §4.6, §4.7)
    bool same_q_ = false;  // regs_q_ holds the block in force in the previous call too (not reloaded)
    // the block presented (the write port; C simulation, and the synthesis view's tick())
    alignas(16) axis_regs presented_ = axis_regs{};
#ifndef __SYNTHESIS__
    bool written_ = false;  // presented_ written since the last clock (reload and check after it)
    bool fast_ = false;     // the next tick runs the blocks only (see tick)
#endif

    static LX_CONSTEXPR reg_check check(const axis_regs& r) {
        reg_check c;
        c.ok = axis_config_ok(r);
        // read only while ok, i.e. with dac_width in W_DAC_MIN..W_DAC_MAX (the shift is defined)
        if (c.ok) c.dac_hi = dac_t((dds_sincos_cfg::amp_t(1) << (r.dac_width - 1)) - 1);
        c.dac_lo = dac_t(-c.dac_hi);
        return c;
    }

    // v clamped to lo .. hi (lo = -hi, formed with hi in check()); a clamp sets the sticky flag
    // dac_clip_st
    dac_t clamp_dac(dac_t v, dac_t hi, dac_t lo) {
        if (v > hi) {
            out_.dac_clip_st = true;
            return hi;
        }
        if (v < lo) {
            out_.dac_clip_st = true;
            return lo;
        }
        return v;
    }
};

}  // namespace lx

#endif  // LASERAX_HLS_LASERAX_TOP_H
