// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_output_pacer.v — vector testbench of rtl_ref/output_pacer.v.
// Spec: block output_pacer of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: output_pacer.
// Reads one vector file in the format of docs/VECTORS.md: output_pacer.hex (golden vectors,
// `laserax vectors`; CTest rtl_output_pacer) or output_pacer_stress.hex (rtl_stress_vectors,
// rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest rtl_output_pacer_stress); both
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
//   field delta in 39 signed
//   field pace_m in 16 unsigned
//   field thr in 32 unsigned
//   field clear in 1 unsigned
//   field wide in 1 unsigned
//   field pstep out 2 signed
//   field slot out 1 unsigned
//   field paced out 38 signed
//   field backlog out 40 signed
//   field ovs out 1 unsigned
//   field ovs_st out 1 unsigned
`timescale 1ns / 1ps
`default_nettype none

module tb_output_pacer;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 192;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_output_pacer";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  [38:0] i_delta;
    reg  [15:0] i_pace_m;
    reg  [31:0] i_thr;
    reg  i_clear;
    reg  i_wide;
    reg  [17:0] i_add;   // idle (not in the vectors)
    wire [1:0] o_pstep;
    wire o_slot;
    wire [37:0] o_paced;
    wire [39:0] o_backlog;
    wire o_ovs;
    wire o_ovs_st;
    wire [1:0] o_pstep_nx;   // not in the vectors
    wire o_slot_nx;   // not in the vectors

    output_pacer dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_delta(i_delta),
        .i_pace_m(i_pace_m),
        .i_thr(i_thr),
        .i_clear(i_clear),
        .i_wide(i_wide),
        .i_add(i_add),
        .o_pstep(o_pstep),
        .o_slot(o_slot),
        .o_paced(o_paced),
        .o_backlog(o_backlog),
        .o_ovs(o_ovs),
        .o_ovs_st(o_ovs_st),
        .o_pstep_nx(o_pstep_nx),
        .o_slot_nx(o_slot_nx)
    );

    `include "tb_common.vh"

    // the second addend (i_add, the error-map delta in the top): the vector's delta is split into
    // i_delta + i_add with i_add from a 32-bit LFSR (one step per row): random, small, the corners
    // -2^17 and 2^17 - 1, or 0; not where |delta| >= 2^37 (i_delta could then wrap)
    reg [31:0] add_lfsr = 32'h1;

    task apply_inputs;
        begin
            i_delta = row[190:152];
            i_pace_m = row[151:136];
            i_thr = row[135:104];
            i_clear = row[100:100];
            i_wide = row[96:96];
            add_lfsr = {add_lfsr[30:0], add_lfsr[31] ^ add_lfsr[21] ^ add_lfsr[1] ^ add_lfsr[0]};
            if (i_delta[38:37] == 2'b00 || i_delta[38:37] == 2'b11) begin
                case (add_lfsr[31:29])
                    3'd0: i_add = add_lfsr[17:0];
                    3'd1: i_add = {{13{add_lfsr[4]}}, add_lfsr[4:0]};
                    3'd2: i_add = add_lfsr[5] ? 18'h20000 : 18'h1ffff;
                    default: i_add = 18'd0;
                endcase
                i_delta = i_delta - {{21{i_add[17]}}, i_add};
            end else begin
                i_add = 18'd0;
            end
        end
    endtask

    task idle_inputs;
        begin
            i_delta = 39'd0;
            i_pace_m = 16'd0;
            i_thr = 32'd0;
            i_clear = 1'd0;
            i_wide = 1'd0;
            i_add = 18'd0;
        end
    endtask

    task ones_inputs;
        begin
            i_delta = {39{1'b1}};
            i_pace_m = {16{1'b1}};
            i_thr = {32{1'b1}};
            i_clear = {1{1'b1}};
            i_wide = {1{1'b1}};
            i_add = {18{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("pstep", row[93:92], o_pstep, 2, 1);
            check("slot", row[88:88], o_slot, 1, 0);
            check("paced", row[85:48], o_paced, 38, 1);
            check("backlog", row[47:8], o_backlog, 40, 1);
            check("ovs", row[4:4], o_ovs, 1, 0);
            check("ovs_st", row[0:0], o_ovs_st, 1, 0);
        end
    endtask

endmodule

`default_nettype wire
