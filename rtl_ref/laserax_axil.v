// laserax_axil.v — the IP top: the register map on an AXI4-Lite slave (laserax_regs, generated
// from regmap/laserax_regs.csv) driving the register inputs of the chain (laserax_top).
//
// Every o_<name> of laserax_regs goes to i_<name> of laserax_top; pins and every laserax_top
// output pass through unchanged. Timing (docs/REGISTERS.md, "RTL slave"): a bus write whose
// handshake completes at rising edge t updates the register at edge t; laserax_top samples it
// from edge t+1 on, i.e. the write acts in call t+1 of hls/laserax_top.h (one register stage,
// what CTest rtl_laserax_axil checks against hls/laserax_top.h every cycle). The pulse and table-port
// registers (rehome, clear, comp_commit, tbl_we, map_we) hold what the host wrote: the core
// acts in every clock they are 1, as in the C++ model.
//
// i_rst (synchronous, active high) resets both: registers at their CSV reset values and the
// chain in its power-up state. The table RAM is not reset (INIT_FILE is its power-up image).
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module laserax_axil #(
    // INIT_FILE: $readmemh image of the DDS table RAM (laserax_top); must not be empty
    parameter INIT_FILE = "dds_table_p256.hex",
    // ADDR_W: byte address width of the slave (laserax_regs: 9..32)
    parameter integer ADDR_W = 12,
    // DEBUG_TAPS: laserax_top's debug taps driven (1) or tied to 0 (0, default)
    parameter integer DEBUG_TAPS = 0
) (
    input  wire                              i_clk,
    input  wire                              i_rst,            // synchronous, active high
    // pins (asynchronous)
    input  wire                              i_a,
    input  wire                              i_b,
    input  wire                              i_sw,
    input  wire                              i_lerr,
    // AXI4-Lite slave (register map, docs/REGISTERS.md)
    input  wire [ADDR_W-1:0]                 s_axil_awaddr,
    input  wire                              s_axil_awvalid,
    output wire                              s_axil_awready,
    input  wire [31:0]                       s_axil_wdata,
    input  wire [3:0]                        s_axil_wstrb,
    input  wire                              s_axil_wvalid,
    output wire                              s_axil_wready,
    output wire [1:0]                        s_axil_bresp,
    output wire                              s_axil_bvalid,
    input  wire                              s_axil_bready,
    input  wire [ADDR_W-1:0]                 s_axil_araddr,
    input  wire                              s_axil_arvalid,
    output wire                              s_axil_arready,
    output wire [31:0]                       s_axil_rdata,
    output wire [1:0]                        s_axil_rresp,
    output wire                              s_axil_rvalid,
    input  wire                              s_axil_rready,
    // outputs of laserax_top
    output wire signed [`LX_W_DAC-1:0]       o_sin,
    output wire signed [`LX_W_DAC-1:0]       o_cos,
    output wire                              o_ref_mark,
    output wire                              o_qa,
    output wire                              o_qb,
    output wire                              o_qz,
    output wire                              o_q_oe,       // A/B/Z line driver enable (pin_cfg hiz_alarm)
    output wire                              o_cfg_err,
    output wire [`LX_W_STAGE-1:0]            o_stage,
    output wire                              o_homed,
    output wire                              o_lerr_alarm,
    output wire                              o_illegal_st,
    output wire [`LX_QD_W_ERRCNT-1:0]        o_err_cnt,
    output wire                              o_ovs_edge_st,
    output wire                              o_ovs_backlog_st,
    output wire                              o_glitch_st,
    output wire                              o_alarm,
    output wire                              o_dac_clip_st,
    output wire signed [`LX_W_RAW-1:0]       o_raw_count,
    output wire signed [`LX_W_STEP-1:0]      o_step,
    output wire signed [`LX_W_POS-1:0]       o_comp_pos,
    output wire signed [`LX_W_DELTA-1:0]     o_delta,
    output wire signed [`LX_W_BACKLOG-1:0]   o_backlog,
    output wire signed [`LX_W_STEP-1:0]      o_pstep,
    output wire signed [`LX_W_POS-1:0]       o_paced_pos,
    output wire signed [`LX_W_STEP-1:0]      o_ostep,
    output wire signed [`LX_W_POS-1:0]       o_out_pos,
    output wire signed [`LX_W_POS-1:0]       o_adj,
    output wire signed [`LX_W_POS-1:0]       o_a_pos,
    output wire signed [`LX_W_POS-1:0]       o_b_pos,
    output wire signed [`LX_W_POS-1:0]       o_c_pos,
    output wire signed [`LX_W_POS-1:0]       o_z_pos,
    output wire [`LX_W_PH-1:0]               o_d,
    output wire                              o_rep_mark,
    output wire                              o_map_cfg_err,
    output wire signed [`LX_EM_W_C-1:0]      o_corr,
    output wire signed [`LX_EM_W_CDELTA-1:0] o_map_delta
);

    // ---- register map: one wire per register (widths of regmap/laserax_regs.csv) ---------------
    wire [12:0]        r_period, r_tbl_period, r_mark_len;
    wire [36:0]        r_ratio;
    wire signed [63:0] r_comp_offset;
    wire [7:0]         r_glitch_n;
    wire [15:0]        r_sw_debounce, r_min_spacing, r_pace_m;
    wire [31:0]        r_backlog_thr;
    wire [4:0]         r_dac_width, r_map_k0, r_map_k1;
    wire [17:0]        r_amplitude;
    wire               r_rehome, r_clear, r_tbl_we, r_map_en, r_bank_sel, r_map_we;
    wire               r_comp_sync, r_comp_commit;
    wire [9:0]         r_tbl_addr;
    wire [16:0]        r_tbl_data;
    wire signed [37:0] r_map_origin0, r_map_origin1;
    wire [10:0]        r_map_n0, r_map_n1;
    wire [9:0]         r_map_addr;
    wire signed [23:0] r_map_data;
    wire [3:0]         r_pin_cfg;

    laserax_regs #(.ADDR_W(ADDR_W)) u_regs (
        .i_clk(i_clk), .i_rst(i_rst),
        .s_axil_awaddr(s_axil_awaddr), .s_axil_awvalid(s_axil_awvalid), .s_axil_awready(s_axil_awready),
        .s_axil_wdata(s_axil_wdata), .s_axil_wstrb(s_axil_wstrb), .s_axil_wvalid(s_axil_wvalid),
        .s_axil_wready(s_axil_wready), .s_axil_bresp(s_axil_bresp), .s_axil_bvalid(s_axil_bvalid),
        .s_axil_bready(s_axil_bready), .s_axil_araddr(s_axil_araddr), .s_axil_arvalid(s_axil_arvalid),
        .s_axil_arready(s_axil_arready), .s_axil_rdata(s_axil_rdata), .s_axil_rresp(s_axil_rresp),
        .s_axil_rvalid(s_axil_rvalid), .s_axil_rready(s_axil_rready),
        .o_period(r_period), .o_tbl_period(r_tbl_period), .o_ratio(r_ratio), .o_comp_offset(r_comp_offset),
        .o_glitch_n(r_glitch_n), .o_sw_debounce(r_sw_debounce), .o_min_spacing(r_min_spacing),
        .o_pace_m(r_pace_m), .o_backlog_thr(r_backlog_thr), .o_mark_len(r_mark_len),
        .o_dac_width(r_dac_width), .o_amplitude(r_amplitude), .o_rehome(r_rehome), .o_clear(r_clear),
        .o_tbl_we(r_tbl_we), .o_tbl_addr(r_tbl_addr), .o_tbl_data(r_tbl_data), .o_map_en(r_map_en),
        .o_bank_sel(r_bank_sel), .o_map_origin0(r_map_origin0), .o_map_k0(r_map_k0), .o_map_n0(r_map_n0),
        .o_map_origin1(r_map_origin1), .o_map_k1(r_map_k1), .o_map_n1(r_map_n1), .o_map_we(r_map_we),
        .o_map_addr(r_map_addr), .o_map_data(r_map_data), .o_comp_sync(r_comp_sync),
        .o_comp_commit(r_comp_commit), .o_pin_cfg(r_pin_cfg));

    laserax_top #(.INIT_FILE(INIT_FILE), .DEBUG_TAPS(DEBUG_TAPS)) u_top (
        .i_clk(i_clk), .i_rst(i_rst), .i_a(i_a), .i_b(i_b), .i_sw(i_sw), .i_lerr(i_lerr),
        .i_period(r_period), .i_ratio(r_ratio), .i_comp_offset(r_comp_offset), .i_comp_sync(r_comp_sync),
        .i_comp_commit(r_comp_commit), .i_glitch_n(r_glitch_n), .i_sw_debounce(r_sw_debounce),
        .i_min_spacing(r_min_spacing), .i_pace_m(r_pace_m), .i_backlog_thr(r_backlog_thr),
        .i_mark_len(r_mark_len), .i_dac_width(r_dac_width), .i_amplitude(r_amplitude),
        .i_tbl_period(r_tbl_period), .i_rehome(r_rehome), .i_clear(r_clear), .i_tbl_we(r_tbl_we),
        .i_tbl_addr(r_tbl_addr), .i_tbl_data(r_tbl_data), .i_map_en(r_map_en), .i_bank_sel(r_bank_sel),
        .i_map_origin0(r_map_origin0), .i_map_k0(r_map_k0), .i_map_n0(r_map_n0),
        .i_map_origin1(r_map_origin1), .i_map_k1(r_map_k1), .i_map_n1(r_map_n1), .i_map_we(r_map_we),
        .i_map_addr(r_map_addr), .i_map_data(r_map_data), .i_pin_cfg(r_pin_cfg),
        .o_sin(o_sin), .o_cos(o_cos), .o_ref_mark(o_ref_mark), .o_qa(o_qa), .o_qb(o_qb), .o_qz(o_qz), .o_q_oe(o_q_oe),
        .o_cfg_err(o_cfg_err), .o_stage(o_stage), .o_homed(o_homed), .o_lerr_alarm(o_lerr_alarm),
        .o_illegal_st(o_illegal_st), .o_err_cnt(o_err_cnt), .o_ovs_edge_st(o_ovs_edge_st),
        .o_ovs_backlog_st(o_ovs_backlog_st), .o_glitch_st(o_glitch_st), .o_alarm(o_alarm), .o_dac_clip_st(o_dac_clip_st),
        .o_raw_count(o_raw_count), .o_step(o_step), .o_comp_pos(o_comp_pos), .o_delta(o_delta),
        .o_backlog(o_backlog), .o_pstep(o_pstep), .o_paced_pos(o_paced_pos), .o_ostep(o_ostep),
        .o_out_pos(o_out_pos), .o_adj(o_adj), .o_a_pos(o_a_pos), .o_b_pos(o_b_pos), .o_c_pos(o_c_pos),
        .o_z_pos(o_z_pos), .o_d(o_d), .o_rep_mark(o_rep_mark), .o_map_cfg_err(o_map_cfg_err),
        .o_corr(o_corr), .o_map_delta(o_map_delta));

endmodule

`default_nettype wire
