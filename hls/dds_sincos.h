// dds_sincos.h — position-in-period counter and quarter-wave sine/cosine table.
//
// DESIGN §4.6. The phase ph = out_pos mod P is kept as quadrant q (2 bits) and offset r in
// [0, P/4), stepped by +-1 with carry, so no divider is needed for any P. Each call reads the
// table twice, T[r] and T[P/4 - r] (true dual-port BRAM), and mirrors them into the four
// quadrants:
//     q | sin        | cos
//     0 |  T[r]      |  T[P/4-r]
//     1 |  T[P/4-r]  | -T[r]
//     2 | -T[r]      | -T[P/4-r]
//     3 | -T[P/4-r]  |  T[r]
// T[P/4] (sin 90 deg) is not stored: it is the amplitude register, so the table is P/4 <= 1024
// words of 17 bits (one 18-kbit BRAM). At ph = P/8 both reads hit T[P/8]: sin == cos exactly.
//
// Table words: T[k] = round-half-away(amp * sin(2 pi k / P)), computed on the host by
// tools/lutgen (or the same routine in the testbench) for the configured P and amplitude and
// loaded through the table port; the RAM powers up with the P = 256, amp = 32767 table
// (hls/dds_table_default.h). Round-half-away makes the four quadrants exact mirrors.
//
// Latency: two stages (DESIGN §4.6): the codes of the phase before a call are formed in that
// call from the registered table read (s1_, c1_) and leave through the output registers in the
// next call; ostep at call t moves the outputs at call t+2.
// Hardware form (DESIGN §4.6): the RAM is read one call early, at the address of the next phase,
// so the mirror address T[P/4 - r] of a call's codes is formed with the period of the previous
// call (qtr_prev_), and so is the up count's wrap test r == P/4 - 1 (a registered flag in
// rtl_ref: no compare with the period in front of the read address). The period only changes
// through the safe state in laserax_top (which resets this block), so this is visible only to a
// caller that changes the period of a running dds_sincos, as the rtl_ref stress vectors do.
//
// The table is an lx::ram (true dual port, one call of read latency, lx_ram.h), read one call
// ahead as rtl_ref reads it: the step of call t issues the reads of the phase after it, at r' and
// P/4 - r' (P/4 of call t), and the read stage of call t+1 takes the words from the RAM's output
// registers. reset() is the call of a reset: the phase to 0 and the read of T[0].
// Table write port: write() presents the write of the call (before that call's step() or
// reset()), which performs it after the call's reads (read-first, as the RAM). With WRITE_BYPASS
// (dds_sincos, the block's contract as rtl_ref's parameter WRITE_BYPASS = 1) a read stage that
// takes a word written in its own call or in the previous one takes the written word (the look-ahead
// read returned the old one): two compares of the registered read address with the write port and
// its previous write, muxes on the read data. laserax_top writes only in the safe state, with one
// more safe call after the last write, so no running call needs them: it uses
// dds_sincos_t<false> (rtl_ref WRITE_BYPASS = 0). load() / peek() are the host's side (C
// simulation, between calls: lx::ram::load).
#ifndef LASERAX_HLS_DDS_SINCOS_H
#define LASERAX_HLS_DDS_SINCOS_H

#include "hls/axis_config.h"
#include "hls/dds_table_default.h"
#include "hls/lx_ram.h"

namespace lx {

struct dds_sincos_cfg {
    static constexpr int TBL_DEPTH = axis_widths::TBL_DEPTH;   // 1024 words
    static constexpr int W_TBL = axis_widths::W_TBL;           // 17 bits
    static constexpr int W_R = axis_widths::W_TBL_ADDR + 1;    // r and P/4 - r: 0..1024
    static constexpr int W_AMP = axis_widths::W_DAC_MAX;       // amplitude register
    using r_t = uint<W_R>;
    using amp_t = uint<W_AMP>;
    using quad_t = uint<2>;
    static_assert((TBL_DEPTH & (TBL_DEPTH - 1)) == 0, "the RAM address is the low bits of r");
};

// The power-up contents (RAM INIT): the P = 256, amp = 32767 table, zeros above it.
struct dds_table_default_words {
    static constexpr int count = LASERAX_DDS_TABLE_DEFAULT_PERIOD / 4;
    static constexpr unsigned word(int i) {
        const unsigned w[count] = {LASERAX_DDS_TABLE_DEFAULT};
        return w[i];
    }
};

struct dds_sincos_out {
    dac_t sin = 0;
    dac_t cos = 0;
};

template <bool WRITE_BYPASS>
class dds_sincos_t {
public:
    using cfg = dds_sincos_cfg;
    using out_t = dds_sincos_out;
    using table_t = ram<tbl_word_t, cfg::TBL_DEPTH, RAM_T2P, ram_list<tbl_word_t, cfg::TBL_DEPTH, dds_table_default_words>>;

    // The call of a reset: the phase and the output registers to 0, the read of T[0] for the
    // first call after it (the table RAM keeps its contents), and the call's write.
    void reset() {
        tbl_.next_call();
        q_ = 0;
        r_ = 0;
        qtr_prev_ = 0;  // not read: r is 0 in the first call after a reset
        s1_ = 0;
        c1_ = 0;
        sin_ = 0;
        cos_ = 0;
        tbl_.template read<0>(0u);
        a_dir_ = 0;
        a_mir_ = 0;
        write_edge();
    }

    // Table write port: the write of this call (see the header).
    void write(tbl_addr_t addr, tbl_word_t data) {
        wr_.we = true;
        wr_.addr = addr;
        wr_.data = data;
    }
    // the host's side, between calls (lx::ram::load / peek; never reached from the synthesis top)
    void load(tbl_addr_t addr, tbl_word_t data) { tbl_.load(addr.to_uint(), data); }
    tbl_word_t read(tbl_addr_t addr) const { return tbl_.peek(addr.to_uint()); }
#ifndef __SYNTHESIS__
    int ram_violations() const { return tbl_.violations(); }
#endif

    out_t step(const step_t& ostep, const period_t& period, const cfg::amp_t& amp) {
#pragma HLS BIND_STORAGE variable = tbl_.m_.w type = ram_t2p impl = bram
        tbl_.next_call();
        const cfg::r_t quarter = cfg::r_t(period >> 2);
        // output stage: the codes of the previous call
        sin_ = s1_;
        cos_ = c1_;
        // read stage: the codes of the phase before this call, from the reads of the previous
        // call at r and P/4 - r (P/4 of the previous call)
        {
            tbl_word_t w_dir = tbl_.template q<0>();
            tbl_word_t w_mir = tbl_.template q<1>();
            if (WRITE_BYPASS) {  // the writes of the previous call and of this one (newest first)
                if (wp_.we && wp_.addr == a_dir_) w_dir = wp_.data;
                if (wp_.we && wp_.addr == a_mir_) w_mir = wp_.data;
                if (wr_.we && wr_.addr == a_dir_) w_dir = wr_.data;
                if (wr_.we && wr_.addr == a_mir_) w_mir = wr_.data;
            }
            const dac_t t_dir = dac_t(w_dir);
            const dac_t t_mir = (r_ == 0) ? dac_t(amp) : dac_t(w_mir);
            switch (q_.to_uint()) {
                case 0: s1_ = t_dir; c1_ = t_mir; break;
                case 1: s1_ = t_mir; c1_ = -t_dir; break;
                case 2: s1_ = -t_dir; c1_ = -t_mir; break;
                default: s1_ = -t_mir; c1_ = t_dir; break;
            }
        }
        // position-in-period counter
        if (ostep > 0) {
            if (r_ == qtr_prev_ - 1) {  // the up count's wrap: P/4 of the previous call too
                r_ = 0;
                q_ = q_ + 1;
            } else {
                r_ = r_ + 1;
            }
        } else if (ostep < 0) {
            if (r_ == 0) {
                r_ = quarter - 1;
                q_ = q_ - 1;
            } else {
                r_ = r_ - 1;
            }
        }
        qtr_prev_ = quarter;
        // the reads of the next call's read stage: r' and P/4 - r' (r' < P/4 <= 1024; the address
        // is the low W_TBL_ADDR bits, as in the RAM: a period that shrinks under a running block
        // can take r past P/4, never out of the table)
        a_dir_ = tbl_addr_t(r_);
        a_mir_ = tbl_addr_t(cfg::r_t(quarter - r_));
        tbl_.template read<0>(a_dir_.to_uint());
        tbl_.template read<1>(a_mir_.to_uint());
        write_edge();
        out_t o;
        o.sin = sin_;
        o.cos = cos_;
        return o;
    }

private:
    struct wr_t {
        bool we = false;
        tbl_addr_t addr = 0;
        tbl_word_t data = 0;
    };
    // the end of a call: the write presented in it, after the reads (read-first); kept one call for
    // the bypass
    void write_edge() {
        if (wr_.we) tbl_.write(wr_.addr.to_uint(), wr_.data);
        wp_ = wr_;
        wr_.we = false;
    }

    // (the initialisers are the reset values, as in reset(), which keeps the table)
    cfg::quad_t q_ = 0;
    cfg::r_t r_ = 0;
    cfg::r_t qtr_prev_ = 0;  // P/4 of the previous call: the mirror address of this call's codes
    dac_t s1_ = 0, c1_ = 0;    // read stage: codes of the phase before the call
    dac_t sin_ = 0, cos_ = 0;  // output registers
    tbl_addr_t a_dir_ = 0, a_mir_ = 0;  // addresses of the reads of the previous call (bypass)
    wr_t wr_;  // the write port of this call (write())
    wr_t wp_;  // the write of the previous call (bypass)
    table_t tbl_;
};

// The block (the contract of its vectors and of rtl_ref's default WRITE_BYPASS = 1).
using dds_sincos = dds_sincos_t<true>;

}  // namespace lx

#endif  // LASERAX_HLS_DDS_SINCOS_H
