// laserax_top.v — the single-axis chain: quad_decoder -> pulse_multiplier -> output_pacer ->
// rephase -> dds_sincos, with the error_map beside the pacer input, plus the switch debounce,
// the configuration check and the digital A/B/Z outputs.
//
// Reference RTL of hls/laserax_top.h / hls/laserax_axil.cpp (DESIGN §4.7, register map §5). One
// rising clock edge = one call of laserax_top::step(); the outputs after edge t are the axis_out of
// call t, for the pins and registers presented before edge t.
//
// Register stages: in the C++ model a block consumes the outputs its upstream block returned at
// the previous call (the *_q members of laserax_top). Every block's outputs here are its own output
// registers, so they *are* that one register stage: each block is wired straight to the output
// registers of its upstream block. qa/qb/qz/ref_mark take the rephase outputs of call t-3 (the
// extra rep_q2 and rep_q3 stages of the C++ plus the output register; the index, one call later
// in rephase, skips rep_q2), so they change in the same call as the sin/cos codes they belong to.
// Latency pin edge -> sin/cos: 12 calls (glitch_n <= 1, DESIGN 4.7).
//
// Register stage (DESIGN 4.7): the register inputs presented before edge t are in force at edge
// t+1 (registers r_*). The configuration check and the period-change test are made on the
// presented values and registered (safe_q), so the block reset is one LUT from a flip-flop.
// Safe state: in a call whose registers in force fail the check, and in the call in which a new
// period is first in force after a running call, every block is reset at the edge (the C++
// laserax_top::reset()), cfg_err = 1, sin = cos = 0, qa/qb the levels of ab_rot, qz = ref_mark = 0,
// q_oe = !hiz_alarm, stage 1. A table
// write (tbl_we = 1) fails the check, so it is made only in a safe-state edge, in which the DDS is
// in reset (hls: dds_.write() only in the safe state of laserax_top::step(); DESIGN 4.6), and the
// next call is a safe-state call too, so no running call reads a word in the call of its write or
// the next one: the DDS is instantiated without its write bypass.
//
// i_rst (synchronous, active high) is the power-up state of the C++ object: the first edge after
// it is the power-up call (blocks in reset, cfg_err = 0, no registers in force yet: a table
// write presented while i_rst is high is not made). The table RAM is not affected by any reset.
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module laserax_top #(
    // INIT_FILE: $readmemh image of the DDS table RAM at configuration time (1024 words of
    // 17 bits, P = 256 / amp = 32767, written by `lutgen --hex` or `laserax vectors`).
    // Must not be empty.
    parameter INIT_FILE = "dds_table_p256.hex",
    // DEBUG_TAPS: 1 drives the debug taps (o_raw_count .. o_rep_mark: the registered outputs of
    // each block, the axis_out taps of the C++ model, which the vector testbenches compare);
    // 0 (default, the deployed core) ties them to 0, so the logic that only feeds them (the
    // absolute points A, B, C, Z of rephase and the like) is removed by synthesis. The functional
    // outputs, the status and the error-map outputs are the same for both values.
    parameter integer DEBUG_TAPS = 0
) (
    input  wire                              i_clk,
    input  wire                              i_rst,            // synchronous, active high: power-up state
    // pins (asynchronous)
    input  wire                              i_a,
    input  wire                              i_b,
    input  wire                              i_sw,
    input  wire                              i_lerr,
    // s_axilite registers (DESIGN §5)
    input  wire [`LX_W_P-1:0]                i_period,         // 256 at reset; 8..4096, multiple of 8
    input  wire [`LX_W_RATIO-1:0]            i_ratio,          // Q5.32, 1..2^37-1
    input  wire signed [`LX_W_OFFSET-1:0]    i_comp_offset,    // Q32.32 output counts added to N*R (any)
    input  wire                              i_comp_sync,      // 1: ratio / comp_offset act only on i_comp_commit
    input  wire                              i_comp_commit,    // pulse: load ratio / comp_offset (with i_comp_sync)
    input  wire [`LX_QD_W_GLITCH-1:0]        i_glitch_n,
    input  wire [`LX_TOP_W_DEBOUNCE-1:0]     i_sw_debounce,
    input  wire [`LX_QD_W_SPACING-1:0]       i_min_spacing,
    input  wire [`LX_OP_W_PACE-1:0]          i_pace_m,         // 2..65535
    input  wire [`LX_OP_W_THR-1:0]           i_backlog_thr,
    input  wire [`LX_W_P-1:0]                i_mark_len,       // P/4..P
    input  wire [`LX_W_DACW-1:0]             i_dac_width,      // 12..18
    input  wire [`LX_DDS_W_AMP-1:0]          i_amplitude,      // 1..2^(dac_width-1)-1
    input  wire [`LX_W_P-1:0]                i_tbl_period,     // must equal period
    input  wire                              i_rehome,         // pulse
    input  wire                              i_clear,          // pulse
    input  wire                              i_tbl_we,
    input  wire [`LX_W_TBL_ADDR-1:0]         i_tbl_addr,
    input  wire [`LX_W_TBL-1:0]              i_tbl_data,
    // error map (docs/ERROR_MAP.md §8); reset values: map disabled
    input  wire                              i_map_en,
    input  wire                              i_bank_sel,       // active bank; the write port writes the other
    input  wire signed [`LX_W_POS-1:0]       i_map_origin0,    // bank 0: position of point 0, comp coordinates
    input  wire [`LX_EM_W_K-1:0]             i_map_k0,         // bank 0: spacing 2^k counts, 4..20
    input  wire [`LX_EM_W_N-1:0]             i_map_n0,         // bank 0: points, 2..1024
    input  wire signed [`LX_W_POS-1:0]       i_map_origin1,
    input  wire [`LX_EM_W_K-1:0]             i_map_k1,
    input  wire [`LX_EM_W_N-1:0]             i_map_n1,
    input  wire                              i_map_we,
    input  wire [`LX_EM_W_ADDR-1:0]          i_map_addr,
    input  wire signed [`LX_EM_W_CORR-1:0]   i_map_data,       // Q15.8 output counts
    // digital pins (DESIGN 4.7): bit 0 qz_window, bits 2:1 ab_rot, bit 3 hiz_alarm; reset 8
    input  wire [`LX_TOP_W_PIN_CFG-1:0]      i_pin_cfg,
    // outputs
    output wire signed [`LX_W_DAC-1:0]       o_sin,
    output wire signed [`LX_W_DAC-1:0]       o_cos,
    output wire                              o_ref_mark,
    output wire                              o_qa,
    output wire                              o_qb,
    output wire                              o_qz,             // index at Z (or the window B..C: qz_window)
    output wire                              o_q_oe,           // A/B/Z driver enable: !(hiz_alarm && alarm)
    // status
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
    output wire                              o_dac_clip_st,    // sticky: a sin/cos code was clamped (DAC range guard)
    // taps: registered outputs of each block at this call (0 unless DEBUG_TAPS = 1)
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
    // error map
    output wire                              o_map_cfg_err,
    output wire signed [`LX_EM_W_C-1:0]      o_corr,
    output wire signed [`LX_EM_W_CDELTA-1:0] o_map_delta
);

    // ---- fixed values (hls: axis_widths) -------------------------------------------------------
    localparam [12:0] P_MIN          = 13'd8;
    localparam [12:0] P_MAX          = 13'd4096;
    localparam [4:0]  W_DAC_MIN      = 5'd12;
    localparam [4:0]  W_DAC_MAX      = 5'd18;
    localparam [36:0] RATIO_DEFAULT  = 37'd34789620252;  // reset value of the ratio register

    generate
        if (INIT_FILE == "") begin : g_bad_init_file
            laserax_top_PARAMETER_INIT_FILE_must_not_be_empty u_param_error ();
        end
        if (DEBUG_TAPS != 0 && DEBUG_TAPS != 1) begin : g_bad_debug_taps
            laserax_top_PARAMETER_DEBUG_TAPS_must_be_0_or_1 u_param_error ();
        end
    endgenerate

    // ---- register stage (DESIGN 4.7): the registers presented in call t are in force in call
    // t+1 (r_*); the configuration check of the presented values is registered with them
    // (safe_q), so the block reset is one LUT from a flip-flop. No reset: the power-up call
    // (blocks in reset) does not read them.
    reg        [12:0]   r_period;
    // constants of the period that rephase and dds_sincos compare with, formed here from the
    // presented period (a decrement in front of a register) instead of behind r_period in every
    // call: P - 1, P - 2 (14-bit signed) and P/4 - 1 (11 bits), those of r_period in every
    // running call. A running call's period passed the check (P % 8 == 0, 8 <= P <= 4096), so
    // all three are P/8 - 1 (0..511) with constant low bits: P - 1 = 8 (P/8 - 1) + 7,
    // P - 2 = 8 (P/8 - 1) + 6, P/4 - 1 = 2 (P/8 - 1) + 1; one 10-bit decrement (r_p8_m1). In a
    // safe-state call they may differ from P - 1 etc., and are not read: rephase and dds_sincos
    // are in reset, and their registers that a reset does not set take none of them.
    reg        [9:0]    r_p8_m1;         // P/8 - 1 of the presented period (10 bits, wrapping)
    wire signed [13:0]  r_period_m1 = $signed({1'b0, r_p8_m1, 3'b111});
    wire signed [13:0]  r_period_m2 = $signed({1'b0, r_p8_m1, 3'b110});
    wire       [10:0]   r_qtr_m1    = {r_p8_m1, 1'b1};
    reg        [7:0]    r_glitch_n;
    reg        [15:0]   r_sw_debounce;
    reg        [15:0]   r_min_spacing;
    reg        [15:0]   r_pace_m;
    reg        [31:0]   r_backlog_thr;
    reg        [12:0]   r_mark_len;
    // ~mark_len for rephase's mark compares (its i_mark_len_n): the inverted operand the
    // configuration check forms anyway (mark_n below), registered, so rephase's compare chains
    // need no inverter of their own
    reg        [12:0]   r_mark_len_n;
    reg        [17:0]   r_dac_hi;        // 2^(dac_width-1) - 1 of the presented dac_width (below)
    reg        [17:0]   r_amplitude;
    reg                 r_rehome;
    reg                 r_clear;
    reg                 r_tbl_we;        // (a write presented while i_rst is high, in force in
                                         // the power-up call, is not made: dds_we below)
    reg        [9:0]    r_tbl_addr;
    reg        [16:0]   r_tbl_data;
    reg                 r_map_en;
    reg                 r_bank_sel;
    reg signed [37:0]   r_map_origin0;
    reg        [4:0]    r_map_k0;
    reg        [10:0]   r_map_n0;
    reg signed [37:0]   r_map_origin1;
    reg        [4:0]    r_map_k1;
    reg        [10:0]   r_map_n1;
    reg                 r_map_we;
    reg        [9:0]    r_map_addr;
    reg signed [23:0]   r_map_data;
    // pin configuration: reset by i_rst to its reset value, so the power-up call (no registers in
    // force) shows the default pins (qa = qb = 0 of ab_rot = 0, q_oe = 1)
    reg        [3:0]    r_pin_cfg;
    // the DAC bound of the presented dac_width, by table (other widths fail the configuration
    // check; they give the 18-bit bound)
    reg  [17:0]         dac_hi_in;
    always @* begin
        case (i_dac_width)
            5'd12:   dac_hi_in = 18'd2047;
            5'd13:   dac_hi_in = 18'd4095;
            5'd14:   dac_hi_in = 18'd8191;
            5'd15:   dac_hi_in = 18'd16383;
            5'd16:   dac_hi_in = 18'd32767;
            5'd17:   dac_hi_in = 18'd65535;
            default: dac_hi_in = 18'd131071;
        endcase
    end
    always @(posedge i_clk) begin
        r_period        <= i_period;
        r_p8_m1         <= i_period[12:3] - 10'd1;
        r_glitch_n      <= i_glitch_n;
        r_sw_debounce   <= i_sw_debounce;
        r_min_spacing   <= i_min_spacing;
        r_pace_m        <= i_pace_m;
        r_backlog_thr   <= i_backlog_thr;
        r_mark_len      <= i_mark_len;
        r_mark_len_n    <= ~i_mark_len;
        r_dac_hi        <= dac_hi_in;
        r_amplitude     <= i_amplitude;
        r_rehome        <= i_rehome;
        r_clear         <= i_clear;
        r_tbl_we        <= i_tbl_we;
        r_tbl_addr      <= i_tbl_addr;
        r_tbl_data      <= i_tbl_data;
        r_map_en        <= i_map_en;
        r_bank_sel      <= i_bank_sel;
        r_map_origin0   <= i_map_origin0;
        r_map_k0        <= i_map_k0;
        r_map_n0        <= i_map_n0;
        r_map_origin1   <= i_map_origin1;
        r_map_k1        <= i_map_k1;
        r_map_n1        <= i_map_n1;
        r_map_we        <= i_map_we;
        r_map_addr      <= i_map_addr;
        r_map_data      <= i_map_data;
        r_pin_cfg       <= i_rst ? 4'd8 : i_pin_cfg;
    end

    // ---- compensation registers in force (DESIGN 4.7): the pair in force in a call is loaded
    // from the registers presented in the call before (every call without comp_sync, else only
    // with comp_commit), so it is formed one call early from the presented values and the
    // multiplier reads it straight from these registers; register-file state, not reset by the
    // safe state (power-up: the reset values, in force until the first load)
    reg  [36:0]        ratio_eff;
    reg                ratio_eff_nz;  // ratio_eff != 0, kept beside it (the check of ratio_next)
    reg  signed [63:0] offset_eff;
    reg                pup_q;       // this call is the power-up call (DESIGN 4.7)
    wire               comp_load_next = !i_comp_sync || i_comp_commit;
    wire [36:0]        ratio_next  = comp_load_next ? i_ratio : ratio_eff;     // in force next call
    wire signed [63:0] offset_next = comp_load_next ? i_comp_offset : offset_eff;
    always @(posedge i_clk) begin
        if (i_rst) begin
            ratio_eff  <= RATIO_DEFAULT;
            ratio_eff_nz <= RATIO_DEFAULT != 37'd0;
            offset_eff <= 64'sd0;
        end else begin
            ratio_eff  <= ratio_next;
            ratio_eff_nz <= comp_load_next ? i_ratio != 37'd0 : ratio_eff_nz;
            offset_eff <= offset_next;
        end
    end

    // ---- configuration check of the presented registers (for the next call) ----------------
    // the range checks against constants as bit logic (no carry chain in front of the AND tree):
    // P % 8 == 0 and 8 <= P <= 4096 <=> bits [2:0] zero, some bit of [12:3] set, and bit 12 only
    // alone; dac_width 12..18 (01100 .. 10010). Equal to the compares with P_MIN, P_MAX,
    // W_DAC_MIN, W_DAC_MAX for every input value (checked exhaustively when written).
    wire        period_ok = i_period[2:0] == 3'd0 && (|i_period[12:3]) && !(i_period[12] && (|i_period[11:3]));
    wire        width_ok  = i_dac_width[4:2] == 3'b011 || i_dac_width[4:1] == 4'b1000 || i_dac_width == 5'b10010;
    // amplitude <= 2^(w-1) - 1  <=>  amplitude < 2^(w-1)  <=>  bits [17:w-1] all 0 (w = 12..18):
    // a mask per legal width, so no shift, decrement or compare chain
    reg  [17:0] amp_hi;                                // bits that must be 0 at this width
    always @* begin
        case (i_dac_width)
            5'd12:   amp_hi = 18'h3f800;
            5'd13:   amp_hi = 18'h3f000;
            5'd14:   amp_hi = 18'h3e000;
            5'd15:   amp_hi = 18'h3c000;
            5'd16:   amp_hi = 18'h38000;
            5'd17:   amp_hi = 18'h30000;
            default: amp_hi = 18'h20000;               // 18 (other widths fail width_ok)
        endcase
    end
    wire        amp_ok    = width_ok && i_amplitude != 18'd0 && (i_amplitude & amp_hi) == 18'd0;
    // P/4 <= mark_len <= P as two carry chains that share the one inverted operand ~mark_len
    // (an inverted operand costs a LUT per bit in front of a chain): mark_len <= P <=> carry of
    // P + ~mark_len + 1; mark_len >= P/4 <=> !(P/4 > mark_len) <=> no carry of P/4 + ~mark_len
    wire [12:0] mark_n    = ~i_mark_len;
    wire [13:0] mark_le_s = {1'b0, i_period} + {1'b0, mark_n} + 14'd1;
    wire [13:0] mark_lt_s = {3'b000, i_period[12:2]} + {1'b0, mark_n};
    wire        mark_ok   = !mark_lt_s[13] && mark_le_s[13];
    // count integrity (DESIGN 4.2): min_spacing > max(glitch_n, 1). glitch_n has 8 bits, so an
    // upper byte of min_spacing that is not 0 passes by itself; else an 8-bit compare (no 16-bit
    // chain in front of the check's AND tree)
    wire        spacing_ok = (|i_min_spacing[15:8]) ||
                             (i_min_spacing[7:0] > i_glitch_n && (|i_min_spacing[7:1]));
    // The terms that end a carry chain (the mark_len compares, the spacing compare) arrive late;
    // they are ANDed in their own LUT (kept as a net, so the mapper cannot bury them under the
    // wide trees of the other terms), which meets the rest of the check in the last LUT in front of
    // safe_q: carry chain + two LUT levels.
    (* keep *) wire cfg_ok_late;
    assign cfg_ok_late = mark_ok && spacing_ok;
    // ratio_next != 0: i_ratio != 0 (a term already) when the pair loads, else ratio_eff != 0
    // (the flag kept beside it), so no 37-bit select sits in front of a zero test
    wire        cfg_ok_tree = period_ok && width_ok && amp_ok && i_ratio != 37'd0 && (comp_load_next || ratio_eff_nz) &&
                              (|i_pace_m[15:1]) && i_tbl_period == i_period && !i_tbl_we;  // pace_m >= 2
    (* keep *) wire cfg_ok_early;
    assign cfg_ok_early = cfg_ok_tree;
    wire        cfg_ok    = cfg_ok_late && cfg_ok_early;

    // a period change between two running calls is a reconfiguration: one call in the safe state
    // (this call runs when !safe_q; r_period is the period in force in it)
    reg         safe_q;                               // this call is in the safe state
    reg         cfg_err_q, run_out_q;
    // the call after a table write in force is a safe-state call too (DESIGN 4.6, 4.7): r_tbl_we
    // is the write in force in this call (none in the power-up call)
    wire        safe_next = !cfg_ok || (r_tbl_we && !pup_q) || (!safe_q && i_period != r_period);
    wire        blk_rst   = i_rst || safe_q;          // every block held in reset
    // the DDS table write in force: none in the power-up call (the C++ model has no call in which
    // a value presented while i_rst is high could be in force)
    wire        dds_we    = r_tbl_we && !pup_q;
    always @(posedge i_clk) begin
        if (i_rst) begin
            safe_q    <= 1'b1;                        // the power-up call: blocks in reset
            pup_q     <= 1'b1;
            cfg_err_q <= 1'b0;
            run_out_q <= 1'b0;
        end else begin
            safe_q    <= safe_next;
            pup_q     <= 1'b0;
            cfg_err_q <= safe_q && !pup_q;
            run_out_q <= !safe_q;
        end
    end

    // ---- blocks ------------------------------------------------------------------------------
    // switch debounce
    wire swf_f, swf_valid, swf_glitch, swf_f_d, swf_valid_d, swf_glitch_d;
    input_filter #(.W_CNT(16)) u_swf (
        .i_clk(i_clk), .i_rst(blk_rst), .i_pin(i_sw), .i_n(r_sw_debounce),
        .o_f(swf_f), .o_valid(swf_valid), .o_glitch(swf_glitch),
        .o_f_d(swf_f_d), .o_valid_d(swf_valid_d), .o_glitch_d(swf_glitch_d));

    // decoder
    wire signed [1:0]  dec_step;
    wire signed [31:0] dec_raw;
    wire               dec_illegal, dec_ovs, dec_illegal_st, dec_ovs_st, dec_lerr, dec_lerr_alarm;
    wire               dec_lerr_nx;   // dec_lerr of the next call (rephase's look-ahead)
    wire               dec_glitch_st;
    wire [7:0]         dec_err_cnt;
    quad_decoder u_dec (
        .i_clk(i_clk), .i_rst(blk_rst), .i_a(i_a), .i_b(i_b), .i_lerr(i_lerr),
        .i_glitch_n(r_glitch_n), .i_min_spacing(r_min_spacing), .i_clear(r_clear),
        .o_step(dec_step), .o_raw_count(dec_raw), .o_illegal(dec_illegal), .o_ovs(dec_ovs),
        .o_err_cnt(dec_err_cnt), .o_illegal_st(dec_illegal_st), .o_ovs_st(dec_ovs_st),
        .o_lerr(dec_lerr), .o_lerr_nx(dec_lerr_nx), .o_lerr_alarm(dec_lerr_alarm), .o_glitch_st(dec_glitch_st));

    // multiplier: consumes the decoder step of the previous call
    wire signed [37:0] mul_comp;
    wire signed [38:0] mul_delta;
    pulse_multiplier u_mul (
        .i_clk(i_clk), .i_rst(blk_rst), .i_step(dec_step), .i_ratio(ratio_eff), .i_comp_offset(offset_eff),
        .o_comp(mul_comp), .o_delta(mul_delta));

    // rephase outputs used by the error map (declared before use)
    wire signed [1:0]  rep_ostep;
    wire signed [37:0] rep_out_pos, rep_a, rep_b, rep_c, rep_z, rep_adj;
    wire               rep_mark, rep_index, rep_homed;
    wire [1:0]         rep_stage;
    wire [11:0]        rep_d;

    // error map: uncorrected comp and rephase homed status of the previous call (the blocks'
    // output registers); a sample every 32 calls, 50 calls of latency (docs/ERROR_MAP.md §6)
    wire signed [16:0] map_corr;
    wire signed [17:0] map_delta;
    wire               map_active, map_in_range, map_clamped, map_cfg_err;
    error_map u_map (
        .i_clk(i_clk), .i_rst(blk_rst), .i_p(mul_comp), .i_homed(rep_homed),
        .i_map_en(r_map_en), .i_bank_sel(r_bank_sel),
        .i_origin0(r_map_origin0), .i_k0(r_map_k0), .i_n0(r_map_n0),
        .i_origin1(r_map_origin1), .i_k1(r_map_k1), .i_n1(r_map_n1),
        .i_we(r_map_we), .i_addr(r_map_addr), .i_data(r_map_data),
        .o_corr(map_corr), .o_delta(map_delta), .o_active(map_active), .o_in_range(map_in_range),
        .o_clamped(map_clamped), .o_cfg_err(map_cfg_err));

    // pacer: consumes the multiplier delta and the map delta of the previous call as two addends
    // (their sum is formed in the pacer's carry-save layer, so no adder precedes it)
    // (wide: rephase was in its window in the previous call, so every count owes a slot there)
    wire signed [1:0]  pac_pstep, pac_pstep_nx;
    wire               pac_slot, pac_slot_nx;
    wire signed [37:0] pac_paced;
    wire signed [39:0] pac_backlog;
    wire               pac_ovs, pac_ovs_st;
    output_pacer u_pac (
        .i_clk(i_clk), .i_rst(blk_rst), .i_delta(mul_delta), .i_add(map_delta), .i_pace_m(r_pace_m),
        .i_thr(r_backlog_thr), .i_clear(r_clear), .i_wide(rep_stage == 2'd2),
        .o_pstep(pac_pstep), .o_pstep_nx(pac_pstep_nx), .o_slot(pac_slot), .o_slot_nx(pac_slot_nx),
        .o_paced(pac_paced), .o_backlog(pac_backlog), .o_ovs(pac_ovs),
        .o_ovs_st(pac_ovs_st));

    // rephase: pacer step and slot, debounced switch and laser error of the previous call; the
    // pacer's look-ahead (its next pstep and slot) for the registered count decode (DESIGN 4.5)
    rephase u_rep (
        .i_clk(i_clk), .i_rst(blk_rst), .i_pstep(pac_pstep), .i_pstep_nx(pac_pstep_nx),
        .i_slot(pac_slot), .i_slot_nx(pac_slot_nx), .i_sw(swf_f), .i_sw_valid(swf_valid),
        .i_rehome(r_rehome), .i_unhome(dec_lerr), .i_unhome_nx(dec_lerr_nx), .i_rehome_nx(i_rehome),
        .i_period(r_period), .i_period_m1(r_period_m1),
        .i_period_m2(r_period_m2), .i_mark_len(r_mark_len), .i_mark_len_n(r_mark_len_n),
        .o_ostep(rep_ostep), .o_out_pos(rep_out_pos), .o_mark(rep_mark), .o_index(rep_index), .o_stage(rep_stage),
        .o_a(rep_a), .o_d(rep_d), .o_b(rep_b), .o_c(rep_c), .o_z(rep_z), .o_adj(rep_adj),
        .o_homed(rep_homed));

    // DDS: rephase output step of the previous call; the table port is always active
    // DAC bound 2^(w-1) - 1 (w = 12..18 in every running call, the only calls that clamp), for
    // the register dac_hi of the guard below and the DDS's magnitude flags: the register stage's
    // r_dac_hi, decoded there from the presented dac_width, so the DDS's compare chains start at
    // a flip-flop
    wire [17:0]        dac_hi_d = r_dac_hi;
    wire signed [17:0] dds_sin, dds_cos;
    wire               dds_sin_over, dds_cos_over;   // |code| > dac_hi, registered with the codes
    // no write bypass: a table write holds the safe state in its call and the next (DESIGN 4.6)
    dds_sincos #(.INIT_FILE(INIT_FILE), .WRITE_BYPASS(0)) u_dds (
        .i_clk(i_clk), .i_rst(blk_rst), .i_ostep(rep_ostep), .i_period(r_period), .i_qtr_m1(r_qtr_m1),
        .i_amplitude(r_amplitude), .i_tbl_we(dds_we), .i_tbl_addr(r_tbl_addr),
        .i_tbl_data(r_tbl_data), .o_sin(dds_sin), .o_cos(dds_cos),
        .i_clip_hi(dac_hi_d), .o_sin_over(dds_sin_over), .o_cos_over(dds_cos_over));

    // ---- digital A/B/Z: rephase outputs of call t-3 ------------------------------------------
    // (the rephase index is one call later than its mark, DESIGN 4.5 step 5: it enters at rep_q3)
    reg [1:0] rep_pos2_q, rep_pos3_q, out_pos2_q;   // out_pos mod 4: rep_q2, rep_q3, output stage
    reg       rep_mark2_q, rep_mark3_q, out_mark2_q;
    reg       rep_idx3_q, out_z_q;                  // rephase index: rep_q3, output stage (qz)
    always @(posedge i_clk) begin
        if (blk_rst) begin
            rep_pos2_q  <= 2'd0;
            rep_mark2_q <= 1'b0;
            rep_pos3_q  <= 2'd0;
            rep_mark3_q <= 1'b0;
            rep_idx3_q  <= 1'b0;
            out_pos2_q  <= 2'd0;
            out_mark2_q <= 1'b0;
            out_z_q     <= 1'b0;
        end else begin
            rep_pos2_q  <= rep_out_pos[1:0];
            rep_mark2_q <= rep_mark;
            rep_pos3_q  <= rep_pos2_q;
            rep_mark3_q <= rep_mark2_q;
            rep_idx3_q  <= rep_index;
            out_pos2_q  <= rep_pos3_q;
            out_mark2_q <= rep_mark3_q;
            out_z_q     <= r_pin_cfg[0] ? rep_mark3_q : rep_idx3_q;   // qz_window in force
        end
    end
    // ab_rot and hiz_alarm of call t for the outputs after its edge (r_pin_cfg then holds call
    // t + 1's value); in the power-up call the reset value
    reg [2:0] pin_o_q;
    always @(posedge i_clk) pin_o_q <= r_pin_cfg[3:1];

    // quadrature level of (pos + ab_rot) mod 4: 0 -> (0,0), 1 -> (1,0), 2 -> (1,1), 3 -> (0,1)
    wire [1:0] q_i  = out_pos2_q + pin_o_q[1:0];
    assign o_qa     = q_i == 2'd1 || q_i == 2'd2;
    assign o_qb     = q_i == 2'd2 || q_i == 2'd3;
    assign o_qz     = out_z_q;
    assign o_ref_mark = out_mark2_q;
    // DAC range guard (DESIGN 4.7): the codes of call t are the DDS registers clamped to
    // +-(2^(dac_width-1) - 1) with the dac_width of call t; a clamp sets the sticky dac_clip_st
    // (clear of call t acts first, the event wins; reset with the chain). The bounds of the
    // dac_width of call t and its clear are registered with the DDS outputs, so the clamp sits
    // after registers only.
    reg  signed [17:0] dac_hi;      // 2^(dac_width-1) - 1 of call t, formed before the register
    reg                clear_q, clip_st_q;
    // (dac_hi_d, the bound of the next call, is formed in front of dds_sincos, which reads it)
    wire               run_now  = run_out_q;     // dac_width is legal (12..18) in a running call
    // The bounds are symmetric (+-dac_hi), so a code is clamped iff |code| > dac_hi, towards its
    // own sign. dds_sincos forms |code| > bound in the call before, from its read-stage words and
    // the bound dac_hi_d that dac_hi holds in this call, and registers it with the code
    // (o_sin_over / o_cos_over): the clamp and the sticky flag follow registers by one or two LUT
    // levels, no compare chain after the DDS registers. In a call that is not running the DDS
    // registers are 0 (the DDS was reset at the edge before): no flag, no clamp.
    // The clamped code is +dac_hi or -dac_hi by the code's sign. dac_hi = 2^(w-1) - 1 is odd for
    // every width (and its reset value 32767), so -dac_hi = ~dac_hi + 1 has bit 0 = 1 and bits
    // >= 1 equal to ~dac_hi: the bound of the sign is dac_hi with bits >= 1 XORed with the sign,
    // four inputs per output bit (over, sign, dac_hi bit, code bit), no -dac_hi register.
    wire signed [17:0] sin_bound = dac_hi ^ {{17{dds_sin[17]}}, 1'b0};
    wire signed [17:0] cos_bound = dac_hi ^ {{17{dds_cos[17]}}, 1'b0};
    (* keep *) wire    clip_hold;
    wire               clip_any  = dds_sin_over || dds_cos_over;
    assign clip_hold = clip_st_q && !clear_q;
    wire               clip_st  = run_now && (clip_hold || clip_any);
    always @(posedge i_clk) begin
        if (i_rst) begin
            dac_hi    <= 18'sd32767;
            clear_q   <= 1'b0;
            clip_st_q <= 1'b0;
        end else begin
            dac_hi    <= $signed(dac_hi_d);
            clear_q   <= r_clear;
            clip_st_q <= clip_st;
        end
    end
    assign o_sin    = dds_sin_over ? sin_bound : dds_sin;
    assign o_cos    = dds_cos_over ? cos_bound : dds_cos;
    assign o_dac_clip_st = clip_st;

    // ---- status (block registers are in their reset state after a safe-state call) -----------
    assign o_cfg_err        = cfg_err_q;
    assign o_stage          = rep_stage;
    assign o_homed          = rep_homed;
    assign o_lerr_alarm     = dec_lerr_alarm;
    assign o_illegal_st     = dec_illegal_st;
    assign o_err_cnt        = dec_err_cnt;
    assign o_ovs_edge_st    = dec_ovs_st;
    assign o_ovs_backlog_st = pac_ovs_st;
    assign o_glitch_st      = dec_glitch_st;
    // the flags that are registers, ORed apart from the late clip_st
    (* keep *) wire alarm_reg;
    assign alarm_reg        = cfg_err_q || dec_lerr_alarm || dec_illegal_st || dec_ovs_st || pac_ovs_st ||
                              map_cfg_err;
    assign o_alarm          = alarm_reg || clip_st;
    assign o_q_oe           = !(pin_o_q[2] && (alarm_reg || clip_st));
    assign o_map_cfg_err    = map_cfg_err;

    // ---- taps (DEBUG_TAPS = 1; else 0) -------------------------------------------------------
    localparam TAPS = DEBUG_TAPS == 1;
    assign o_raw_count = TAPS ? dec_raw : {32{1'b0}};
    assign o_step      = TAPS ? dec_step : {2{1'b0}};
    assign o_comp_pos  = TAPS ? mul_comp : {38{1'b0}};
    assign o_delta     = TAPS ? mul_delta : {39{1'b0}};
    assign o_backlog   = TAPS ? pac_backlog : {40{1'b0}};
    assign o_pstep     = TAPS ? pac_pstep : {2{1'b0}};
    assign o_paced_pos = TAPS ? pac_paced : {38{1'b0}};
    assign o_ostep     = TAPS ? rep_ostep : {2{1'b0}};
    assign o_out_pos   = TAPS ? rep_out_pos : {38{1'b0}};
    assign o_adj       = TAPS ? rep_adj : {38{1'b0}};
    assign o_a_pos     = TAPS ? rep_a : {38{1'b0}};
    assign o_b_pos     = TAPS ? rep_b : {38{1'b0}};
    assign o_c_pos     = TAPS ? rep_c : {38{1'b0}};
    assign o_z_pos     = TAPS ? rep_z : {38{1'b0}};
    assign o_d         = TAPS ? rep_d : {12{1'b0}};
    assign o_rep_mark  = TAPS ? rep_mark : {1{1'b0}};
    assign o_corr      = map_corr;
    assign o_map_delta = map_delta;

endmodule

`default_nettype wire
