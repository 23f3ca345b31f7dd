// encoder_counter.h — two 32-bit signed wrapping encoder counters with encoder simulation,
// reset now / at the next start trigger, on-the-fly correction every 10 us and wait-for-encoder.
//
// docs/PSO_COUNTERS.md §3 is the normative per-call description; in short, per call:
//   correction  every corr_period calls (1000 = 10 us at 100 MHz) a sample call takes cnt_c (the
//               counter register before the call), scale_c and pos_c; CORR_LAT = 33 calls later
//               corr_c' = pos_c + round_half_up(scale_c * cnt_c / 2^24) and tick = 1. The product
//               is sequenced: the sample call loads the operands, then one shift-add step (a
//               33-bit add) per call for 32 calls, the last subtracting (two's complement
//               multiplier), then one 40-bit add of pos; corr_period >= CORR_LAT keeps one product
//               in flight (a sample while one runs, after a live lowering of corr_period, is
//               dropped);
//   counting    source 0: the quadrature step input; source 1: simulation, a Q0.32 phase
//               accumulator (1 MHz = 0.01 count/clock by default) whose carry is one count, up
//               or down, in the call after the carry (registered carry); cnt' = cnt + step with
//               32-bit wrap (max + 1 -> min);
//               reset request: immediately, or (rst_on_trig) at the first start trigger in a
//               later call; a reset clears the counter, the simulation phase and carry, and takes
//               priority over a load (preset) and over the step of that call;
//   wait        armed by wait_arm (channel, value, direction latched); judged on the wrap-aware
//               signed difference s32(cnt - value) of the counter register, strictly beyond the
//               value in the chosen direction, through two register stages: a counter that
//               passes the value in call t gives reached in call t + 2 (a value already passed
//               when armed in call a: reached in call a + 2).
//
// Widths: counters 32 signed; simulation rate Q0.32 (legal <= 0.25 count/clock = 25 MHz);
// scale Q8.24 signed (bits per count); product 64 signed; correction output 40 signed.
// Latency: a step at call t is in cnt of call t; the correction sampled in call s is in corr (with
// tick) in call s + CORR_LAT.
#ifndef LASERAX_HLS_ENCODER_COUNTER_H
#define LASERAX_HLS_ENCODER_COUNTER_H

#include "hls/axis_config.h"

namespace lx {

struct encoder_counter_cfg {
    // primary
    static constexpr int N_CH = 2;
    static constexpr int W_CNT = 32;     // counters, signed, wrap
    static constexpr int W_INC = 32;     // simulation rate, Q0.32 counts per clock
    static constexpr int S_FRAC = 24;    // scale fraction bits
    static constexpr int W_SCALE = 32;   // scale, signed Q8.24 bits per count
    static constexpr int W_PER = 16;     // correction period register, clocks
    static constexpr int W_POSIN = 32;   // nominal output position input, bits, signed
    static constexpr int PERIOD_DEFAULT = 1000;  // 10 us at 100 MHz
    static constexpr int CLOCK_HZ = 100000000;
    static constexpr int SIM_HZ_DEFAULT = 1000000;  // 1 MHz counting rate
    static constexpr int SIM_HZ_MAX = 25000000;     // 0.25 count per clock
    // derived
    static constexpr int W_PROD = W_SCALE + W_CNT;            // 64: |scale * cnt| <= 2^62
    static constexpr int W_CORR = W_PROD - S_FRAC;            // 40: |prod / 2^24| <= 2^38, + pos < 2^39
    // sequenced product: operand load (sample call), W_CNT shift-add steps, the add of pos
    static constexpr int CORR_LAT = W_CNT + 1;                // 33 calls from sample to corr
    static constexpr int W_ACC = W_SCALE + 1;                 // 33: partial-product register
    static constexpr int W_STEP = 6;                          // step counter 0..CORR_LAT
    // round(1 MHz / 100 MHz * 2^32) = 42949673 (0.9 ppb fast)
    static constexpr unsigned long long SIM_INC_DEFAULT =
        ((static_cast<unsigned long long>(SIM_HZ_DEFAULT) << (W_INC + 1)) / CLOCK_HZ + 1) / 2;
    static constexpr unsigned long long SIM_INC_MAX =
        (static_cast<unsigned long long>(SIM_HZ_MAX) << W_INC) / CLOCK_HZ;  // 2^30
    static constexpr unsigned long long HALF = 1ULL << (S_FRAC - 1);

    using cnt_t = sint<W_CNT>;
    using inc_t = uint<W_INC>;
    using scale_t = sint<W_SCALE>;
    using per_t = uint<W_PER>;
    using posin_t = sint<W_POSIN>;
    using prod_t = sint<W_PROD>;
    using corr_t = sint<W_CORR>;
    using acc_t = sint<W_ACC>;
    using lo_t = uint<W_CNT>;
    using stepcnt_t = uint<W_STEP>;
    static constexpr int W_SRC = 2;  // source register
    using src_t = uint<W_SRC>;  // 0 quadrature step, 1 simulation (2, 3 illegal)
};

// Per-channel arrays are listed element by element: neither vendor integer type zeroes itself, so
// an array member needs an initialiser for each element (a shorter list would leave the rest to
// the vendor's default constructor).
static_assert(encoder_counter_cfg::N_CH == 2, "the per-channel initialisers below list two channels");

struct encoder_counter_regs {
    encoder_counter_cfg::src_t src[encoder_counter_cfg::N_CH] = {0, 0};
    encoder_counter_cfg::inc_t sim_inc[encoder_counter_cfg::N_CH] = {encoder_counter_cfg::SIM_INC_DEFAULT,
                                                                     encoder_counter_cfg::SIM_INC_DEFAULT};
    bool sim_down[encoder_counter_cfg::N_CH] = {false, false};
    encoder_counter_cfg::scale_t scale[encoder_counter_cfg::N_CH] = {0, 0};
    bool rst_req[encoder_counter_cfg::N_CH] = {false, false};  // pulse: reset request
    bool load[encoder_counter_cfg::N_CH] = {false, false};     // pulse: preset the counter to load_val
    encoder_counter_cfg::cnt_t load_val[encoder_counter_cfg::N_CH] = {0, 0};
    bool rst_on_trig = false;                  // reset at the next start trigger instead of now
    encoder_counter_cfg::per_t corr_period = encoder_counter_cfg::PERIOD_DEFAULT;
    bool wait_arm = false;                     // pulse
    bool wait_ch = false;                      // false: counter 0, true: counter 1
    encoder_counter_cfg::cnt_t wait_val = 0;
    bool wait_down = false;                    // false: wait to overstep, true: to understep
};

struct encoder_counter_in {
    step_t qstep[encoder_counter_cfg::N_CH] = {0, 0};                 // from the quadrature decoders
    bool trig = false;                                                // start trigger (pulse)
    encoder_counter_cfg::posin_t pos[encoder_counter_cfg::N_CH] = {0, 0};  // nominal output position, bits
};

inline bool encoder_counter_config_ok(const encoder_counter_regs& r) {
    bool ok = r.corr_period >= encoder_counter_cfg::CORR_LAT;
#pragma hls_unroll yes
    LX_LOOP(check_ch) for (int c = 0; c < encoder_counter_cfg::N_CH; ++c) {
#pragma HLS UNROLL
        ok = ok && r.src[c] <= 1;
        ok = ok && (r.src[c] != 1 || r.sim_inc[c] <= encoder_counter_cfg::SIM_INC_MAX);
    }
    return ok;
}

class encoder_counter {
public:
    using cfg = encoder_counter_cfg;
    struct out_t {
        cfg::cnt_t cnt[cfg::N_CH] = {0, 0};
        step_t step[cfg::N_CH] = {0, 0};              // count applied in this call
        bool rst_done[cfg::N_CH] = {false, false};    // the counter was reset in this call
        bool rst_pending[cfg::N_CH] = {false, false}; // waiting for a start trigger
        cfg::corr_t corr[cfg::N_CH] = {0, 0};         // corrected output positions (held between ticks)
        bool tick = false;                            // corr updated in this call (CORR_LAT after its sample call)
        bool waiting = false;
        bool reached = false;                         // pulse: the awaited counter passed the value
        bool cfg_err = false;
    };

    void reset() { *this = encoder_counter{}; }  // every register to its initialiser (the reset value)

    out_t step(const encoder_counter_in& in, const encoder_counter_regs& r) {
        out_t o;  // every field 0 / false (default member initialisers)
        if (!encoder_counter_config_ok(r)) {
            reset();
            o.cfg_err = true;
            return o;
        }
        // correction, sequenced (docs/PSO_COUNTERS.md §3.2): k_ = 0 idle, 1 + i: step i next
        // (i = 0..W_CNT-1), CORR_LAT: add pos. Step i adds bit i of the counter times the scale
        // (i = W_CNT - 1 subtracts: the sign bit of a two's complement multiplier) to the upper
        // half, then shifts {hi, lo} right. hi starts at 2^(S_FRAC-1): after W_CNT shifts
        // {hi, lo} = scale * cnt + 2^(S_FRAC-1).
        const bool done = k_ == cfg::CORR_LAT;
#pragma hls_unroll yes
        LX_LOOP(corr_ch) for (int c = 0; c < cfg::N_CH; ++c) {
#pragma HLS UNROLL
            if (done) {
                // {hi, lo} >> S_FRAC, low W_CORR bits (the quotient fits), plus the sampled position
                const cfg::corr_t q = (hi_[c].to_uint64() << (cfg::W_CNT - cfg::S_FRAC)) |
                                      (lo_[c].to_uint64() >> cfg::S_FRAC);
                corr_[c] = q + p_[c];
            } else if (k_ != 0) {
                shift_add(c, k_.to_int() == cfg::W_CNT);
            }
        }
        k_ = done ? cfg::stepcnt_t(0) : k_ != 0 ? cfg::stepcnt_t(k_ + 1) : k_;
        const bool sample = timer_ + 1 >= r.corr_period;
        timer_ = sample ? cfg::per_t(0) : cfg::per_t(timer_ + 1);
        // a sample while a product is in flight (only after corr_period was lowered live) is
        // dropped: the running product finishes
        if (sample && k_ == 0) {
#pragma hls_unroll yes
            LX_LOOP(sample_ch) for (int c = 0; c < cfg::N_CH; ++c) {
#pragma HLS UNROLL
                hi_[c] = cfg::acc_t(cfg::HALF);
                lo_[c] = cfg::lo_t(cnt_[c]);  // the counter before this call
                m_[c] = r.scale[c];
                p_[c] = in.pos[c];
            }
            k_ = 1;
        }
        // wait, two register stages: the flags computed in the previous call (from the counter
        // before it and the value latched then) decide this call, unless an arm came between;
        // then this call's flags from the counter registers before the call
        bool reached = false;
        if (waiting_ && f_ok_) {
            reached = w_down_ ? f_neg_ : f_pos_;
            if (reached) waiting_ = false;
        }
        {
            const cfg::cnt_t diff = cnt_[w_ch_ ? 1 : 0] - w_val_;  // wrap-aware signed difference
            f_neg_ = diff < 0;
            f_pos_ = diff > 0;
            f_ok_ = !r.wait_arm;  // an arm in this call changes the value: these flags are stale
        }
#pragma hls_unroll yes
        LX_LOOP(count_ch) for (int c = 0; c < cfg::N_CH; ++c) {
#pragma HLS UNROLL
            // simulation: the carry of the phase accumulator counts in the next call (sc_)
            const uint<cfg::W_INC + 1> sum = uint<cfg::W_INC + 1>(ph_[c]) + r.sim_inc[c];
            const bool carry = (sum >> cfg::W_INC) != 0;
            ph_[c] = sum;
            step_t st = 0;
            if (r.src[c] == 1) {
                if (sc_[c]) st = r.sim_down[c] ? step_t(-1) : step_t(1);
            } else {
                st = in.qstep[c];
            }
            sc_[c] = carry;
            const bool do_rst = (r.rst_req[c] && !r.rst_on_trig) || (pending_[c] && in.trig);
            pending_[c] = (r.rst_req[c] && r.rst_on_trig) || (pending_[c] && !in.trig);
            if (do_rst) {
                cnt_[c] = 0;
                ph_[c] = 0;
                sc_[c] = false;
                st = 0;
            } else if (r.load[c]) {
                cnt_[c] = r.load_val[c];
                st = 0;
            } else {
                cnt_[c] = cnt_[c] + st;  // 32-bit wrap: max + 1 -> min
            }
            o.step[c] = st;
            o.rst_done[c] = do_rst;
        }
        if (r.wait_arm) {
            waiting_ = true;
            w_ch_ = r.wait_ch;
            w_val_ = r.wait_val;
            w_down_ = r.wait_down;
        }
#pragma hls_unroll yes
        LX_LOOP(out_ch) for (int c = 0; c < cfg::N_CH; ++c) {
#pragma HLS UNROLL
            o.cnt[c] = cnt_[c];
            o.rst_pending[c] = pending_[c];
            o.corr[c] = corr_[c];
        }
        o.tick = done;
        o.waiting = waiting_;
        o.reached = reached;
        return o;
    }

private:
    // one step of the sequenced product of channel c: hi += bit0(lo) ? (last ? -m : m) : 0, then
    // {hi, lo} >>= 1 (arithmetic); |hi +- m| < 2^32 fits W_ACC bits
    void shift_add(int c, bool last) {
        const bool b = (lo_[c].to_uint64() & 1u) != 0;
        const cfg::acc_t add = !b ? cfg::acc_t(0) : last ? cfg::acc_t(-cfg::acc_t(m_[c])) : cfg::acc_t(m_[c]);
        const cfg::acc_t s = hi_[c] + add;
        lo_[c] = cfg::lo_t((lo_[c].to_uint64() >> 1) | ((s.to_uint64() & 1u) << (cfg::W_CNT - 1)));
        hi_[c] = cfg::acc_t(s >> 1);
    }

    cfg::cnt_t cnt_[cfg::N_CH] = {0, 0};
    cfg::inc_t ph_[cfg::N_CH] = {0, 0};
    bool sc_[cfg::N_CH] = {false, false};       // simulation carry of the previous call (counted in this call)
    bool pending_[cfg::N_CH] = {false, false};
    cfg::corr_t corr_[cfg::N_CH] = {0, 0};
    cfg::acc_t hi_[cfg::N_CH] = {0, 0};         // sequenced product: upper half (signed)
    cfg::lo_t lo_[cfg::N_CH] = {0, 0};          //   lower half: counter bits not yet used, product bits below
    cfg::scale_t m_[cfg::N_CH] = {0, 0};        //   sampled scale
    cfg::posin_t p_[cfg::N_CH] = {0, 0};        //   sampled position
    cfg::stepcnt_t k_ = 0;                      //   0 idle, 1 + i: step i this call, CORR_LAT: add pos
    cfg::per_t timer_ = 0;
    bool waiting_ = false;
    bool f_neg_ = false, f_pos_ = false, f_ok_ = false;  // wait flags of the previous call: s32(cnt - val) < 0, > 0, valid
    bool w_ch_ = false;
    cfg::cnt_t w_val_ = 0;
    bool w_down_ = false;
};

}  // namespace lx

#endif  // LASERAX_HLS_ENCODER_COUNTER_H
