// error_map.h — position error mapping: a correction table over equally spaced positions, linear
// interpolation between points, the correction delivered as whole output counts to add or remove.
//
// docs/ERROR_MAP.md is the normative per-call description; in short:
//
//   stage A (this call's inputs)   off = p - origin; clamp to the table ([0, (n-1) * 2^k]: outside
//                                  it the end point is used with frac = 0); i = off >> k,
//                                  frac = off & (2^k - 1); both table reads T[i], T[i+1] of the
//                                  active bank (true dual-port BRAM, registered read), frac and the
//                                  flags are registered beside them.
//   stage B (stage A of last call) num = T[i] * 2^k + (T[i+1] - T[i]) * frac   (exact, Q.(F+k))
//                                  corr' = active ? floor(num / 2^(F+k) + 1/2) : 0
//                                  delta = corr' - corr
//
// Two banks, two separate arrays (RAMs): the table write port always writes the bank that is
// *not* selected by bank_sel in that call (so each true dual-port RAM sees at most two accesses
// per call: two reads, or one write), and each bank has its own geometry (origin, spacing_log2,
// n_points). Both reads of a call and the geometry they use come from the bank selected in
// that call, so a flip of bank_sel switches table and geometry together at one call boundary
// and a reload can never mix tables.
//
// Widths (derived in error_map_cfg): table words 24 bits signed Q15.8 counts, offset 39 signed,
// frac 20 unsigned, interpolation numerator 46 signed, corr 17 signed, delta 18 signed.
// Latency: 2 calls — p given in call t is reflected in the corr/delta returned by call t+1.
#ifndef LASERAX_HLS_ERROR_MAP_H
#define LASERAX_HLS_ERROR_MAP_H

#include "hls/axis_config.h"

namespace lx {

struct error_map_cfg {
    // primary
    static constexpr int TBL_DEPTH = 2048;  // points per bank
    static constexpr int W_CORR = 24;       // table word, signed
    static constexpr int F = 8;             // fraction bits of a table word (1/256 count)
    static constexpr int K_MIN = 4;         // spacing 2^k counts, k = K_MIN..K_MAX
    static constexpr int K_MAX = 20;
    static constexpr int N_BANKS = 2;
    // derived
    static constexpr int W_ADDR = clog2p1(TBL_DEPTH - 1);        // 11
    static constexpr int W_N = clog2p1(2 * TBL_DEPTH - 1);        // 12, n_points register
    static constexpr int W_K = clog2p1(31);                       // 5, spacing_log2 register
    static constexpr int W_OFF = axis_widths::W_POS + 1;          // 39, p - origin
    static constexpr int W_FRAC = K_MAX;                          // 20, position inside an interval
    static constexpr int W_ONE = K_MAX + 1;                       // 21, 2^k
    static constexpr int W_DIFF = W_CORR + 1;                     // 25, T[i+1] - T[i]
    static constexpr int W_NUM = W_DIFF + W_ONE;                  // 46, interpolation numerator
    static constexpr int W_C = W_CORR - F + 1;                    // 17, rounded correction
    static constexpr int W_CDELTA = W_C + 1;                      // 18, corr' - corr

    using word_t = sint<W_CORR>;
    using addr_t = uint<W_ADDR>;
    using n_t = uint<W_N>;
    using k_t = uint<W_K>;
    using off_t = sint<W_OFF>;
    using frac_t = uint<W_FRAC>;
    using one_t = uint<W_ONE>;
    using num_t = sint<W_NUM>;
    using corr_t = sint<W_C>;
    using cdelta_t = sint<W_CDELTA>;
};

// Geometry of one bank.
struct error_map_geom {
    pos_t origin = 0;                          // position of table point 0, output counts
    error_map_cfg::k_t spacing_log2 = 10;      // points are 2^k counts apart
    error_map_cfg::n_t n_points = error_map_cfg::TBL_DEPTH;
};

// Register block.
struct error_map_regs {
    bool map_en = false;
    bool bank_sel = false;                     // active bank of this call
    error_map_geom geom[error_map_cfg::N_BANKS];
    bool we = false;                           // table write port: writes bank !bank_sel
    error_map_cfg::addr_t addr = 0;
    error_map_cfg::word_t data = 0;            // correction, Q15.8 output counts
};

inline bool error_map_geom_ok(const error_map_geom& g) {
    return g.spacing_log2 >= error_map_cfg::K_MIN && g.spacing_log2 <= error_map_cfg::K_MAX &&
           g.n_points >= 2 && g.n_points <= error_map_cfg::TBL_DEPTH;
}

class error_map {
public:
    using cfg = error_map_cfg;
    struct out_t {
        cfg::corr_t corr = 0;     // correction in whole output counts (0 while inactive)
        cfg::cdelta_t delta = 0;  // corr' - corr: counts to add (> 0) or remove (< 0)
        bool active = false;          // map_en && homed && valid geometry (of the input call)
        bool in_range = false;        // active and p inside [origin, origin + (n-1) * 2^k]
        bool clamped = false;         // active and p outside: the end value is held
        bool cfg_err = false;         // map_en and the selected bank's geometry is invalid
    };

    error_map() {
        for (int a = 0; a < cfg::TBL_DEPTH; ++a) {
            tbl0_[a] = 0;
            tbl1_[a] = 0;
        }
        reset();
    }

    // Reset of the pipeline (not of the table RAM).
    void reset() {
        t0_q_ = 0;
        t1_q_ = 0;
        frac_q_ = 0;
        k_q_ = cfg::K_MIN;
        act_q_ = false;
        inr_q_ = false;
        err_q_ = false;
        corr_ = 0;
    }

    out_t step(pos_t p, bool homed, const error_map_regs& r) {
        // ---- stage B: interpolate the reads registered by the previous call -----------------
        const cfg::one_t one = cfg::one_t(1) << k_q_.to_uint();  // 2^k
        const cfg::num_t diff = cfg::num_t(t1_q_) - cfg::num_t(t0_q_);
        const cfg::num_t num = cfg::num_t(t0_q_) * cfg::num_t(one) + diff * cfg::num_t(frac_q_);
        const int sh = cfg::F + k_q_.to_int();
        const cfg::num_t half = cfg::num_t(1) << (sh - 1);
        const cfg::corr_t c_next = act_q_ ? cfg::corr_t((num + half) >> sh) : cfg::corr_t(0);
        out_t o;
        o.corr = c_next;
        o.delta = cfg::cdelta_t(c_next) - cfg::cdelta_t(corr_);
        o.active = act_q_;
        o.in_range = act_q_ && inr_q_;
        o.clamped = act_q_ && !inr_q_;
        o.cfg_err = err_q_;
        corr_ = c_next;

        // ---- stage A: address, clamp and the two reads of the selected bank ----------------
        const int bs = r.bank_sel ? 1 : 0;
        const error_map_geom& g = r.geom[bs];
        const bool geom_ok = error_map_geom_ok(g);
        const int k = geom_ok ? g.spacing_log2.to_int() : cfg::K_MIN;
        const cfg::addr_t last_i = geom_ok ? cfg::addr_t(g.n_points - 1) : cfg::addr_t(0);
        const cfg::off_t off = cfg::off_t(p) - cfg::off_t(g.origin);
        const cfg::off_t last_off = cfg::off_t(last_i) << k;  // (n-1) * 2^k < 2^31
        cfg::addr_t i0 = 0;
        cfg::frac_t frac = 0;
        bool inr = false;
        if (off < 0) {
            i0 = 0;
            frac = 0;
            inr = false;
        } else if (off >= last_off) {
            i0 = last_i;
            frac = 0;
            inr = off == last_off;
        } else {
            i0 = cfg::addr_t(off >> k);
            frac = cfg::frac_t(off & ((cfg::off_t(1) << k) - 1));
            inr = true;
        }
        const cfg::addr_t i1 = (i0 == last_i) ? i0 : cfg::addr_t(i0 + 1);
        // Two separate RAMs: the selected bank sees the two reads, the other one at most the
        // write port (below), so neither has more than two accesses in a call.
        if (bs == 0) {
            t0_q_ = tbl0_[i0.to_uint()];
            t1_q_ = tbl0_[i1.to_uint()];
        } else {
            t0_q_ = tbl1_[i0.to_uint()];
            t1_q_ = tbl1_[i1.to_uint()];
        }
        frac_q_ = frac;
        k_q_ = k;
        act_q_ = r.map_en && homed && geom_ok;
        inr_q_ = inr;
        err_q_ = r.map_en && !geom_ok;

        // ---- write port: the inactive bank only (never read in this call) --------------------
        if (r.we) {
            if (bs == 0) tbl1_[r.addr.to_uint()] = r.data;
            else tbl0_[r.addr.to_uint()] = r.data;
        }
        return o;
    }

private:
    // the two banks, each its own true dual-port BRAM (2048 x 24 bits)
    static_assert(cfg::N_BANKS == 2, "error_map: banks tbl0_, tbl1_");
    cfg::word_t tbl0_[cfg::TBL_DEPTH];
#pragma HLS BIND_STORAGE variable = tbl0_ type = ram_t2p impl = bram
    cfg::word_t tbl1_[cfg::TBL_DEPTH];
#pragma HLS BIND_STORAGE variable = tbl1_ type = ram_t2p impl = bram
    cfg::word_t t0_q_, t1_q_;  // T[i], T[i+1] (registered BRAM outputs)
    cfg::frac_t frac_q_;
    cfg::k_t k_q_;
    bool act_q_, inr_q_, err_q_;
    cfg::corr_t corr_;
};

}  // namespace lx

#endif  // LASERAX_HLS_ERROR_MAP_H
