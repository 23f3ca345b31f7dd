// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_rephase.v — vector testbench of rtl_ref/rephase.v.
// Spec: block rephase of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: rephase.
// Reads one vector file in the format of docs/VECTORS.md: rephase.hex (golden vectors, `laserax
// vectors`; CTest rtl_rephase) or rephase_stress.hex (rtl_stress_vectors,
// rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest rtl_rephase_stress); both have
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
//   field pstep in 2 signed
//   field slot in 1 unsigned
//   field sw in 1 unsigned
//   field sw_valid in 1 unsigned
//   field rehome in 1 unsigned
//   field unhome in 1 unsigned
//   field period in 13 unsigned
//   field mark_len in 13 unsigned
//   field ostep out 2 signed
//   field out_pos out 38 signed
//   field mark out 1 unsigned
//   field index out 1 unsigned
//   field stage out 2 unsigned
//   field a out 38 signed
//   field d out 12 unsigned
//   field b out 38 signed
//   field c out 38 signed
//   field z out 38 signed
//   field adj out 38 signed
//   field homed out 1 unsigned
`timescale 1ns / 1ps
`default_nettype none

module tb_rephase;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 328;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_rephase";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  [1:0] i_pstep;
    reg  i_slot;
    reg  i_sw;
    reg  i_sw_valid;
    reg  i_rehome;
    reg  i_unhome;
    reg  [12:0] i_period;
    reg  [12:0] i_mark_len;
    reg  [13:0] i_period_m1;   // idle (not in the vectors)
    reg  [13:0] i_period_m2;   // idle (not in the vectors)
    reg  [12:0] i_mark_len_n;   // idle (not in the vectors)
    reg  [1:0] i_pstep_nx;   // idle (not in the vectors)
    reg  i_slot_nx;   // idle (not in the vectors)
    reg  i_unhome_nx;   // idle (not in the vectors)
    reg  i_rehome_nx;   // idle (not in the vectors)
    wire [1:0] o_ostep;
    wire [37:0] o_out_pos;
    wire o_mark;
    wire o_index;
    wire [1:0] o_stage;
    wire [37:0] o_a;
    wire [11:0] o_d;
    wire [37:0] o_b;
    wire [37:0] o_c;
    wire [37:0] o_z;
    wire [37:0] o_adj;
    wire o_homed;

    rephase dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_pstep(i_pstep),
        .i_slot(i_slot),
        .i_sw(i_sw),
        .i_sw_valid(i_sw_valid),
        .i_rehome(i_rehome),
        .i_unhome(i_unhome),
        .i_period(i_period),
        .i_mark_len(i_mark_len),
        .i_period_m1(i_period_m1),
        .i_period_m2(i_period_m2),
        .i_mark_len_n(i_mark_len_n),
        .i_pstep_nx(i_pstep_nx),
        .i_slot_nx(i_slot_nx),
        .i_unhome_nx(i_unhome_nx),
        .i_rehome_nx(i_rehome_nx),
        .o_ostep(o_ostep),
        .o_out_pos(o_out_pos),
        .o_mark(o_mark),
        .o_index(o_index),
        .o_stage(o_stage),
        .o_a(o_a),
        .o_d(o_d),
        .o_b(o_b),
        .o_c(o_c),
        .o_z(o_z),
        .o_adj(o_adj),
        .o_homed(o_homed)
    );

    `include "tb_common.vh"

    // the look-ahead inputs pstep_nx, slot_nx, unhome_nx, rehome_nx are those of the next call (DESIGN
    // 4.5): the next row's (row 0's during reset, 0 after the last row)
    reg [ROW_BITS-1:0] row_nx;

    task apply_inputs;
        begin
            i_pstep = row[325:324];
            i_slot = row[320:320];
            i_sw = row[316:316];
            i_sw_valid = row[312:312];
            i_rehome = row[308:308];
            i_unhome = row[304:304];
            i_period = row[300:288];
            i_mark_len = row[284:272];
            i_period_m1 = $signed({1'b0, i_period}) - 14'sd1;
            i_period_m2 = $signed({1'b0, i_period}) - 14'sd2;
            i_mark_len_n = ~i_mark_len;
            row_nx = (k + 1 < rows) ? vec[k + 1] : {ROW_BITS{1'b0}};
            i_pstep_nx = row_nx[325:324];
            i_slot_nx = row_nx[320:320];
            i_unhome_nx = row_nx[304:304];
            i_rehome_nx = row_nx[308:308];
        end
    endtask

    task idle_inputs;
        begin
            i_pstep = 2'd0;
            i_slot = 1'd0;
            i_sw = 1'd0;
            i_sw_valid = 1'd0;
            i_rehome = 1'd0;
            i_unhome = 1'd0;
            i_period = 13'd0;
            i_mark_len = 13'd0;
            i_period_m1 = 14'd16383;
            i_period_m2 = 14'd16382;
            i_mark_len_n = 13'd8191;
            i_pstep_nx = 2'd0;
            i_slot_nx = 1'd0;
            i_unhome_nx = 1'd0;
            i_rehome_nx = 1'd0;
            row_nx = vec[0];
            i_pstep_nx = row_nx[325:324];
            i_slot_nx = row_nx[320:320];
            i_unhome_nx = row_nx[304:304];
            i_rehome_nx = row_nx[308:308];
        end
    endtask

    task ones_inputs;
        begin
            i_pstep = {2{1'b1}};
            i_slot = {1{1'b1}};
            i_sw = {1{1'b1}};
            i_sw_valid = {1{1'b1}};
            i_rehome = {1{1'b1}};
            i_unhome = {1{1'b1}};
            i_period = {13{1'b1}};
            i_mark_len = {13{1'b1}};
            i_period_m1 = {14{1'b1}};
            i_period_m2 = {14{1'b1}};
            i_mark_len_n = {13{1'b1}};
            i_pstep_nx = {2{1'b1}};
            i_slot_nx = {1{1'b1}};
            i_unhome_nx = {1{1'b1}};
            i_rehome_nx = {1{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("ostep", row[269:268], o_ostep, 2, 1);
            check("out_pos", row[265:228], o_out_pos, 38, 1);
            check("mark", row[224:224], o_mark, 1, 0);
            check("index", row[220:220], o_index, 1, 0);
            check("stage", row[217:216], o_stage, 2, 0);
            check("a", row[213:176], o_a, 38, 1);
            check("d", row[175:164], o_d, 12, 0);
            check("b", row[161:124], o_b, 38, 1);
            check("c", row[121:84], o_c, 38, 1);
            check("z", row[81:44], o_z, 38, 1);
            check("adj", row[41:4], o_adj, 38, 1);
            check("homed", row[0:0], o_homed, 1, 0);
        end
    endtask

endmodule

`default_nettype wire
