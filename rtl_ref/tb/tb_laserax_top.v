// tb_laserax_top.v — vector testbench of rtl_ref/laserax_top.v.
//
// DUT: laserax_top (whole chain; the table write port is idle, as in the vectors).
// Reads laserax_top.hex written by `laserax vectors` (docs/VECTORS.md) and, for every row, applies
// the row's inputs before a rising clock edge and compares every output column with the DUT
// outputs after that edge. Row k is call k after reset: the DUT is held in reset for a few
// edges, row 0 is applied together with the release of i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file, TBL_FILE = table RAM image.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field a in 1 unsigned
//   field b in 1 unsigned
//   field sw in 1 unsigned
//   field lerr in 1 unsigned
//   field period in 13 unsigned
//   field ratio in 37 unsigned
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
//   field map_en in 1 unsigned
//   field bank_sel in 1 unsigned
//   field map_origin0 in 38 signed
//   field map_k0 in 5 unsigned
//   field map_n0 in 12 unsigned
//   field map_origin1 in 38 signed
//   field map_k1 in 5 unsigned
//   field map_n1 in 12 unsigned
//   field map_we in 1 unsigned
//   field map_addr in 11 unsigned
//   field map_data in 24 signed
//   field sin out 18 signed
//   field cos out 18 signed
//   field ref_mark out 1 unsigned
//   field qa out 1 unsigned
//   field qb out 1 unsigned
//   field qz out 1 unsigned
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
//   field map_cfg_err out 1 unsigned
//   field corr out 17 signed
//   field map_delta out 18 signed
`timescale 1ns / 1ps
`default_nettype none

module tb_laserax_top;
    parameter integer N_MAX = 40000;   // rows in the vector file
    parameter TBL_FILE = "dds_table_p256.hex";   // table RAM image
    localparam integer ROW_BITS = 704;   // 4 * sum(ceil(bits/4)) over the fields
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
    reg  i_tbl_we;   // idle
    reg  [9:0] i_tbl_addr;   // idle
    reg  [16:0] i_tbl_data;   // idle
    reg  i_map_en;
    reg  i_bank_sel;
    reg  [37:0] i_map_origin0;
    reg  [4:0] i_map_k0;
    reg  [11:0] i_map_n0;
    reg  [37:0] i_map_origin1;
    reg  [4:0] i_map_k1;
    reg  [11:0] i_map_n1;
    reg  i_map_we;
    reg  [10:0] i_map_addr;
    reg  [23:0] i_map_data;
    wire [17:0] o_sin;
    wire [17:0] o_cos;
    wire o_ref_mark;
    wire o_qa;
    wire o_qb;
    wire o_qz;
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
    wire [1:0] o_step;   // not in the vectors
    wire [37:0] o_comp_pos;
    wire [38:0] o_delta;   // not in the vectors
    wire [39:0] o_backlog;   // not in the vectors
    wire [1:0] o_pstep;   // not in the vectors
    wire [37:0] o_paced_pos;
    wire [1:0] o_ostep;   // not in the vectors
    wire [37:0] o_out_pos;
    wire [37:0] o_adj;   // not in the vectors
    wire [37:0] o_a_pos;   // not in the vectors
    wire [37:0] o_b_pos;   // not in the vectors
    wire [37:0] o_c_pos;   // not in the vectors
    wire [37:0] o_z_pos;   // not in the vectors
    wire [11:0] o_d;
    wire o_rep_mark;   // not in the vectors
    wire o_map_cfg_err;
    wire [16:0] o_corr;
    wire [17:0] o_map_delta;

    laserax_top #(.INIT_FILE(TBL_FILE)) dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_a(i_a),
        .i_b(i_b),
        .i_sw(i_sw),
        .i_lerr(i_lerr),
        .i_period(i_period),
        .i_ratio(i_ratio),
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
        .o_sin(o_sin),
        .o_cos(o_cos),
        .o_ref_mark(o_ref_mark),
        .o_qa(o_qa),
        .o_qb(o_qb),
        .o_qz(o_qz),
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
        .o_step(o_step),
        .o_comp_pos(o_comp_pos),
        .o_delta(o_delta),
        .o_backlog(o_backlog),
        .o_pstep(o_pstep),
        .o_paced_pos(o_paced_pos),
        .o_ostep(o_ostep),
        .o_out_pos(o_out_pos),
        .o_adj(o_adj),
        .o_a_pos(o_a_pos),
        .o_b_pos(o_b_pos),
        .o_c_pos(o_c_pos),
        .o_z_pos(o_z_pos),
        .o_d(o_d),
        .o_rep_mark(o_rep_mark),
        .o_map_cfg_err(o_map_cfg_err),
        .o_corr(o_corr),
        .o_map_delta(o_map_delta)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_a = row[700:700];
            i_b = row[696:696];
            i_sw = row[692:692];
            i_lerr = row[688:688];
            i_period = row[684:672];
            i_ratio = row[668:632];
            i_glitch_n = row[631:624];
            i_sw_debounce = row[623:608];
            i_min_spacing = row[607:592];
            i_pace_m = row[591:576];
            i_backlog_thr = row[575:544];
            i_mark_len = row[540:528];
            i_dac_width = row[524:520];
            i_amplitude = row[517:500];
            i_tbl_period = row[496:484];
            i_rehome = row[480:480];
            i_clear = row[476:476];
            i_map_en = row[472:472];
            i_bank_sel = row[468:468];
            i_map_origin0 = row[465:428];
            i_map_k0 = row[424:420];
            i_map_n0 = row[419:408];
            i_map_origin1 = row[405:368];
            i_map_k1 = row[364:360];
            i_map_n1 = row[359:348];
            i_map_we = row[344:344];
            i_map_addr = row[342:332];
            i_map_data = row[331:308];
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
            i_map_n0 = 12'd0;
            i_map_origin1 = 38'd0;
            i_map_k1 = 5'd0;
            i_map_n1 = 12'd0;
            i_map_we = 1'd0;
            i_map_addr = 11'd0;
            i_map_data = 24'd0;
        end
    endtask

    task check_outputs;
        begin
            check("sin", row[305:288], o_sin, 18, 1);
            check("cos", row[285:268], o_cos, 18, 1);
            check("ref_mark", row[264:264], o_ref_mark, 1, 0);
            check("qa", row[260:260], o_qa, 1, 0);
            check("qb", row[256:256], o_qb, 1, 0);
            check("qz", row[252:252], o_qz, 1, 0);
            check("cfg_err", row[248:248], o_cfg_err, 1, 0);
            check("stage", row[245:244], o_stage, 2, 0);
            check("homed", row[240:240], o_homed, 1, 0);
            check("lerr_alarm", row[236:236], o_lerr_alarm, 1, 0);
            check("illegal_st", row[232:232], o_illegal_st, 1, 0);
            check("err_cnt", row[231:224], o_err_cnt, 8, 0);
            check("ovs_edge_st", row[220:220], o_ovs_edge_st, 1, 0);
            check("ovs_backlog_st", row[216:216], o_ovs_backlog_st, 1, 0);
            check("glitch_st", row[212:212], o_glitch_st, 1, 0);
            check("alarm", row[208:208], o_alarm, 1, 0);
            check("raw_count", row[207:176], o_raw_count, 32, 1);
            check("comp_pos", row[173:136], o_comp_pos, 38, 1);
            check("paced_pos", row[133:96], o_paced_pos, 38, 1);
            check("out_pos", row[93:56], o_out_pos, 38, 1);
            check("d", row[55:44], o_d, 12, 0);
            check("map_cfg_err", row[40:40], o_map_cfg_err, 1, 0);
            check("corr", row[36:20], o_corr, 17, 1);
            check("map_delta", row[17:0], o_map_delta, 18, 1);
        end
    endtask

endmodule

`default_nettype wire
