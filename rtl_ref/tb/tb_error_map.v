// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_error_map.v — vector testbench of rtl_ref/error_map.v.
// Spec: block error_map of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: error_map (2 banks x 1024 x 24-bit table RAM as even/odd RAMs, a sample every 32 calls,
// 50-call latency); the RAMs start at 0 as the C++ tables; both vector sets still write every word
// before a call that is active reads it (the golden set after the chain scenario's map: a directed
// tail with flips, both table ends, invalid geometries and every spacing).
// Reads one vector file in the format of docs/VECTORS.md: error_map.hex (golden vectors, `laserax
// vectors`; CTest rtl_error_map) or error_map_stress.hex (rtl_stress_vectors,
// rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest rtl_error_map_stress); both have
// the field list below. For every row it applies the row's inputs before a rising clock edge and
// compares every output column with the DUT outputs after that edge. Row k is call k after reset:
// the DUT is held in reset for a few edges, row 0 is applied together with the release of i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field p in 38 signed
//   field homed in 1 unsigned
//   field map_en in 1 unsigned
//   field bank_sel in 1 unsigned
//   field origin0 in 38 signed
//   field k0 in 5 unsigned
//   field n0 in 11 unsigned
//   field origin1 in 38 signed
//   field k1 in 5 unsigned
//   field n1 in 11 unsigned
//   field we in 1 unsigned
//   field addr in 10 unsigned
//   field data in 24 signed
//   field corr out 17 signed
//   field delta out 18 signed
//   field active out 1 unsigned
//   field in_range out 1 unsigned
//   field clamped out 1 unsigned
//   field cfg_err out 1 unsigned
`timescale 1ns / 1ps
`default_nettype none

module tb_error_map;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 268;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_error_map";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  [37:0] i_p;
    reg  i_homed;
    reg  i_map_en;
    reg  i_bank_sel;
    reg  [37:0] i_origin0;
    reg  [4:0] i_k0;
    reg  [10:0] i_n0;
    reg  [37:0] i_origin1;
    reg  [4:0] i_k1;
    reg  [10:0] i_n1;
    reg  i_we;
    reg  [9:0] i_addr;
    reg  [23:0] i_data;
    wire [16:0] o_corr;
    wire [17:0] o_delta;
    wire o_active;
    wire o_in_range;
    wire o_clamped;
    wire o_cfg_err;

    error_map dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_p(i_p),
        .i_homed(i_homed),
        .i_map_en(i_map_en),
        .i_bank_sel(i_bank_sel),
        .i_origin0(i_origin0),
        .i_k0(i_k0),
        .i_n0(i_n0),
        .i_origin1(i_origin1),
        .i_k1(i_k1),
        .i_n1(i_n1),
        .i_we(i_we),
        .i_addr(i_addr),
        .i_data(i_data),
        .o_corr(o_corr),
        .o_delta(o_delta),
        .o_active(o_active),
        .o_in_range(o_in_range),
        .o_clamped(o_clamped),
        .o_cfg_err(o_cfg_err)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_p = row[265:228];
            i_homed = row[224:224];
            i_map_en = row[220:220];
            i_bank_sel = row[216:216];
            i_origin0 = row[213:176];
            i_k0 = row[172:168];
            i_n0 = row[166:156];
            i_origin1 = row[153:116];
            i_k1 = row[112:108];
            i_n1 = row[106:96];
            i_we = row[92:92];
            i_addr = row[89:80];
            i_data = row[79:56];
        end
    endtask

    task idle_inputs;
        begin
            i_p = 38'd0;
            i_homed = 1'd0;
            i_map_en = 1'd0;
            i_bank_sel = 1'd0;
            i_origin0 = 38'd0;
            i_k0 = 5'd0;
            i_n0 = 11'd0;
            i_origin1 = 38'd0;
            i_k1 = 5'd0;
            i_n1 = 11'd0;
            i_we = 1'd0;
            i_addr = 10'd0;
            i_data = 24'd0;
        end
    endtask

    task ones_inputs;
        begin
            i_p = {38{1'b1}};
            i_homed = {1{1'b1}};
            i_map_en = {1{1'b1}};
            i_bank_sel = {1{1'b1}};
            i_origin0 = {38{1'b1}};
            i_k0 = {5{1'b1}};
            i_n0 = {11{1'b1}};
            i_origin1 = {38{1'b1}};
            i_k1 = {5{1'b1}};
            i_n1 = {11{1'b1}};
            i_we = {1{1'b1}};
            i_addr = 10'd0;
            i_data = {24{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("corr", row[52:36], o_corr, 17, 1);
            check("delta", row[33:16], o_delta, 18, 1);
            check("active", row[12:12], o_active, 1, 0);
            check("in_range", row[8:8], o_in_range, 1, 0);
            check("clamped", row[4:4], o_clamped, 1, 0);
            check("cfg_err", row[0:0], o_cfg_err, 1, 0);
        end
    endtask

endmodule

`default_nettype wire
