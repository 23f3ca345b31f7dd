// error_map.h — position error mapping: a correction table over equally spaced positions, linear
// interpolation between points, the correction delivered as whole output counts to add or remove.
//
// docs/ERROR_MAP.md is the normative per-call description (§4: the inputs are sampled once every
// S_MAP = 32 calls; stages A .. D run every call, one register stage per call, then a sequenced
// shift-and-add multiplier; sized for an iCE40 HX8K clock of >= 120 MHz); in short:
//
//   A  off = p - origin (registered 39-bit subtract), geometry check, k, last, flags
//   B  i = floor(off / 2^k) mod TBL_DEPTH, u = (off mod 2^k) * 2^(20-k), off < 0, off beyond
//      every address (no compare: field selects of the registered offset)
//   C  clamp to [0, last] (10-bit compare), the addresses: even RAM (i+1)/2, odd RAM i/2
//   R  the two reads of the selected bank (T[i] and T[i+1] always lie in different RAMs: one read
//      per RAM), and the delayed write into the other bank
//   D  bank multiplexer: e = even word, o = odd word; v = i odd ? 2^20 - u : u (no swap mux)
//   M  (sample call t: calls t+5 .. t+26) load diff = o - e, v, e + 128; 21 steps of
//      s = hi + (v bit j ? diff : 0), hi = s >> 1 (LSB first, 26-bit adder)
//   G  (call t+27) corr = floor((2 hi + e + 128 + last bit shifted out) / 2^8)
//      = floor((e 2^20 + diff v + 2^27) / 2^28), held until the next sample's G
//   H  output registers: corr, delta = corr' - corr, flags (every call)
//
// Two banks, each two RAMs (even and odd words): the table write port always writes the bank that
// is *not* selected by bank_sel in that call, delayed by three registers so that it is performed
// in the same call as that call's reads (stage R) — into the other bank, so each RAM sees one access
// per call (a read, or a write) and the reads of call t see exactly the writes of the calls before
// t. Each bank has its own geometry (origin, spacing_log2, n_points); a flip of bank_sel switches
// table and geometry together at one call boundary and a reload can never mix tables.
//
// Widths (derived in error_map_cfg): table words 24 bits signed Q15.8 counts, offset 39 signed,
// u 20 unsigned, v 21, diff 25 signed, multiplier accumulator 26 signed, corr 17 signed, delta 18.
// Sample period S_MAP = 32 calls (phase counter 0 after reset: the first call after a reset is a
// sample call); latency L_MAP = 29 calls — the inputs of sample call t are reflected in the
// corr/delta returned by call t+28 and held until call t+59.
#ifndef LASERAX_HLS_ERROR_MAP_H
#define LASERAX_HLS_ERROR_MAP_H

#include "hls/axis_config.h"

namespace lx {

struct error_map_cfg {
    // primary
    static constexpr int TBL_DEPTH = 1024;  // points per bank (iCE40 default: 12 SB_RAM40_4K)
    static constexpr int W_CORR = 24;       // table word, signed
    static constexpr int F = 8;             // fraction bits of a table word (1/256 count)
    static constexpr int K_MIN = 4;         // spacing 2^k counts, k = K_MIN..K_MAX
    static constexpr int K_MAX = 20;
    static constexpr int N_BANKS = 2;
    static constexpr int S_MAP = 32;        // calls per sample (a power of two: wrapping counter)
    static constexpr int L_MAP = 29;        // sample call t -> outputs of call t + L_MAP - 1
    // derived
    static constexpr int W_ADDR = clog2p1(TBL_DEPTH - 1);        // 10
    static constexpr int HALF_DEPTH = TBL_DEPTH / 2;             // 512 words per parity RAM
    static constexpr int W_HADDR = W_ADDR - 1;                   // 9
    static constexpr int W_N = clog2p1(2 * TBL_DEPTH - 1);        // 11, n_points register
    static constexpr int W_K = clog2p1(31);                       // 5, spacing_log2 register
    static constexpr int W_OFF = axis_widths::W_POS + 1;          // 39, p - origin
    static constexpr int W_FRAC = K_MAX;                          // 20, u: frac in 2^-K_MAX units
    static constexpr int W_V = K_MAX + 1;                         // 21, v: 0 .. 2^K_MAX
    static constexpr int W_PHM = clog2p1(S_MAP - 1);              // 5, phase counter
    static constexpr int PH_LOAD = 5;                             // stage D holds the sample
    static constexpr int PH_G = PH_LOAD + 1 + W_V;                // 27: after the 21 steps
    static constexpr int W_DIFF = W_CORR + 1;                     // 25, odd word - even word
    static constexpr int W_MHI = W_DIFF + 1;                      // 26, multiplier accumulator
    static constexpr int W_ME = W_CORR + 1;                       // 25, e + 2^(F-1)
    static constexpr int W_G = W_MHI + 1;                         // 27, 2 hi + m_e + bit
    static constexpr int W_C = W_CORR - F + 1;                    // 17, rounded correction
    static constexpr int W_CDELTA = W_C + 1;                      // 18, corr' - corr
    static_assert(TBL_DEPTH % 2 == 0 && (1 << W_ADDR) == TBL_DEPTH, "error_map: depth a power of two");
    static_assert((S_MAP & (S_MAP - 1)) == 0 && PH_G + 1 == L_MAP - 1 && L_MAP - 1 < S_MAP,
                  "error_map: one sample in flight, published before the next is sampled");
    static_assert(K_MAX + 1 == W_V, "error_map: G folds the 2^(K_MAX) term of v into m_hi's bit");
    static_assert(K_MAX + W_ADDR < W_OFF - 1, "error_map: the 'beyond every address' bound fits off_t");

    using word_t = sint<W_CORR>;
    using addr_t = uint<W_ADDR>;
    using haddr_t = uint<W_HADDR>;
    using n_t = uint<W_N>;
    using k_t = uint<W_K>;
    using off_t = sint<W_OFF>;
    using frac_t = uint<W_FRAC>;
    using v_t = uint<W_V>;
    using diff_t = sint<W_DIFF>;
    using mhi_t = sint<W_MHI>;
    using me_t = sint<W_ME>;
    using g_t = sint<W_G>;
    using phm_t = uint<W_PHM>;
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
        for (int a = 0; a < cfg::HALF_DEPTH; ++a) {
            tbl0e_[a] = 0;
            tbl0o_[a] = 0;
            tbl1e_[a] = 0;
            tbl1o_[a] = 0;
        }
        w1_ = wr_t{};
        w2_ = wr_t{};
        w3_ = wr_t{};
        reset();
    }

    // Reset of the pipeline (not of the table RAM). The writes already in the write-port
    // registers belong to running calls: they are performed, never dropped (ERROR_MAP.md §4).
    void reset() {
        write(w3_);
        write(w2_);
        write(w1_);
        w1_ = wr_t{};
        w2_ = wr_t{};
        w3_ = wr_t{};
        a_ = st_a{};
        b_ = st_b{};
        c_ = st_c{};
        rd_ = st_r{};
        d_ = st_d{};
        m_ = st_m{};
        g_ = st_g{};
        ph_ = 0;
        corr_ = 0;
        idle_ = true;
    }

    out_t step(pos_t p, bool homed, const error_map_regs& r) {
        // ---- idle hold: a clock enable of the stages A .. H (not of the write port and ph) ----
        // With map_en = 0 and no active or erroneous sample anywhere in the stages (idle_), a
        // full call would shift in values flagged inactive and return corr = delta = 0 with every
        // flag false; the data fields of inactive stages are never read (every use of them is
        // gated by the act flag that travels with them, and the flags are recomputed from the
        // call's inputs in stage A), so the stages may hold instead. Same outputs, fewer toggles.
        if (!r.map_en && idle_) {
            // the write port holds too while no write is in flight or presented: its delay
            // registers then all have we = 0, and their bank, address and data are read only
            // with we = 1 (a clock enable; same writes, same outputs)
            if (r.we || w1_.we || w2_.we || w3_.we) {
                write(w3_);
                shift_write_port(r);
            }
            ph_ = cfg::phm_t(ph_ + 1);  // wraps at S_MAP
            return out_t{};
        }
        // ---- H: output registers ------------------------------------------------------------
        out_t o;
        o.corr = g_.corr;
        o.delta = cfg::cdelta_t(g_.corr) - cfg::cdelta_t(corr_);
        o.active = g_.fl.act;
        o.in_range = g_.fl.act && g_.fl.inr;
        o.clamped = g_.fl.act && !g_.fl.inr;
        o.cfg_err = g_.fl.err;
        corr_ = g_.corr;

        // ---- G (ph = PH_G): round the sample's product; held in every other call -----------
        const unsigned ph = ph_.to_uint();
        st_g g = g_;
        if (ph == cfg::PH_G) {
            const cfg::g_t x = cfg::g_t(m_.hi) * cfg::g_t(2) + cfg::g_t(m_.e) + cfg::g_t(m_.b ? 1 : 0);
            g.corr = m_.fl.act ? cfg::corr_t(x >> cfg::F) : cfg::corr_t(0);
            g.fl = m_.fl;
        }

        // ---- M: sequenced multiply diff * v, LSB first (load at PH_LOAD, 21 steps) ------------
        st_m m = m_;
        if (ph == cfg::PH_LOAD) {
            m.hi = 0;
            m.b = false;
            m.v = d_.v;
            m.diff = cfg::diff_t(d_.o) - cfg::diff_t(d_.e);
            m.e = cfg::me_t(d_.e) + cfg::me_t(1 << (cfg::F - 1));
            m.fl = d_.fl;
        } else if (ph > cfg::PH_LOAD && ph < cfg::PH_G) {
            const cfg::mhi_t sum = cfg::mhi_t(m_.hi) + ((m_.v & 1) != 0 ? cfg::mhi_t(m_.diff) : cfg::mhi_t(0));
            m.hi = sum >> 1;
            m.b = (sum & 1) != 0;
            m.v = m_.v >> 1;
        }

        // ---- D: difference of the two words, orientation of the interval ----------------------
        st_d d;
        d.e = rd_.we;
        d.o = rd_.wo;
        d.v = rd_.lsb ? cfg::v_t(cfg::v_t(1 << cfg::K_MAX) - cfg::v_t(rd_.u)) : cfg::v_t(rd_.u);
        d.fl = rd_.fl;

        // ---- R: the two reads (one per RAM of the selected bank), the delayed write ------------
        st_r rd;
        if (c_.bank) {
            rd.we = tbl1e_[c_.ea.to_uint()];
            rd.wo = tbl1o_[c_.oa.to_uint()];
        } else {
            rd.we = tbl0e_[c_.ea.to_uint()];
            rd.wo = tbl0o_[c_.oa.to_uint()];
        }
        rd.u = c_.u;
        rd.lsb = c_.lsb;
        rd.fl = c_.fl;
        write(w3_);  // the write of the same call as these reads: always the other bank

        // ---- C: clamp, the two addresses (registered) --------------------------------------------
        st_c c;
        const bool above = !b_.neg && (b_.hi || b_.i >= b_.last);
        const cfg::addr_t i = b_.neg ? cfg::addr_t(0) : (above ? b_.last : b_.i);
        c.u = (b_.neg || above) ? cfg::frac_t(0) : b_.u;
        c.lsb = (i & 1) != 0;
        c.fl = b_.fl;
        c.fl.inr = !b_.neg && (!above || (!b_.hi && b_.i == b_.last && b_.u == 0));
        c.ea = cfg::haddr_t((uint<cfg::W_ADDR + 1>(i) + 1) >> 1);  // (i + 1) / 2, wraps at the end
        c.oa = cfg::haddr_t(i >> 1);
        c.bank = b_.bank;

        // ---- B: split the registered offset (field selects by k, no compare) -------------------
        st_b b;
        const int kb = a_.k.to_int();
        b.neg = a_.off < 0;
        b.hi = a_.off >= (cfg::off_t(1) << (kb + cfg::W_ADDR));
        b.i = cfg::addr_t(a_.off >> kb);
        b.u = cfg::frac_t(cfg::frac_t(a_.off) << (cfg::K_MAX - kb));  // low k bits, left-aligned
        b.last = a_.last;
        b.bank = a_.bank;
        b.fl = a_.fl;

        // ---- A: this call's inputs: geometry of the selected bank, registered subtract ---------
        st_a a;
        const int bs = r.bank_sel ? 1 : 0;
        const error_map_geom& gm = r.geom[bs];
        const bool geom_ok = error_map_geom_ok(gm);
        a.k = geom_ok ? gm.spacing_log2 : cfg::k_t(cfg::K_MIN);
        a.last = geom_ok ? cfg::addr_t(gm.n_points - 1) : cfg::addr_t(0);
        a.off = cfg::off_t(p) - cfg::off_t(gm.origin);
        a.bank = r.bank_sel;
        a.fl.act = r.map_en && homed && geom_ok;
        a.fl.inr = false;
        a.fl.err = r.map_en && !geom_ok;

        // ---- write port: first register (the write goes to the bank not selected now) ---------
        shift_write_port(r);

        a_ = a;
        b_ = b;
        c_ = c;
        rd_ = rd;
        d_ = d;
        m_ = m;
        g_ = g;
        ph_ = cfg::phm_t(ph + 1);  // wraps at S_MAP
        idle_ = !(a.fl.act || a.fl.err || b.fl.act || b.fl.err || c.fl.act || c.fl.err || rd.fl.act || rd.fl.err ||
                  d.fl.act || d.fl.err || m.fl.act || m.fl.err || g.fl.act || g.fl.err) &&
                g.corr == 0 && corr_ == 0;
        return o;
    }

private:
    struct flags_t {
        bool act = false, inr = false, err = false;
    };
    struct wr_t {
        bool we = false;
        bool bank = false;
        cfg::addr_t addr = 0;
        cfg::word_t data = 0;
    };
    struct st_a {
        cfg::off_t off = 0;
        cfg::k_t k = cfg::K_MIN;
        cfg::addr_t last = 0;
        bool bank = false;
        flags_t fl;
    };
    struct st_b {
        bool neg = false, hi = false;
        cfg::addr_t i = 0, last = 0;
        cfg::frac_t u = 0;
        bool bank = false;
        flags_t fl;
    };
    struct st_c {
        cfg::haddr_t ea = 0, oa = 0;  // even-RAM address (i + 1) / 2, odd-RAM address i / 2
        cfg::frac_t u = 0;
        bool lsb = false;
        bool bank = false;
        flags_t fl;
    };
    struct st_r {
        cfg::word_t we = 0, wo = 0;  // registered RAM outputs: even and odd word
        cfg::frac_t u = 0;
        bool lsb = false;
        flags_t fl;
    };
    struct st_d {
        cfg::word_t e = 0, o = 0;  // even and odd word of the selected bank
        cfg::v_t v = 0;
        flags_t fl;
    };
    struct st_m {
        cfg::mhi_t hi = 0;      // floor(partial product / 2^j)
        bool b = false;         // the bit shifted out last (bit 20 of the product at the end)
        cfg::v_t v = 0;         // multiplier bits still to go, LSB first
        cfg::diff_t diff = 0;
        cfg::me_t e = 0;        // even word + 2^(F-1) (the rounding half)
        flags_t fl;
    };
    struct st_g {
        cfg::corr_t corr = 0;
        flags_t fl;
    };

    // the write port's delay registers w1 -> w2 -> w3; w1 takes this call's write (to the bank
    // not selected now)
    void shift_write_port(const error_map_regs& r) {
        w3_ = w2_;
        w2_ = w1_;
        w1_.we = r.we;
        w1_.bank = !r.bank_sel;
        w1_.addr = r.addr;
        w1_.data = r.data;
    }

    void write(const wr_t& w) {
        if (!w.we) return;
        const unsigned ha = cfg::haddr_t(w.addr >> 1).to_uint();
        const bool odd = (w.addr & 1) != 0;
        if (w.bank) {
            if (odd) tbl1o_[ha] = w.data;
            else tbl1e_[ha] = w.data;
        } else {
            if (odd) tbl0o_[ha] = w.data;
            else tbl0e_[ha] = w.data;
        }
    }

    // two banks, each an even and an odd RAM (TBL_DEPTH/2 x 24 bits, simple dual port): per call one
    // read of each RAM of the selected bank, at most one write into one RAM of the other bank
    static_assert(cfg::N_BANKS == 2, "error_map: banks tbl0*, tbl1*");
    cfg::word_t tbl0e_[cfg::HALF_DEPTH];
#pragma HLS BIND_STORAGE variable = tbl0e_ type = ram_s2p impl = bram
    cfg::word_t tbl0o_[cfg::HALF_DEPTH];
#pragma HLS BIND_STORAGE variable = tbl0o_ type = ram_s2p impl = bram
    cfg::word_t tbl1e_[cfg::HALF_DEPTH];
#pragma HLS BIND_STORAGE variable = tbl1e_ type = ram_s2p impl = bram
    cfg::word_t tbl1o_[cfg::HALF_DEPTH];
#pragma HLS BIND_STORAGE variable = tbl1o_ type = ram_s2p impl = bram
    wr_t w1_, w2_, w3_;  // write port delayed to stage R
    st_a a_;
    st_b b_;
    st_c c_;
    st_r rd_;
    st_d d_;
    st_m m_;
    st_g g_;
    cfg::phm_t ph_;  // phase of this call in the sample period (0: sample call)
    cfg::corr_t corr_;
    bool idle_;  // no stage holds an active or erroneous sample, corr = 0 (see the idle hold)
};

}  // namespace lx

#endif  // LASERAX_HLS_ERROR_MAP_H
