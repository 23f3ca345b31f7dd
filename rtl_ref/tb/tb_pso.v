// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_pso.v — vector testbench of rtl_ref/pso.v.
// Spec: block pso of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: pso (position-synchronised output: register stage (values in force one call after they are
// presented, the configuration check registered), chord tracking window with the chord ROM, fire in
// call t + 3 with remainder carry, pulse, window, array RAM in four copies with prefetched, write-
// forwarded thresholds, part-speed generator with the 24 MHz clamp, sequenced spacing check); every
// input is a column (the golden set: one scenario in four parts; the stress set: every register
// moved, array writes while running, invalid configurations, enable drops).
// Reads one vector file in the format of docs/VECTORS.md: pso.hex (golden vectors, `laserax
// vectors`; CTest rtl_pso) or pso_stress.hex (rtl_stress_vectors, rtl_ref/tb/stress_vectors.cpp,
// expected columns from hls/; CTest rtl_pso_stress); both have the field list below. For every row
// it applies the row's inputs before a rising clock edge and compares every output column with the
// DUT outputs after that edge. Row k is call k after reset: the DUT is held in reset for a few
// edges, row 0 is applied together with the release of i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field step0 in 2 signed
//   field step1 in 2 signed
//   field step2 in 2 signed
//   field pos0 in 38 signed
//   field pos1 in 38 signed
//   field pos2 in 38 signed
//   field ps_inc in 32 unsigned
//   field enable in 1 unsigned
//   field part_speed in 1 unsigned
//   field axis_mask in 3 unsigned
//   field win_k in 5 unsigned
//   field fire_dist in 56 unsigned
//   field arr_en in 1 unsigned
//   field arr_len in 7 unsigned
//   field arr_wrap in 1 unsigned
//   field arr_we in 1 unsigned
//   field arr_addr in 6 unsigned
//   field arr_data in 56 unsigned
//   field pulse_w in 16 unsigned
//   field win_en in 1 unsigned
//   field win_src in 2 unsigned
//   field win_low in 38 signed
//   field win_high in 38 signed
//   field min_period in 16 unsigned
//   field clear in 1 unsigned
//   field fire out 1 unsigned
//   field emit out 1 unsigned
//   field pulse out 1 unsigned
//   field in_win out 1 unsigned
//   field dist out 58 signed
//   field idx out 7 unsigned
//   field arr_done out 1 unsigned
//   field fire_cnt out 32 unsigned
//   field overlap_cnt out 16 unsigned
//   field overlap out 1 unsigned
//   field overlap_st out 1 unsigned
//   field rate_over out 1 unsigned
//   field rate_over_st out 1 unsigned
//   field spacing_err out 1 unsigned
//   field spacing_st out 1 unsigned
//   field freq_err out 1 unsigned
//   field freq_st out 1 unsigned
//   field ps_pulse out 1 unsigned
//   field ps_count out 38 signed
//   field cfg_err out 1 unsigned
`timescale 1ns / 1ps
`default_nettype none

module tb_pso;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 664;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_pso";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  [1:0] i_step0;
    reg  [1:0] i_step1;
    reg  [1:0] i_step2;
    reg  [37:0] i_pos0;
    reg  [37:0] i_pos1;
    reg  [37:0] i_pos2;
    reg  [31:0] i_ps_inc;
    reg  i_enable;
    reg  i_part_speed;
    reg  [2:0] i_axis_mask;
    reg  [4:0] i_win_k;
    reg  [55:0] i_fire_dist;
    reg  i_arr_en;
    reg  [6:0] i_arr_len;
    reg  i_arr_wrap;
    reg  i_arr_we;
    reg  [5:0] i_arr_addr;
    reg  [55:0] i_arr_data;
    reg  [15:0] i_pulse_w;
    reg  i_win_en;
    reg  [1:0] i_win_src;
    reg  [37:0] i_win_low;
    reg  [37:0] i_win_high;
    reg  [15:0] i_min_period;
    reg  i_clear;
    wire o_fire;
    wire o_emit;
    wire o_pulse;
    wire o_in_win;
    wire [57:0] o_dist;
    wire [6:0] o_idx;
    wire o_arr_done;
    wire [31:0] o_fire_cnt;
    wire [15:0] o_overlap_cnt;
    wire o_overlap;
    wire o_overlap_st;
    wire o_rate_over;
    wire o_rate_over_st;
    wire o_spacing_err;
    wire o_spacing_st;
    wire o_freq_err;
    wire o_freq_st;
    wire o_ps_pulse;
    wire [37:0] o_ps_count;
    wire o_cfg_err;

    pso dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_step0(i_step0),
        .i_step1(i_step1),
        .i_step2(i_step2),
        .i_pos0(i_pos0),
        .i_pos1(i_pos1),
        .i_pos2(i_pos2),
        .i_ps_inc(i_ps_inc),
        .i_enable(i_enable),
        .i_part_speed(i_part_speed),
        .i_axis_mask(i_axis_mask),
        .i_win_k(i_win_k),
        .i_fire_dist(i_fire_dist),
        .i_arr_en(i_arr_en),
        .i_arr_len(i_arr_len),
        .i_arr_wrap(i_arr_wrap),
        .i_arr_we(i_arr_we),
        .i_arr_addr(i_arr_addr),
        .i_arr_data(i_arr_data),
        .i_pulse_w(i_pulse_w),
        .i_win_en(i_win_en),
        .i_win_src(i_win_src),
        .i_win_low(i_win_low),
        .i_win_high(i_win_high),
        .i_min_period(i_min_period),
        .i_clear(i_clear),
        .o_fire(o_fire),
        .o_emit(o_emit),
        .o_pulse(o_pulse),
        .o_in_win(o_in_win),
        .o_dist(o_dist),
        .o_idx(o_idx),
        .o_arr_done(o_arr_done),
        .o_fire_cnt(o_fire_cnt),
        .o_overlap_cnt(o_overlap_cnt),
        .o_overlap(o_overlap),
        .o_overlap_st(o_overlap_st),
        .o_rate_over(o_rate_over),
        .o_rate_over_st(o_rate_over_st),
        .o_spacing_err(o_spacing_err),
        .o_spacing_st(o_spacing_st),
        .o_freq_err(o_freq_err),
        .o_freq_st(o_freq_st),
        .o_ps_pulse(o_ps_pulse),
        .o_ps_count(o_ps_count),
        .o_cfg_err(o_cfg_err)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_step0 = row[661:660];
            i_step1 = row[657:656];
            i_step2 = row[653:652];
            i_pos0 = row[649:612];
            i_pos1 = row[609:572];
            i_pos2 = row[569:532];
            i_ps_inc = row[531:500];
            i_enable = row[496:496];
            i_part_speed = row[492:492];
            i_axis_mask = row[490:488];
            i_win_k = row[484:480];
            i_fire_dist = row[479:424];
            i_arr_en = row[420:420];
            i_arr_len = row[418:412];
            i_arr_wrap = row[408:408];
            i_arr_we = row[404:404];
            i_arr_addr = row[401:396];
            i_arr_data = row[395:340];
            i_pulse_w = row[339:324];
            i_win_en = row[320:320];
            i_win_src = row[317:316];
            i_win_low = row[313:276];
            i_win_high = row[273:236];
            i_min_period = row[235:220];
            i_clear = row[216:216];
        end
    endtask

    task idle_inputs;
        begin
            i_step0 = 2'd0;
            i_step1 = 2'd0;
            i_step2 = 2'd0;
            i_pos0 = 38'd0;
            i_pos1 = 38'd0;
            i_pos2 = 38'd0;
            i_ps_inc = 32'd0;
            i_enable = 1'd0;
            i_part_speed = 1'd0;
            i_axis_mask = 3'd0;
            i_win_k = 5'd0;
            i_fire_dist = 56'd0;
            i_arr_en = 1'd0;
            i_arr_len = 7'd0;
            i_arr_wrap = 1'd0;
            i_arr_we = 1'd0;
            i_arr_addr = 6'd0;
            i_arr_data = 56'd0;
            i_pulse_w = 16'd0;
            i_win_en = 1'd0;
            i_win_src = 2'd0;
            i_win_low = 38'd0;
            i_win_high = 38'd0;
            i_min_period = 16'd0;
            i_clear = 1'd0;
        end
    endtask

    task ones_inputs;
        begin
            i_step0 = {2{1'b1}};
            i_step1 = {2{1'b1}};
            i_step2 = {2{1'b1}};
            i_pos0 = {38{1'b1}};
            i_pos1 = {38{1'b1}};
            i_pos2 = {38{1'b1}};
            i_ps_inc = {32{1'b1}};
            i_enable = {1{1'b1}};
            i_part_speed = {1{1'b1}};
            i_axis_mask = {3{1'b1}};
            i_win_k = {5{1'b1}};
            i_fire_dist = {56{1'b1}};
            i_arr_en = {1{1'b1}};
            i_arr_len = {7{1'b1}};
            i_arr_wrap = {1{1'b1}};
            i_arr_we = {1{1'b1}};
            i_arr_addr = 6'd0;
            i_arr_data = {56{1'b1}};
            i_pulse_w = {16{1'b1}};
            i_win_en = {1{1'b1}};
            i_win_src = {2{1'b1}};
            i_win_low = {38{1'b1}};
            i_win_high = {38{1'b1}};
            i_min_period = {16{1'b1}};
            i_clear = {1{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("fire", row[212:212], o_fire, 1, 0);
            check("emit", row[208:208], o_emit, 1, 0);
            check("pulse", row[204:204], o_pulse, 1, 0);
            check("in_win", row[200:200], o_in_win, 1, 0);
            check("dist", row[197:140], o_dist, 58, 1);
            check("idx", row[138:132], o_idx, 7, 0);
            check("arr_done", row[128:128], o_arr_done, 1, 0);
            check("fire_cnt", row[127:96], o_fire_cnt, 32, 0);
            check("overlap_cnt", row[95:80], o_overlap_cnt, 16, 0);
            check("overlap", row[76:76], o_overlap, 1, 0);
            check("overlap_st", row[72:72], o_overlap_st, 1, 0);
            check("rate_over", row[68:68], o_rate_over, 1, 0);
            check("rate_over_st", row[64:64], o_rate_over_st, 1, 0);
            check("spacing_err", row[60:60], o_spacing_err, 1, 0);
            check("spacing_st", row[56:56], o_spacing_st, 1, 0);
            check("freq_err", row[52:52], o_freq_err, 1, 0);
            check("freq_st", row[48:48], o_freq_st, 1, 0);
            check("ps_pulse", row[44:44], o_ps_pulse, 1, 0);
            check("ps_count", row[41:4], o_ps_count, 38, 1);
            check("cfg_err", row[0:0], o_cfg_err, 1, 0);
        end
    endtask

endmodule

`default_nettype wire
