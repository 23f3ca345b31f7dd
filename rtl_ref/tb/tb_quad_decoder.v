// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_quad_decoder.v — vector testbench of rtl_ref/quad_decoder.v.
// Spec: block quad_decoder of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: quad_decoder.
// Reads one vector file in the format of docs/VECTORS.md: quad_decoder.hex (golden vectors,
// `laserax vectors`; CTest rtl_quad_decoder) or quad_decoder_stress.hex (rtl_stress_vectors,
// rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest rtl_quad_decoder_stress); both
// have the field list below. For every row it applies the row's inputs before a rising clock edge
// and compares every output column with the DUT outputs after that edge. Row k is call k after
// reset: the DUT is held in reset for a few edges, row 0 is applied together with the release of
// i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field a in 1 unsigned
//   field b in 1 unsigned
//   field lerr in 1 unsigned
//   field glitch_n in 8 unsigned
//   field min_spacing in 16 unsigned
//   field clear in 1 unsigned
//   field step out 2 signed
//   field raw_count out 32 signed
//   field illegal out 1 unsigned
//   field ovs out 1 unsigned
//   field err_cnt out 8 unsigned
//   field illegal_st out 1 unsigned
//   field ovs_st out 1 unsigned
//   field lerr_out out 1 unsigned
//   field lerr_alarm out 1 unsigned
//   field glitch_st out 1 unsigned
`timescale 1ns / 1ps
`default_nettype none

module tb_quad_decoder;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 112;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_quad_decoder";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  i_a;
    reg  i_b;
    reg  i_lerr;
    reg  [7:0] i_glitch_n;
    reg  [15:0] i_min_spacing;
    reg  i_clear;
    wire [1:0] o_step;
    wire [31:0] o_raw_count;
    wire o_illegal;
    wire o_ovs;
    wire [7:0] o_err_cnt;
    wire o_illegal_st;
    wire o_ovs_st;
    wire o_lerr;
    wire o_lerr_alarm;
    wire o_glitch_st;
    wire o_lerr_nx;   // not in the vectors

    quad_decoder dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_a(i_a),
        .i_b(i_b),
        .i_lerr(i_lerr),
        .i_glitch_n(i_glitch_n),
        .i_min_spacing(i_min_spacing),
        .i_clear(i_clear),
        .o_step(o_step),
        .o_raw_count(o_raw_count),
        .o_illegal(o_illegal),
        .o_ovs(o_ovs),
        .o_err_cnt(o_err_cnt),
        .o_illegal_st(o_illegal_st),
        .o_ovs_st(o_ovs_st),
        .o_lerr(o_lerr),
        .o_lerr_alarm(o_lerr_alarm),
        .o_glitch_st(o_glitch_st),
        .o_lerr_nx(o_lerr_nx)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_a = row[108:108];
            i_b = row[104:104];
            i_lerr = row[100:100];
            i_glitch_n = row[99:92];
            i_min_spacing = row[91:76];
            i_clear = row[72:72];
        end
    endtask

    task idle_inputs;
        begin
            i_a = 1'd0;
            i_b = 1'd0;
            i_lerr = 1'd0;
            i_glitch_n = 8'd0;
            i_min_spacing = 16'd0;
            i_clear = 1'd0;
        end
    endtask

    task ones_inputs;
        begin
            i_a = {1{1'b1}};
            i_b = {1{1'b1}};
            i_lerr = {1{1'b1}};
            i_glitch_n = {8{1'b1}};
            i_min_spacing = {16{1'b1}};
            i_clear = {1{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("step", row[69:68], o_step, 2, 1);
            check("raw_count", row[67:36], o_raw_count, 32, 1);
            check("illegal", row[32:32], o_illegal, 1, 0);
            check("ovs", row[28:28], o_ovs, 1, 0);
            check("err_cnt", row[27:20], o_err_cnt, 8, 0);
            check("illegal_st", row[16:16], o_illegal_st, 1, 0);
            check("ovs_st", row[12:12], o_ovs_st, 1, 0);
            check("lerr_out", row[8:8], o_lerr, 1, 0);
            check("lerr_alarm", row[4:4], o_lerr_alarm, 1, 0);
            check("glitch_st", row[0:0], o_glitch_st, 1, 0);
        end
    endtask

endmodule

`default_nettype wire
