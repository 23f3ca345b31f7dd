// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_laserax_regs.v — vector testbench of rtl_ref/laserax_regs.v.
// Spec: block laserax_regs of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: laserax_regs #(.ADDR_W(12)), the register map as an AXI4-Lite slave (generated from
// regmap/laserax_regs.csv by scripts/gen_regmap.py); the AXI4-Lite signals and every register port
// o_<name> are columns.
// Reads laserax_regs.hex, written by regmap_vectors (rtl_ref/tb/regmap_vectors.cpp; CTest
// rtl_laserax_regs): one row per clock, expected columns from the C++ host helper (lxt::reg_image)
// and the AXI4-Lite slave timing documented in docs/REGISTERS.md. Every output column is compared
// with the DUT after every rising edge. Row k is clock k after reset: the DUT is held in reset for
// a few edges, row 0 is applied together with the release of i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
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
//   field period out 13 unsigned
//   field tbl_period out 13 unsigned
//   field ratio out 37 unsigned
//   field comp_offset out 64 signed
//   field glitch_n out 8 unsigned
//   field sw_debounce out 16 unsigned
//   field min_spacing out 16 unsigned
//   field pace_m out 16 unsigned
//   field backlog_thr out 32 unsigned
//   field mark_len out 13 unsigned
//   field dac_width out 5 unsigned
//   field amplitude out 18 unsigned
//   field rehome out 1 unsigned
//   field clear out 1 unsigned
//   field tbl_we out 1 unsigned
//   field tbl_addr out 10 unsigned
//   field tbl_data out 17 unsigned
//   field map_en out 1 unsigned
//   field bank_sel out 1 unsigned
//   field map_origin0 out 38 signed
//   field map_k0 out 5 unsigned
//   field map_n0 out 11 unsigned
//   field map_origin1 out 38 signed
//   field map_k1 out 5 unsigned
//   field map_n1 out 11 unsigned
//   field map_we out 1 unsigned
//   field map_addr out 10 unsigned
//   field map_data out 24 signed
//   field comp_sync out 1 unsigned
//   field comp_commit out 1 unsigned
//   field pin_cfg out 4 unsigned
`timescale 1ns / 1ps
`default_nettype none

module tb_laserax_regs;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 632;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_laserax_regs";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
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
    wire [12:0] o_period;
    wire [12:0] o_tbl_period;
    wire [36:0] o_ratio;
    wire [63:0] o_comp_offset;
    wire [7:0] o_glitch_n;
    wire [15:0] o_sw_debounce;
    wire [15:0] o_min_spacing;
    wire [15:0] o_pace_m;
    wire [31:0] o_backlog_thr;
    wire [12:0] o_mark_len;
    wire [4:0] o_dac_width;
    wire [17:0] o_amplitude;
    wire o_rehome;
    wire o_clear;
    wire o_tbl_we;
    wire [9:0] o_tbl_addr;
    wire [16:0] o_tbl_data;
    wire o_map_en;
    wire o_bank_sel;
    wire [37:0] o_map_origin0;
    wire [4:0] o_map_k0;
    wire [10:0] o_map_n0;
    wire [37:0] o_map_origin1;
    wire [4:0] o_map_k1;
    wire [10:0] o_map_n1;
    wire o_map_we;
    wire [9:0] o_map_addr;
    wire [23:0] o_map_data;
    wire o_comp_sync;
    wire o_comp_commit;
    wire [3:0] o_pin_cfg;

    laserax_regs #(.ADDR_W(12)) dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
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
        .o_period(o_period),
        .o_tbl_period(o_tbl_period),
        .o_ratio(o_ratio),
        .o_comp_offset(o_comp_offset),
        .o_glitch_n(o_glitch_n),
        .o_sw_debounce(o_sw_debounce),
        .o_min_spacing(o_min_spacing),
        .o_pace_m(o_pace_m),
        .o_backlog_thr(o_backlog_thr),
        .o_mark_len(o_mark_len),
        .o_dac_width(o_dac_width),
        .o_amplitude(o_amplitude),
        .o_rehome(o_rehome),
        .o_clear(o_clear),
        .o_tbl_we(o_tbl_we),
        .o_tbl_addr(o_tbl_addr),
        .o_tbl_data(o_tbl_data),
        .o_map_en(o_map_en),
        .o_bank_sel(o_bank_sel),
        .o_map_origin0(o_map_origin0),
        .o_map_k0(o_map_k0),
        .o_map_n0(o_map_n0),
        .o_map_origin1(o_map_origin1),
        .o_map_k1(o_map_k1),
        .o_map_n1(o_map_n1),
        .o_map_we(o_map_we),
        .o_map_addr(o_map_addr),
        .o_map_data(o_map_data),
        .o_comp_sync(o_comp_sync),
        .o_comp_commit(o_comp_commit),
        .o_pin_cfg(o_pin_cfg)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            s_axil_awaddr = row[631:620];
            s_axil_awvalid = row[616:616];
            s_axil_wdata = row[615:584];
            s_axil_wstrb = row[583:580];
            s_axil_wvalid = row[576:576];
            s_axil_bready = row[572:572];
            s_axil_araddr = row[571:560];
            s_axil_arvalid = row[556:556];
            s_axil_rready = row[552:552];
        end
    endtask

    task idle_inputs;
        begin
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
            check("awready", row[548:548], s_axil_awready, 1, 0);
            check("wready", row[544:544], s_axil_wready, 1, 0);
            check("bvalid", row[540:540], s_axil_bvalid, 1, 0);
            check("bresp", row[537:536], s_axil_bresp, 2, 0);
            check("arready", row[532:532], s_axil_arready, 1, 0);
            check("rvalid", row[528:528], s_axil_rvalid, 1, 0);
            check("rdata", row[527:496], s_axil_rdata, 32, 0);
            check("rresp", row[493:492], s_axil_rresp, 2, 0);
            check("period", row[488:476], o_period, 13, 0);
            check("tbl_period", row[472:460], o_tbl_period, 13, 0);
            check("ratio", row[456:420], o_ratio, 37, 0);
            check("comp_offset", row[419:356], o_comp_offset, 64, 1);
            check("glitch_n", row[355:348], o_glitch_n, 8, 0);
            check("sw_debounce", row[347:332], o_sw_debounce, 16, 0);
            check("min_spacing", row[331:316], o_min_spacing, 16, 0);
            check("pace_m", row[315:300], o_pace_m, 16, 0);
            check("backlog_thr", row[299:268], o_backlog_thr, 32, 0);
            check("mark_len", row[264:252], o_mark_len, 13, 0);
            check("dac_width", row[248:244], o_dac_width, 5, 0);
            check("amplitude", row[241:224], o_amplitude, 18, 0);
            check("rehome", row[220:220], o_rehome, 1, 0);
            check("clear", row[216:216], o_clear, 1, 0);
            check("tbl_we", row[212:212], o_tbl_we, 1, 0);
            check("tbl_addr", row[209:200], o_tbl_addr, 10, 0);
            check("tbl_data", row[196:180], o_tbl_data, 17, 0);
            check("map_en", row[176:176], o_map_en, 1, 0);
            check("bank_sel", row[172:172], o_bank_sel, 1, 0);
            check("map_origin0", row[169:132], o_map_origin0, 38, 1);
            check("map_k0", row[128:124], o_map_k0, 5, 0);
            check("map_n0", row[122:112], o_map_n0, 11, 0);
            check("map_origin1", row[109:72], o_map_origin1, 38, 1);
            check("map_k1", row[68:64], o_map_k1, 5, 0);
            check("map_n1", row[62:52], o_map_n1, 11, 0);
            check("map_we", row[48:48], o_map_we, 1, 0);
            check("map_addr", row[45:36], o_map_addr, 10, 0);
            check("map_data", row[35:12], o_map_data, 24, 1);
            check("comp_sync", row[8:8], o_comp_sync, 1, 0);
            check("comp_commit", row[4:4], o_comp_commit, 1, 0);
            check("pin_cfg", row[3:0], o_pin_cfg, 4, 0);
        end
    endtask

endmodule

`default_nettype wire
