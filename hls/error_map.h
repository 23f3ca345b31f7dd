// error_map.h — position error mapping: a correction table over equally spaced positions, linear
// interpolation between points, the correction delivered as whole output counts to add or remove.
//
// docs/ERROR_MAP.md is the normative per-call description (§4: the inputs are sampled once every
// S_MAP = 32 calls; one register stage per call along a fixed schedule, a serial shift and a
// sequenced shift-and-add multiplier; sized for an iCE40 HX8K clock of >= 120 MHz); for the sample
// call t (ph = 0), in short:
//
//   A1 (t)      low 20 bits of off = p - origin and their carry, p and ~origin >> 20 registered,
//               geometry check, k, last, flags
//   A2 (t+1)    high 19 bits of off (one add of registers)
//   S  (t+2 .. t+21) the offset shifted right one bit per call in the first k of these 20 calls,
//               the bits shifted out entering u from the top: off >> k, u = (off mod 2^k) 2^(20-k)
//   B  (t+22)   i = the low 10 bits, off beyond every address, off < 0, i >= last, i == last,
//               (i + 1) / 2, u == 0 (compares of registers)
//   C  (t+23)   clamp to [0, last] (multiplexers), the addresses: even RAM (i+1)/2, odd RAM i/2
//   R  (t+24)   the two reads of the selected bank (T[i] and T[i+1] always lie in different RAMs:
//               one read per RAM), and the delayed write into the other bank
//   D  (t+25)   e = even word, o = odd word; v = i odd ? 2^20 - u : u (no swap mux)
//   M  (t+26 .. t+47) load diff = o - e, v, e + 128; 21 steps of s = hi + (v bit j ? diff : 0),
//               hi = s >> 1 (LSB first, 26-bit adder)
//   G  (t+48)   corr = floor((2 hi + e + 128 + last bit shifted out) / 2^8)
//               = floor((e 2^20 + diff v + 2^27) / 2^28), held until the next sample's G
//   H  (every call) output registers: corr, delta = corr' - corr, flags
// (the RTL runs B, C, R and D in every call; this model evaluates each in its call of the
// schedule only, which gives the same outputs: M takes D's registers only at ph = PH_LOAD)
//
// Two banks in two RAMs, even and odd words (lx::ram, simple dual port; the bank is the address
// MSB, as in rtl_ref): the table write port always writes the bank that is *not* selected by
// bank_sel in that call, delayed by W_DLY = 24 calls so that it is performed in the same call as
// the reads of a sample call (stage R) — into the other bank, so each RAM sees at most one read
// and one write per call and the reads of sample call t see exactly the writes of the calls
// before t. Each bank has its own geometry (origin, spacing_log2, n_points); a flip of bank_sel switches
// table and geometry together at one call boundary and a reload can never mix tables.
//
// Widths (derived in error_map_cfg): table words 24 bits signed Q15.8 counts, offset 39 signed,
// u 20 unsigned, v 21, diff 25 signed, multiplier accumulator 26 signed, corr 17 signed, delta 18.
// Sample period S_MAP = 32 calls (phase counter 0 after reset: the first call after a reset is a
// sample call); latency L_MAP = 50 calls — the inputs of sample call t are reflected in the
// corr/delta returned by call t+49 and held until call t+80.
#ifndef LASERAX_HLS_ERROR_MAP_H
#define LASERAX_HLS_ERROR_MAP_H

#include "hls/axis_config.h"
#include "hls/lx_ram.h"

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
    static constexpr int W_LO = 20;         // low half of the subtract (A1); A2 the rest
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
    static constexpr int PH_S0 = 2;                               // first shift call (after A1, A2)
    static constexpr int PH_B = PH_S0 + K_MAX;                    // 22: K_MAX shift calls, then B
    static constexpr int PH_C = PH_B + 1;                         // 23
    static constexpr int PH_R = PH_B + 2;                         // 24: the RAM reads
    static constexpr int PH_D = PH_B + 3;                         // 25
    static constexpr int PH_LOAD = PH_B + 4;                      // 26: stage D holds the sample
    static constexpr int PH_G = (PH_LOAD + 1 + W_V) % S_MAP;      // 16: after the 21 steps
    static constexpr int L_MAP = PH_LOAD + 1 + W_V + 2;           // 50: sample call t -> outputs
                                                                  //   of call t + L_MAP - 1
    static constexpr int W_DLY = PH_R;                            // 24: write of call t done in t + 24
    static constexpr int DL_DEPTH = 32;                           // the delay line's RAM (a power of two)
    static constexpr int DL_READ = DL_DEPTH + 2 - W_DLY;          // 10: read slot wp + 10 = wp - 22
    static constexpr int W_DIFF = W_CORR + 1;                     // 25, odd word - even word
    static constexpr int W_MHI = W_DIFF + 1;                      // 26, multiplier accumulator
    static constexpr int W_ME = W_CORR + 1;                       // 25, e + 2^(F-1)
    static constexpr int W_G = W_MHI + 1;                         // 27, 2 hi + m_e + bit
    static constexpr int W_C = W_CORR - F + 1;                    // 17, rounded correction
    static constexpr int W_CDELTA = W_C + 1;                      // 18, corr' - corr
    static_assert(TBL_DEPTH % 2 == 0 && (1 << W_ADDR) == TBL_DEPTH, "error_map: depth a power of two");
    static_assert((S_MAP & (S_MAP - 1)) == 0 && PH_LOAD < S_MAP && 1 + W_V + 1 <= S_MAP &&
                      (PH_G + 1) % S_MAP == (L_MAP - 1) % S_MAP,
                  "error_map: each stage holds one sample at a time (shift done before the next A1, "
                  "G before the next load)");
    static_assert(K_MAX + 1 == W_V, "error_map: G folds the 2^(K_MAX) term of v into m_hi's bit");
    static_assert(K_MAX + W_ADDR < W_OFF - 1, "error_map: the 'beyond every address' bound fits off_t");
    static_assert(W_LO < W_OFF && W_OFF - W_LO == 19, "error_map: the subtract's halves");

    using word_t = sint<W_CORR>;
    using addr_t = uint<W_ADDR>;
    using haddr_t = uint<W_HADDR>;
    using n_t = uint<W_N>;
    using k_t = uint<W_K>;
    using off_t = sint<W_OFF>;
    using mag_t = uint<W_OFF - 1>;       // off's bits below the sign (shifted by S)
    using lo_t = uint<W_LO>;
    using hi_t = sint<W_OFF - W_LO>;
    using dlp_t = uint<clog2p1(DL_DEPTH - 1)>;  // slot of the write delay line (wraps)
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

    // Reset of the pipeline's registers (not of the table RAM, not of the write port's delay line).
    void reset() {
        a_ = st_a{};
        b_ = st_b{};
        c_ = st_c{};
        rd_ = st_r{};
        d_ = st_d{};
        m_ = st_m{};
        g_ = st_g{};
        ph_ = 0;
        corr_ = 0;
    }

    // The write port in a call in reset (the safe state of laserax_top, which also calls reset();
    // rtl_ref i_rst): the delay line keeps running, so a write already in it lands in its own call
    // (one RAM write at most, as in every call), and the port takes no further write
    // (ERROR_MAP.md §4: a write of a running call is never lost, none is taken in reset).
    void step_reset_port() {
        next_call();
        write_port(error_map_regs{});
    }

#ifndef __SYNTHESIS__
    int ram_violations() const { return tble_.violations() | tblo_.violations() | dl_.violations(); }
#endif

    out_t step(const pos_t& p, bool homed, const error_map_regs& r) {
#pragma HLS BIND_STORAGE variable = tble_.m_.w type = ram_s2p impl = bram
#pragma HLS BIND_STORAGE variable = tblo_.m_.w type = ram_s2p impl = bram
#pragma HLS BIND_STORAGE variable = dl_.m_.w type = ram_s2p impl = bram
        next_call();
        const unsigned ph = ph_.to_uint();
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
        if (ph == cfg::PH_G) {
            const cfg::g_t x = cfg::g_t(m_.hi) * cfg::g_t(2) + cfg::g_t(m_.e) + cfg::g_t(m_.b ? 1 : 0);
            g_.corr = m_.fl.act ? cfg::corr_t(x >> cfg::F) : cfg::corr_t(0);
            g_.fl = m_.fl;
        }

        // ---- M: sequenced multiply diff * v, LSB first (load at PH_LOAD, 21 steps after it) ---
        if (ph == cfg::PH_LOAD) {
            m_.hi = 0;
            m_.b = false;
            m_.v = d_.v;
            m_.diff = cfg::diff_t(d_.o) - cfg::diff_t(d_.e);
            m_.e = cfg::me_t(d_.e) + cfg::me_t(1 << (cfg::F - 1));
            m_.fl = d_.fl;
        } else if (((ph - cfg::PH_LOAD - 1u) & (cfg::S_MAP - 1)) < unsigned(cfg::W_V)) {
            const cfg::mhi_t sum = cfg::mhi_t(m_.hi) + ((m_.v & 1) != 0 ? cfg::mhi_t(m_.diff) : cfg::mhi_t(0));
            m_.hi = sum >> 1;
            m_.b = (sum & 1) != 0;
            m_.v = m_.v >> 1;
        }

        // ---- D (ph = PH_D): the two words, orientation of the interval -------------------------
        if (ph == cfg::PH_D) {
            d_.e = tble_.q<0>();  // the RAMs' output registers (read at PH_R = PH_D - 1)
            d_.o = tblo_.q<0>();
            d_.v = rd_.lsb ? cfg::v_t(cfg::v_t(1 << cfg::K_MAX) - cfg::v_t(rd_.u)) : cfg::v_t(rd_.u);
            d_.fl = rd_.fl;
        }

        // ---- R (ph = PH_R): the two reads (one per RAM, the selected bank's half) --------------
        if (ph == cfg::PH_R) {
            const unsigned bk = c_.bank ? unsigned(cfg::HALF_DEPTH) : 0u;  // bank: the address MSB
            tble_.read<0>(bk + c_.ea.to_uint());
            tblo_.read<0>(bk + c_.oa.to_uint());
            rd_.u = c_.u;
            rd_.lsb = c_.lsb;
            rd_.fl = c_.fl;
        }
        // the write of call t - W_DLY, after the reads (always the other bank), and this call's
        // into the delay line
        write_port(r);

        // ---- C (ph = PH_C): clamp, the two addresses (multiplexers only) ------------------------
        if (ph == cfg::PH_C) {
            const bool above = !b_.neg && (b_.hi || b_.ge);
            const cfg::addr_t i = b_.neg ? cfg::addr_t(0) : (above ? b_.last : b_.i);
            c_.u = (b_.neg || above) ? cfg::frac_t(0) : b_.u;
            c_.lsb = (i & 1) != 0;
            c_.fl = b_.fl;
            c_.fl.inr = !b_.neg && (!above || (!b_.hi && b_.eq && b_.u0));
            c_.ea = b_.neg ? cfg::haddr_t(0) : (above ? b_.le : b_.ie);  // (i + 1) / 2, wraps at the end
            c_.oa = cfg::haddr_t(i >> 1);
            c_.bank = b_.bank;
        }

        // ---- B (ph = PH_B): the shifted offset's fields and their compares with last -----------
        if (ph == cfg::PH_B) {
            b_.neg = a_.neg;
            b_.hi = (a_.mag >> cfg::W_ADDR) != 0;
            b_.i = cfg::addr_t(a_.mag);
            b_.u = a_.u;
            b_.ge = b_.i >= a_.last;
            b_.eq = b_.i == a_.last;
            b_.u0 = a_.u == 0;
            b_.ie = cfg::haddr_t((uint<cfg::W_ADDR + 1>(b_.i) + 1) >> 1);
            b_.le = cfg::haddr_t((uint<cfg::W_ADDR + 1>(a_.last) + 1) >> 1);
            b_.last = a_.last;
            b_.bank = a_.bank;
            b_.fl = a_.fl;
        }

        // ---- S (ph = PH_S0 .. PH_B - 1): the offset right by one, in the first k of the calls ----
        if (ph >= unsigned(cfg::PH_S0) && ph < unsigned(cfg::PH_B) && a_.kc != 0) {
            a_.u = cfg::frac_t((a_.u >> 1) | (cfg::frac_t(a_.mag & 1) << (cfg::W_FRAC - 1)));
            a_.mag = a_.mag >> 1;
            a_.kc = cfg::k_t(a_.kc - 1);
        }

        // ---- A2 (ph = 1): the high half of the subtract, from registers --------------------------
        if (ph == 1) {
            const cfg::hi_t hi = cfg::hi_t(a_.phi + a_.ohi + cfg::hi_t(a_.c ? 1 : 0));
            a_.neg = hi < 0;
            a_.mag = cfg::mag_t((cfg::mag_t(uint<cfg::W_OFF - cfg::W_LO>(hi)) << cfg::W_LO) | cfg::mag_t(a_.lo));
        }

        // ---- A1 (ph = 0, the sample call): its inputs, the low half of the subtract -------------
        if (ph == 0) {
            const int bs = r.bank_sel ? 1 : 0;
            const error_map_geom& gm = r.geom[bs];
            const bool geom_ok = error_map_geom_ok(gm);
            a_.kc = geom_ok ? gm.spacing_log2 : cfg::k_t(cfg::K_MIN);
            a_.last = geom_ok ? cfg::addr_t(gm.n_points - 1) : cfg::addr_t(0);
            const pos_t no = pos_t(~gm.origin);  // p - origin = p + ~origin + 1
            const uint<cfg::W_LO + 1> lo =
                uint<cfg::W_LO + 1>(cfg::lo_t(p)) + uint<cfg::W_LO + 1>(cfg::lo_t(no)) + uint<cfg::W_LO + 1>(1);
            a_.lo = cfg::lo_t(lo);
            a_.c = (lo >> cfg::W_LO) != 0;
            a_.phi = cfg::hi_t(p >> cfg::W_LO);
            a_.ohi = cfg::hi_t(no >> cfg::W_LO);
            a_.u = 0;
            a_.bank = r.bank_sel;
            a_.fl.act = r.map_en && homed && geom_ok;
            a_.fl.inr = false;
            a_.fl.err = r.map_en && !geom_ok;
        }

        ph_ = cfg::phm_t(ph + 1);  // wraps at S_MAP
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
        cfg::lo_t lo = 0;  // A1: low half of the subtract and its carry
        bool c = false;
        cfg::hi_t phi = 0, ohi = 0;  // A1: p >> 20, ~origin >> 20
        bool neg = false;          // A2: off < 0
        cfg::mag_t mag = 0;        // A2: off below the sign; shifted right by S
        cfg::frac_t u = 0;         // S: the bits shifted out, from the top
        cfg::k_t kc = cfg::K_MIN;  // shifts still to do
        cfg::addr_t last = 0;
        bool bank = false;
        flags_t fl;
    };
    struct st_b {
        bool neg = false, hi = false, ge = false, eq = false, u0 = false;
        cfg::addr_t i = 0, last = 0;
        cfg::haddr_t ie = 0, le = 0;  // (i + 1) / 2, (last + 1) / 2
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

    // the clock edge of the block's RAMs (every call: the write port runs in every call)
    void next_call() {
        tble_.next_call();
        tblo_.next_call();
        dl_.next_call();
    }

    // The write port's delay line (W_DLY = 24 calls, rtl_ref's structure): w1_ takes the call's
    // write (to the bank not selected now; none in a reset call); the block RAM dl_ holds it for
    // 22 calls (write pointer wp_, free running and never reset, so the writes in flight keep
    // their calls across a reset; read pointer wp_ + 10 = wp_ - 22 mod 32); dl_'s output register
    // is the write of call t - 24 in call t, performed into the table RAM after the reads of R.
    void write_port(const error_map_regs& r) {
        const wr_t wd = dl_.q<0>();
        if (wv_ && wd.we) {
            const unsigned a = (wd.bank ? unsigned(cfg::HALF_DEPTH) : 0u) + cfg::haddr_t(wd.addr >> 1).to_uint();
            if ((wd.addr & 1) != 0) tblo_.write(a, wd.data);
            else tble_.write(a, wd.data);
        }
        dl_.read<0>(cfg::dlp_t(wp_ + cfg::DL_READ).to_uint());
        dl_.write(wp_.to_uint(), w1_);
        w1_.we = r.we;
        w1_.bank = !r.bank_sel;
        w1_.addr = r.addr;
        w1_.data = r.data;
        wp_ = cfg::dlp_t(wp_ + 1);
        wv_ = true;
    }

    // two RAMs, even and odd words (TBL_DEPTH x 24 bits each, simple dual port; the bank is the
    // address MSB): per call one read of each (the selected bank's half) and at most one write
    // into one of them (the other bank's half)
    static_assert(cfg::N_BANKS == 2, "error_map: the bank is the RAM address MSB");
    ram<cfg::word_t, cfg::TBL_DEPTH, RAM_S2P> tble_;  // power-up: zero (RAM INIT)
    ram<cfg::word_t, cfg::TBL_DEPTH, RAM_S2P> tblo_;
    ram<wr_t, cfg::DL_DEPTH, RAM_S2P> dl_;  // the write delay line (power-up: no writes)
    wr_t w1_;
    cfg::dlp_t wp_ = 0;
    bool wv_ = false;  // dl_'s output register holds a word of the delay line (false at power-up)
    st_a a_;
    st_b b_;
    st_c c_;
    st_r rd_;
    st_d d_;
    st_m m_;
    st_g g_;
    cfg::phm_t ph_ = 0;  // phase of this call in the sample period (0: sample call)
    cfg::corr_t corr_ = 0;
};

}  // namespace lx

#endif  // LASERAX_HLS_ERROR_MAP_H
