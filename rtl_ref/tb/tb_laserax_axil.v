// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_laserax_axil.v — vector testbench of rtl_ref/laserax_axil.v.
// Spec: block laserax_axil of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: laserax_axil (laserax_regs + laserax_top), table RAM at its power-up contents TBL_FILE; the
// pins, the AXI4-Lite signals and every laserax_top output are columns: the chain is programmed
// only through the bus.
// Reads laserax_axil.hex, written by regmap_vectors (rtl_ref/tb/regmap_vectors.cpp; CTest
// rtl_laserax_axil): one row per clock, expected columns from the C++ host helper (lxt::reg_image)
// and the AXI4-Lite slave timing documented in docs/REGISTERS.md, and the chain (hls/laserax_top.h)
// stepped with the registers before each edge's write (a write completing at edge t acts in call
// t+1). Every output column is compared with the DUT after every rising edge. Row k is clock k
// after reset: the DUT is held in reset for a few edges, row 0 is applied together with the release
// of i_rst.
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
//   field awaddr in 12 unsigned
//   field awvalid in 1 unsigned
//   field wdata in 32 unsigned
//   field wstrb in 4 unsigned
//   field wvalid in 1 unsigned
//   field bready in 1 unsigned
//   field araddr in 12 unsigned
//   field arvalid in 1 unsigned
//   field rready in 1 unsigned
//   field awready out 1 unsigned
//   field wready out 1 unsigned
//   field bvalid out 1 unsigned
//   field bresp out 2 unsigned
//   field arready out 1 unsigned
//   field rvalid out 1 unsigned
//   field rdata out 32 unsigned
//   field rresp out 2 unsigned
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

module tb_laserax_axil;
    parameter integer N_MAX = 40000;   // rows in the vector file
    parameter TBL_FILE = "dds_table_p256.hex";   // table RAM image
    parameter DEBUG_TAPS = 1;   // 1: the DUT's debug taps compared with the vectors; 0: a DUT without taps, each tap column must read 0
    localparam integer ROW_BITS = 764;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_laserax_axil";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  i_a;
    reg  i_b;
    reg  i_sw;
    reg  i_lerr;
    reg  [11:0] s_axil_awaddr;
    reg  s_axil_awvalid;
    reg  [31:0] s_axil_wdata;
    reg  [3:0] s_axil_wstrb;
    reg  s_axil_wvalid;
    reg  s_axil_bready;
    reg  [11:0] s_axil_araddr;
    reg  s_axil_arvalid;
    reg  s_axil_rready;
    wire s_axil_awready;
    wire s_axil_wready;
    wire s_axil_bvalid;
    wire [1:0] s_axil_bresp;
    wire s_axil_arready;
    wire s_axil_rvalid;
    wire [31:0] s_axil_rdata;
    wire [1:0] s_axil_rresp;
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

    laserax_axil #(.INIT_FILE(TBL_FILE), .ADDR_W(12), .DEBUG_TAPS(DEBUG_TAPS)) dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_a(i_a),
        .i_b(i_b),
        .i_sw(i_sw),
        .i_lerr(i_lerr),
        .s_axil_awaddr(s_axil_awaddr),
        .s_axil_awvalid(s_axil_awvalid),
        .s_axil_wdata(s_axil_wdata),
        .s_axil_wstrb(s_axil_wstrb),
        .s_axil_wvalid(s_axil_wvalid),
        .s_axil_bready(s_axil_bready),
        .s_axil_araddr(s_axil_araddr),
        .s_axil_arvalid(s_axil_arvalid),
        .s_axil_rready(s_axil_rready),
        .s_axil_awready(s_axil_awready),
        .s_axil_wready(s_axil_wready),
        .s_axil_bvalid(s_axil_bvalid),
        .s_axil_bresp(s_axil_bresp),
        .s_axil_arready(s_axil_arready),
        .s_axil_rvalid(s_axil_rvalid),
        .s_axil_rdata(s_axil_rdata),
        .s_axil_rresp(s_axil_rresp),
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
            i_a = row[760:760];
            i_b = row[756:756];
            i_sw = row[752:752];
            i_lerr = row[748:748];
            s_axil_awaddr = row[747:736];
            s_axil_awvalid = row[732:732];
            s_axil_wdata = row[731:700];
            s_axil_wstrb = row[699:696];
            s_axil_wvalid = row[692:692];
            s_axil_bready = row[688:688];
            s_axil_araddr = row[687:676];
            s_axil_arvalid = row[672:672];
            s_axil_rready = row[668:668];
        end
    endtask

    task idle_inputs;
        begin
            i_a = 1'd0;
            i_b = 1'd0;
            i_sw = 1'd0;
            i_lerr = 1'd0;
            s_axil_awaddr = 12'd0;
            s_axil_awvalid = 1'd0;
            s_axil_wdata = 32'd0;
            s_axil_wstrb = 4'd0;
            s_axil_wvalid = 1'd0;
            s_axil_bready = 1'd0;
            s_axil_araddr = 12'd0;
            s_axil_arvalid = 1'd0;
            s_axil_rready = 1'd0;
        end
    endtask

    task ones_inputs;
        begin
            i_a = {1{1'b1}};
            i_b = {1{1'b1}};
            i_sw = {1{1'b1}};
            i_lerr = {1{1'b1}};
            s_axil_awaddr = {12{1'b1}};
            s_axil_awvalid = {1{1'b1}};
            s_axil_wdata = {32{1'b1}};
            s_axil_wstrb = {4{1'b1}};
            s_axil_wvalid = {1{1'b1}};
            s_axil_bready = {1{1'b1}};
            s_axil_araddr = {12{1'b1}};
            s_axil_arvalid = {1{1'b1}};
            s_axil_rready = {1{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("awready", row[664:664], s_axil_awready, 1, 0);
            check("wready", row[660:660], s_axil_wready, 1, 0);
            check("bvalid", row[656:656], s_axil_bvalid, 1, 0);
            check("bresp", row[653:652], s_axil_bresp, 2, 0);
            check("arready", row[648:648], s_axil_arready, 1, 0);
            check("rvalid", row[644:644], s_axil_rvalid, 1, 0);
            check("rdata", row[643:612], s_axil_rdata, 32, 0);
            check("rresp", row[609:608], s_axil_rresp, 2, 0);
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
