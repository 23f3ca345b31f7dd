// GENERATED FILE - do not edit. Command: /usr/bin/python3 scripts/gen_rtl_tb.py --out rtl_ref/tb
// tb_encoder_counter.v — vector testbench of rtl_ref/encoder_counter.v.
// Spec: block encoder_counter of BLOCKS in scripts/gen_rtl_tb.py; shared body: tb_common.vh.
//
// DUT: encoder_counter (two 32-bit wrapping counters, simulation, reset now / at a trigger, wait-
// for-encoder, the 10 us correction as a sequenced product: sample call + 32); every input is a
// column (the golden set: one scenario; the stress set: every register moved, invalid
// configurations, live period changes). corr_period is 1000 during reset.
// Reads one vector file in the format of docs/VECTORS.md: encoder_counter.hex (golden vectors,
// `laserax vectors`; CTest rtl_encoder_counter) or encoder_counter_stress.hex (rtl_stress_vectors,
// rtl_ref/tb/stress_vectors.cpp, expected columns from hls/; CTest rtl_encoder_counter_stress);
// both have the field list below. For every row it applies the row's inputs before a rising clock
// edge and compares every output column with the DUT outputs after that edge. Row k is call k after
// reset: the DUT is held in reset for a few edges, row 0 is applied together with the release of
// i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field qstep0 in 2 signed
//   field qstep1 in 2 signed
//   field trig in 1 unsigned
//   field pos0 in 32 signed
//   field pos1 in 32 signed
//   field src0 in 2 unsigned
//   field src1 in 2 unsigned
//   field sim_inc0 in 32 unsigned
//   field sim_inc1 in 32 unsigned
//   field sim_down0 in 1 unsigned
//   field sim_down1 in 1 unsigned
//   field scale0 in 32 signed
//   field scale1 in 32 signed
//   field rst_req0 in 1 unsigned
//   field rst_req1 in 1 unsigned
//   field load0 in 1 unsigned
//   field load1 in 1 unsigned
//   field load_val0 in 32 signed
//   field load_val1 in 32 signed
//   field rst_on_trig in 1 unsigned
//   field corr_period in 16 unsigned
//   field wait_arm in 1 unsigned
//   field wait_ch in 1 unsigned
//   field wait_val in 32 signed
//   field wait_down in 1 unsigned
//   field cnt0 out 32 signed
//   field cnt1 out 32 signed
//   field step0 out 2 signed
//   field step1 out 2 signed
//   field rst_done0 out 1 unsigned
//   field rst_done1 out 1 unsigned
//   field rst_pending0 out 1 unsigned
//   field rst_pending1 out 1 unsigned
//   field corr0 out 40 signed
//   field corr1 out 40 signed
//   field tick out 1 unsigned
//   field waiting out 1 unsigned
//   field reached out 1 unsigned
//   field cfg_err out 1 unsigned
`timescale 1ns / 1ps
`default_nettype none

module tb_encoder_counter;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 548;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_encoder_counter";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  [1:0] i_qstep0;
    reg  [1:0] i_qstep1;
    reg  i_trig;
    reg  [31:0] i_pos0;
    reg  [31:0] i_pos1;
    reg  [1:0] i_src0;
    reg  [1:0] i_src1;
    reg  [31:0] i_sim_inc0;
    reg  [31:0] i_sim_inc1;
    reg  i_sim_down0;
    reg  i_sim_down1;
    reg  [31:0] i_scale0;
    reg  [31:0] i_scale1;
    reg  i_rst_req0;
    reg  i_rst_req1;
    reg  i_load0;
    reg  i_load1;
    reg  [31:0] i_load_val0;
    reg  [31:0] i_load_val1;
    reg  i_rst_on_trig;
    reg  [15:0] i_corr_period;
    reg  i_wait_arm;
    reg  i_wait_ch;
    reg  [31:0] i_wait_val;
    reg  i_wait_down;
    wire [31:0] o_cnt0;
    wire [31:0] o_cnt1;
    wire [1:0] o_step0;
    wire [1:0] o_step1;
    wire o_rst_done0;
    wire o_rst_done1;
    wire o_rst_pending0;
    wire o_rst_pending1;
    wire [39:0] o_corr0;
    wire [39:0] o_corr1;
    wire o_tick;
    wire o_waiting;
    wire o_reached;
    wire o_cfg_err;

    encoder_counter dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_qstep0(i_qstep0),
        .i_qstep1(i_qstep1),
        .i_trig(i_trig),
        .i_pos0(i_pos0),
        .i_pos1(i_pos1),
        .i_src0(i_src0),
        .i_src1(i_src1),
        .i_sim_inc0(i_sim_inc0),
        .i_sim_inc1(i_sim_inc1),
        .i_sim_down0(i_sim_down0),
        .i_sim_down1(i_sim_down1),
        .i_scale0(i_scale0),
        .i_scale1(i_scale1),
        .i_rst_req0(i_rst_req0),
        .i_rst_req1(i_rst_req1),
        .i_load0(i_load0),
        .i_load1(i_load1),
        .i_load_val0(i_load_val0),
        .i_load_val1(i_load_val1),
        .i_rst_on_trig(i_rst_on_trig),
        .i_corr_period(i_corr_period),
        .i_wait_arm(i_wait_arm),
        .i_wait_ch(i_wait_ch),
        .i_wait_val(i_wait_val),
        .i_wait_down(i_wait_down),
        .o_cnt0(o_cnt0),
        .o_cnt1(o_cnt1),
        .o_step0(o_step0),
        .o_step1(o_step1),
        .o_rst_done0(o_rst_done0),
        .o_rst_done1(o_rst_done1),
        .o_rst_pending0(o_rst_pending0),
        .o_rst_pending1(o_rst_pending1),
        .o_corr0(o_corr0),
        .o_corr1(o_corr1),
        .o_tick(o_tick),
        .o_waiting(o_waiting),
        .o_reached(o_reached),
        .o_cfg_err(o_cfg_err)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_qstep0 = row[545:544];
            i_qstep1 = row[541:540];
            i_trig = row[536:536];
            i_pos0 = row[535:504];
            i_pos1 = row[503:472];
            i_src0 = row[469:468];
            i_src1 = row[465:464];
            i_sim_inc0 = row[463:432];
            i_sim_inc1 = row[431:400];
            i_sim_down0 = row[396:396];
            i_sim_down1 = row[392:392];
            i_scale0 = row[391:360];
            i_scale1 = row[359:328];
            i_rst_req0 = row[324:324];
            i_rst_req1 = row[320:320];
            i_load0 = row[316:316];
            i_load1 = row[312:312];
            i_load_val0 = row[311:280];
            i_load_val1 = row[279:248];
            i_rst_on_trig = row[244:244];
            i_corr_period = row[243:228];
            i_wait_arm = row[224:224];
            i_wait_ch = row[220:220];
            i_wait_val = row[219:188];
            i_wait_down = row[184:184];
        end
    endtask

    task idle_inputs;
        begin
            i_qstep0 = 2'd0;
            i_qstep1 = 2'd0;
            i_trig = 1'd0;
            i_pos0 = 32'd0;
            i_pos1 = 32'd0;
            i_src0 = 2'd0;
            i_src1 = 2'd0;
            i_sim_inc0 = 32'd0;
            i_sim_inc1 = 32'd0;
            i_sim_down0 = 1'd0;
            i_sim_down1 = 1'd0;
            i_scale0 = 32'd0;
            i_scale1 = 32'd0;
            i_rst_req0 = 1'd0;
            i_rst_req1 = 1'd0;
            i_load0 = 1'd0;
            i_load1 = 1'd0;
            i_load_val0 = 32'd0;
            i_load_val1 = 32'd0;
            i_rst_on_trig = 1'd0;
            i_corr_period = 16'd1000;
            i_wait_arm = 1'd0;
            i_wait_ch = 1'd0;
            i_wait_val = 32'd0;
            i_wait_down = 1'd0;
        end
    endtask

    task ones_inputs;
        begin
            i_qstep0 = {2{1'b1}};
            i_qstep1 = {2{1'b1}};
            i_trig = {1{1'b1}};
            i_pos0 = {32{1'b1}};
            i_pos1 = {32{1'b1}};
            i_src0 = {2{1'b1}};
            i_src1 = {2{1'b1}};
            i_sim_inc0 = {32{1'b1}};
            i_sim_inc1 = {32{1'b1}};
            i_sim_down0 = {1{1'b1}};
            i_sim_down1 = {1{1'b1}};
            i_scale0 = {32{1'b1}};
            i_scale1 = {32{1'b1}};
            i_rst_req0 = {1{1'b1}};
            i_rst_req1 = {1{1'b1}};
            i_load0 = {1{1'b1}};
            i_load1 = {1{1'b1}};
            i_load_val0 = {32{1'b1}};
            i_load_val1 = {32{1'b1}};
            i_rst_on_trig = {1{1'b1}};
            i_corr_period = {16{1'b1}};
            i_wait_arm = {1{1'b1}};
            i_wait_ch = {1{1'b1}};
            i_wait_val = {32{1'b1}};
            i_wait_down = {1{1'b1}};
        end
    endtask

    task check_outputs;
        begin
            check("cnt0", row[183:152], o_cnt0, 32, 1);
            check("cnt1", row[151:120], o_cnt1, 32, 1);
            check("step0", row[117:116], o_step0, 2, 1);
            check("step1", row[113:112], o_step1, 2, 1);
            check("rst_done0", row[108:108], o_rst_done0, 1, 0);
            check("rst_done1", row[104:104], o_rst_done1, 1, 0);
            check("rst_pending0", row[100:100], o_rst_pending0, 1, 0);
            check("rst_pending1", row[96:96], o_rst_pending1, 1, 0);
            check("corr0", row[95:56], o_corr0, 40, 1);
            check("corr1", row[55:16], o_corr1, 40, 1);
            check("tick", row[12:12], o_tick, 1, 0);
            check("waiting", row[8:8], o_waiting, 1, 0);
            check("reached", row[4:4], o_reached, 1, 0);
            check("cfg_err", row[0:0], o_cfg_err, 1, 0);
        end
    endtask

endmodule

`default_nettype wire
