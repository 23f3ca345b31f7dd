// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_input_filter.v — vector testbench of rtl_ref/input_filter.v.
// Spec: block input_filter of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: input_filter #(.W_CNT(8)) (the A-pin glitch filter of the chain).
// Reads one vector file in the format of docs/VECTORS.md: input_filter.hex (golden vectors,
// `laserax vectors`; CTest rtl_input_filter) or input_filter_stress.hex (rtl_stress_vectors,
// rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest rtl_input_filter_stress); both
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
//   field pin in 1 unsigned
//   field n in 8 unsigned
//   field f out 1 unsigned
//   field valid out 1 unsigned
//   field glitch out 1 unsigned
`timescale 1ns / 1ps
`default_nettype none

module tb_input_filter;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 24;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_input_filter";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  i_pin;
    reg  [7:0] i_n;
    wire o_f;
    wire o_valid;
    wire o_glitch;
    wire o_f_d;   // not in the vectors
    wire o_valid_d;   // not in the vectors
    wire o_glitch_d;   // not in the vectors

    input_filter #(.W_CNT(8)) dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_pin(i_pin),
        .i_n(i_n),
        .o_f(o_f),
        .o_valid(o_valid),
        .o_glitch(o_glitch),
        .o_f_d(o_f_d),
        .o_valid_d(o_valid_d),
        .o_glitch_d(o_glitch_d)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_pin = row[20:20];
            i_n = row[19:12];
        end
    endtask

    task idle_inputs;
        begin
            i_pin = 1'd0;
            i_n = 8'd0;
        end
    endtask

    task ones_inputs;
        begin
            i_pin = {1{1'b1}};
            i_n = {8{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("f", row[8:8], o_f, 1, 0);
            check("valid", row[4:4], o_valid, 1, 0);
            check("glitch", row[0:0], o_glitch, 1, 0);
        end
    endtask

endmodule

`default_nettype wire
