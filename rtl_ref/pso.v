// pso.v — position-synchronised output: vector-distance tracking of up to three axes (chord
// ROM over a tracking window), firing comparator with remainder carry, pulse of programmable
// width, position window, array of firing distances, part-speed pulse generator (24 MHz limit)
// and the sequenced minimum-spacing check.
//
// Reference RTL of hls/pso.h (docs/PSO_COUNTERS.md §2). One rising clock edge = one call of
// pso::step(); every output is a register holding the out_t of that call. Synchronous
// active-high reset = a freshly constructed lx::pso (every array entry "not written", state in
// reset). A call with an invalid configuration resets everything except the array RAM and its
// "entry below 2 counts" map and raises cfg_err for that call; a call with enable = 0 resets the
// tracking state (counters and sticky flags are kept).
//
// Stages (registers before the edge; §2.4):
//   A   this call's steps: tracking window (travel D per axis, reversal / |D| >= K closes), ROM
//       address s = sum D^2 -> a_s; part-speed phase accumulator (clamped to INC_MAX), pulse
//       count; window condition -> a_inwin; minimum-spacing shift-add (sample every 17 calls).
//   R   chord ROM (769 x 37 bits, filled at elaboration by the same digit-by-digit square root
//       as hls/pso.h) read at a_s: its output register is r_chord.
//   B1  y = (r_rev ? part : 0) + chord (+1.0 for a generator pulse), x = r_kclose ? y : ..., and
//       x - thr, y - thr for thr0 (the next fire's threshold if this call's B2 does not fire)
//       and thr1 (if it does): fire_dist, or the array entries idx and next(idx).
//   B2  fire = b_v && !done && rem + (y - thr) >= 0; rem' = rem + x (- thr): each result one add
//       of the remainder and a register (the candidate picked by the registered fire of the last
//       call). Array index, pulse timer, overlap / frequency flags.
// A step in call t fires in call t + 3.
//
// Array RAM (64 x 56): three copies (one read port each, the write port shared), read with
// addresses formed from the index register of the call before B1 (idx, next(idx),
// next(next(idx))); B1 picks two of the three with the registered fire of the last call, then
// forwards the write of the last call and of this call, so it sees the RAM after this call's
// write, as hls/ does. In the first call of a run (idx = 0 after a reset call, whose read
// addresses may be stale) entry 0 comes from a copy register (entry0) instead.
//
// Widths (pso_cfg): distances Q24.32 (56 unsigned), remainder and dist 58 signed, chord 37,
// x / y 38, travel 6 signed, K 5, positions 38 signed, part-speed rate Q0.32, pulse width and
// laser minimum period 16, fire counter 32 (wraps), overlap counter 16 (saturates).
`timescale 1ns / 1ps
`default_nettype none

module pso (
    input  wire               i_clk,
    input  wire               i_rst,         // synchronous, active high: a fresh lx::pso
    // per-call inputs (pso_in)
    input  wire signed [1:0]  i_step0,       // tracked axis steps (-1, 0, +1)
    input  wire signed [1:0]  i_step1,
    input  wire signed [1:0]  i_step2,
    input  wire signed [37:0] i_pos0,        // axis positions after the step (window)
    input  wire signed [37:0] i_pos1,
    input  wire signed [37:0] i_pos2,
    input  wire [31:0]        i_ps_inc,      // part-speed command, Q0.32 counts per clock
    // registers (pso_regs)
    input  wire               i_enable,
    input  wire               i_part_speed,  // latched at the start of a run
    input  wire [2:0]         i_axis_mask,   // latched; != 0 unless part_speed
    input  wire [4:0]         i_win_k,       // tracking window K, 1..16
    input  wire [55:0]        i_fire_dist,   // Q24.32 counts, >= 2 counts unless arr_en
    input  wire               i_arr_en,      // latched
    input  wire [6:0]         i_arr_len,     // latched; 1..64 when arr_en
    input  wire               i_arr_wrap,    // latched
    input  wire               i_arr_we,      // array write port (every call, also disabled)
    input  wire [5:0]         i_arr_addr,
    input  wire [55:0]        i_arr_data,
    input  wire [15:0]        i_pulse_w,     // pulse width, clocks, >= 1
    input  wire               i_win_en,
    input  wire [1:0]         i_win_src,     // 0..2 axis position, 3 pulse count (part-speed)
    input  wire signed [37:0] i_win_low,
    input  wire signed [37:0] i_win_high,
    input  wire [15:0]        i_min_period,  // laser minimum period, clocks (0: no check)
    input  wire               i_clear,       // pulse: clears sticky flags and overlap counter
    // outputs (pso::out_t)
    output wire               o_fire,
    output wire               o_emit,
    output wire               o_pulse,
    output wire               o_in_win,
    output wire signed [57:0] o_dist,        // distance since the last fire, Q.32
    output wire [6:0]         o_idx,
    output wire               o_arr_done,
    output wire [31:0]        o_fire_cnt,
    output wire [15:0]        o_overlap_cnt,
    output wire               o_overlap,
    output wire               o_overlap_st,
    output wire               o_rate_over,
    output wire               o_rate_over_st,
    output wire               o_spacing_err,
    output wire               o_spacing_st,
    output wire               o_freq_err,
    output wire               o_freq_st,
    output wire               o_ps_pulse,
    output wire signed [37:0] o_ps_count,
    output wire               o_cfg_err
);

    // ---- fixed widths (hls: pso_cfg) ---------------------------------------------------------
    localparam integer D_FRAC   = 32;   // fraction bits of every distance
    localparam integer W_DIST   = 56;   // Q24.32 unsigned
    localparam integer W_REM    = 58;   // remainder, signed
    localparam integer K_MAX    = 16;   // longest tracking window
    localparam integer W_K      = 5;
    localparam integer W_WIN    = 6;    // travel D, signed -K..K
    localparam integer S_MAX    = 768;  // 3 K_MAX^2
    localparam integer W_S      = 10;
    localparam integer W_CHORD  = 37;
    localparam integer W_INCR   = 38;   // x, y
    localparam integer W_POS    = 38;
    localparam integer W_INC    = 32;
    localparam integer W_GAP    = 16;
    localparam integer W_PW     = 16;
    localparam integer W_FCNT   = 32;
    localparam integer W_OVL    = 16;
    localparam integer W_PROD   = 48;   // inc * min_period
    localparam integer W_SPHI   = 33;
    localparam [W_INC-1:0] INC_MAX = 32'd1030792151;  // floor(0.24 * 2^32): 24 MHz

    // ---- chord ROM contents: round(sqrt(s) * 2^32), digit-by-digit (as pso_chord_rom) ---------
    function [W_CHORD-1:0] round_sqrt;
        input [W_S-1:0] s;
        reg [63:0] root, rem, trial;
        reg [1:0]  pair;
        integer    i;
        begin
            root = 64'd0;
            rem = 64'd0;
            for (i = 0; i < (W_S + 1) / 2 + D_FRAC; i = i + 1) begin
                pair = (i < (W_S + 1) / 2) ? ((s >> (2 * ((W_S + 1) / 2 - 1 - i))) & 10'd3) : 2'd0;
                rem = (rem << 2) | {62'd0, pair};
                trial = (root << 2) | 64'd1;
                if (rem >= trial) begin
                    rem = rem - trial;
                    root = (root << 1) | 64'd1;
                end else begin
                    root = root << 1;
                end
            end
            round_sqrt = (rem > root) ? root[W_CHORD-1:0] + 1'b1 : root[W_CHORD-1:0];
        end
    endfunction

    reg [W_CHORD-1:0] rom [0:S_MAX];
    integer ri;
    initial begin
        for (ri = 0; ri <= S_MAX; ri = ri + 1) rom[ri] = round_sqrt(ri[W_S-1:0]);
    end

    // ---- array RAM: three copies with one read port each ---------------------------------------
    reg [W_DIST-1:0] arr0 [0:63];
    reg [W_DIST-1:0] arr1 [0:63];
    reg [W_DIST-1:0] arr2 [0:63];
    integer ai;
    initial begin
        for (ai = 0; ai < 64; ai = ai + 1) begin
            arr0[ai] = {W_DIST{1'b0}};
            arr1[ai] = {W_DIST{1'b0}};
            arr2[ai] = {W_DIST{1'b0}};
        end
    end

    // ---- registers ---------------------------------------------------------------------------
    reg [63:0]              bad_q;        // entry below 2 counts (or never written)
    reg [W_DIST-1:0]        entry0_q;     // copy of entry 0
    reg [W_DIST-1:0]        rd0_q, rd1_q, rd2_q;   // array read data (BRAM output registers)
    reg                     fw0_q, fw1_q, fw2_q;   // the last call's write hit that read address
    reg [W_DIST-1:0]        wd_q;         // the last call's write data
    // run state and latched mode registers
    reg                     run_q, ps_q, arr_en_q, arr_wrap_q;
    reg [2:0]               mask_q;
    reg [6:0]               len_q;
    // stage A
    reg signed [W_WIN-1:0]  trav0_q, trav1_q, trav2_q;
    reg                     a_rev_q, a_kclose_q, a_pulse_q, a_inwin_q, a_v_q;
    reg [W_S-1:0]           a_s_q;
    reg [W_INC-1:0]         ph_q;
    reg signed [W_POS-1:0]  ps_cnt_q;
    // spacing product
    reg [4:0]               sp_k_q;
    reg                     sp_full_q, sp_mnz_q;
    reg [W_INC-1:0]         sp_inc_q;
    reg [W_GAP-1:0]         sp_m_q;       // min_period, shifted right once per step
    reg [W_DIST-1:0]        sp_thr_q;
    reg [W_SPHI-1:0]        sp_hi_q;
    reg [W_GAP-1:0]         sp_lo_q;
    // stage R
    reg [W_CHORD-1:0]       r_chord_q;    // ROM output register (not reset: masked by r_v)
    reg                     r_rev_q, r_kclose_q, r_pulse_q, r_inwin_q, r_v_q;
    // stage B1
    reg [W_INCR-1:0]        b_x_q, b_y_q;
    reg [W_REM-1:0]         b_xm0_q, b_ym0_q, b_xm1_q, b_ym1_q;
    reg                     b_inwin_q, b_v_q, b_fire1_q;
    reg [W_CHORD-1:0]       part_q;
    // stage B2
    reg [W_REM-1:0]         rem_q, dist_q;
    reg [6:0]               idx_q;
    reg                     done_q;
    reg [W_PW-1:0]          timer_q;
    reg [W_GAP-1:0]         since_q;
    reg [W_FCNT-1:0]        fire_cnt_q;
    reg [W_OVL-1:0]         ovl_cnt_q;
    reg                     overlap_st_q, rate_over_st_q, spacing_st_q, freq_st_q;
    // per-call outputs
    reg                     fire_q, emit_q, pulse_q, in_win_q, overlap_q, rate_over_q;
    reg                     spacing_err_q, freq_err_q, ps_pulse_q, cfg_err_q;

    // ---- array write port and the map of bad entries (after this call's write) ---------------
    wire        wr_bad = (i_arr_data[W_DIST-1:D_FRAC+1] == 23'd0);   // data < 2 counts
    wire [63:0] wr_bit = 64'd1 << i_arr_addr;
    wire [63:0] bad_d  = !i_arr_we ? bad_q : wr_bad ? (bad_q | wr_bit) : (bad_q & ~wr_bit);

    // ---- configuration check (pso_config_ok) ---------------------------------------------------
    wire        k_ok    = (i_win_k != 5'd0) && (!i_win_k[4] || (i_win_k[3:0] == 4'd0));
    wire        axes_ok = i_part_speed || (i_axis_mask != 3'd0);
    wire        len_ok  = (i_arr_len != 7'd0) && (!i_arr_len[6] || (i_arr_len[5:0] == 6'd0));
    wire [63:0] used    = i_arr_len[6] ? {64{1'b1}} : ((64'd1 << i_arr_len[5:0]) - 64'd1);
    wire        thr_ok  = i_arr_en ? (len_ok && ((bad_d & used) == 64'd0))
                                   : (i_fire_dist[W_DIST-1:D_FRAC+1] != 23'd0);
    wire        win_ok  = !i_win_en || ((i_win_low <= i_win_high) && (i_win_src != 2'd3 || i_part_speed));
    wire        cfg_ok  = k_ok && axes_ok && thr_ok && win_ok && (i_pulse_w != 16'd0);

    // latched modes as seen in this call (the first call of a run latches them)
    wire       ps_e     = run_q ? ps_q : i_part_speed;
    wire [2:0] mask_e   = run_q ? mask_q : i_axis_mask;
    wire       arr_en_e = run_q ? arr_en_q : i_arr_en;
    wire [6:0] len_e    = run_q ? len_q : i_arr_len;

    function [6:0] next_idx;   // next array index (0 after the last entry)
        input [6:0] i;
        input [6:0] len;
        reg   [7:0] n;
        begin
            n = {1'b0, i} + 8'd1;
            next_idx = (n >= {1'b0, len}) ? 7'd0 : n[6:0];
        end
    endfunction

    // ---- stage B1 ------------------------------------------------------------------------------
    // array data read with the addresses of the last call (i, next(i), next(next(i)) of its idx),
    // the last call's write forwarded (read-before-write RAM)
    wire [W_DIST-1:0] e0 = fw0_q ? wd_q : rd0_q;
    wire [W_DIST-1:0] e1 = fw1_q ? wd_q : rd1_q;
    wire [W_DIST-1:0] e2 = fw2_q ? wd_q : rd2_q;
    // entries idx and next(idx) after the last call (its fire moved idx by b_fire1)
    wire [W_DIST-1:0] a0 = !run_q ? entry0_q : b_fire1_q ? e1 : e0;
    wire [W_DIST-1:0] a1 = b_fire1_q ? e2 : e1;
    // this call's write forwarded
    wire [6:0]        nx  = next_idx(idx_q, len_q);
    wire [W_DIST-1:0] t0a = (i_arr_we && i_arr_addr == idx_q[5:0]) ? i_arr_data : a0;
    wire [W_DIST-1:0] t1a = (i_arr_we && i_arr_addr == nx[5:0]) ? i_arr_data : a1;
    wire [W_DIST-1:0] thr0 = arr_en_e ? t0a : i_fire_dist;
    wire [W_DIST-1:0] thr1 = arr_en_q ? t1a : i_fire_dist;

    wire [W_CHORD-1:0] chord = r_v_q ? r_chord_q : {W_CHORD{1'b0}};
    wire [W_CHORD-1:0] pr    = r_rev_q ? part_q : {W_CHORD{1'b0}};
    wire [W_INCR-1:0]  one   = {{(W_INCR-D_FRAC-1){1'b0}}, r_pulse_q, {D_FRAC{1'b0}}};
    wire [W_INCR-1:0]  y     = {1'b0, pr} + {1'b0, chord} + one;
    wire [W_INCR-1:0]  x     = r_kclose_q ? y : ({1'b0, pr} + one);
    wire [W_REM-1:0]   y58   = {{(W_REM-W_INCR){1'b0}}, y};
    wire [W_REM-1:0]   x58   = {{(W_REM-W_INCR){1'b0}}, x};
    wire [W_REM-1:0]   ym0_d = y58 - {2'b00, thr0};
    wire [W_REM-1:0]   xm0_d = x58 - {2'b00, thr0};
    wire [W_REM-1:0]   ym1_d = y58 - {2'b00, thr1};
    wire [W_REM-1:0]   xm1_d = x58 - {2'b00, thr1};

    // ---- stage B2 ------------------------------------------------------------------------------
    wire [W_REM-1:0] ym   = b_fire1_q ? b_ym1_q : b_ym0_q;
    wire [W_REM-1:0] xm   = b_fire1_q ? b_xm1_q : b_xm0_q;
    wire [W_REM-1:0] vm   = rem_q + ym;                      // value - thr
    wire             fire = b_v_q && !done_q && !vm[W_REM-1];
    wire [W_REM-1:0] rem_d  = done_q ? rem_q : fire ? rem_q + xm : rem_q + {{(W_REM-W_INCR){1'b0}}, b_x_q};
    wire [W_REM-1:0] dist_d = done_q ? dist_q : fire ? vm : rem_q + {{(W_REM-W_INCR){1'b0}}, b_y_q};
    wire             last   = ({1'b0, idx_q} + 8'd1) >= {1'b0, len_q};
    wire [6:0]       idx_d  = (fire && arr_en_q) ? (last ? (arr_wrap_q ? 7'd0 : idx_q) : idx_q + 7'd1) : idx_q;
    wire             done_d = done_q || (fire && arr_en_q && last && !arr_wrap_q);
    wire             emit   = fire && b_inwin_q;
    wire             overlap  = emit && (timer_q != 16'd0);
    wire             freq_err = emit && (i_min_period != 16'd0) &&
                                (({1'b0, since_q} + 17'd1) < {1'b0, i_min_period});
    wire [W_PW-1:0]  timer_d  = emit ? i_pulse_w : (timer_q != 16'd0) ? timer_q - 16'd1 : 16'd0;
    wire [W_GAP-1:0] since_d  = emit ? 16'd0 : (since_q != 16'hffff) ? since_q + 16'd1 : since_q;
    wire [W_FCNT-1:0] fire_cnt_d = emit ? fire_cnt_q + 32'd1 : fire_cnt_q;
    // clear acts first, an event of this call sets its flag again
    wire [W_OVL-1:0] ovl_base = i_clear ? 16'd0 : ovl_cnt_q;
    wire [W_OVL-1:0] ovl_d    = (overlap && ovl_base != 16'hffff) ? ovl_base + 16'd1 : ovl_base;

    // ---- stage A: part-speed generator ---------------------------------------------------------
    wire             rate_over = ps_e && (i_ps_inc > INC_MAX);
    wire [W_INC-1:0] inc       = (i_ps_inc > INC_MAX) ? INC_MAX : i_ps_inc;
    wire [W_INC:0]   ph_sum    = {1'b0, ph_q} + {1'b0, inc};
    wire             ps_pulse  = ps_e && ph_sum[W_INC];
    wire [W_INC-1:0] ph_d      = ps_e ? ph_sum[W_INC-1:0] : ph_q;
    wire signed [W_POS-1:0] ps_cnt_d = ps_pulse ? ps_cnt_q + 38'sd1 : ps_cnt_q;
    // minimum spacing: k = 0 shows the previous sample's check and loads; k = 1..16 step k - 1
    wire             sp_load   = ps_e && (sp_k_q == 5'd0);
    wire             sp_step   = ps_e && (sp_k_q != 5'd0);
    wire [W_PROD-1:0] sp_prod  = {sp_hi_q[W_INC-1:0], sp_lo_q};
    wire             spacing_err = sp_load && sp_full_q && sp_mnz_q && ({8'd0, sp_prod} > sp_thr_q);
    wire [W_SPHI-1:0] sp_sh    = sp_hi_q + (sp_m_q[0] ? {1'b0, sp_inc_q} : {W_SPHI{1'b0}});

    // ---- stage A: tracking window --------------------------------------------------------------
    wire signed [W_WIN-1:0] d0 = (!ps_e && mask_e[0]) ? {{(W_WIN-2){i_step0[1]}}, i_step0} : {W_WIN{1'b0}};
    wire signed [W_WIN-1:0] d1 = (!ps_e && mask_e[1]) ? {{(W_WIN-2){i_step1[1]}}, i_step1} : {W_WIN{1'b0}};
    wire signed [W_WIN-1:0] d2 = (!ps_e && mask_e[2]) ? {{(W_WIN-2){i_step2[1]}}, i_step2} : {W_WIN{1'b0}};
    wire rev = ((d0 != 0) && (trav0_q != 0) && (d0[W_WIN-1] != trav0_q[W_WIN-1])) ||
               ((d1 != 0) && (trav1_q != 0) && (d1[W_WIN-1] != trav1_q[W_WIN-1])) ||
               ((d2 != 0) && (trav2_q != 0) && (d2[W_WIN-1] != trav2_q[W_WIN-1]));
    wire signed [W_WIN-1:0] dn0 = (rev ? {W_WIN{1'b0}} : trav0_q) + d0;
    wire signed [W_WIN-1:0] dn1 = (rev ? {W_WIN{1'b0}} : trav1_q) + d1;
    wire signed [W_WIN-1:0] dn2 = (rev ? {W_WIN{1'b0}} : trav2_q) + d2;
    wire [W_WIN-1:0] mg0 = dn0[W_WIN-1] ? -dn0 : dn0;
    wire [W_WIN-1:0] mg1 = dn1[W_WIN-1] ? -dn1 : dn1;
    wire [W_WIN-1:0] mg2 = dn2[W_WIN-1] ? -dn2 : dn2;
    wire kclose = (mg0 >= {1'b0, i_win_k}) || (mg1 >= {1'b0, i_win_k}) || (mg2 >= {1'b0, i_win_k});
    wire [W_S-1:0] s_d = mg0 * mg0 + mg1 * mg1 + mg2 * mg2;
    // window
    wire signed [W_POS-1:0] wp = (i_win_src == 2'd3) ? ps_cnt_d : (i_win_src == 2'd2) ? i_pos2 :
                                 (i_win_src == 2'd1) ? i_pos1 : i_pos0;
    wire inw = !i_win_en || ((i_win_low <= wp) && (wp <= i_win_high));

    // array read addresses for the next call's B1 (from this call's index)
    wire [6:0] rn1 = next_idx(idx_q, len_e);
    wire [6:0] rn2 = next_idx(rn1, len_e);

    // ---- register update -----------------------------------------------------------------------
    always @(posedge i_clk) begin
        if (i_rst) begin
            bad_q <= {64{1'b1}};
            entry0_q <= {W_DIST{1'b0}};
        end else begin
            bad_q <= bad_d;
            if (i_arr_we && i_arr_addr == 6'd0) entry0_q <= i_arr_data;
        end
    end

    // array RAM copies: read before write, no reset
    always @(posedge i_clk) begin
        if (i_arr_we) begin
            arr0[i_arr_addr] <= i_arr_data;
            arr1[i_arr_addr] <= i_arr_data;
            arr2[i_arr_addr] <= i_arr_data;
        end
        rd0_q <= arr0[idx_q[5:0]];
        rd1_q <= arr1[rn1[5:0]];
        rd2_q <= arr2[rn2[5:0]];
        fw0_q <= i_arr_we && (i_arr_addr == idx_q[5:0]);
        fw1_q <= i_arr_we && (i_arr_addr == rn1[5:0]);
        fw2_q <= i_arr_we && (i_arr_addr == rn2[5:0]);
        wd_q <= i_arr_data;
    end

    // chord ROM: registered read (stage R), no reset
    always @(posedge i_clk) begin
        r_chord_q <= rom[a_s_q];
    end

    always @(posedge i_clk) begin
        if (i_rst || !cfg_ok || !i_enable) begin
            // tracking state (pso::reset_track)
            run_q <= 1'b0;
            ps_q <= 1'b0;
            arr_en_q <= 1'b0;
            arr_wrap_q <= 1'b0;
            mask_q <= 3'd0;
            len_q <= 7'd1;
            trav0_q <= {W_WIN{1'b0}};
            trav1_q <= {W_WIN{1'b0}};
            trav2_q <= {W_WIN{1'b0}};
            a_rev_q <= 1'b0;
            a_kclose_q <= 1'b0;
            a_pulse_q <= 1'b0;
            a_inwin_q <= 1'b0;
            a_v_q <= 1'b0;
            a_s_q <= {W_S{1'b0}};
            ph_q <= {W_INC{1'b0}};
            ps_cnt_q <= {W_POS{1'b0}};
            sp_k_q <= 5'd0;
            sp_full_q <= 1'b0;
            sp_mnz_q <= 1'b0;
            sp_inc_q <= {W_INC{1'b0}};
            sp_m_q <= {W_GAP{1'b0}};
            sp_thr_q <= {W_DIST{1'b0}};
            sp_hi_q <= {W_SPHI{1'b0}};
            sp_lo_q <= {W_GAP{1'b0}};
            r_rev_q <= 1'b0;
            r_kclose_q <= 1'b0;
            r_pulse_q <= 1'b0;
            r_inwin_q <= 1'b0;
            r_v_q <= 1'b0;
            b_x_q <= {W_INCR{1'b0}};
            b_y_q <= {W_INCR{1'b0}};
            b_xm0_q <= {W_REM{1'b0}};
            b_ym0_q <= {W_REM{1'b0}};
            b_xm1_q <= {W_REM{1'b0}};
            b_ym1_q <= {W_REM{1'b0}};
            b_inwin_q <= 1'b0;
            b_v_q <= 1'b0;
            b_fire1_q <= 1'b0;
            part_q <= {W_CHORD{1'b0}};
            rem_q <= {W_REM{1'b0}};
            dist_q <= {W_REM{1'b0}};
            idx_q <= 7'd0;
            done_q <= 1'b0;
            timer_q <= {W_PW{1'b0}};
            since_q <= {W_GAP{1'b1}};
            fire_q <= 1'b0;
            emit_q <= 1'b0;
            pulse_q <= 1'b0;
            in_win_q <= 1'b0;
            overlap_q <= 1'b0;
            rate_over_q <= 1'b0;
            spacing_err_q <= 1'b0;
            freq_err_q <= 1'b0;
            ps_pulse_q <= 1'b0;
        end else begin
            run_q <= 1'b1;
            ps_q <= ps_e;
            arr_en_q <= arr_en_e;
            arr_wrap_q <= run_q ? arr_wrap_q : i_arr_wrap;
            mask_q <= mask_e;
            len_q <= len_e;
            // A
            trav0_q <= kclose ? {W_WIN{1'b0}} : dn0;
            trav1_q <= kclose ? {W_WIN{1'b0}} : dn1;
            trav2_q <= kclose ? {W_WIN{1'b0}} : dn2;
            a_rev_q <= rev;
            a_kclose_q <= kclose;
            a_pulse_q <= ps_pulse;
            a_inwin_q <= inw;
            a_v_q <= 1'b1;
            a_s_q <= s_d;
            ph_q <= ph_d;
            ps_cnt_q <= ps_cnt_d;
            if (sp_load) begin
                sp_k_q <= 5'd1;
                sp_full_q <= 1'b1;
                sp_mnz_q <= (i_min_period != 16'd0);
                sp_inc_q <= inc;
                sp_m_q <= i_min_period;
                sp_thr_q <= thr0;
                sp_hi_q <= {W_SPHI{1'b0}};
                sp_lo_q <= {W_GAP{1'b0}};
            end else if (sp_step) begin
                sp_k_q <= (sp_k_q == 5'd16) ? 5'd0 : sp_k_q + 5'd1;
                sp_m_q <= sp_m_q >> 1;
                sp_hi_q <= sp_sh >> 1;
                sp_lo_q <= {sp_sh[0], sp_lo_q[W_GAP-1:1]};
            end
            // R
            r_rev_q <= a_rev_q;
            r_kclose_q <= a_kclose_q;
            r_pulse_q <= a_pulse_q;
            r_inwin_q <= a_inwin_q;
            r_v_q <= a_v_q;
            // B1
            b_x_q <= x;
            b_y_q <= y;
            b_xm0_q <= xm0_d;
            b_ym0_q <= ym0_d;
            b_xm1_q <= xm1_d;
            b_ym1_q <= ym1_d;
            b_inwin_q <= r_inwin_q;
            b_v_q <= r_v_q;
            b_fire1_q <= fire;
            if (!done_q) part_q <= r_kclose_q ? {W_CHORD{1'b0}} : chord;
            // B2
            rem_q <= rem_d;
            dist_q <= dist_d;
            idx_q <= idx_d;
            done_q <= done_d;
            timer_q <= timer_d;
            since_q <= since_d;
            fire_q <= fire;
            emit_q <= emit;
            pulse_q <= (timer_d != 16'd0);
            in_win_q <= b_inwin_q;
            overlap_q <= overlap;
            rate_over_q <= rate_over;
            spacing_err_q <= spacing_err;
            freq_err_q <= freq_err;
            ps_pulse_q <= ps_pulse;
        end
    end

    // counters and sticky flags: kept while enable = 0, cleared by an invalid configuration
    always @(posedge i_clk) begin
        if (i_rst || !cfg_ok) begin
            fire_cnt_q <= {W_FCNT{1'b0}};
            ovl_cnt_q <= {W_OVL{1'b0}};
            overlap_st_q <= 1'b0;
            rate_over_st_q <= 1'b0;
            spacing_st_q <= 1'b0;
            freq_st_q <= 1'b0;
            cfg_err_q <= !i_rst;
        end else if (!i_enable) begin
            ovl_cnt_q <= ovl_base;
            overlap_st_q <= overlap_st_q && !i_clear;
            rate_over_st_q <= rate_over_st_q && !i_clear;
            spacing_st_q <= spacing_st_q && !i_clear;
            freq_st_q <= freq_st_q && !i_clear;
            cfg_err_q <= 1'b0;
        end else begin
            fire_cnt_q <= fire_cnt_d;
            ovl_cnt_q <= ovl_d;
            overlap_st_q <= (overlap_st_q && !i_clear) || overlap;
            rate_over_st_q <= (rate_over_st_q && !i_clear) || rate_over;
            spacing_st_q <= (spacing_st_q && !i_clear) || spacing_err;
            freq_st_q <= (freq_st_q && !i_clear) || freq_err;
            cfg_err_q <= 1'b0;
        end
    end

    assign o_fire         = fire_q;
    assign o_emit         = emit_q;
    assign o_pulse        = pulse_q;
    assign o_in_win       = in_win_q;
    assign o_dist         = dist_q;
    assign o_idx          = idx_q;
    assign o_arr_done     = done_q;
    assign o_fire_cnt     = fire_cnt_q;
    assign o_overlap_cnt  = ovl_cnt_q;
    assign o_overlap      = overlap_q;
    assign o_overlap_st   = overlap_st_q;
    assign o_rate_over    = rate_over_q;
    assign o_rate_over_st = rate_over_st_q;
    assign o_spacing_err  = spacing_err_q;
    assign o_spacing_st   = spacing_st_q;
    assign o_freq_err     = freq_err_q;
    assign o_freq_st      = freq_st_q;
    assign o_ps_pulse     = ps_pulse_q;
    assign o_ps_count     = ps_cnt_q;
    assign o_cfg_err      = cfg_err_q;

endmodule

`default_nettype wire
