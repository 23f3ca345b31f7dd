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
#ifndef LASERAX_HLS_DDS_SINCOS_H
#define LASERAX_HLS_DDS_SINCOS_H

#include "hls/axis_config.h"
#include "hls/dds_table_default.h"

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

class dds_sincos {
public:
    using cfg = dds_sincos_cfg;
    struct out_t {
        dac_t sin = 0;
        dac_t cos = 0;
    };

    // Resets the phase and the output registers; the table RAM keeps its contents.
    void reset() {
        q_ = 0;
        r_ = 0;
        qtr_prev_ = 0;  // not read: r is 0 in the first call after a reset
        s1_ = 0;
        c1_ = 0;
        sin_ = 0;
        cos_ = 0;
    }

    // Table write port (host side of the RAM).
    void write(tbl_addr_t addr, tbl_word_t data) {
        tbl_[addr.to_uint()] = data;
    }
    tbl_word_t read(tbl_addr_t addr) const { return tbl_[addr.to_uint()]; }

    out_t step(const step_t& ostep, const period_t& period, const cfg::amp_t& amp) {
        const cfg::r_t quarter = cfg::r_t(period >> 2);
        // output stage: the codes of the previous call
        sin_ = s1_;
        cos_ = c1_;
        // read stage: the codes of the phase before this call
        {
            const cfg::r_t r_mirror = qtr_prev_ - r_;  // 1..P/4 of the previous call (r < that P/4)
            // r < P/4 <= 1024; the address is the low W_TBL_ADDR bits, as in the RAM (a period
            // that shrinks under a running block can take r past P/4: never out of the array)
            const unsigned amask = cfg::TBL_DEPTH - 1;
            const dac_t t_dir = dac_t(tbl_[r_.to_uint() & amask]);
            const dac_t t_mir = (r_ == 0) ? dac_t(amp) : dac_t(tbl_[r_mirror.to_uint() & amask]);
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
        out_t o;
        o.sin = sin_;
        o.cos = cos_;
        return o;
    }

private:
    // (the initialisers are the reset values, as in reset(), which keeps the table)
    cfg::quad_t q_ = 0;
    cfg::r_t r_ = 0;
    cfg::r_t qtr_prev_ = 0;  // P/4 of the previous call: the mirror address of this call's codes
    dac_t s1_ = 0, c1_ = 0;    // read stage: codes of the phase before the call
    dac_t sin_ = 0, cos_ = 0;  // output registers
    tbl_word_t tbl_[cfg::TBL_DEPTH] = {LASERAX_DDS_TABLE_DEFAULT};
#pragma HLS BIND_STORAGE variable = tbl_ type = ram_t2p impl = bram
};

}  // namespace lx

#endif  // LASERAX_HLS_DDS_SINCOS_H
