// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_dds_sincos.v — vector testbench of rtl_ref/dds_sincos.v.
// Spec: block dds_sincos of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: dds_sincos, table RAM at its power-up contents TBL_FILE (P = 256, amp = 32767); the table
// write port comes from the vectors (idle in the golden set; table loads, stray writes read in the
// same call and periods up to 4096 in the stress set).
// Reads one vector file in the format of docs/VECTORS.md: dds_sincos.hex (golden vectors, `laserax
// vectors`; CTest rtl_dds_sincos) or dds_sincos_stress.hex (rtl_stress_vectors,
// rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest rtl_dds_sincos_stress); both
// have the field list below. For every row it applies the row's inputs before a rising clock edge
// and compares every output column with the DUT outputs after that edge. Row k is call k after
// reset: the DUT is held in reset for a few edges, row 0 is applied together with the release of
// i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file, TBL_FILE = table RAM image.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field ostep in 2 signed
//   field period in 13 unsigned
//   field amplitude in 18 unsigned
//   field tbl_we in 1 unsigned
//   field tbl_addr in 10 unsigned
//   field tbl_data in 17 unsigned
//   field sin out 18 signed
//   field cos out 18 signed
`timescale 1ns / 1ps
`default_nettype none

module tb_dds_sincos;
    parameter integer N_MAX = 40000;   // rows in the vector file
    parameter TBL_FILE = "dds_table_p256.hex";   // table RAM image
    localparam integer ROW_BITS = 116;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_dds_sincos";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  [1:0] i_ostep;
    reg  [12:0] i_period;
    reg  [17:0] i_amplitude;
    reg  i_tbl_we;
    reg  [9:0] i_tbl_addr;
    reg  [16:0] i_tbl_data;
    reg  [10:0] i_qtr_m1;   // idle (not in the vectors)
    reg  [17:0] i_clip_hi;   // idle (not in the vectors)
    wire [17:0] o_sin;
    wire [17:0] o_cos;
    wire o_sin_over;   // not in the vectors
    wire o_cos_over;   // not in the vectors

    dds_sincos #(.INIT_FILE(TBL_FILE)) dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_ostep(i_ostep),
        .i_period(i_period),
        .i_amplitude(i_amplitude),
        .i_tbl_we(i_tbl_we),
        .i_tbl_addr(i_tbl_addr),
        .i_tbl_data(i_tbl_data),
        .i_qtr_m1(i_qtr_m1),
        .i_clip_hi(i_clip_hi),
        .o_sin(o_sin),
        .o_cos(o_cos),
        .o_sin_over(o_sin_over),
        .o_cos_over(o_cos_over)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_ostep = row[113:112];
            i_period = row[108:96];
            i_amplitude = row[93:76];
            i_tbl_we = row[72:72];
            i_tbl_addr = row[69:60];
            i_tbl_data = row[56:40];
            i_qtr_m1 = i_period[12:2] - 11'd1;
        end
    endtask

    task idle_inputs;
        begin
            i_ostep = 2'd0;
            i_period = 13'd0;
            i_amplitude = 18'd0;
            i_tbl_we = 1'd0;
            i_tbl_addr = 10'd0;
            i_tbl_data = 17'd0;
            i_qtr_m1 = 11'd2047;
            i_clip_hi = 18'd262143;
        end
    endtask

    task ones_inputs;
        begin
            i_ostep = {2{1'b1}};
            i_period = {13{1'b1}};
            i_amplitude = {18{1'b1}};
            i_tbl_we = {1{1'b1}};
            i_tbl_addr = 10'd0;
            i_tbl_data = {17{1'b1}};
            i_qtr_m1 = {11{1'b1}};
            i_clip_hi = {18{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("sin", row[37:20], o_sin, 18, 1);
            check("cos", row[17:0], o_cos, 18, 1);
        end
    endtask

endmodule

`default_nettype wire
