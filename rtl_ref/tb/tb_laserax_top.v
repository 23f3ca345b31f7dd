// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_laserax_top.v — vector testbench of rtl_ref/laserax_top.v.
// Spec: block laserax_top of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: laserax_top (whole chain), table RAM at its power-up contents TBL_FILE; every input is a
// column (the table write port is idle in the golden set; period changes with table reloads,
// invalid configurations and the error map run in the stress set).
// Reads one vector file in the format of docs/VECTORS.md: laserax_top.hex (golden vectors, `laserax
// vectors`; CTest rtl_laserax_top) or laserax_top_stress.hex (rtl_stress_vectors,
// rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest rtl_laserax_top_stress); both
// have the field list below. For every row it applies the row's inputs before a rising clock edge
// and compares every output column with the DUT outputs after that edge. Row k is call k after
// reset: the DUT is held in reset for a few edges, row 0 is applied together with the release of
// i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file, TBL_FILE = table RAM image, DEBUG_TAPS = 1: the DUT's debug taps compared with the vectors; 0: a DUT without taps, each tap column must read 0.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field a in 1 unsigned
//   field b in 1 unsigned
//   field sw in 1 unsigned
//   field lerr in 1 unsigned
//   field period in 13 unsigned
//   field ratio in 37 unsigned
//   field comp_offset in 64 signed
//   field comp_sync in 1 unsigned
//   field comp_commit in 1 unsigned
//   field glitch_n in 8 unsigned
//   field sw_debounce in 16 unsigned
//   field min_spacing in 16 unsigned
//   field pace_m in 16 unsigned
//   field backlog_thr in 32 unsigned
//   field mark_len in 13 unsigned
//   field dac_width in 5 unsigned
//   field amplitude in 18 unsigned
//   field tbl_period in 13 unsigned
//   field rehome in 1 unsigned
//   field clear in 1 unsigned
//   field tbl_we in 1 unsigned
//   field tbl_addr in 10 unsigned
//   field tbl_data in 17 unsigned
//   field map_en in 1 unsigned
//   field bank_sel in 1 unsigned
//   field map_origin0 in 38 signed
//   field map_k0 in 5 unsigned
//   field map_n0 in 11 unsigned
//   field map_origin1 in 38 signed
//   field map_k1 in 5 unsigned
//   field map_n1 in 11 unsigned
//   field map_we in 1 unsigned
//   field map_addr in 10 unsigned
//   field map_data in 24 signed
//   field pin_cfg in 4 unsigned
//   field sin out 18 signed
//   field cos out 18 signed
//   field ref_mark out 1 unsigned
//   field qa out 1 unsigned
//   field qb out 1 unsigned
//   field qz out 1 unsigned
//   field q_oe out 1 unsigned
//   field cfg_err out 1 unsigned
//   field stage out 2 unsigned
//   field homed out 1 unsigned
//   field lerr_alarm out 1 unsigned
//   field illegal_st out 1 unsigned
//   field err_cnt out 8 unsigned
//   field ovs_edge_st out 1 unsigned
//   field ovs_backlog_st out 1 unsigned
//   field glitch_st out 1 unsigned
//   field alarm out 1 unsigned
//   field raw_count out 32 signed
//   field comp_pos out 38 signed
//   field paced_pos out 38 signed
//   field out_pos out 38 signed
//   field d out 12 unsigned
//   field step out 2 signed
//   field delta out 39 signed
//   field backlog out 40 signed
//   field pstep out 2 signed
//   field ostep out 2 signed
//   field adj out 38 signed
//   field a_pos out 38 signed
//   field b_pos out 38 signed
//   field c_pos out 38 signed
//   field z_pos out 38 signed
//   field rep_mark out 1 unsigned
//   field map_cfg_err out 1 unsigned
//   field corr out 17 signed
//   field map_delta out 18 signed
`timescale 1ns / 1ps
`default_nettype none

module tb_laserax_top;
    parameter integer N_MAX = 40000;   // rows in the vector file
    parameter TBL_FILE = "dds_table_p256.hex";   // table RAM image
    parameter DEBUG_TAPS = 1;   // 1: the DUT's debug taps compared with the vectors; 0: a DUT without taps, each tap column must read 0
    localparam integer ROW_BITS = 1116;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_laserax_top";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  i_a;
    reg  i_b;
    reg  i_sw;
    reg  i_lerr;
    reg  [12:0] i_period;
    reg  [36:0] i_ratio;
    reg  [63:0] i_comp_offset;
    reg  i_comp_sync;
    reg  i_comp_commit;
    reg  [7:0] i_glitch_n;
    reg  [15:0] i_sw_debounce;
    reg  [15:0] i_min_spacing;
    reg  [15:0] i_pace_m;
    reg  [31:0] i_backlog_thr;
    reg  [12:0] i_mark_len;
    reg  [4:0] i_dac_width;
    reg  [17:0] i_amplitude;
    reg  [12:0] i_tbl_period;
    reg  i_rehome;
    reg  i_clear;
    reg  i_tbl_we;
    reg  [9:0] i_tbl_addr;
    reg  [16:0] i_tbl_data;
    reg  i_map_en;
    reg  i_bank_sel;
    reg  [37:0] i_map_origin0;
    reg  [4:0] i_map_k0;
    reg  [10:0] i_map_n0;
    reg  [37:0] i_map_origin1;
    reg  [4:0] i_map_k1;
    reg  [10:0] i_map_n1;
    reg  i_map_we;
    reg  [9:0] i_map_addr;
    reg  [23:0] i_map_data;
    reg  [3:0] i_pin_cfg;
    wire [17:0] o_sin;
    wire [17:0] o_cos;
    wire o_ref_mark;
    wire o_qa;
    wire o_qb;
    wire o_qz;
    wire o_q_oe;
    wire o_cfg_err;
    wire [1:0] o_stage;
    wire o_homed;
    wire o_lerr_alarm;
    wire o_illegal_st;
    wire [7:0] o_err_cnt;
    wire o_ovs_edge_st;
    wire o_ovs_backlog_st;
    wire o_glitch_st;
    wire o_alarm;
    wire [31:0] o_raw_count;
    wire [37:0] o_comp_pos;
    wire [37:0] o_paced_pos;
    wire [37:0] o_out_pos;
    wire [11:0] o_d;
    wire [1:0] o_step;
    wire [38:0] o_delta;
    wire [39:0] o_backlog;
    wire [1:0] o_pstep;
    wire [1:0] o_ostep;
    wire [37:0] o_adj;
    wire [37:0] o_a_pos;
    wire [37:0] o_b_pos;
    wire [37:0] o_c_pos;
    wire [37:0] o_z_pos;
    wire o_rep_mark;
    wire o_map_cfg_err;
    wire [16:0] o_corr;
    wire [17:0] o_map_delta;
    wire o_dac_clip_st;   // not in the vectors

    laserax_top #(.INIT_FILE(TBL_FILE), .DEBUG_TAPS(DEBUG_TAPS)) dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_a(i_a),
        .i_b(i_b),
        .i_sw(i_sw),
        .i_lerr(i_lerr),
        .i_period(i_period),
        .i_ratio(i_ratio),
        .i_comp_offset(i_comp_offset),
        .i_comp_sync(i_comp_sync),
        .i_comp_commit(i_comp_commit),
        .i_glitch_n(i_glitch_n),
        .i_sw_debounce(i_sw_debounce),
        .i_min_spacing(i_min_spacing),
        .i_pace_m(i_pace_m),
        .i_backlog_thr(i_backlog_thr),
        .i_mark_len(i_mark_len),
        .i_dac_width(i_dac_width),
        .i_amplitude(i_amplitude),
        .i_tbl_period(i_tbl_period),
        .i_rehome(i_rehome),
        .i_clear(i_clear),
        .i_tbl_we(i_tbl_we),
        .i_tbl_addr(i_tbl_addr),
        .i_tbl_data(i_tbl_data),
        .i_map_en(i_map_en),
        .i_bank_sel(i_bank_sel),
        .i_map_origin0(i_map_origin0),
        .i_map_k0(i_map_k0),
        .i_map_n0(i_map_n0),
        .i_map_origin1(i_map_origin1),
        .i_map_k1(i_map_k1),
        .i_map_n1(i_map_n1),
        .i_map_we(i_map_we),
        .i_map_addr(i_map_addr),
        .i_map_data(i_map_data),
        .i_pin_cfg(i_pin_cfg),
        .o_sin(o_sin),
        .o_cos(o_cos),
        .o_ref_mark(o_ref_mark),
        .o_qa(o_qa),
        .o_qb(o_qb),
        .o_qz(o_qz),
        .o_q_oe(o_q_oe),
        .o_cfg_err(o_cfg_err),
        .o_stage(o_stage),
        .o_homed(o_homed),
        .o_lerr_alarm(o_lerr_alarm),
        .o_illegal_st(o_illegal_st),
        .o_err_cnt(o_err_cnt),
        .o_ovs_edge_st(o_ovs_edge_st),
        .o_ovs_backlog_st(o_ovs_backlog_st),
        .o_glitch_st(o_glitch_st),
        .o_alarm(o_alarm),
        .o_raw_count(o_raw_count),
        .o_comp_pos(o_comp_pos),
        .o_paced_pos(o_paced_pos),
        .o_out_pos(o_out_pos),
        .o_d(o_d),
        .o_step(o_step),
        .o_delta(o_delta),
        .o_backlog(o_backlog),
        .o_pstep(o_pstep),
        .o_ostep(o_ostep),
        .o_adj(o_adj),
        .o_a_pos(o_a_pos),
        .o_b_pos(o_b_pos),
        .o_c_pos(o_c_pos),
        .o_z_pos(o_z_pos),
        .o_rep_mark(o_rep_mark),
        .o_map_cfg_err(o_map_cfg_err),
        .o_corr(o_corr),
        .o_map_delta(o_map_delta),
        .o_dac_clip_st(o_dac_clip_st)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_a = row[1112:1112];
            i_b = row[1108:1108];
            i_sw = row[1104:1104];
            i_lerr = row[1100:1100];
            i_period = row[1096:1084];
            i_ratio = row[1080:1044];
            i_comp_offset = row[1043:980];
            i_comp_sync = row[976:976];
            i_comp_commit = row[972:972];
            i_glitch_n = row[971:964];
            i_sw_debounce = row[963:948];
            i_min_spacing = row[947:932];
            i_pace_m = row[931:916];
            i_backlog_thr = row[915:884];
            i_mark_len = row[880:868];
            i_dac_width = row[864:860];
            i_amplitude = row[857:840];
            i_tbl_period = row[836:824];
            i_rehome = row[820:820];
            i_clear = row[816:816];
            i_tbl_we = row[812:812];
            i_tbl_addr = row[809:800];
            i_tbl_data = row[796:780];
            i_map_en = row[776:776];
            i_bank_sel = row[772:772];
            i_map_origin0 = row[769:732];
            i_map_k0 = row[728:724];
            i_map_n0 = row[722:712];
            i_map_origin1 = row[709:672];
            i_map_k1 = row[668:664];
            i_map_n1 = row[662:652];
            i_map_we = row[648:648];
            i_map_addr = row[645:636];
            i_map_data = row[635:612];
            i_pin_cfg = row[611:608];
        end
    endtask

    task idle_inputs;
        begin
            i_a = 1'd0;
            i_b = 1'd0;
            i_sw = 1'd0;
            i_lerr = 1'd0;
            i_period = 13'd0;
            i_ratio = 37'd0;
            i_comp_offset = 64'd0;
            i_comp_sync = 1'd0;
            i_comp_commit = 1'd0;
            i_glitch_n = 8'd0;
            i_sw_debounce = 16'd0;
            i_min_spacing = 16'd0;
            i_pace_m = 16'd0;
            i_backlog_thr = 32'd0;
            i_mark_len = 13'd0;
            i_dac_width = 5'd0;
            i_amplitude = 18'd0;
            i_tbl_period = 13'd0;
            i_rehome = 1'd0;
            i_clear = 1'd0;
            i_tbl_we = 1'd0;
            i_tbl_addr = 10'd0;
            i_tbl_data = 17'd0;
            i_map_en = 1'd0;
            i_bank_sel = 1'd0;
            i_map_origin0 = 38'd0;
            i_map_k0 = 5'd0;
            i_map_n0 = 11'd0;
            i_map_origin1 = 38'd0;
            i_map_k1 = 5'd0;
            i_map_n1 = 11'd0;
            i_map_we = 1'd0;
            i_map_addr = 10'd0;
            i_map_data = 24'd0;
            i_pin_cfg = 4'd8;
        end
    endtask

    task ones_inputs;
        begin
            i_a = {1{1'b1}};
            i_b = {1{1'b1}};
            i_sw = {1{1'b1}};
            i_lerr = {1{1'b1}};
            i_period = {13{1'b1}};
            i_ratio = {37{1'b1}};
            i_comp_offset = {64{1'b1}};
            i_comp_sync = {1{1'b1}};
            i_comp_commit = {1{1'b1}};
            i_glitch_n = {8{1'b1}};
            i_sw_debounce = {16{1'b1}};
            i_min_spacing = {16{1'b1}};
            i_pace_m = {16{1'b1}};
            i_backlog_thr = {32{1'b1}};
            i_mark_len = {13{1'b1}};
            i_dac_width = {5{1'b1}};
            i_amplitude = {18{1'b1}};
            i_tbl_period = {13{1'b1}};
            i_rehome = {1{1'b1}};
            i_clear = {1{1'b1}};
            i_tbl_we = {1{1'b1}};
            i_tbl_addr = 10'd0;
            i_tbl_data = {17{1'b1}};
            i_map_en = {1{1'b1}};
            i_bank_sel = {1{1'b1}};
            i_map_origin0 = {38{1'b1}};
            i_map_k0 = {5{1'b1}};
            i_map_n0 = {11{1'b1}};
            i_map_origin1 = {38{1'b1}};
            i_map_k1 = {5{1'b1}};
            i_map_n1 = {11{1'b1}};
            i_map_we = {1{1'b1}};
            i_map_addr = 10'd0;
            i_map_data = {24{1'b1}};
            i_pin_cfg = {4{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("sin", row[605:588], o_sin, 18, 1);
            check("cos", row[585:568], o_cos, 18, 1);
            check("ref_mark", row[564:564], o_ref_mark, 1, 0);
            check("qa", row[560:560], o_qa, 1, 0);
            check("qb", row[556:556], o_qb, 1, 0);
            check("qz", row[552:552], o_qz, 1, 0);
            check("q_oe", row[548:548], o_q_oe, 1, 0);
            check("cfg_err", row[544:544], o_cfg_err, 1, 0);
            check("stage", row[541:540], o_stage, 2, 0);
            check("homed", row[536:536], o_homed, 1, 0);
            check("lerr_alarm", row[532:532], o_lerr_alarm, 1, 0);
            check("illegal_st", row[528:528], o_illegal_st, 1, 0);
            check("err_cnt", row[527:520], o_err_cnt, 8, 0);
            check("ovs_edge_st", row[516:516], o_ovs_edge_st, 1, 0);
            check("ovs_backlog_st", row[512:512], o_ovs_backlog_st, 1, 0);
            check("glitch_st", row[508:508], o_glitch_st, 1, 0);
            check("alarm", row[504:504], o_alarm, 1, 0);
            check("raw_count", (DEBUG_TAPS ? row[503:472] : 32'd0), o_raw_count, 32, 1);
            check("comp_pos", (DEBUG_TAPS ? row[469:432] : 38'd0), o_comp_pos, 38, 1);
            check("paced_pos", (DEBUG_TAPS ? row[429:392] : 38'd0), o_paced_pos, 38, 1);
            check("out_pos", (DEBUG_TAPS ? row[389:352] : 38'd0), o_out_pos, 38, 1);
            check("d", (DEBUG_TAPS ? row[351:340] : 12'd0), o_d, 12, 0);
            check("step", (DEBUG_TAPS ? row[337:336] : 2'd0), o_step, 2, 1);
            check("delta", (DEBUG_TAPS ? row[334:296] : 39'd0), o_delta, 39, 1);
            check("backlog", (DEBUG_TAPS ? row[295:256] : 40'd0), o_backlog, 40, 1);
            check("pstep", (DEBUG_TAPS ? row[253:252] : 2'd0), o_pstep, 2, 1);
            check("ostep", (DEBUG_TAPS ? row[249:248] : 2'd0), o_ostep, 2, 1);
            check("adj", (DEBUG_TAPS ? row[245:208] : 38'd0), o_adj, 38, 1);
            check("a_pos", (DEBUG_TAPS ? row[205:168] : 38'd0), o_a_pos, 38, 1);
            check("b_pos", (DEBUG_TAPS ? row[165:128] : 38'd0), o_b_pos, 38, 1);
            check("c_pos", (DEBUG_TAPS ? row[125:88] : 38'd0), o_c_pos, 38, 1);
            check("z_pos", (DEBUG_TAPS ? row[85:48] : 38'd0), o_z_pos, 38, 1);
            check("rep_mark", (DEBUG_TAPS ? row[44:44] : 1'd0), o_rep_mark, 1, 0);
            check("map_cfg_err", row[40:40], o_map_cfg_err, 1, 0);
            check("corr", row[36:20], o_corr, 17, 1);
            check("map_delta", row[17:0], o_map_delta, 18, 1);
        end
    endtask

endmodule

`default_nettype wire
