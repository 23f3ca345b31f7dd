// laserax_axil.cpp — Vitis HLS top function of the single-axis interface.
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
//
// One call = one clock (pipeline, II = 1). Pins are plain wires (ap_none); every register of docs/REGISTERS.md is one scalar argument on the s_axilite
// slave at its fixed offset (a register wider than 32 bits takes consecutive words, low word
// first); the outputs are wires. The state of the axis lives in one static laserax_top, so the
// function is the whole IP. The block-level control is on the same s_axilite slave (port=return:
// ap_start / ap_done / auto-restart in the control word at 0x00, the words 0x00..0x0F), as
// Vitis requires when arguments are s_axilite and as C/RTL co-simulation needs; software starts
// the IP once with ap_start = 1 and auto_restart = 1 (control word 0x81), after which the II = 1
// pipeline takes one call per clock. The registers start at 0, not at their reset values (an
// s_axilite argument has no initial value): software writes the whole image before the start
// (lxt::init_registers, host/ip_init.h). The debug taps of lx::axis_out are 0 unless
// LASERAX_HLS_DEBUG_TAPS = 1 (laserax_axil.h). Build for Vitis with -DLASERAX_USE_AP_TYPES (see
// scripts/run_hls.tcl); the default build uses lx_types' own classes.
#include "hls/laserax_axil.h"

#include "hls/laserax_regmap.h"

// Catapult HLS: this function is the design top (Vitis HLS ignores the pragma; its top is named
// by set_top in scripts/run_hls.tcl)
#pragma hls_design top
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
                 lx::axis_out& out) {
#pragma HLS INTERFACE mode=s_axilite port=return bundle=ctrl
#pragma HLS INTERFACE mode=ap_none port=a
#pragma HLS INTERFACE mode=ap_none port=b
#pragma HLS INTERFACE mode=ap_none port=sw
#pragma HLS INTERFACE mode=ap_none port=lerr
#pragma HLS INTERFACE mode=s_axilite port=period offset=0x10 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=tbl_period offset=0x18 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=ratio offset=0x20 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=comp_offset offset=0x30 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=glitch_n offset=0x40 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=sw_debounce offset=0x48 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=min_spacing offset=0x50 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=pace_m offset=0x58 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=backlog_thr offset=0x60 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=mark_len offset=0x68 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=dac_width offset=0x70 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=amplitude offset=0x78 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=rehome offset=0x80 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=clear offset=0x88 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=tbl_we offset=0x90 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=tbl_addr offset=0x98 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=tbl_data offset=0xA0 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_en offset=0xA8 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=bank_sel offset=0xB0 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_origin0 offset=0xC0 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_k0 offset=0xD0 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_n0 offset=0xD8 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_origin1 offset=0xE0 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_k1 offset=0xF0 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_n1 offset=0xF8 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_we offset=0x100 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_addr offset=0x108 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=map_data offset=0x110 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=comp_sync offset=0x118 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=comp_commit offset=0x120 bundle=ctrl
#pragma HLS INTERFACE mode=s_axilite port=pin_cfg offset=0x128 bundle=ctrl
#pragma HLS INTERFACE mode=ap_none port=out
#pragma HLS AGGREGATE variable=out
#pragma HLS PIPELINE II=1 style=frp
    static lx::laserax_top core;
    lx::axis_pins pins;
    pins.a = a;
    pins.b = b;
    pins.sw = sw;
    pins.lerr = lerr;
    lx::axis_regs regs;
    regs.period = period;
    regs.tbl_period = tbl_period;
    regs.ratio = ratio;
    regs.comp_offset = comp_offset;
    regs.glitch_n = glitch_n;
    regs.sw_debounce = sw_debounce;
    regs.min_spacing = min_spacing;
    regs.pace_m = pace_m;
    regs.backlog_thr = backlog_thr;
    regs.mark_len = mark_len;
    regs.dac_width = dac_width;
    regs.amplitude = amplitude;
    regs.rehome = rehome;
    regs.clear = clear;
    regs.tbl_we = tbl_we;
    regs.tbl_addr = tbl_addr;
    regs.tbl_data = tbl_data;
    regs.emap.map_en = map_en;
    regs.emap.bank_sel = bank_sel;
    regs.emap.geom[0].origin = map_origin0;
    regs.emap.geom[0].spacing_log2 = map_k0;
    regs.emap.geom[0].n_points = map_n0;
    regs.emap.geom[1].origin = map_origin1;
    regs.emap.geom[1].spacing_log2 = map_k1;
    regs.emap.geom[1].n_points = map_n1;
    regs.emap.we = map_we;
    regs.emap.addr = map_addr;
    regs.emap.data = map_data;
    regs.comp_sync = comp_sync;
    regs.comp_commit = comp_commit;
    regs.pin_cfg = pin_cfg;
    out = core.step(pins, regs);
#if !LASERAX_HLS_DEBUG_TAPS
    // the debug taps dropped (laserax_axil.h): constant 0, as DEBUG_TAPS = 0 ties them in rtl_ref
    out.raw_count = 0;
    out.step = 0;
    out.comp_pos = 0;
    out.delta = 0;
    out.backlog = 0;
    out.pstep = 0;
    out.paced_pos = 0;
    out.ostep = 0;
    out.out_pos = 0;
    out.adj = 0;
    out.a_pos = 0;
    out.b_pos = 0;
    out.c_pos = 0;
    out.z_pos = 0;
    out.d = 0;
    out.rep_mark = 0;
#endif
}
