// axis_config.h — widths and constants shared by the single-axis chain (docs/DESIGN.md §3).
//
// Only primary widths are written as numbers; every other width is derived here, never retyped
// in a block. Per-block configuration structs (quad_decoder_cfg, ...) sit in the block headers
// and take their widths from axis_widths.
#ifndef LASERAX_HLS_AXIS_CONFIG_H
#define LASERAX_HLS_AXIS_CONFIG_H

#include "hls/lx_types.h"

namespace lx {

struct axis_widths {
    // primary
    static constexpr int W_RAW = 32;     // raw laser count, signed, wraps
    static constexpr int R_FRAC = 32;    // ratio fraction bits (2^-32 ~ 0.23 ppb)
    static constexpr int R_INT = 5;      // ratio integer bits: ratios < 32
    static constexpr int OFF_INT = 32;   // comp offset integer bits: |offset| < 2^31 output counts
    static constexpr int P_MAX = 4096;   // longest sin/cos period in output counts
    static constexpr int P_MIN = 8;      // shortest period; periods are multiples of P_STEP
    static constexpr int P_STEP = 8;
    static constexpr int W_DAC_MAX = 18; // widest DAC code
    static constexpr int W_DAC_MIN = 12;
    // derived
    static constexpr int W_RATIO = R_INT + R_FRAC;             // 37, unsigned
    static constexpr int W_ACC = W_RAW + W_RATIO + 1;          // 70, exact N*R, signed
    static constexpr int W_OFFSET = OFF_INT + R_FRAC;          // 64, comp offset Q32.32, signed
    static constexpr int W_POS = W_RAW + R_INT + 1;            // 38, positions in output counts
    static constexpr int W_DELTA = W_POS + 1;                  // 39, comp(t) - comp(t-1)
    static constexpr int W_BACKLOG = W_POS + 2;                // 40, pacer backlog
    static constexpr int W_P = clog2p1(P_MAX);                 // 13, period register
    static constexpr int W_PH = clog2p1(P_MAX - 1);            // 12, phase 0..P-1
    static constexpr int TBL_DEPTH = P_MAX / 4;                // 1024 quarter-wave words
    static constexpr int W_TBL_ADDR = clog2p1(TBL_DEPTH - 1);  // 10
    static constexpr int W_TBL = W_DAC_MAX - 1;                // 17, table words are >= 0
    static constexpr int W_DACW = clog2p1(W_DAC_MAX);          // 5, dac_width register
};

using raw_t = sint<axis_widths::W_RAW>;
using ratio_t = uint<axis_widths::W_RATIO>;
using acc_t = sint<axis_widths::W_ACC>;
using offset_t = sint<axis_widths::W_OFFSET>;
using pos_t = sint<axis_widths::W_POS>;
using delta_t = sint<axis_widths::W_DELTA>;
using backlog_t = sint<axis_widths::W_BACKLOG>;
using period_t = uint<axis_widths::W_P>;
using phase_t = uint<axis_widths::W_PH>;
using dac_t = sint<axis_widths::W_DAC_MAX>;
using tbl_word_t = uint<axis_widths::W_TBL>;
using tbl_addr_t = uint<axis_widths::W_TBL_ADDR>;
using step_t = sint<2>;  // -1, 0, +1

}  // namespace lx

#endif  // LASERAX_HLS_AXIS_CONFIG_H
