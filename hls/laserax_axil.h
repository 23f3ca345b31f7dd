// laserax_axil.h — declaration of the synthesis top (see laserax_axil.cpp).
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
#ifndef LASERAX_HLS_LASERAX_AXIL_H
#define LASERAX_HLS_LASERAX_AXIL_H

#include "hls/laserax_top.h"

// LASERAX_HLS_DEBUG_TAPS, a compile-time switch (0 or 1; default 0, as DEBUG_TAPS = 0 of
// rtl_ref/laserax_top.v): 0 drops the debug taps from the top's outputs, the lx::axis_out members
//   raw_count, step, comp_pos, delta, backlog, pstep, paced_pos, ostep, out_pos, adj, a_pos,
//   b_pos, c_pos, z_pos, d, rep_mark
// are 0 in every call, so synthesis removes the logic that only feeds them (the deployed core);
// 1 drives them, for the testbenches that compare them (CTest tb_hls_csim_taps). The pins, the
// status and the error-map outputs (map_cfg_err, corr, map_delta) are the same for both values.
#ifndef LASERAX_HLS_DEBUG_TAPS
#define LASERAX_HLS_DEBUG_TAPS 0
#endif
#if LASERAX_HLS_DEBUG_TAPS != 0 && LASERAX_HLS_DEBUG_TAPS != 1
#error "LASERAX_HLS_DEBUG_TAPS must be 0 or 1"
#endif

// Pins a, b, sw, lerr and the outputs are wires; every other argument is one register of the
// s_axilite slave (bundle ctrl), in offset order (docs/REGISTERS.md).
void laserax_axil(bool a, bool b, bool sw, bool lerr,
                 lx::uint<13> period,
                 lx::uint<13> tbl_period,
                 lx::uint<37> ratio,
                 lx::sint<64> comp_offset,
                 lx::uint<8> glitch_n,
                 lx::uint<16> sw_debounce,
                 lx::uint<16> min_spacing,
                 lx::uint<16> pace_m,
                 lx::uint<32> backlog_thr,
                 lx::uint<13> mark_len,
                 lx::uint<5> dac_width,
                 lx::uint<18> amplitude,
                 bool rehome,
                 bool clear,
                 bool tbl_we,
                 lx::uint<10> tbl_addr,
                 lx::uint<17> tbl_data,
                 bool map_en,
                 bool bank_sel,
                 lx::sint<38> map_origin0,
                 lx::uint<5> map_k0,
                 lx::uint<11> map_n0,
                 lx::sint<38> map_origin1,
                 lx::uint<5> map_k1,
                 lx::uint<11> map_n1,
                 bool map_we,
                 lx::uint<10> map_addr,
                 lx::sint<24> map_data,
                 bool comp_sync,
                 bool comp_commit,
                 lx::uint<4> pin_cfg,
                 lx::axis_out& out);

#endif  // LASERAX_HLS_LASERAX_AXIL_H
