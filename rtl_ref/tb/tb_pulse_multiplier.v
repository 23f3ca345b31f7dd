// tb_pulse_multiplier.v — vector testbench of rtl_ref/pulse_multiplier.v.
//
// DUT: pulse_multiplier.
// Reads pulse_multiplier.hex written by `laserax vectors` (docs/VECTORS.md) and, for every row, applies
// the row's inputs before a rising clock edge and compares every output column with the DUT
// outputs after that edge. Row k is call k after reset: the DUT is held in reset for a few
// edges, row 0 is applied together with the release of i_rst.
// Mismatches print `cycle N signal S: expected E got G` (the first 10); the last line is
// `PASS ...` or `FAIL ...` (scripts/rtl_sim.sh checks it).
//
// Plusargs: +vectors=PATH (required)  +rows=N (default: all N_MAX rows)  +vcd=PATH (optional dump)
// Parameters (iverilog -P): N_MAX = number of rows in the file.
//
// vector fields (must equal the `// field` lines of the .hex file; scripts/rtl_sim.sh checks):
//   field step in 2 signed
//   field ratio in 37 unsigned
//   field comp out 38 signed
//   field delta out 39 signed
`timescale 1ns / 1ps
`default_nettype none

module tb_pulse_multiplier;
    parameter integer N_MAX = 40000;   // rows in the vector file
    localparam integer ROW_BITS = 124;   // 4 * sum(ceil(bits/4)) over the fields
    localparam TB_NAME = "tb_pulse_multiplier";

    reg [ROW_BITS-1:0] vec [0:N_MAX-1];
    reg [ROW_BITS-1:0] row;

    // DUT ports
    reg i_clk, i_rst;
    reg  [1:0] i_step;
    reg  [36:0] i_ratio;
    wire [37:0] o_comp;
    wire [38:0] o_delta;

    pulse_multiplier dut (
        .i_clk(i_clk),
        .i_rst(i_rst),
        .i_step(i_step),
        .i_ratio(i_ratio),
        .o_comp(o_comp),
        .o_delta(o_delta)
    );

    `include "tb_common.vh"

    task apply_inputs;
        begin
            i_step = row[121:120];
            i_ratio = row[116:80];
        end
    endtask

    task idle_inputs;
        begin
            i_step = 2'd0;
            i_ratio = 37'd0;
        end
    endtask

    task check_outputs;
        begin
            check("comp", row[77:40], o_comp, 38, 1);
            check("delta", row[38:0], o_delta, 39, 1);
        end
    endtask

endmodule

`default_nettype wire
