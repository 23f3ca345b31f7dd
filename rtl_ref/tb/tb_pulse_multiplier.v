// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_pulse_multiplier.v — vector testbench of rtl_ref/pulse_multiplier.v.
// Spec: block pulse_multiplier of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: pulse_multiplier. A row with preset = 1 first loads the DUT registers as
// pulse_multiplier::preset(preset_n, ratio, comp_offset) does (the preset is a C++ testbench aid,
// not an RTL port; always 0 in the golden set), then steps.
// Reads one vector file in the format of docs/VECTORS.md: pulse_multiplier.hex (golden vectors,
// `laserax vectors`; CTest rtl_pulse_multiplier) or pulse_multiplier_stress.hex
// (rtl_stress_vectors, rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest
// rtl_pulse_multiplier_stress); both have the field list below. For every row it applies the row's
// inputs before a rising clock edge and compares every output column with the DUT outputs after
// that edge. Row k is call k after reset: the DUT is held in reset for a few edges, row 0 is
// applied together with the release of i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field step in 2 signed
//   field ratio in 37 unsigned
//   field comp_offset in 64 signed
//   field preset in 1 unsigned
//   field preset_n in 32 signed
//   field comp out 38 signed
//   field delta out 39 signed
`timescale 1ns / 1ps
`default_nettype none

module tb_pulse_multiplier;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 224;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_pulse_multiplier";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  [1:0] i_step;
    reg  [36:0] i_ratio;
    reg  [63:0] i_comp_offset;
    wire [37:0] o_comp;
    wire [38:0] o_delta;

    pulse_multiplier dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_step(i_step),
        .i_ratio(i_ratio),
        .i_comp_offset(i_comp_offset),
        .o_comp(o_comp),
        .o_delta(o_delta)
    );

    `include "tb_common.vh"

    // pulse_multiplier::preset(N, R, OFF): reset, then N, the target pair, acc = N * R, T = OFF and
    // every pipeline stage holding floor((N * R + OFF) / 2^32)
    reg signed [69:0] preset_acc, preset_t, preset_sum;

    task apply_inputs;
        begin
            i_step = row[221:220];
            i_ratio = row[216:180];
            i_comp_offset = row[179:116];
            if (row[112:112]) begin
                preset_acc = $signed(row[111:80]) * $signed({1'b0, row[216:180]});
                preset_t   = {{6{i_comp_offset[63]}}, i_comp_offset};  // applied above
                preset_sum = preset_acc + preset_t;
                dut.busy_q = 1'b0; dut.pend_q = 1'b0; dut.cnt_q = 0;
                dut.f_dr0_q = 1'b0; dut.f_dr1_q = 1'b0; dut.f_s_q = 4'd0; dut.f_mul_q = 1'b0; dut.f_mul_pre_q = 1'b0; dut.f_pre0_q = 1'b0;
                dut.f_x_q = 4'd0; dut.f_y_q = 4'd0; dut.f_last_q = 1'b0;
                dut.c_q = 1'b0; dut.inc_q = 0;
                dut.n_q       = row[111:80];
                dut.nmax_q    = row[111:80] == 32'sh7fffffff;
                dut.nmin_q    = row[111:80] == 32'sh80000000;
                dut.r_use_q   = row[216:180];
                dut.wrap_pos_q = $signed({34'd0, i_ratio[36:32]}) - $signed({2'd0, i_ratio});
                dut.off_tgt_q = row[179:116];
                dut.lo_q      = preset_acc[31:0];
                dut.hi_q      = preset_acc[69:32];
                dut.t_lo_q    = preset_t[31:0];
                dut.t_hi_q    = preset_t[69:32];
                dut.t_hi_d_q  = preset_t[69:32];
                dut.c2_q      = ({1'b0, preset_acc[31:0]} + {1'b0, preset_t[31:0]}) >> 32;
                dut.ci_q      = preset_sum[69:32];
                dut.comp_q    = preset_sum[69:32];
            end
        end
    endtask

    task idle_inputs;
        begin
            i_step = 2'd0;
            i_ratio = 37'd0;
            i_comp_offset = 64'd0;
        end
    endtask

    task ones_inputs;
        begin
            i_step = {2{1'b1}};
            i_ratio = {37{1'b1}};
            i_comp_offset = {64{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("comp", row[77:40], o_comp, 38, 1);
            check("delta", row[38:0], o_delta, 39, 1);
        end
    endtask

endmodule

`default_nettype wire
