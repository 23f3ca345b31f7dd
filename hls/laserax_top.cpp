// laserax_top.cpp — Vitis HLS top function of the single-axis interface.
//
// One call = one clock (free-running pipeline, II = 1, no block-level handshake). Pins are plain
// wires (ap_none); the register block is an s_axilite slave; the outputs are wires. The state of
// the axis lives in one static axis_core, so the function is the whole IP. Build for Vitis with
// -DLASERAX_USE_AP_TYPES (see scripts/run_hls.tcl); the default build uses lx_types' own classes.
#include "hls/laserax_top.h"

void laserax_top(bool a, bool b, bool sw, bool lerr, const lx::axis_regs& regs, lx::axis_out& out) {
#pragma HLS INTERFACE mode=ap_ctrl_none port=return
#pragma HLS INTERFACE mode=ap_none port=a
#pragma HLS INTERFACE mode=ap_none port=b
#pragma HLS INTERFACE mode=ap_none port=sw
#pragma HLS INTERFACE mode=ap_none port=lerr
#pragma HLS INTERFACE mode=s_axilite port=regs bundle=ctrl
#pragma HLS INTERFACE mode=ap_none port=out
#pragma HLS AGGREGATE variable=out
#pragma HLS PIPELINE II=1 style=frp
    static lx::axis_core core;
    lx::axis_pins pins;
    pins.a = a;
    pins.b = b;
    pins.sw = sw;
    pins.lerr = lerr;
    out = core.step(pins, regs);
}
