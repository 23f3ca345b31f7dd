// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
// laserax_regs.v — the laserax register map (docs/REGISTERS.md) as an AXI4-Lite slave: every
// register of regmap/laserax_regs.csv at its byte offset, with its width and reset value, drives
// one output port o_<name> (the i_<name> input of laserax_top; rtl_ref/laserax_axil.v wires the two).
//
// Bus: AXI4-Lite, 32-bit data, ADDR_W-bit byte addresses (AWPROT/ARPROT are not used).
//   write   AW and W are accepted independently, in the same cycle or in different ones (AWREADY =
//           no address held and no response pending, WREADY likewise). The write takes effect at
//           the rising edge at which the later of the two handshakes completes; BVALID rises at
//           that same edge (BRESP = OKAY) and AWREADY/WREADY stay 0 until the B handshake (one
//           write outstanding). o_<name> has the new value after that edge, so laserax_top uses
//           it from the following edge on (a write completing at edge t acts in call t+1).
//   strobe  WSTRB[i] writes byte i of the word; bits above a register's width are dropped; a
//           register wider than 32 bits takes consecutive words, low word first.
//   read    ARREADY = !RVALID. At the edge of the AR handshake RDATA is registered from the
//           registers before that edge (a write completing at the same edge is not seen) and
//           RVALID rises; it stays until the R handshake (RRESP = OKAY). A register word reads
//           its bits with 0 above the register's width, signed registers too (as the Vitis HLS
//           slave: sign-extend from the width in software).
//   other   0x00..0x0F, the reserved word after each register and every address from 0x130 on
//           read 0 and ignore writes, with an OKAY response (no SLVERR). Address bits [1:0] are
//           ignored. Pulse and table-port registers hold what the host wrote (the core acts on
//           the level; nothing clears them).
// i_rst (synchronous, active high): every register at its reset value, no transaction held.
`timescale 1ns / 1ps
`default_nettype none

module laserax_regs #(
    // ADDR_W: byte address width, 9..32 (the map ends at 0x130); addresses past the map read 0
    parameter integer ADDR_W = 12
) (
    input  wire              i_clk,
    input  wire              i_rst,            // synchronous, active high: reset values
    // AXI4-Lite slave
    input  wire [ADDR_W-1:0] s_axil_awaddr,
    input  wire              s_axil_awvalid,
    output wire              s_axil_awready,
    input  wire [31:0]       s_axil_wdata,
    input  wire [3:0]        s_axil_wstrb,
    input  wire              s_axil_wvalid,
    output wire              s_axil_wready,
    output wire [1:0]        s_axil_bresp,
    output wire              s_axil_bvalid,
    input  wire              s_axil_bready,
    input  wire [ADDR_W-1:0] s_axil_araddr,
    input  wire              s_axil_arvalid,
    output wire              s_axil_arready,
    output wire [31:0]       s_axil_rdata,
    output wire [1:0]        s_axil_rresp,
    output wire              s_axil_rvalid,
    input  wire              s_axil_rready,
    // registers, offset order
    output wire [12:0]        o_period,          // 0x10 rw, reset 256
    output wire [12:0]        o_tbl_period,      // 0x18 rw, reset 256
    output wire [36:0]        o_ratio,           // 0x20 rw, reset 34789620252
    output wire signed [63:0] o_comp_offset,     // 0x30 rw, reset 0
    output wire [7:0]         o_glitch_n,        // 0x40 rw, reset 2
    output wire [15:0]        o_sw_debounce,     // 0x48 rw, reset 16
    output wire [15:0]        o_min_spacing,     // 0x50 rw, reset 8
    output wire [15:0]        o_pace_m,          // 0x58 rw, reset 61
    output wire [31:0]        o_backlog_thr,     // 0x60 rw, reset 4096
    output wire [12:0]        o_mark_len,        // 0x68 rw, reset 64
    output wire [4:0]         o_dac_width,       // 0x70 rw, reset 16
    output wire [17:0]        o_amplitude,       // 0x78 rw, reset 32767
    output wire               o_rehome,          // 0x80 pulse, reset 0
    output wire               o_clear,           // 0x88 pulse, reset 0
    output wire               o_tbl_we,          // 0x90 port, reset 0
    output wire [9:0]         o_tbl_addr,        // 0x98 port, reset 0
    output wire [16:0]        o_tbl_data,        // 0xA0 port, reset 0
    output wire               o_map_en,          // 0xA8 rw, reset 0
    output wire               o_bank_sel,        // 0xB0 rw, reset 0
    output wire signed [37:0] o_map_origin0,     // 0xC0 rw, reset 0
    output wire [4:0]         o_map_k0,          // 0xD0 rw, reset 10
    output wire [10:0]        o_map_n0,          // 0xD8 rw, reset 1024
    output wire signed [37:0] o_map_origin1,     // 0xE0 rw, reset 0
    output wire [4:0]         o_map_k1,          // 0xF0 rw, reset 10
    output wire [10:0]        o_map_n1,          // 0xF8 rw, reset 1024
    output wire               o_map_we,          // 0x100 port, reset 0
    output wire [9:0]         o_map_addr,        // 0x108 port, reset 0
    output wire signed [23:0] o_map_data,        // 0x110 port, reset 0
    output wire               o_comp_sync,       // 0x118 rw, reset 0
    output wire               o_comp_commit,     // 0x120 pulse, reset 0
    output wire [3:0]         o_pin_cfg          // 0x128 rw, reset 8
);

    localparam integer MAP_ADDR_W = 9;       // byte address bits of the map (0x00 .. 0x12F)
    localparam integer WA_W       = ADDR_W - 2;  // word address bits
    localparam [1:0]   RESP_OKAY  = 2'b00;

    generate
        if (ADDR_W < MAP_ADDR_W || ADDR_W > 32) begin : g_bad_addr_w
            laserax_regs_PARAMETER_ADDR_W_must_be_9_to_32 u_param_error ();
        end
    endgenerate

    // ---- word addresses (byte offset / 4) of the register words --------------------------------
    localparam [WA_W-1:0] A_PERIOD         = 4;   // 0x10: period
    localparam [WA_W-1:0] A_TBL_PERIOD     = 6;   // 0x18: tbl_period
    localparam [WA_W-1:0] A_RATIO_0        = 8;   // 0x20: ratio bits 31..0
    localparam [WA_W-1:0] A_RATIO_1        = 9;   // 0x24: ratio bits 36..32
    localparam [WA_W-1:0] A_COMP_OFFSET_0  = 12;  // 0x30: comp_offset bits 31..0
    localparam [WA_W-1:0] A_COMP_OFFSET_1  = 13;  // 0x34: comp_offset bits 63..32
    localparam [WA_W-1:0] A_GLITCH_N       = 16;  // 0x40: glitch_n
    localparam [WA_W-1:0] A_SW_DEBOUNCE    = 18;  // 0x48: sw_debounce
    localparam [WA_W-1:0] A_MIN_SPACING    = 20;  // 0x50: min_spacing
    localparam [WA_W-1:0] A_PACE_M         = 22;  // 0x58: pace_m
    localparam [WA_W-1:0] A_BACKLOG_THR    = 24;  // 0x60: backlog_thr
    localparam [WA_W-1:0] A_MARK_LEN       = 26;  // 0x68: mark_len
    localparam [WA_W-1:0] A_DAC_WIDTH      = 28;  // 0x70: dac_width
    localparam [WA_W-1:0] A_AMPLITUDE      = 30;  // 0x78: amplitude
    localparam [WA_W-1:0] A_REHOME         = 32;  // 0x80: rehome
    localparam [WA_W-1:0] A_CLEAR          = 34;  // 0x88: clear
    localparam [WA_W-1:0] A_TBL_WE         = 36;  // 0x90: tbl_we
    localparam [WA_W-1:0] A_TBL_ADDR       = 38;  // 0x98: tbl_addr
    localparam [WA_W-1:0] A_TBL_DATA       = 40;  // 0xA0: tbl_data
    localparam [WA_W-1:0] A_MAP_EN         = 42;  // 0xA8: map_en
    localparam [WA_W-1:0] A_BANK_SEL       = 44;  // 0xB0: bank_sel
    localparam [WA_W-1:0] A_MAP_ORIGIN0_0  = 48;  // 0xC0: map_origin0 bits 31..0
    localparam [WA_W-1:0] A_MAP_ORIGIN0_1  = 49;  // 0xC4: map_origin0 bits 37..32
    localparam [WA_W-1:0] A_MAP_K0         = 52;  // 0xD0: map_k0
    localparam [WA_W-1:0] A_MAP_N0         = 54;  // 0xD8: map_n0
    localparam [WA_W-1:0] A_MAP_ORIGIN1_0  = 56;  // 0xE0: map_origin1 bits 31..0
    localparam [WA_W-1:0] A_MAP_ORIGIN1_1  = 57;  // 0xE4: map_origin1 bits 37..32
    localparam [WA_W-1:0] A_MAP_K1         = 60;  // 0xF0: map_k1
    localparam [WA_W-1:0] A_MAP_N1         = 62;  // 0xF8: map_n1
    localparam [WA_W-1:0] A_MAP_WE         = 64;  // 0x100: map_we
    localparam [WA_W-1:0] A_MAP_ADDR       = 66;  // 0x108: map_addr
    localparam [WA_W-1:0] A_MAP_DATA       = 68;  // 0x110: map_data
    localparam [WA_W-1:0] A_COMP_SYNC      = 70;  // 0x118: comp_sync
    localparam [WA_W-1:0] A_COMP_COMMIT    = 72;  // 0x120: comp_commit
    localparam [WA_W-1:0] A_PIN_CFG        = 74;  // 0x128: pin_cfg

    // ---- write channel: address and data held until both are there -----------------------------
    reg              aw_full_q;                  // address accepted, data not yet
    reg [WA_W-1:0]   aw_word_q;
    reg              w_full_q;                   // data accepted, address not yet
    reg [31:0]       w_data_q;
    reg [3:0]        w_strb_q;
    reg              bvalid_q;
    wire             aw_hs     = s_axil_awvalid && s_axil_awready;
    wire             w_hs      = s_axil_wvalid && s_axil_wready;
    wire             wr_fire   = (aw_full_q || aw_hs) && (w_full_q || w_hs);   // the write edge
    wire [WA_W-1:0]  wr_word   = aw_full_q ? aw_word_q : s_axil_awaddr[ADDR_W-1:2];
    wire [31:0]      wr_data   = w_full_q ? w_data_q : s_axil_wdata;
    wire [3:0]       wr_strb   = w_full_q ? w_strb_q : s_axil_wstrb;
    wire             aw_full_d = (aw_full_q || aw_hs) && !wr_fire;
    wire             w_full_d  = (w_full_q || w_hs) && !wr_fire;
    wire             bvalid_d  = wr_fire || (bvalid_q && !s_axil_bready);

    assign s_axil_awready = !aw_full_q && !bvalid_q;
    assign s_axil_wready  = !w_full_q && !bvalid_q;
    assign s_axil_bvalid  = bvalid_q;
    assign s_axil_bresp   = RESP_OKAY;

    // ---- read channel ----------------------------------------------------------------------------
    reg              rvalid_q;
    reg [31:0]       rdata_q;
    wire             ar_hs    = s_axil_arvalid && s_axil_arready;
    wire [WA_W-1:0]  rd_addr  = s_axil_araddr[ADDR_W-1:2];
    wire             rvalid_d = ar_hs || (rvalid_q && !s_axil_rready);

    assign s_axil_arready = !rvalid_q;
    assign s_axil_rvalid  = rvalid_q;
    assign s_axil_rdata   = rdata_q;
    assign s_axil_rresp   = RESP_OKAY;

    // ---- registers -------------------------------------------------------------------------------
    reg         [12:0]  reg_period_q;
    reg         [12:0]  reg_tbl_period_q;
    reg         [36:0]  reg_ratio_q;
    reg  signed [63:0]  reg_comp_offset_q;
    reg         [7:0]   reg_glitch_n_q;
    reg         [15:0]  reg_sw_debounce_q;
    reg         [15:0]  reg_min_spacing_q;
    reg         [15:0]  reg_pace_m_q;
    reg         [31:0]  reg_backlog_thr_q;
    reg         [12:0]  reg_mark_len_q;
    reg         [4:0]   reg_dac_width_q;
    reg         [17:0]  reg_amplitude_q;
    reg                 reg_rehome_q;
    reg                 reg_clear_q;
    reg                 reg_tbl_we_q;
    reg         [9:0]   reg_tbl_addr_q;
    reg         [16:0]  reg_tbl_data_q;
    reg                 reg_map_en_q;
    reg                 reg_bank_sel_q;
    reg  signed [37:0]  reg_map_origin0_q;
    reg         [4:0]   reg_map_k0_q;
    reg         [10:0]  reg_map_n0_q;
    reg  signed [37:0]  reg_map_origin1_q;
    reg         [4:0]   reg_map_k1_q;
    reg         [10:0]  reg_map_n1_q;
    reg                 reg_map_we_q;
    reg         [9:0]   reg_map_addr_q;
    reg  signed [23:0]  reg_map_data_q;
    reg                 reg_comp_sync_q;
    reg                 reg_comp_commit_q;
    reg         [3:0]   reg_pin_cfg_q;

    // next state: the bytes of the addressed word that WSTRB selects, at the write edge; a write
    // to a reserved or unmapped word enables nothing
    wire wen_period = wr_fire && wr_word == A_PERIOD;
    wire [12:0] reg_period_d = {
        (wen_period && wr_strb[1]) ? wr_data[12:8] : reg_period_q[12:8],
        (wen_period && wr_strb[0]) ? wr_data[7:0] : reg_period_q[7:0]};
    wire wen_tbl_period = wr_fire && wr_word == A_TBL_PERIOD;
    wire [12:0] reg_tbl_period_d = {
        (wen_tbl_period && wr_strb[1]) ? wr_data[12:8] : reg_tbl_period_q[12:8],
        (wen_tbl_period && wr_strb[0]) ? wr_data[7:0] : reg_tbl_period_q[7:0]};
    wire wen_ratio_0 = wr_fire && wr_word == A_RATIO_0;
    wire wen_ratio_1 = wr_fire && wr_word == A_RATIO_1;
    wire [36:0] reg_ratio_d = {
        (wen_ratio_1 && wr_strb[0]) ? wr_data[4:0] : reg_ratio_q[36:32],
        (wen_ratio_0 && wr_strb[3]) ? wr_data[31:24] : reg_ratio_q[31:24],
        (wen_ratio_0 && wr_strb[2]) ? wr_data[23:16] : reg_ratio_q[23:16],
        (wen_ratio_0 && wr_strb[1]) ? wr_data[15:8] : reg_ratio_q[15:8],
        (wen_ratio_0 && wr_strb[0]) ? wr_data[7:0] : reg_ratio_q[7:0]};
    wire wen_comp_offset_0 = wr_fire && wr_word == A_COMP_OFFSET_0;
    wire wen_comp_offset_1 = wr_fire && wr_word == A_COMP_OFFSET_1;
    wire signed [63:0] reg_comp_offset_d = {
        (wen_comp_offset_1 && wr_strb[3]) ? wr_data[31:24] : reg_comp_offset_q[63:56],
        (wen_comp_offset_1 && wr_strb[2]) ? wr_data[23:16] : reg_comp_offset_q[55:48],
        (wen_comp_offset_1 && wr_strb[1]) ? wr_data[15:8] : reg_comp_offset_q[47:40],
        (wen_comp_offset_1 && wr_strb[0]) ? wr_data[7:0] : reg_comp_offset_q[39:32],
        (wen_comp_offset_0 && wr_strb[3]) ? wr_data[31:24] : reg_comp_offset_q[31:24],
        (wen_comp_offset_0 && wr_strb[2]) ? wr_data[23:16] : reg_comp_offset_q[23:16],
        (wen_comp_offset_0 && wr_strb[1]) ? wr_data[15:8] : reg_comp_offset_q[15:8],
        (wen_comp_offset_0 && wr_strb[0]) ? wr_data[7:0] : reg_comp_offset_q[7:0]};
    wire wen_glitch_n = wr_fire && wr_word == A_GLITCH_N;
    wire [7:0] reg_glitch_n_d = (wen_glitch_n && wr_strb[0]) ? wr_data[7:0] : reg_glitch_n_q[7:0];
    wire wen_sw_debounce = wr_fire && wr_word == A_SW_DEBOUNCE;
    wire [15:0] reg_sw_debounce_d = {
        (wen_sw_debounce && wr_strb[1]) ? wr_data[15:8] : reg_sw_debounce_q[15:8],
        (wen_sw_debounce && wr_strb[0]) ? wr_data[7:0] : reg_sw_debounce_q[7:0]};
    wire wen_min_spacing = wr_fire && wr_word == A_MIN_SPACING;
    wire [15:0] reg_min_spacing_d = {
        (wen_min_spacing && wr_strb[1]) ? wr_data[15:8] : reg_min_spacing_q[15:8],
        (wen_min_spacing && wr_strb[0]) ? wr_data[7:0] : reg_min_spacing_q[7:0]};
    wire wen_pace_m = wr_fire && wr_word == A_PACE_M;
    wire [15:0] reg_pace_m_d = {
        (wen_pace_m && wr_strb[1]) ? wr_data[15:8] : reg_pace_m_q[15:8],
        (wen_pace_m && wr_strb[0]) ? wr_data[7:0] : reg_pace_m_q[7:0]};
    wire wen_backlog_thr = wr_fire && wr_word == A_BACKLOG_THR;
    wire [31:0] reg_backlog_thr_d = {
        (wen_backlog_thr && wr_strb[3]) ? wr_data[31:24] : reg_backlog_thr_q[31:24],
        (wen_backlog_thr && wr_strb[2]) ? wr_data[23:16] : reg_backlog_thr_q[23:16],
        (wen_backlog_thr && wr_strb[1]) ? wr_data[15:8] : reg_backlog_thr_q[15:8],
        (wen_backlog_thr && wr_strb[0]) ? wr_data[7:0] : reg_backlog_thr_q[7:0]};
    wire wen_mark_len = wr_fire && wr_word == A_MARK_LEN;
    wire [12:0] reg_mark_len_d = {
        (wen_mark_len && wr_strb[1]) ? wr_data[12:8] : reg_mark_len_q[12:8],
        (wen_mark_len && wr_strb[0]) ? wr_data[7:0] : reg_mark_len_q[7:0]};
    wire wen_dac_width = wr_fire && wr_word == A_DAC_WIDTH;
    wire [4:0] reg_dac_width_d = (wen_dac_width && wr_strb[0]) ? wr_data[4:0] : reg_dac_width_q[4:0];
    wire wen_amplitude = wr_fire && wr_word == A_AMPLITUDE;
    wire [17:0] reg_amplitude_d = {
        (wen_amplitude && wr_strb[2]) ? wr_data[17:16] : reg_amplitude_q[17:16],
        (wen_amplitude && wr_strb[1]) ? wr_data[15:8] : reg_amplitude_q[15:8],
        (wen_amplitude && wr_strb[0]) ? wr_data[7:0] : reg_amplitude_q[7:0]};
    wire wen_rehome = wr_fire && wr_word == A_REHOME;
    wire reg_rehome_d = (wen_rehome && wr_strb[0]) ? wr_data[0] : reg_rehome_q;
    wire wen_clear = wr_fire && wr_word == A_CLEAR;
    wire reg_clear_d = (wen_clear && wr_strb[0]) ? wr_data[0] : reg_clear_q;
    wire wen_tbl_we = wr_fire && wr_word == A_TBL_WE;
    wire reg_tbl_we_d = (wen_tbl_we && wr_strb[0]) ? wr_data[0] : reg_tbl_we_q;
    wire wen_tbl_addr = wr_fire && wr_word == A_TBL_ADDR;
    wire [9:0] reg_tbl_addr_d = {
        (wen_tbl_addr && wr_strb[1]) ? wr_data[9:8] : reg_tbl_addr_q[9:8],
        (wen_tbl_addr && wr_strb[0]) ? wr_data[7:0] : reg_tbl_addr_q[7:0]};
    wire wen_tbl_data = wr_fire && wr_word == A_TBL_DATA;
    wire [16:0] reg_tbl_data_d = {
        (wen_tbl_data && wr_strb[2]) ? wr_data[16] : reg_tbl_data_q[16],
        (wen_tbl_data && wr_strb[1]) ? wr_data[15:8] : reg_tbl_data_q[15:8],
        (wen_tbl_data && wr_strb[0]) ? wr_data[7:0] : reg_tbl_data_q[7:0]};
    wire wen_map_en = wr_fire && wr_word == A_MAP_EN;
    wire reg_map_en_d = (wen_map_en && wr_strb[0]) ? wr_data[0] : reg_map_en_q;
    wire wen_bank_sel = wr_fire && wr_word == A_BANK_SEL;
    wire reg_bank_sel_d = (wen_bank_sel && wr_strb[0]) ? wr_data[0] : reg_bank_sel_q;
    wire wen_map_origin0_0 = wr_fire && wr_word == A_MAP_ORIGIN0_0;
    wire wen_map_origin0_1 = wr_fire && wr_word == A_MAP_ORIGIN0_1;
    wire signed [37:0] reg_map_origin0_d = {
        (wen_map_origin0_1 && wr_strb[0]) ? wr_data[5:0] : reg_map_origin0_q[37:32],
        (wen_map_origin0_0 && wr_strb[3]) ? wr_data[31:24] : reg_map_origin0_q[31:24],
        (wen_map_origin0_0 && wr_strb[2]) ? wr_data[23:16] : reg_map_origin0_q[23:16],
        (wen_map_origin0_0 && wr_strb[1]) ? wr_data[15:8] : reg_map_origin0_q[15:8],
        (wen_map_origin0_0 && wr_strb[0]) ? wr_data[7:0] : reg_map_origin0_q[7:0]};
    wire wen_map_k0 = wr_fire && wr_word == A_MAP_K0;
    wire [4:0] reg_map_k0_d = (wen_map_k0 && wr_strb[0]) ? wr_data[4:0] : reg_map_k0_q[4:0];
    wire wen_map_n0 = wr_fire && wr_word == A_MAP_N0;
    wire [10:0] reg_map_n0_d = {
        (wen_map_n0 && wr_strb[1]) ? wr_data[10:8] : reg_map_n0_q[10:8],
        (wen_map_n0 && wr_strb[0]) ? wr_data[7:0] : reg_map_n0_q[7:0]};
    wire wen_map_origin1_0 = wr_fire && wr_word == A_MAP_ORIGIN1_0;
    wire wen_map_origin1_1 = wr_fire && wr_word == A_MAP_ORIGIN1_1;
    wire signed [37:0] reg_map_origin1_d = {
        (wen_map_origin1_1 && wr_strb[0]) ? wr_data[5:0] : reg_map_origin1_q[37:32],
        (wen_map_origin1_0 && wr_strb[3]) ? wr_data[31:24] : reg_map_origin1_q[31:24],
        (wen_map_origin1_0 && wr_strb[2]) ? wr_data[23:16] : reg_map_origin1_q[23:16],
        (wen_map_origin1_0 && wr_strb[1]) ? wr_data[15:8] : reg_map_origin1_q[15:8],
        (wen_map_origin1_0 && wr_strb[0]) ? wr_data[7:0] : reg_map_origin1_q[7:0]};
    wire wen_map_k1 = wr_fire && wr_word == A_MAP_K1;
    wire [4:0] reg_map_k1_d = (wen_map_k1 && wr_strb[0]) ? wr_data[4:0] : reg_map_k1_q[4:0];
    wire wen_map_n1 = wr_fire && wr_word == A_MAP_N1;
    wire [10:0] reg_map_n1_d = {
        (wen_map_n1 && wr_strb[1]) ? wr_data[10:8] : reg_map_n1_q[10:8],
        (wen_map_n1 && wr_strb[0]) ? wr_data[7:0] : reg_map_n1_q[7:0]};
    wire wen_map_we = wr_fire && wr_word == A_MAP_WE;
    wire reg_map_we_d = (wen_map_we && wr_strb[0]) ? wr_data[0] : reg_map_we_q;
    wire wen_map_addr = wr_fire && wr_word == A_MAP_ADDR;
    wire [9:0] reg_map_addr_d = {
        (wen_map_addr && wr_strb[1]) ? wr_data[9:8] : reg_map_addr_q[9:8],
        (wen_map_addr && wr_strb[0]) ? wr_data[7:0] : reg_map_addr_q[7:0]};
    wire wen_map_data = wr_fire && wr_word == A_MAP_DATA;
    wire signed [23:0] reg_map_data_d = {
        (wen_map_data && wr_strb[2]) ? wr_data[23:16] : reg_map_data_q[23:16],
        (wen_map_data && wr_strb[1]) ? wr_data[15:8] : reg_map_data_q[15:8],
        (wen_map_data && wr_strb[0]) ? wr_data[7:0] : reg_map_data_q[7:0]};
    wire wen_comp_sync = wr_fire && wr_word == A_COMP_SYNC;
    wire reg_comp_sync_d = (wen_comp_sync && wr_strb[0]) ? wr_data[0] : reg_comp_sync_q;
    wire wen_comp_commit = wr_fire && wr_word == A_COMP_COMMIT;
    wire reg_comp_commit_d = (wen_comp_commit && wr_strb[0]) ? wr_data[0] : reg_comp_commit_q;
    wire wen_pin_cfg = wr_fire && wr_word == A_PIN_CFG;
    wire [3:0] reg_pin_cfg_d = (wen_pin_cfg && wr_strb[0]) ? wr_data[3:0] : reg_pin_cfg_q[3:0];

    // read data: the addressed word, 0 above the register's width; 0 for any other address
    wire [31:0] rdw_period           = {19'd0, reg_period_q};
    wire [31:0] rdw_tbl_period       = {19'd0, reg_tbl_period_q};
    wire [31:0] rdw_ratio_0          = reg_ratio_q[31:0];
    wire [31:0] rdw_ratio_1          = {27'd0, reg_ratio_q[36:32]};
    wire [31:0] rdw_comp_offset_0    = reg_comp_offset_q[31:0];
    wire [31:0] rdw_comp_offset_1    = reg_comp_offset_q[63:32];
    wire [31:0] rdw_glitch_n         = {24'd0, reg_glitch_n_q};
    wire [31:0] rdw_sw_debounce      = {16'd0, reg_sw_debounce_q};
    wire [31:0] rdw_min_spacing      = {16'd0, reg_min_spacing_q};
    wire [31:0] rdw_pace_m           = {16'd0, reg_pace_m_q};
    wire [31:0] rdw_backlog_thr      = reg_backlog_thr_q;
    wire [31:0] rdw_mark_len         = {19'd0, reg_mark_len_q};
    wire [31:0] rdw_dac_width        = {27'd0, reg_dac_width_q};
    wire [31:0] rdw_amplitude        = {14'd0, reg_amplitude_q};
    wire [31:0] rdw_rehome           = {31'd0, reg_rehome_q};
    wire [31:0] rdw_clear            = {31'd0, reg_clear_q};
    wire [31:0] rdw_tbl_we           = {31'd0, reg_tbl_we_q};
    wire [31:0] rdw_tbl_addr         = {22'd0, reg_tbl_addr_q};
    wire [31:0] rdw_tbl_data         = {15'd0, reg_tbl_data_q};
    wire [31:0] rdw_map_en           = {31'd0, reg_map_en_q};
    wire [31:0] rdw_bank_sel         = {31'd0, reg_bank_sel_q};
    wire [31:0] rdw_map_origin0_0    = reg_map_origin0_q[31:0];
    wire [31:0] rdw_map_origin0_1    = {26'd0, reg_map_origin0_q[37:32]};
    wire [31:0] rdw_map_k0           = {27'd0, reg_map_k0_q};
    wire [31:0] rdw_map_n0           = {21'd0, reg_map_n0_q};
    wire [31:0] rdw_map_origin1_0    = reg_map_origin1_q[31:0];
    wire [31:0] rdw_map_origin1_1    = {26'd0, reg_map_origin1_q[37:32]};
    wire [31:0] rdw_map_k1           = {27'd0, reg_map_k1_q};
    wire [31:0] rdw_map_n1           = {21'd0, reg_map_n1_q};
    wire [31:0] rdw_map_we           = {31'd0, reg_map_we_q};
    wire [31:0] rdw_map_addr         = {22'd0, reg_map_addr_q};
    wire [31:0] rdw_map_data         = {8'd0, reg_map_data_q};
    wire [31:0] rdw_comp_sync        = {31'd0, reg_comp_sync_q};
    wire [31:0] rdw_comp_commit      = {31'd0, reg_comp_commit_q};
    wire [31:0] rdw_pin_cfg          = {28'd0, reg_pin_cfg_q};
    reg [31:0] rd_word;
    always @* begin
        case (rd_addr)
            A_PERIOD:          rd_word = rdw_period;
            A_TBL_PERIOD:      rd_word = rdw_tbl_period;
            A_RATIO_0:         rd_word = rdw_ratio_0;
            A_RATIO_1:         rd_word = rdw_ratio_1;
            A_COMP_OFFSET_0:   rd_word = rdw_comp_offset_0;
            A_COMP_OFFSET_1:   rd_word = rdw_comp_offset_1;
            A_GLITCH_N:        rd_word = rdw_glitch_n;
            A_SW_DEBOUNCE:     rd_word = rdw_sw_debounce;
            A_MIN_SPACING:     rd_word = rdw_min_spacing;
            A_PACE_M:          rd_word = rdw_pace_m;
            A_BACKLOG_THR:     rd_word = rdw_backlog_thr;
            A_MARK_LEN:        rd_word = rdw_mark_len;
            A_DAC_WIDTH:       rd_word = rdw_dac_width;
            A_AMPLITUDE:       rd_word = rdw_amplitude;
            A_REHOME:          rd_word = rdw_rehome;
            A_CLEAR:           rd_word = rdw_clear;
            A_TBL_WE:          rd_word = rdw_tbl_we;
            A_TBL_ADDR:        rd_word = rdw_tbl_addr;
            A_TBL_DATA:        rd_word = rdw_tbl_data;
            A_MAP_EN:          rd_word = rdw_map_en;
            A_BANK_SEL:        rd_word = rdw_bank_sel;
            A_MAP_ORIGIN0_0:   rd_word = rdw_map_origin0_0;
            A_MAP_ORIGIN0_1:   rd_word = rdw_map_origin0_1;
            A_MAP_K0:          rd_word = rdw_map_k0;
            A_MAP_N0:          rd_word = rdw_map_n0;
            A_MAP_ORIGIN1_0:   rd_word = rdw_map_origin1_0;
            A_MAP_ORIGIN1_1:   rd_word = rdw_map_origin1_1;
            A_MAP_K1:          rd_word = rdw_map_k1;
            A_MAP_N1:          rd_word = rdw_map_n1;
            A_MAP_WE:          rd_word = rdw_map_we;
            A_MAP_ADDR:        rd_word = rdw_map_addr;
            A_MAP_DATA:        rd_word = rdw_map_data;
            A_COMP_SYNC:       rd_word = rdw_comp_sync;
            A_COMP_COMMIT:     rd_word = rdw_comp_commit;
            A_PIN_CFG:         rd_word = rdw_pin_cfg;
            default:           rd_word = 32'd0;
        endcase
    end

    always @(posedge i_clk) begin
        if (i_rst) begin
            aw_full_q <= 1'b0;
            aw_word_q <= {WA_W{1'b0}};
            w_full_q  <= 1'b0;
            w_data_q  <= 32'd0;
            w_strb_q  <= 4'd0;
            bvalid_q  <= 1'b0;
            rvalid_q  <= 1'b0;
            rdata_q   <= 32'd0;
            reg_period_q <= 13'd256;
            reg_tbl_period_q <= 13'd256;
            reg_ratio_q <= 37'd34789620252;
            reg_comp_offset_q <= 64'd0;
            reg_glitch_n_q <= 8'd2;
            reg_sw_debounce_q <= 16'd16;
            reg_min_spacing_q <= 16'd8;
            reg_pace_m_q <= 16'd61;
            reg_backlog_thr_q <= 32'd4096;
            reg_mark_len_q <= 13'd64;
            reg_dac_width_q <= 5'd16;
            reg_amplitude_q <= 18'd32767;
            reg_rehome_q <= 1'd0;
            reg_clear_q <= 1'd0;
            reg_tbl_we_q <= 1'd0;
            reg_tbl_addr_q <= 10'd0;
            reg_tbl_data_q <= 17'd0;
            reg_map_en_q <= 1'd0;
            reg_bank_sel_q <= 1'd0;
            reg_map_origin0_q <= 38'd0;
            reg_map_k0_q <= 5'd10;
            reg_map_n0_q <= 11'd1024;
            reg_map_origin1_q <= 38'd0;
            reg_map_k1_q <= 5'd10;
            reg_map_n1_q <= 11'd1024;
            reg_map_we_q <= 1'd0;
            reg_map_addr_q <= 10'd0;
            reg_map_data_q <= 24'd0;
            reg_comp_sync_q <= 1'd0;
            reg_comp_commit_q <= 1'd0;
            reg_pin_cfg_q <= 4'd8;
        end else begin
            aw_full_q <= aw_full_d;
            if (aw_hs) aw_word_q <= s_axil_awaddr[ADDR_W-1:2];
            w_full_q  <= w_full_d;
            if (w_hs) begin
                w_data_q <= s_axil_wdata;
                w_strb_q <= s_axil_wstrb;
            end
            bvalid_q  <= bvalid_d;
            rvalid_q  <= rvalid_d;
            if (ar_hs) rdata_q <= rd_word;
            reg_period_q <= reg_period_d;
            reg_tbl_period_q <= reg_tbl_period_d;
            reg_ratio_q <= reg_ratio_d;
            reg_comp_offset_q <= reg_comp_offset_d;
            reg_glitch_n_q <= reg_glitch_n_d;
            reg_sw_debounce_q <= reg_sw_debounce_d;
            reg_min_spacing_q <= reg_min_spacing_d;
            reg_pace_m_q <= reg_pace_m_d;
            reg_backlog_thr_q <= reg_backlog_thr_d;
            reg_mark_len_q <= reg_mark_len_d;
            reg_dac_width_q <= reg_dac_width_d;
            reg_amplitude_q <= reg_amplitude_d;
            reg_rehome_q <= reg_rehome_d;
            reg_clear_q <= reg_clear_d;
            reg_tbl_we_q <= reg_tbl_we_d;
            reg_tbl_addr_q <= reg_tbl_addr_d;
            reg_tbl_data_q <= reg_tbl_data_d;
            reg_map_en_q <= reg_map_en_d;
            reg_bank_sel_q <= reg_bank_sel_d;
            reg_map_origin0_q <= reg_map_origin0_d;
            reg_map_k0_q <= reg_map_k0_d;
            reg_map_n0_q <= reg_map_n0_d;
            reg_map_origin1_q <= reg_map_origin1_d;
            reg_map_k1_q <= reg_map_k1_d;
            reg_map_n1_q <= reg_map_n1_d;
            reg_map_we_q <= reg_map_we_d;
            reg_map_addr_q <= reg_map_addr_d;
            reg_map_data_q <= reg_map_data_d;
            reg_comp_sync_q <= reg_comp_sync_d;
            reg_comp_commit_q <= reg_comp_commit_d;
            reg_pin_cfg_q <= reg_pin_cfg_d;
        end
    end

    assign o_period = reg_period_q;
    assign o_tbl_period = reg_tbl_period_q;
    assign o_ratio = reg_ratio_q;
    assign o_comp_offset = reg_comp_offset_q;
    assign o_glitch_n = reg_glitch_n_q;
    assign o_sw_debounce = reg_sw_debounce_q;
    assign o_min_spacing = reg_min_spacing_q;
    assign o_pace_m = reg_pace_m_q;
    assign o_backlog_thr = reg_backlog_thr_q;
    assign o_mark_len = reg_mark_len_q;
    assign o_dac_width = reg_dac_width_q;
    assign o_amplitude = reg_amplitude_q;
    assign o_rehome = reg_rehome_q;
    assign o_clear = reg_clear_q;
    assign o_tbl_we = reg_tbl_we_q;
    assign o_tbl_addr = reg_tbl_addr_q;
    assign o_tbl_data = reg_tbl_data_q;
    assign o_map_en = reg_map_en_q;
    assign o_bank_sel = reg_bank_sel_q;
    assign o_map_origin0 = reg_map_origin0_q;
    assign o_map_k0 = reg_map_k0_q;
    assign o_map_n0 = reg_map_n0_q;
    assign o_map_origin1 = reg_map_origin1_q;
    assign o_map_k1 = reg_map_k1_q;
    assign o_map_n1 = reg_map_n1_q;
    assign o_map_we = reg_map_we_q;
    assign o_map_addr = reg_map_addr_q;
    assign o_map_data = reg_map_data_q;
    assign o_comp_sync = reg_comp_sync_q;
    assign o_comp_commit = reg_comp_commit_q;
    assign o_pin_cfg = reg_pin_cfg_q;

endmodule

`default_nettype wire
