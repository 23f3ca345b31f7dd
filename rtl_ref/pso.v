// pso.v — position-synchronised output: vector-distance tracking of up to three axes (chord
// ROM over a tracking window), firing comparator with remainder carry, pulse of programmable
// width, position window, array of firing distances, part-speed pulse generator (24 MHz limit)
// and the sequenced minimum-spacing check.
//
// Reference RTL of hls/pso.h (docs/PSO_COUNTERS.md §2). One rising clock edge = one call of
// pso::step(); every output holds the out_t of that call: a register, except o_ps_count, a
// select of two registers by the last call's pulse (a register). Synchronous
// active-high reset = a freshly constructed lx::pso (every array entry "not written", state in
// reset). A call with an invalid configuration resets everything except the array RAM and its
// "entry below 4 counts" map and raises cfg_err for that call; a call with enable = 0 resets the
// tracking state (counters and sticky flags are kept).
//
// Register stage (§2.2): the register inputs presented at an edge are in force at the next one
// (f_* registers, the reset values after i_rst). The configuration check is formed on the
// presented values (against the bad-entry map after their write) and registered (ok_*_q), so
// the reset of the state is a register plus one gate. The array RAM is written at the edge of
// the call that presents the write (the data are in force, for the model, one call later:
// the reads below forward accordingly).
//
// Stages (registers before the edge; §2.4):
//   A   this call's steps: tracking window (travel D per axis, reversal / |D| >= K closes; the
//       close three LUT levels from registers), the squares D_i^2 of the new travel (hls a_sq);
//       part-speed phase accumulator (clamped to INC_MAX), pulse count; window operands;
//       minimum-spacing shift-add (sample every 17 calls).
//   Q   the ROM address s = sum D_i^2 from A's squares (a carry-save layer and one chain; the
//       address register of the ROM's block RAM: hls rom_.read); the window position (source 3: the
//       pulse count after the pulse of A's call) and edges registered.
//   R   chord ROM (769 x 37 bits, filled at elaboration by the same digit-by-digit square root
//       as hls/pso.h): its data output feeds Y = chord (+1.0 for a generator pulse) - (q_rev ?
//       0 : part), the growth of the estimate; part' = q_kclose ? 0 : chord; the window
//       compares (in 19-bit halves, combined in B1).
//   B1  Y - th for the two prefetched thresholds (entries next, next^2 of the index before
//       the last call's move, or fire_dist; the first operands of a run take the start
//       threshold thr as the first), straight from registers: no select in front of the adds;
//       all 0 while R holds no data. Each a 38-bit add (Y < 2^38) in 19-bit carry-select, its
//       carry picking the upper bits between ~th and -th (the prefetch registers hold ~th).
//   P   the loop operands: Y, and Y - thF for the threshold of the fire after the next (hls:
//       next(idx) of the index after the last call's move), picked from B1's two by "the index
//       moved in one of the last two calls" (a register; at most one of them can, since no two
//       calls in a row fire, §2.7): selects only.
//   B2  the loop on u = value - thr of the entry held: the decision is u >= 0 and no fire in the
//       last call, from registers (u is kept carry-deferred: halves hi, lo of 29 bits, the carry
//       out of lo added into hi at the next update, and a flag "hi[27:0] all ones" formed beside
//       the update without a carry chain: sign = hi[28] ^ (c & ones)); u' = u + (decision ?
//       Y - thF : Y), both sums formed from registers and picked by the decision: one 29-bit
//       chain and a select. A fire (or the run start) takes the next threshold (thr). Array
//       index. The decision goes into registers only (c_fire, the index move).
//   B3  applies the decision of the last call (c_fire): fire / emit, pulse timer, overlap /
//       frequency flags, counters, dist = u (+ thr if it did not fire) resolved from the
//       registered halves, the index and done outputs.
// A step in call t fires in call t + 7.
//
// Array RAM (64 x 56): three copies (one read port each, the write port shared), read in call
// t - 2 at next(idx) .. next^3(idx) of that call. Threshold prefetch: in call t - 1 two of the
// three (picked by the registered index move of call t - 2) are completed with the writes in
// force in calls t - 1 and t (forwarded: the first was written after the read, the second is
// presented in call t - 1), or replaced by fire_dist in force in call t, and registered
// inverted (thn1, thn2: ~ the entries next(idx), next^2(idx) of call t - 1). B1 in call t
// subtracts both from Y; P in call t + 1 picks one with the index moves of calls t - 1 and t
// (at most one of the two moves). The start threshold of a run beginning in the next call
// (fire_dist presented, or entry 0 from a copy register, entry0, with the presented write) is
// registered in every call (st); the threshold register thr loads it in every call without a
// run (so it holds it from run call 1 on; run call 0 reads st).
//
// Widths (pso_cfg): distances Q24.32 (56 unsigned), u (value - thr) and dist 58 signed, chord 37,
// x / y 38, travel 6 signed, K 5, positions 38 signed, part-speed rate Q0.32, pulse width and
// laser minimum period 16, fire counter 32 (wraps), overlap counter 16 (saturates).
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module pso (
    input  wire                            i_clk,
    input  wire                            i_rst,          // synchronous, active high: a fresh lx::pso
    // per-call inputs (pso_in)
    input  wire signed [`LX_W_STEP-1:0]    i_step0,        // tracked axis steps (-1, 0, +1)
    input  wire signed [`LX_W_STEP-1:0]    i_step1,
    input  wire signed [`LX_W_STEP-1:0]    i_step2,
    input  wire signed [`LX_W_POS-1:0]     i_pos0,         // axis positions after the step (window)
    input  wire signed [`LX_W_POS-1:0]     i_pos1,
    input  wire signed [`LX_W_POS-1:0]     i_pos2,
    input  wire [`LX_PSO_W_INC-1:0]        i_ps_inc,       // part-speed command, Q0.32 counts per clock
    // registers (pso_regs)
    input  wire                            i_enable,
    input  wire                            i_part_speed,   // latched at the start of a run
    input  wire [`LX_PSO_N_AXES-1:0]       i_axis_mask,    // latched; != 0 unless part_speed
    input  wire [`LX_PSO_W_K-1:0]          i_win_k,        // tracking window K, 1..16
    input  wire [`LX_PSO_W_DIST-1:0]       i_fire_dist,    // Q24.32 counts, >= 4 counts unless arr_en
    input  wire                            i_arr_en,       // latched
    input  wire [`LX_PSO_W_LEN-1:0]        i_arr_len,      // latched; 1..64 when arr_en
    input  wire                            i_arr_wrap,     // latched
    input  wire                            i_arr_we,       // array write port (every call, also disabled)
    input  wire [`LX_PSO_W_ADDR-1:0]       i_arr_addr,
    input  wire [`LX_PSO_W_DIST-1:0]       i_arr_data,
    input  wire [`LX_PSO_W_PW-1:0]         i_pulse_w,      // pulse width, clocks, >= 1
    input  wire                            i_win_en,
    input  wire [`LX_PSO_W_SRC-1:0]        i_win_src,      // 0..2 axis position, 3 pulse count (part-speed)
    input  wire signed [`LX_W_POS-1:0]     i_win_low,
    input  wire signed [`LX_W_POS-1:0]     i_win_high,
    input  wire [`LX_PSO_W_GAP-1:0]        i_min_period,   // laser minimum period, clocks (0: no check)
    input  wire                            i_clear,        // pulse: clears sticky flags and overlap counter
    // outputs (pso::out_t)
    output wire                            o_fire,
    output wire                            o_emit,
    output wire                            o_pulse,
    output wire                            o_in_win,
    output wire signed [`LX_PSO_W_REM-1:0] o_dist,         // distance since the last fire, Q.32
    output wire [`LX_PSO_W_LEN-1:0]        o_idx,
    output wire                            o_arr_done,
    output wire [`LX_PSO_W_FCNT-1:0]       o_fire_cnt,
    output wire [`LX_PSO_W_OVL-1:0]        o_overlap_cnt,
    output wire                            o_overlap,
    output wire                            o_overlap_st,
    output wire                            o_rate_over,
    output wire                            o_rate_over_st,
    output wire                            o_spacing_err,
    output wire                            o_spacing_st,
    output wire                            o_freq_err,
    output wire                            o_freq_st,
    output wire                            o_ps_pulse,
    output wire signed [`LX_W_POS-1:0]     o_ps_count,
    output wire                            o_cfg_err
);

    // ---- fixed widths (hls: pso_cfg) ---------------------------------------------------------
    localparam integer D_FRAC   = `LX_PSO_D_FRAC;  // fraction bits of every distance
    localparam integer W_DIST   = `LX_PSO_W_DIST;  // Q24.32 unsigned
    localparam integer W_REM    = `LX_PSO_W_REM;   // u (value - thr) and dist, signed
    localparam integer K_MAX    = `LX_PSO_K_MAX;   // longest tracking window
    localparam integer W_K      = `LX_PSO_W_K;
    localparam integer S_MAX    = `LX_PSO_S_MAX;   // 3 K_MAX^2
    localparam integer W_S      = `LX_PSO_W_S;
    localparam integer W_SQ     = 2 * W_K - 1;   // |Dn|^2 <= K_MAX^2 = 2^(2 (W_K - 1))
    localparam integer W_CHORD  = `LX_PSO_W_CHORD;
    localparam integer W_INCR   = `LX_PSO_W_INCR;  // x, y
    localparam integer W_POS    = `LX_W_POS;
    localparam integer W_INC    = `LX_PSO_W_INC;
    localparam integer W_GAP    = `LX_PSO_W_GAP;
    localparam integer W_PW     = `LX_PSO_W_PW;
    localparam integer W_FCNT   = `LX_PSO_W_FCNT;
    localparam integer W_OVL    = `LX_PSO_W_OVL;
    localparam integer W_PROD   = `LX_PSO_W_PROD;  // inc * min_period
    localparam integer W_SPHI   = `LX_PSO_W_SPHI;
    localparam [W_INC-1:0] INC_MAX = 32'd1030792151;  // floor(0.24 * 2^32): 24 MHz
    localparam integer LH       = W_REM / 2;   // 29: halves of u and of the carry-select adds

    // 3-bit compares as gates (no carry chain): v > k for k = 0..7, and a > b
    function [7:0] gt3_therm;
        input [2:0] v;
        begin
            gt3_therm = {1'b0, &v, v[2] & v[1], v[2] & (v[1] | v[0]), v[2], v[2] | (v[1] & v[0]),
                         v[2] | v[1], |v};
        end
    endfunction

    function gt3;
        input [2:0] a, b;
        begin
            gt3 = (a[2] & ~b[2]) | (~(a[2] ^ b[2]) & ((a[1] & ~b[1]) | (~(a[1] ^ b[1]) & a[0] & ~b[0])));
        end
    endfunction

    function [15:0] gt_table;   // bit v: v > k (a 4-bit compare with a constant, as a table)
        input [3:0] k;
        integer v;
        begin
            for (v = 0; v < 16; v = v + 1) gt_table[v] = (v > k);
        end
    endfunction

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
    reg [W_DIST-1:0] arr1 [0:63];
    reg [W_DIST-1:0] arr2 [0:63];
    reg [W_DIST-1:0] arr3 [0:63];
    integer ai;
    initial begin
        for (ai = 0; ai < 64; ai = ai + 1) begin
            arr1[ai] = {W_DIST{1'b0}};
            arr2[ai] = {W_DIST{1'b0}};
            arr3[ai] = {W_DIST{1'b0}};
        end
    end

    // ---- registers ---------------------------------------------------------------------------
    // register stage: the values in force (presented in the last call)
    reg                     f_enable_q, f_part_speed_q, f_arr_en_q, f_arr_wrap_q, f_win_en_q, f_clear_q;
    reg [2:0]               f_axis_mask_q;
    reg [4:0]               f_win_k_q;
    reg                     f_k1_q;       // f_win_k_q <= 1, registered with it (from z1)
    reg [6:0]               f_arr_len_q;
    reg [W_PW-1:0]          f_pulse_w_q;
    reg [1:0]               f_win_src_q;
    reg signed [W_POS-1:0]  f_win_low_q, f_win_high_q;
    reg [W_GAP-1:0]         f_min_period_q;
    reg                     f_we_q;       // the write in force (made in the RAM at the last edge)
    reg [W_DIST-1:0]        f_data_q;
    reg                     ok_a_q, ok_w_q, ok_t_q;   // configuration check of the values in
                                          //   force: K, axes, width / window / threshold
    reg                     ok_ae_q;      // ok_a and enable
    reg [63:0]              bad_q;        // entry below 4 counts (or never written), after the
                                          //   writes presented so far
    reg [W_DIST-1:0]        entry0_q;     // copy of entry 0 (the RAM after the last edge)
    reg [W_DIST-1:0]        rd1_q, rd2_q, rd3_q;   // array read data (BRAM output registers)
    reg                     fw1_q, fw2_q, fw3_q;   // the write presented with the read hit its address
    reg [W_DIST-1:0]        thn1_q, thn2_q;        // thresholds, inverted: ~ entries next(idx),
                                                   //   next^2(idx) of the last call, or ~fire_dist
    reg                     adv_q;        // the last call moved the index
    // copies of adv_q, one per group of its loads (about 60 each instead of about 450 on one
    // net): each is adv and a register that is 1 in every call that can move the index (the
    // valid bits and the check, all 1 while the tracking state runs), so that Yosys keeps them
    // apart (equal flip-flops would be merged into one)
    reg                     adv_g1_q, adv_g2_q;   // the prefetch's g1, g2, pw1, pw2
    reg                     adv_i_q;      //   the index registers' pick (idx_l .. nx4_l)
    reg [1:0]               mv_q;         // P's picks (opF, thF): the index moved in one of the last
                                          //   two calls (at most one of them can, §2.7)
    // run state and latched mode registers
    reg                     run_q, ps_q, arr_en_q, arr_wrap_q;
    reg [2:0]               mask_q;
    reg [6:0]               len_q;
    // stage A
    reg [11:0]              ta_q;         // |D| per axis (4 bits each, axis 0 low)
    reg [2:0]               tp_q, tn_q;   // D > 0, D < 0 per axis
    reg [2:0]               tr_q;         // the tracked axes of this call
    reg [2:0]               gs_q;         // per axis: tracked ? ge1 : ge0 (the close if a step
                                          //   comes on that axis), and K <= 1 on a tracked axis
    reg [2:0]               k1t_q;        //   (the close after a reversal), formed a call ahead
    reg [2:0]               ge0_q, ge1_q; // |D| >= K, |D| + 1 >= K per axis (K in force in this
                                          //   call: formed in the last call with the K presented)
    reg                     a_rev_q, a_kclose_q, a_pulse_q, a_v_q;
    reg [3*W_SQ-1:0]        a_sq_q;       // |Dn|^2 per axis (axis 0 low): the ROM address's terms
    reg                     a_wen_q;      // window of this call: enable, position, edges (the
    reg signed [W_POS-1:0]  a_wp_q, a_wlo_q, a_whi_q;   //   compares are in stage R; source 3,
    reg                     a_w3_q;                      //   the pulse count: ps_cnt itself)
    reg [W_CHORD-1:0]       rom_q;        // ROM data at the address s of the last call's stage Q
                                          //   (block RAM, not reset: masked by q_v)
    reg [W_INC-1:0]         ph_q;
    reg signed [W_POS-1:0]  ps_b_q, ps_i_q;   // pulse count before the last call's pulse
                                          //   (a_pulse), and it + 1: the count is one of the two
    // spacing product
    reg [4:0]               sp_k_q;
    reg                     sp_en_q;      // a sample is held, its min_period != 0 and its
                                          //   threshold < 2^48 (else the product is below it)
    reg                     sp_go_q;      // this call shows a sample's check: sp_load && sp_en
    reg                     sp_gth_q, sp_eqh_q, sp_gtl_q;   // the held sample's product > its
                                          //   threshold, in 24-bit halves: upper >, upper ==,
                                          //   lower > (combined where it is shown)
    reg [W_INC-1:0]         sp_inc_q;
    reg [W_GAP-1:0]         sp_m_q;       // min_period, shifted right once per step
    reg [W_SPHI-1:0]        sp_a_q;       // the addend of the next step: sp_m[0] ? inc : 0 (formed
                                          //   with sp_m's update, so the step is one chain)
    reg [W_PROD-1:0]        sp_thr_q;     // its threshold, low 48 bits
    reg [W_SPHI-1:0]        sp_hi_q;
    reg [W_GAP-1:0]         sp_lo_q;
    // stage Q (the ROM address)
    reg                     q_rev_q, q_kclose_q, q_pulse_q, q_v_q;
    reg                     q_wen_q;      // window enable, position (source 3: the pulse count
    reg signed [W_POS-1:0]  q_w_q, q_wlo_q, q_whi_q;   //   after the pulse of A's call) and edges
    // stage R
    reg [W_INCR-1:0]        r_y_q;        // Y: the growth of the estimate
    reg [W_CHORD-1:0]       part_q;       // chord of the open window
    reg                     r_v_q;
    reg                     r_wen_q;      // window enable, and the window compares in halves:
    reg [5:0]               r_wc_q;       //   hls a_inwin = !a_wen || (lo <= w && w <= hi), below
    // stage B1
    reg [W_INCR-1:0]        p_y_q;
    reg [W_DP-1:0]          p_d1_q, p_d2_q;       // Y - th1, Y - th2 in parts (sub_y)
    reg [W_DIST-1:0]        p_thn1_q, p_thn2_q;   // ~th1, ~th2
    reg                     p_inwin_q, p_v_q;
    // stage P
    reg [W_INCR-1:0]        b_y_q;
    reg [W_REM-1:0]         b_opf0_q;     // Y - thF
    reg [W_DIST-1:0]        b_thf0_q;     // the threshold after a fire (for the index after the
                                          //   last call's decision)
    reg                     b_inwin_q, b_v_q;
    // stage B2 (u carry-deferred: value = (hi + c) * 2^29 + lo, ao = &hi[27:0])
    reg [LH-1:0]            u_hi_q, u_lo_q;
    reg                     u_c_q, u_ao_q;
    reg                     u_v_q, u_inwin_q;
    reg                     e_q;          // u_v && !done
    reg                     tk_q;         // b_v && !c_fire && !done && !stop0 (take = u >= 0 && tk)
    reg [W_DIST-1:0]        thr_q;        // threshold of the next fire (from run call 1 on)
    reg [W_DIST-1:0]        st_q;         // the start threshold of a run beginning in this call
    reg [6:0]               idx_p_q;      // the index before the last call's move (adv_q), and
    reg [6:0]               nx_p_q, nx2_p_q, nx3_p_q, nx4_p_q;   //   next .. next^4 of it (so
                                          //   that a move of the deepest read is a select of
                                          //   registers)
    reg                     done_q;
    reg                     stop0_q;      // a fire ends the array (arr_en, no wrap, the last
                                          //   entry) with the index of this call (a fire never
                                          //   follows a move, so idx_l = idx_p there)
    reg                     c_fire_q, c_inwin_q, c_live_q;   // decision, its window, made while
                                                             //   not done
    reg [LH-1:0]            c_hic_q;      // u of the decision, resolved: hi + c
    reg [LH-1:0]            c_lo_q;       // lo of u
    reg [LH:0]              c_lt_q;       // lo of u + lo of its threshold, with the carry out
    reg                     c_f_q;        // the decision's u >= 0 (its threshold not added)
    reg [W_DIST-LH-1:0]     c_tm_q;       // the threshold's upper bits if it did not fire, else 0
    // stage B3
    reg [W_REM-1:0]         dist_q;
    reg [6:0]               idx_o_q;
    reg                     done_o_q;
    reg [W_PW-1:0]          timer_q;
    // calls since the last emit (hls since_, saturating at 2^16 - 1), held as ~(since + 2) in
    // W_GAP + 1 bits, and the laser-period compare of the next call made one call early (fc):
    // fc = since + 1 < min_period, with the min_period of the next call (the value presented now)
    reg [W_GAP:0]           nsp2_q;
    reg                     fc_q;
    reg [W_FCNT-1:0]        fire_cnt_q;
    reg [W_OVL-1:0]         ovl_cnt_q;
    reg                     overlap_st_q, rate_over_st_q, spacing_st_q, freq_st_q;
    // per-call outputs
    reg                     fire_q, emit_q, pulse_q, in_win_q, overlap_q, rate_over_q;
    reg                     spacing_err_q, freq_err_q, ps_pulse_q, cfg_err_q;

    // ---- array write port and the map of bad entries (after this call's write) ---------------
    wire        wr_bad = (i_arr_data[W_DIST-1:D_FRAC+2] == {(W_DIST-D_FRAC-2){1'b0}});   // data < 4 counts
    wire [63:0] wr_bit = 64'd1 << i_arr_addr;
    wire [63:0] bad_d  = !i_arr_we ? bad_q : wr_bad ? (bad_q | wr_bit) : (bad_q & ~wr_bit);

    // ---- configuration check (pso_config_ok) ---------------------------------------------------
    wire        k_ok    = (i_win_k != 5'd0) && (!i_win_k[4] || (i_win_k[3:0] == 4'd0));
    wire        axes_ok = i_part_speed || (i_axis_mask != 3'd0);
    wire        len_ok  = (i_arr_len != 7'd0) && (!i_arr_len[6] || (i_arr_len[5:0] == 6'd0));
    // entries 0 .. arr_len - 1 as a thermometer code, written as gates (a compare with a constant
    // would be a carry chain each): j < len iff len >= 64, or len[5:3] > j[5:3], or they are
    // equal and len[2:0] > j[2:0]
    wire [63:0] used;
    wire [7:0]  lh_gt = gt3_therm(i_arr_len[5:3]);
    wire [7:0]  ll_gt = gt3_therm(i_arr_len[2:0]);
    genvar ug;
    generate
        for (ug = 0; ug < 64; ug = ug + 1) begin : g_used
            assign used[ug] = i_arr_len[6] || lh_gt[ug / 8] || ((i_arr_len[5:3] == ug / 8) && ll_gt[ug % 8]);
        end
    endgenerate
    // (bad_d & used) == 0 without the written entry's data compare in front of the 64-input OR:
    // the map before the presented write with the written entry masked, and the written entry
    // alone (bad after the write iff wr_bad)
    wire [63:0] hit     = i_arr_we ? wr_bit : 64'd0;
    wire        bad_old = ((bad_q & ~hit & used) != 64'd0);
    wire        bad_new = i_arr_we && wr_bad &&      // the written entry is used: addr < len
                          (i_arr_len[6] || gt3(i_arr_len[5:3], i_arr_addr[5:3]) ||
                           ((i_arr_len[5:3] == i_arr_addr[5:3]) && gt3(i_arr_len[2:0], i_arr_addr[2:0])));
    wire        thr_ok  = i_arr_en ? (len_ok && !bad_old && !bad_new)
                                   : (i_fire_dist[W_DIST-1:D_FRAC+2] != {(W_DIST-D_FRAC-2){1'b0}});
    // win_low <= win_high: the sign of high - low (39 bits) as a carry-select subtract (19-bit low
    // part; the upper 20 bits with borrow 0 and 1)
    wire [20:0] wlo_l = {1'b0, i_win_high[18:0], 1'b1} + {1'b0, ~i_win_low[18:0], 1'b1};  // [20]: no borrow
    wire [19:0] wup0  = {i_win_high[37], i_win_high[37:19]} + {~i_win_low[37], ~i_win_low[37:19]};
    wire [20:0] wup1  = {i_win_high[37], i_win_high[37:19], 1'b1} + {~i_win_low[37], ~i_win_low[37:19], 1'b1};
    wire        win_le = !(wlo_l[20] ? wup1[20] : wup0[19]);
    wire        win_ok  = !i_win_en || (win_le && (i_win_src != 2'd3 || i_part_speed));
    // the check of the presented values, in force (registered) with them in the next call
    // (three registers, so that each part is one gate from its compare; the resets below take
    // them together: one gate of registers)
    wire        ok_a_d   = k_ok && axes_ok && (i_pulse_w != 16'd0);
    // resets of this call: invalid configuration (everything but the RAM), enable = 0 (tracking)
    wire        rst_cfg  = i_rst || !(ok_a_q && ok_w_q && ok_t_q);
    wire        rst_trk  = i_rst || !(ok_ae_q && ok_w_q && ok_t_q);   // rst_cfg || !enable

    // latched modes as seen in this call (the first call of a run latches them)
    wire       ps_e     = run_q ? ps_q : f_part_speed_q;
    wire [2:0] mask_e   = run_q ? mask_q : f_axis_mask_q;
    wire       arr_en_e = run_q ? arr_en_q : f_arr_en_q;
    wire [6:0] len_e    = run_q ? len_q : f_arr_len_q;

    // y - th = y + thn + 1 for y < 2^38 (W_REM bits; thn = ~th, a register): the low 19 bits
    // one chain with carry-in 1, bits 37..19 for carry 0 and 1, and for each the upper 20 bits
    // picked by that part's carry out (nh = -th[55:38], 20 bits, or ~th[55:38] with two ones).
    // Returned in parts, {low carry, low 19 bits, upper 39 bits for carry 1, for carry 0}: the
    // low carry's select is made after the register (sub_fin, in stage P)
    localparam integer W_DP = 2 * W_REM - 18;   // 98: the parts of one difference
    function [W_REM-1:0] sub_fin;
        input [W_DP-1:0] p;
        begin
            sub_fin = p[W_DP-1] ? {p[2*(W_REM-19)-1:W_REM-19], p[W_DP-2:2*(W_REM-19)]}
                                : {p[W_REM-20:0], p[W_DP-2:2*(W_REM-19)]};
        end
    endfunction
    function [W_DP-1:0] sub_y;
        input [W_INCR-1:0] y;
        input [W_DIST-1:0] thn;
        input [19:0]       nh;
        reg [20:0] lo;
        reg [19:0] m0;
        reg [20:0] m1;
        reg [19:0] ih, u0, u1;
        begin
            lo = {1'b0, y[18:0], 1'b1} + {1'b0, thn[18:0], 1'b1};
            m0 = {1'b0, y[37:19]} + {1'b0, thn[37:19]};
            m1 = {1'b0, y[37:19], 1'b1} + {1'b0, thn[37:19], 1'b1};
            ih = {2'b11, thn[W_DIST-1:W_INCR]};
            u0 = m0[19] ? nh : ih;
            u1 = m1[20] ? nh : ih;
            sub_y = {lo[20], lo[19:1], u1, m1[19:1], u0, m0[18:0]};
        end
    endfunction

    // carry-select W_INCR-bit add with carry-in (low 19 bits, upper 19 bits for carry 0 and 1)
    localparam integer LY = W_INCR / 2;
    function [W_INCR-1:0] csel19;
        input [W_INCR-1:0] a, b;
        input              cin;
        reg [LY+1:0]        lo;
        reg [W_INCR-LY-1:0] hi0;
        reg [W_INCR-LY:0]   hi1;
        begin
            lo  = {1'b0, a[LY-1:0], cin} + {1'b0, b[LY-1:0], cin};
            hi0 = a[W_INCR-1:LY] + b[W_INCR-1:LY];
            hi1 = {a[W_INCR-1:LY], 1'b1} + {b[W_INCR-1:LY], 1'b1};
            csel19 = {lo[LY+1] ? hi1[W_INCR-LY:1] : hi0, lo[LY:1]};
        end
    endfunction

    // upper half of u: a + b + c (LH bits, one chain: {a, 1} + {b, c}, whose carry out of bit 0
    // is c; {a, c} + {b, c} put the net c on two inputs of one logic cell, which nextpnr's
    // router could not route: one arc ripped up again and again at some seeds)
    function [LH-1:0] hi_add;
        input [LH-1:0] a, b;
        input          c;
        reg   [LH:0]   t;
        begin
            t = {a, 1'b1} + {b, c};
            hi_add = t[LH:1];
        end
    endfunction

    // bits LH-2..0 of a + b + c all ones, without a carry chain: with p = ~(a ^ b), g = a & b,
    // the sum is all ones iff the carry into each bit is p of that bit: c = p[0] and
    // p[i+1] = g[i] (the carry out of bit i when its carry-in is p[i])
    function ones_lo;
        input [LH-2:0] a, b;
        input          c;
        reg   [LH-2:0] pp, gg;
        begin
            pp = ~(a ^ b);
            gg = a & b;
            ones_lo = (c == pp[0]) && (pp[LH-2:1] == gg[LH-3:0]);
        end
    endfunction

    // (a + off)^2 for a 4-bit a, off = 0, 1: a table of constants, bit-sliced (bit k of the square
    // for every a in bits 16k .. 16k + 15), indexed per bit: one LUT per bit and no multiplier.
    // (A case statement would become a ROM, and Yosys would then move the travel register ta
    // behind it: registers of the squares with the window close as their reset, in series after
    // the close.)
    function [16*9-1:0] sq_slices;   // constant function (elaboration only)
        input integer off;
        integer v, k;
        reg [8:0] q;
        begin
            sq_slices = {16*9{1'b0}};
            for (v = 0; v < 16; v = v + 1) begin
                q = (v + off) * (v + off);
                for (k = 0; k < 9; k = k + 1) sq_slices[16*k + v] = q[k];
            end
        end
    endfunction
    localparam [16*9-1:0] SQ0_T = sq_slices(0);
    localparam [16*9-1:0] SQ1_T = sq_slices(1);

    function [8:0] sq4;     // a * a
        input [3:0] a;
        integer k;
        begin
            for (k = 0; k < 9; k = k + 1) sq4[k] = SQ0_T[16*k + a];
        end
    endfunction

    function [8:0] sq4p1;   // (a + 1)^2
        input [3:0] a;
        integer k;
        begin
            for (k = 0; k < 9; k = k + 1) sq4p1[k] = SQ1_T[16*k + a];
        end
    endfunction

    function [6:0] next_idx;   // next array index (0 after the last entry)
        input [6:0] i;
        input [6:0] len;
        reg   [7:0] n;
        begin
            n = {1'b0, i} + 8'd1;
            next_idx = (n >= {1'b0, len}) ? 7'd0 : n[6:0];
        end
    endfunction

    // ---- array index ---------------------------------------------------------------------------
    // The index of this call (after the decisions up to the last call) is idx_l: the registers
    // idx_p .. nx4_p hold it before the last call's move and adv_q is that move, so a decision
    // goes into one register (adv_q) and not into the index registers.
    wire [6:0]       idx_l  = adv_i_q ? nx_p_q : idx_p_q;
    wire [6:0]       nx_l   = adv_i_q ? nx2_p_q : nx_p_q;
    wire [6:0]       nx2_l  = adv_i_q ? nx3_p_q : nx2_p_q;
    wire [6:0]       nx3_l  = adv_i_q ? nx4_p_q : nx3_p_q;
    wire [6:0]       nx4_l  = adv_i_q ? next_idx(nx4_p_q, len_q) : nx4_p_q;

    // ---- threshold prefetch (for the next call's B1) --------------------------------------------
    // read data of the last call (addresses next(idx) .. next^3(idx) of that call), the write
    // presented with the read forwarded (it was made after the read: read-before-write),
    // shifted by one entry when the last call moved the index: entries next(idx), next^2(idx)
    // of this call, after the write in force in this call
    wire [W_DIST-1:0] e1 = fw1_q ? f_data_q : rd1_q;
    wire [W_DIST-1:0] e2 = fw2_q ? f_data_q : rd2_q;
    wire [W_DIST-1:0] e3 = fw3_q ? f_data_q : rd3_q;
    wire [W_DIST-1:0] g1 = adv_g1_q ? e2 : e1;
    wire [W_DIST-1:0] g2 = adv_g2_q ? e3 : e2;
    // the write presented in this call (in force in the next) forwarded: its address compared
    // with both index registers, picked by adv_q after the compare; the forward is the last
    // select (pwk: the write hits entry k of the next call in array mode; th1 of the run's first
    // operands is the start threshold)
    wire              nf    = q_v_q && !r_v_q;   // the next call's B1 makes the run's first operands
    wire              pwe   = i_arr_we && arr_en_e;
    wire              eq1   = (i_arr_addr == nx_p_q[5:0]);
    wire              eq2   = (i_arr_addr == nx2_p_q[5:0]);
    wire              eq3   = (i_arr_addr == nx3_p_q[5:0]);
    wire              pw1   = pwe && !nf && (adv_g1_q ? eq2 : eq1);
    wire              pw2   = pwe && (adv_g2_q ? eq3 : eq2);
    // array mode of the next call (a run's calls 1, 2, ..: the latched mode), else fire_dist
    // presented now; the first operands of a run take the start threshold thr (th1, picked
    // with adv_q = 0)
    wire [W_DIST-1:0] q1    = nf ? thr_q : arr_en_e ? g1 : i_fire_dist;
    wire [W_DIST-1:0] q2    = arr_en_e ? g2 : i_fire_dist;
    wire [W_DIST-1:0] th1_d = pw1 ? i_arr_data : q1;
    wire [W_DIST-1:0] th2_d = pw2 ? i_arr_data : q2;
    // the start threshold of a run beginning in the next call: fire_dist presented now, or entry 0
    // after the write presented now (registered as st_q, the presented values' path ends there;
    // thr_q loads st_q in every call without a run, so it holds the start threshold from run
    // call 1 on, and run call 0, whose spacing sample takes the threshold, reads st_q)
    wire [W_DIST-1:0] thr_st = i_arr_en ? ((i_arr_we && i_arr_addr == 6'd0) ? i_arr_data : entry0_q)
                                        : i_fire_dist;
    wire [W_DIST-1:0] thr_now = run_q ? thr_q : st_q;   // the threshold of the next fire

    // ---- stage B1 ------------------------------------------------------------------------------
    // Y - th for the two prefetched thresholds (entries next(idx), next^2(idx) of the last
    // call's index: the candidates of hls for this call's index, next, next^2, are picked from
    // them by the last call's move in P). Y - th = Y + ~th + 1. Y < 2^38, so bits 57..38
    // are {2'b11, ~th[55:38]} plus the carry out of bit 37: that part for carry 1 (-th[55:38])
    // is formed from the prefetch registers beside the add, and the add itself is 38 bits in
    // carry-select (19-bit chains)
    wire [19:0]       nh1    = {2'b11, thn1_q[W_DIST-1:W_INCR]} + 20'd1;
    wire [19:0]       nh2    = {2'b11, thn2_q[W_DIST-1:W_INCR]} + 20'd1;
    wire [W_DP-1:0]   d1_d   = sub_y(r_y_q, thn1_q, nh1);
    wire [W_DP-1:0]   d2_d   = sub_y(r_y_q, thn2_q, nh2);
    wire              b_clr  = rst_trk || !r_v_q;   // no operands before R holds data

    // ---- stage P -------------------------------------------------------------------------------
    // hls: B1's candidates next, next^2 of the index before the move of call t - 1 are
    // p_d(1 + m1), p_d(2 + m1), m1 = that move; P picks one of them by the move of the last call
    // (m0): p_d(1 + m1 + m0), m1 + m0 <= 1 (no fire in two calls in a row), so the pick is the
    // register mv = m1 | m0: the operand for the index after the last call's move (a fire in B2
    // never follows a move)
    wire [W_REM-1:0]  opf0_d = mv_q[0] ? sub_fin(p_d2_q) : sub_fin(p_d1_q);   // (the low carry's
                                                   //   select of B1's difference, then the pick)
    wire [W_DIST-1:0] thf0_d = ~(mv_q[1] ? p_thn2_q : p_thn1_q);
    wire              pb_clr = rst_trk || !p_v_q;

    // ---- stage B2: the loop ----------------------------------------------------------------------
    // u = (hi + c) * 2^29 + lo; its sign is hi[28] flipped by the deferred carry iff hi[27:0] is
    // all ones (u_ao): one LUT of registers with c_fire. Both sums are formed from registers and
    // picked by the decision.
    // (and no fire in the call after a fire, §2.7: with thresholds >= 4 counts u < 0 there, so
    // this never acts on a legal configuration; it also means a fire never follows a move of the
    // last call, so one operand, b_opf0, is enough)
    wire             pos    = !(u_hi_q[LH-1] ^ (u_c_q & u_ao_q)) && !c_fire_q;   // u >= 0, no fire
    wire [W_DIST-1:0] thf   = b_thf0_q;
    wire [LH-1:0]    yhi    = {{(2*LH-W_INCR){1'b0}}, b_y_q[W_INCR-1:LH]};
    wire [LH:0]      sf_lo  = {1'b0, u_lo_q} + {1'b0, b_opf0_q[LH-1:0]};
    wire [LH-1:0]    sf_hi  = hi_add(u_hi_q, b_opf0_q[W_REM-1:LH], u_c_q);
    wire             sf_ao  = ones_lo(u_hi_q[LH-2:0], b_opf0_q[W_REM-2:LH], u_c_q);
    wire [LH:0]      sn_lo  = {1'b0, u_lo_q} + {1'b0, b_y_q[LH-1:0]};
    wire [LH-1:0]    sn_hi  = hi_add(u_hi_q, yhi, u_c_q);
    wire             sn_ao  = ones_lo(u_hi_q[LH-2:0], yhi[LH-2:0], u_c_q);
    wire             dec    = e_q && pos;                      // u_v && !done && u >= 0
    // u resolved for dist (B3): hi + c, beside the loop
    wire [LH-1:0]    u_hic  = u_hi_q + {{(LH-1){1'b0}}, u_c_q};
    wire [LH:0]      ut_lo  = {1'b0, u_lo_q} + {1'b0, thr_q[LH-1:0]};   // dist without a fire: low half
    // The index moves to next(idx) (idx_l .. nx4_l above); idx is the last entry iff
    // next(idx) = 0: "a fire here ends the array" is formed a call ahead (stop0, a register) for
    // the index without the last call's move (a fire never follows a move)
    wire             done_c = stop0_q;
    wire             adv_c  = arr_en_q && !done_c;
    wire             adv    = dec && adv_c;
    wire             done_d = done_q || (dec && done_c);
    // a fire (or the run start) takes the next threshold: b_v && pos && !done && !done_c, i.e. the
    // sign of u and tk = b_v && !c_fire && !done && !stop0, a register formed in the last call,
    // so that the enable of the 56 threshold flip-flops is one LUT of registers (with the reset)
    wire             usign  = !(u_hi_q[LH-1] ^ (u_c_q & u_ao_q));   // u >= 0
    wire             take   = usign && tk_q;
    // a call that resets the tracking state: next(0) .. next^4(0) for the length presented (in
    // force in the next call, which may start a run and latch it)
    wire [6:0]       nx_0   = (i_arr_len > 7'd1) ? 7'd1 : 7'd0;
    wire [6:0]       nx2_0  = (i_arr_len > 7'd2) ? 7'd2 : 7'd0;
    wire [6:0]       nx3_0  = (i_arr_len > 7'd3) ? 7'd3 : (i_arr_len == 7'd2) ? 7'd1 : 7'd0;
    wire [6:0]       nx4_0  = (i_arr_len > 7'd4) ? 7'd4 : (i_arr_len == 7'd3) ? 7'd1 : 7'd0;
    // stop0 of the next call: the latched modes (or the ones in force in the next call
    // when it starts a run) and next(idx) = 0 for the index registers written now
    wire             stop_m = run_q ? (arr_en_q && !arr_wrap_q) : (f_arr_en_q && !f_arr_wrap_q);
    wire             stop0_d = stop_m && (nx_l == 7'd0);

    // ---- stage B3: the decision of the last call (registers only) ------------------------------
    wire             fire   = c_fire_q;
    wire             emit   = fire && c_inwin_q;
    wire             overlap  = emit && (timer_q != 16'd0);
    // (since + 1 < min_period implies min_period != 0)
    wire             freq_err = emit && fc_q;
    wire [W_PW-1:0]  timer_n  = (timer_q != 16'd0) ? timer_q - 16'd1 : 16'd0;   // no emit
    wire [W_PW-1:0]  timer_d  = emit ? f_pulse_w_q : timer_n;
    wire             pulse_d  = emit ? (f_pulse_w_q != 16'd0) : (timer_n != 16'd0);
    // since' = 0 after an emit: 1 < min_period'; since' = since + 1: since + 2 < min_period', the
    // carry of min_period' + ~(since + 2) (one chain from a register and the presented value);
    // since saturated: 2^16 < min_period' never
    localparam [W_GAP:0] NSP2_MAX = ~({1'b0, {W_GAP{1'b1}}} + {{(W_GAP-1){1'b0}}, 2'd2});
    localparam [W_GAP:0] NSP2_TWO = ~{{(W_GAP-1){1'b0}}, 2'd2};
    wire [W_GAP+1:0] fc_s     = {2'b00, i_min_period} + {1'b0, nsp2_q};
    wire             sat      = nsp2_q == NSP2_MAX;
    wire [W_GAP:0]   nsp2_d   = emit ? NSP2_TWO : sat ? nsp2_q : nsp2_q - {{W_GAP{1'b0}}, 1'b1};
    wire             fc_d     = emit ? (i_min_period[W_GAP-1:1] != {(W_GAP-1){1'b0}})
                                     : (!sat && fc_s[W_GAP+1]);
    wire [W_FCNT-1:0] fire_cnt_d = emit ? fire_cnt_q + 32'd1 : fire_cnt_q;
    // clear acts first, an event of this call sets its flag again
    wire [W_OVL-1:0] ovl_base = f_clear_q ? 16'd0 : ovl_cnt_q;
    wire [W_OVL-1:0] ovl_d    = (overlap && ovl_base != 16'hffff) ? ovl_base + 16'd1 : ovl_base;
    // distance after the fire: u of that decision, plus its threshold if it did not fire
    // (the low half summed in B2: the upper half one chain with the carry from a register)
    wire [LH-1:0]    dist_lo  = c_f_q ? c_lo_q : c_lt_q[LH-1:0];
    wire             dist_c   = !c_f_q && c_lt_q[LH];
    wire [W_REM-1:0] dist_n   = {hi_add(c_hic_q, {{(W_REM-W_DIST){1'b0}}, c_tm_q}, dist_c), dist_lo};

    // ---- stage A: part-speed generator ---------------------------------------------------------
    // the clamp compare and the two phase sums side by side (no add after the compare)
    // (the compare with the constant INC_MAX without a carry chain: per nibble "greater" as a
    // table of the nibble and "equal", combined in a tree of gates; the command's sum in
    // carry-select 16-bit halves)
    (* keep *) wire [7:0] nb_gt, nb_eq;   // (kept nets: the tree in four LUT levels)
    genvar nb;
    generate
        for (nb = 0; nb < 8; nb = nb + 1) begin : g_nib
            wire [15:0] gtab = gt_table(INC_MAX[4*nb+3:4*nb]);
            assign nb_gt[nb] = gtab[i_ps_inc[4*nb+3:4*nb]];
            assign nb_eq[nb] = (i_ps_inc[4*nb+3:4*nb] == INC_MAX[4*nb+3:4*nb]);
        end
    endgenerate
    // pairs of nibbles, then pairs of pairs: greater = the upper greater, or the upper equal
    // and the lower greater
    (* keep *) wire [3:0] p1_gt, p1_eq;
    (* keep *) wire [1:0] p2_gt;
    (* keep *) wire       p2_eq_hi;
    assign p1_gt    = {nb_gt[7] | (nb_eq[7] & nb_gt[6]), nb_gt[5] | (nb_eq[5] & nb_gt[4]),
                       nb_gt[3] | (nb_eq[3] & nb_gt[2]), nb_gt[1] | (nb_eq[1] & nb_gt[0])};
    assign p1_eq    = {nb_eq[7] & nb_eq[6], nb_eq[5] & nb_eq[4], nb_eq[3] & nb_eq[2], nb_eq[1] & nb_eq[0]};
    assign p2_gt    = {p1_gt[3] | (p1_eq[3] & p1_gt[2]), p1_gt[1] | (p1_eq[1] & p1_gt[0])};
    assign p2_eq_hi = p1_eq[3] & p1_eq[2];
    wire             over      = p2_gt[1] | (p2_eq_hi & p2_gt[0]);   // i_ps_inc > INC_MAX
    // the flag from a compare of its own, a carry chain (i_ps_inc + ~INC_MAX carries out iff
    // i_ps_inc > INC_MAX), so that the flag's path and the phase's select are not one tree with
    // a fanout of about 70
    wire [W_INC:0]   ov_c      = {1'b0, i_ps_inc} + {1'b0, ~INC_MAX};
    wire             rate_over = ps_e && ov_c[W_INC];
    wire [W_INC-1:0] inc       = over ? INC_MAX : i_ps_inc;
    wire [16:0]      pi_lo     = {1'b0, ph_q[15:0]} + {1'b0, i_ps_inc[15:0]};
    wire [16:0]      pi_hi0    = {1'b0, ph_q[31:16]} + {1'b0, i_ps_inc[31:16]};
    wire [17:0]      pi_hi1    = {1'b0, ph_q[31:16], 1'b1} + {1'b0, i_ps_inc[31:16], 1'b1};
    wire [W_INC:0]   ph_in     = {pi_lo[16] ? pi_hi1[17:1] : pi_hi0, pi_lo[15:0]};   // ph + i_ps_inc
    // ph + INC_MAX likewise in 16-bit halves (carry-select)
    wire [16:0]      pm_lo     = {1'b0, ph_q[15:0]} + {1'b0, INC_MAX[15:0]};
    wire [16:0]      pm_hi0    = {1'b0, ph_q[31:16]} + {1'b0, INC_MAX[31:16]};
    wire [17:0]      pm_hi1    = {1'b0, ph_q[31:16], 1'b1} + {1'b0, INC_MAX[31:16], 1'b1};
    wire [W_INC:0]   ph_max    = {pm_lo[16] ? pm_hi1[17:1] : pm_hi0, pm_lo[15:0]};
    wire [W_INC:0]   ph_sum    = over ? ph_max : ph_in;
    // the carries alone (each a pick of two chain outputs by the low half's carry), so that the
    // pulse is one gate after them
    wire             c_in      = pi_lo[16] ? pi_hi1[17] : pi_hi0[16];
    wire             c_max     = pm_lo[16] ? pm_hi1[17] : pm_hi0[16];
    wire             ps_pulse  = ps_e && (over ? c_max : c_in);
    // (the phase runs in every call: it is only used in a part-speed run and reset with the
    // tracking state, and part_speed is latched for the run; no clock enable behind the clamp)
    wire [W_INC-1:0] ph_d      = ph_sum[W_INC-1:0];
    // The pulse count after the last call (hls ps_count) is picked from two registers by the
    // last call's pulse (a_pulse): the pulse of this call goes into one flip-flop only, and the
    // count's update is a select and an increment of registers.
    wire signed [W_POS-1:0] ps_cnt   = a_pulse_q ? ps_i_q : ps_b_q;
    // minimum spacing: k = 0 shows the previous sample's check and loads; k = 1..16 step k - 1
    wire             sp_load   = ps_e && (sp_k_q == 5'd0);
    wire             sp_step   = ps_e && (sp_k_q != 5'd0);
    wire [W_PROD-1:0] sp_prod  = {sp_hi_q[W_INC-1:0], sp_lo_q};
    // The load call also makes step 0 (hi starts at 0: a select, no add), calls k = 1..15 make
    // steps 1..15, so the product is complete one call early and call k = 16 registers the
    // compare in 24-bit halves (sp_gth, sp_eqh, sp_gtl); the sample call shows it. (hls: steps
    // 0..15 in calls 1..16; the same product and flag.)
    wire             sp_gt       = sp_gth_q || (sp_eqh_q && sp_gtl_q);   // product > threshold
    wire             spacing_err = sp_go_q && sp_gt;
    wire [W_SPHI-1:0] sp_h0    = f_min_period_q[0] ? {1'b0, inc} : {W_SPHI{1'b0}};   // step 0
    wire [W_SPHI-1:0] sp_sh    = sp_hi_q + sp_a_q;   // sp_a = sp_m[0] ? inc : 0

    // ---- stage A: tracking window -------------------------------------------------------------
    // Per axis the travel D is kept as |D| (ta, 0..15: a window closes when |D| reaches K <= 16)
    // and its sign (tp: D > 0, tn: D < 0), so the call needs no add before the decisions:
    //   rev_i  = step +1 against D < 0, or step -1 against D > 0 (an untracked axis has D = 0)
    //   |Dn_i| = (rev ? 0 : |D_i|) + |d_i|, and its square = rev ? |d_i| : (|d_i| ? (|D_i| + 1)^2
    //            : |D_i|^2) (squares of the 4-bit register: LUTs)
    //   kclose = some |Dn_i| >= K (compares of the register with K, picked by rev and the move)
    // (compares with a constant as bit logic: Yosys maps them to a carry chain with an inverter
    // per bit; K <= 1 is a register beside K)
    wire       k1 = f_k1_q;
    // the compares with K of the next call (K presented now) for the values |D| can take next:
    // 0, 1 (after a close or a reversal), |D|, |D| + 1 (registered as ge0, ge1 with the new |D|)
    wire       z0 = (i_win_k == 5'd0);
    wire       z1 = (i_win_k[4:1] == 4'd0);
    wire       z2 = (i_win_k[4:2] == 3'd0) && !(i_win_k[1] && i_win_k[0]);
    wire [2:0] stp = {i_step2 == 2'sd1, i_step1 == 2'sd1, i_step0 == 2'sd1};
    wire [2:0] stm = {i_step2 == -2'sd1, i_step1 == -2'sd1, i_step0 == -2'sd1};
    // tracked axes (hls: run ? mask & !ps : the values in force), a register: loaded while the
    // tracking state is in reset with the values presented (in force in the next call, which
    // may start the run and latch them), then kept for the run
    wire [2:0] tr  = tr_q;
    // (kept nets, so that the close is three LUT levels: rev_i and the per-axis closes; rev and
    // the two closes; the pick)
    (* keep *) wire [2:0] rev_i;
    (* keep *) wire       rev;
    assign rev_i = (stp & tn_q) | (stm & tp_q);
    assign rev   = |rev_i;
    wire [2:0] up  = stp & tr;
    wire [2:0] dw  = stm & tr;
    wire [2:0] mv  = up | dw;
    wire [2:0] nz  = stp | stm;   // a step on the axis, tracked or not
    wire [8:0] sqs [0:2];
    wire [2:0] kc;
    wire [3:0] ta_n [0:2];
    wire [2:0] p0, p1, p2;   // |D| >= K, |D| + 1 >= K, |D| + 2 >= K for the K presented
    genvar ax;
    generate
        for (ax = 0; ax < 3; ax = ax + 1) begin : g_axis
            wire [3:0] a    = ta_q[4*ax+3:4*ax];
            wire [8:0] sq0  = sq4(a);                 // |D|^2 and (|D| + 1)^2: one LUT per bit
            wire [8:0] sq1  = sq4p1(a);
            wire [4:0] magn = (rev ? 5'd0 : {1'b0, a}) + {4'd0, mv[ax]};
            assign sqs[ax]  = mv[ax] ? sq1 : sq0;     // without a reversal
            assign kc[ax]   = nz[ax] ? gs_q[ax] : ge0_q[ax];   // the close without a reversal
            assign p0[ax]   = ({1'b0, a} >= i_win_k);
            assign p1[ax]   = ({1'b0, a} + 5'd1 >= i_win_k);
            assign p2[ax]   = ({1'b0, a} + 5'd2 >= i_win_k);
            assign ta_n[ax] = magn[3:0];
        end
    endgenerate
    // after a reversal |Dn_i| = |d_i| <= 1: a close iff K <= 1 and an axis moves (K = 0 is an
    // invalid configuration, never in force in a run); the decision last, on rev
    // (three LUT levels from registers: rev_i, then rev and the two closes, then the pick)
    (* keep *) wire kc_r;   // the close after a reversal
    (* keep *) wire kc_n;   // the close without one
    assign kc_r = |(k1t_q & nz);
    assign kc_n = |kc;
    wire           kclose = rev ? kc_r : kc_n;
    // after a reversal s is the number of moving axes; the pick on rev after the sum
    wire [3*W_SQ-1:0] sq_d = rev ? {8'd0, mv[2], 8'd0, mv[1], 8'd0, mv[0]} : {sqs[2], sqs[1], sqs[0]};
    // stage Q: the ROM address s = sum |Dn_i|^2 from the registered squares (a 3:2 carry-save
    // layer, then one chain)
    wire [W_SQ-1:0] sq_0 = a_sq_q[W_SQ-1:0], sq_1 = a_sq_q[2*W_SQ-1:W_SQ], sq_2 = a_sq_q[3*W_SQ-1:2*W_SQ];
    wire [W_SQ-1:0] s_x = sq_0 ^ sq_1 ^ sq_2;
    wire [W_SQ-1:0] s_c = (sq_0 & sq_1) | (sq_0 & sq_2) | (sq_1 & sq_2);
    wire [W_S-1:0] s_d    = {1'b0, s_x} + {s_c, 1'b0};
    wire [11:0]    ta_d   = kclose ? 12'd0 : {ta_n[2], ta_n[1], ta_n[0]};
    wire [2:0]     tp_d   = (up | (tp_q & {3{!rev}})) & {3{!kclose}};
    wire [2:0]     tn_d   = (dw | (tn_q & {3{!rev}})) & {3{!kclose}};
    // ge0 / ge1 of the next call for |D|' = 0 (close), mv (reversal), |D| + mv
    wire [2:0]     ge0_d  = kclose ? {3{z0}} : rev ? ((mv & {3{z1}}) | (~mv & {3{z0}}))
                                                   : ((mv & p1) | (~mv & p0));
    wire [2:0]     ge1_d  = kclose ? {3{z1}} : rev ? ((mv & {3{z2}}) | (~mv & {3{z1}}))
                                                   : ((mv & p2) | (~mv & p1));
    // window
    wire signed [W_POS-1:0] wp = (f_win_src_q == 2'd2) ? i_pos2 : (f_win_src_q == 2'd1) ? i_pos1 : i_pos0;
    // (the compares are made in stage R from Q's registered operands: a_inwin of hls/ is
    // !a_wen || (a_wlo <= a_wp && a_wp <= a_whi))
    // (source 3: the count after the last call's pulse is ps_cnt now)
    wire signed [W_POS-1:0] a_w = a_w3_q ? ps_cnt : a_wp_q;
    // Each compare as a 19-bit upper part (signed: <, <=) and a 19-bit lower part (unsigned <=),
    // registered in R and combined in B1 (the window result is used in B3):
    //   lo <= w  iff  lo_u < w_u || (lo_u <= w_u && lo_l <= w_l), and w <= hi likewise
    // (stage Q registers the position, stage R compares, B1 combines)
    wire [5:0] r_wc_d = {($signed(q_wlo_q[37:19]) <  $signed(q_w_q[37:19])),
                         ($signed(q_wlo_q[37:19]) <= $signed(q_w_q[37:19])),
                         (q_wlo_q[18:0] <= q_w_q[18:0]),
                         ($signed(q_w_q[37:19]) <  $signed(q_whi_q[37:19])),
                         ($signed(q_w_q[37:19]) <= $signed(q_whi_q[37:19])),
                         (q_w_q[18:0] <= q_whi_q[18:0])};
    wire b_inwin_d = r_v_q && (!r_wen_q || ((r_wc_q[5] || (r_wc_q[4] && r_wc_q[3])) &&
                                            (r_wc_q[2] || (r_wc_q[1] && r_wc_q[0]))));

    // ---- stage R: the growth of the estimate from the ROM data -----------------------------------
    // rom_q is ROM[s] of the last call's stage Q while q_v = 1 (the call before ran); while q_v = 0
    // (a run's first call, or no run) Y and part are stored as 0, as hls (stage R masked by q_v).
    // Y = chord + one - (q_rev ? 0 : part) = cp + ~pm + 1 (a generator pulse, 1.0 = bit 32, only
    // comes with chord 0 and part 0, so chord + one = chord | one)
    wire [W_INCR-1:0]  cp  = {1'b0, rom_q | {q_pulse_q, {D_FRAC{1'b0}}}};
    wire [W_INCR-1:0]  pm  = {1'b0, q_rev_q ? {W_CHORD{1'b0}} : part_q};
    wire [W_INCR-1:0]  y_d = csel19(cp, ~pm, 1'b1);
    wire [W_CHORD-1:0] part_d = q_kclose_q ? {W_CHORD{1'b0}} : rom_q;
    wire               r_clr  = rst_trk || !q_v_q;

    // ---- register update -----------------------------------------------------------------------
    // register stage (reset values of pso_regs after i_rst), the check, the bad-entry map
    always @(posedge i_clk) begin
        if (i_rst) begin
            f_enable_q <= 1'b0;
            f_part_speed_q <= 1'b0;
            f_axis_mask_q <= 3'd3;
            f_win_k_q <= 5'd16;
            f_k1_q <= 1'b0;
            f_arr_en_q <= 1'b0;
            f_arr_len_q <= 7'd1;
            f_arr_wrap_q <= 1'b0;
            f_pulse_w_q <= 16'd10;
            f_win_en_q <= 1'b0;
            f_win_src_q <= 2'd0;
            f_win_low_q <= {W_POS{1'b0}};
            f_win_high_q <= {W_POS{1'b0}};
            f_min_period_q <= {W_GAP{1'b0}};
            f_clear_q <= 1'b0;
            f_we_q <= 1'b0;
            ok_a_q <= 1'b1;                   // the reset values are a legal configuration
            ok_w_q <= 1'b1;
            ok_t_q <= 1'b1;
            ok_ae_q <= 1'b0;
            bad_q <= {64{1'b1}};
            entry0_q <= {W_DIST{1'b0}};
        end else begin
            f_enable_q <= i_enable;
            f_part_speed_q <= i_part_speed;
            f_axis_mask_q <= i_axis_mask;
            f_win_k_q <= i_win_k;
            f_k1_q <= z1;
            f_arr_en_q <= i_arr_en;
            f_arr_len_q <= i_arr_len;
            f_arr_wrap_q <= i_arr_wrap;
            f_pulse_w_q <= i_pulse_w;
            f_win_en_q <= i_win_en;
            f_win_src_q <= i_win_src;
            f_win_low_q <= i_win_low;
            f_win_high_q <= i_win_high;
            f_min_period_q <= i_min_period;
            f_clear_q <= i_clear;
            f_we_q <= i_arr_we;
            ok_a_q <= ok_a_d;
            ok_w_q <= win_ok;
            ok_t_q <= thr_ok;
            ok_ae_q <= ok_a_d && i_enable;
            bad_q <= bad_d;
            if (i_arr_we && i_arr_addr == 6'd0) entry0_q <= i_arr_data;
        end
    end

    // array RAM copies: written at the edge of the call that presents the write, read before
    // write, no reset
    always @(posedge i_clk) begin
        if (i_arr_we) begin
            arr1[i_arr_addr] <= i_arr_data;
            arr2[i_arr_addr] <= i_arr_data;
            arr3[i_arr_addr] <= i_arr_data;
        end
        rd1_q <= arr1[nx_l[5:0]];
        rd2_q <= arr2[nx2_l[5:0]];
        rd3_q <= arr3[nx3_l[5:0]];
        fw1_q <= i_arr_we && (i_arr_addr == nx_l[5:0]);
        fw2_q <= i_arr_we && (i_arr_addr == nx2_l[5:0]);
        fw3_q <= i_arr_we && (i_arr_addr == nx3_l[5:0]);
        f_data_q <= i_arr_data;
        thn1_q <= ~th1_d;
        thn2_q <= ~th2_d;
    end

    // chord ROM: the block RAM registers this call's address s (stage Q), its data is used in
    // the next call (stage R); no reset
    always @(posedge i_clk) begin
        rom_q <= rom[s_d];
    end

    // stage R registers: cleared with the tracking state and in a call without ROM data
    always @(posedge i_clk) begin
        if (r_clr) begin
            r_y_q <= {W_INCR{1'b0}};
            part_q <= {W_CHORD{1'b0}};
        end else begin
            r_y_q <= y_d;
            part_q <= part_d;
        end
    end

    // stage B1 registers: cleared with the tracking state and while R holds no data (the
    // thresholds are not: they are used only by a take, which needs valid operands)
    always @(posedge i_clk) begin
        if (b_clr) begin
            p_y_q <= {W_INCR{1'b0}};
            p_d1_q <= {W_DP{1'b0}};
            p_d2_q <= {W_DP{1'b0}};
        end else begin
            p_y_q <= r_y_q;
            p_d1_q <= d1_d;
            p_d2_q <= d2_d;
        end
        p_thn1_q <= thn1_q;
        p_thn2_q <= thn2_q;
    end

    // stage P registers: cleared with the tracking state and while B1 holds no data
    always @(posedge i_clk) begin
        if (pb_clr) begin
            b_y_q <= {W_INCR{1'b0}};
            b_opf0_q <= {W_REM{1'b0}};
        end else begin
            b_y_q <= p_y_q;
            b_opf0_q <= opf0_d;
        end
        b_thf0_q <= thf0_d;
    end

    // the threshold of the next fire: the start threshold while the tracking state is in reset,
    // then taken at each fire
    always @(posedge i_clk) begin
        st_q <= thr_st;
        if (!run_q) thr_q <= st_q;
        else if (take) thr_q <= thf;
    end

    always @(posedge i_clk) begin
        if (rst_trk) begin
            // tracking state (pso::reset_track)
            run_q <= 1'b0;
            ps_q <= 1'b0;
            arr_en_q <= 1'b0;
            arr_wrap_q <= 1'b0;
            mask_q <= 3'd0;
            len_q <= 7'd1;
            ta_q <= 12'd0;
            tp_q <= 3'd0;
            tn_q <= 3'd0;
            tr_q <= i_rst ? 3'd3 : (i_axis_mask & {3{!i_part_speed}});   // (reset values: mask 3, no ps)
            ge0_q <= {3{!i_rst && z0}};   // |D| = 0 in the next call (K = 16 after i_rst)
            ge1_q <= {3{!i_rst && z1}};
            gs_q <= i_rst ? 3'd0 : ((i_axis_mask & {3{!i_part_speed}} & {3{z1}}) |
                                    (~(i_axis_mask & {3{!i_part_speed}}) & {3{z0}}));
            k1t_q <= i_rst ? 3'd0 : (i_axis_mask & {3{!i_part_speed}} & {3{z1}});
            a_rev_q <= 1'b0;
            a_kclose_q <= 1'b0;
            a_pulse_q <= 1'b0;
            a_wen_q <= 1'b0;
            a_wp_q <= {W_POS{1'b0}};
            a_w3_q <= 1'b0;
            a_wlo_q <= {W_POS{1'b0}};
            a_whi_q <= {W_POS{1'b0}};
            a_v_q <= 1'b0;
            a_sq_q <= {3*W_SQ{1'b0}};
            q_rev_q <= 1'b0;
            q_kclose_q <= 1'b0;
            q_pulse_q <= 1'b0;
            q_v_q <= 1'b0;
            q_wen_q <= 1'b0;
            q_w_q <= {W_POS{1'b0}};
            q_wlo_q <= {W_POS{1'b0}};
            q_whi_q <= {W_POS{1'b0}};
            ph_q <= {W_INC{1'b0}};
            ps_b_q <= {W_POS{1'b0}};
            ps_i_q <= {{(W_POS-1){1'b0}}, 1'b1};
            sp_k_q <= 5'd0;
            sp_en_q <= 1'b0;
            sp_go_q <= 1'b0;
            sp_gth_q <= 1'b0;
            sp_eqh_q <= 1'b0;
            sp_gtl_q <= 1'b0;
            sp_inc_q <= {W_INC{1'b0}};
            sp_m_q <= {W_GAP{1'b0}};
            sp_a_q <= {W_SPHI{1'b0}};
            sp_thr_q <= {W_PROD{1'b0}};
            sp_hi_q <= {W_SPHI{1'b0}};
            sp_lo_q <= {W_GAP{1'b0}};
            r_wen_q <= 1'b0;
            r_wc_q <= 6'd0;
            r_v_q <= 1'b0;
            p_inwin_q <= 1'b0;
            p_v_q <= 1'b0;
            b_inwin_q <= 1'b0;
            b_v_q <= 1'b0;
            u_hi_q <= {LH{1'b0}};
            u_lo_q <= {LH{1'b0}};
            u_c_q <= 1'b0;
            u_ao_q <= 1'b0;
            u_v_q <= 1'b0;
            u_inwin_q <= 1'b0;
            e_q <= 1'b0;
            tk_q <= 1'b0;
            c_fire_q <= 1'b0;
            c_inwin_q <= 1'b0;
            c_live_q <= 1'b0;
            c_hic_q <= {LH{1'b0}};
            c_lo_q <= {LH{1'b0}};
            c_lt_q <= {(LH+1){1'b0}};
            c_f_q <= 1'b0;
            c_tm_q <= {(W_DIST-LH){1'b0}};
            dist_q <= {W_REM{1'b0}};
            idx_o_q <= 7'd0;
            done_o_q <= 1'b0;
            idx_p_q <= 7'd0;
            adv_q <= 1'b0;
            adv_g1_q <= 1'b0;
            adv_g2_q <= 1'b0;
            adv_i_q <= 1'b0;
            mv_q <= 2'd0;
            nx_p_q <= i_rst ? 7'd0 : nx_0;
            nx2_p_q <= i_rst ? 7'd0 : nx2_0;
            nx3_p_q <= i_rst ? 7'd0 : nx3_0;
            nx4_p_q <= i_rst ? 7'd0 : nx4_0;
            stop0_q <= !i_rst && i_arr_en && !i_arr_wrap && (nx_0 == 7'd0);
            done_q <= 1'b0;
            timer_q <= {W_PW{1'b0}};
            nsp2_q <= NSP2_MAX;
            fc_q <= 1'b0;
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
            arr_wrap_q <= run_q ? arr_wrap_q : f_arr_wrap_q;
            mask_q <= mask_e;
            len_q <= len_e;
            // A
            ta_q <= ta_d;
            tp_q <= tp_d;
            tn_q <= tn_d;
            ge0_q <= ge0_d;
            ge1_q <= ge1_d;
            gs_q <= (tr_q & ge1_d) | (~tr_q & ge0_d);
            k1t_q <= tr_q & {3{z1}};
            a_rev_q <= rev;
            a_kclose_q <= kclose;
            a_pulse_q <= ps_pulse;
            a_wen_q <= f_win_en_q;
            a_wp_q <= wp;
            a_w3_q <= (f_win_src_q == 2'd3);
            a_wlo_q <= f_win_low_q;
            a_whi_q <= f_win_high_q;
            a_v_q <= 1'b1;
            a_sq_q <= sq_d;
            // Q
            q_rev_q <= a_rev_q;
            q_kclose_q <= a_kclose_q;
            q_pulse_q <= a_pulse_q;
            q_v_q <= a_v_q;
            q_wen_q <= a_wen_q;
            q_w_q <= a_w;
            q_wlo_q <= a_wlo_q;
            q_whi_q <= a_whi_q;
            ph_q <= ph_d;
            ps_b_q <= ps_cnt;
            // ps_i = ps_b + 1 always (both reset together, both follow ps_cnt), so ps_cnt + 1
            // is ps_i + 1 after a pulse and ps_i itself otherwise: the increment starts at the
            // register, the last call's pulse only enables it
            if (a_pulse_q) ps_i_q <= ps_i_q + 38'sd1;
            sp_go_q <= sp_step && (sp_k_q == 5'd16) && sp_en_q;   // k = 0 and a sample held next
            if (sp_load) begin
                sp_k_q <= 5'd1;
                sp_en_q <= (f_min_period_q != 16'd0) && (thr_now[W_DIST-1:W_PROD] == 8'd0);
                sp_inc_q <= inc;
                sp_m_q <= f_min_period_q >> 1;
                sp_a_q <= f_min_period_q[1] ? {1'b0, inc} : {W_SPHI{1'b0}};
                sp_thr_q <= thr_now[W_PROD-1:0];
                sp_hi_q <= sp_h0 >> 1;
                sp_lo_q <= {sp_h0[0], {(W_GAP-1){1'b0}}};
            end else if (sp_step) begin
                sp_k_q <= (sp_k_q == 5'd16) ? 5'd0 : sp_k_q + 5'd1;
                if (sp_k_q == 5'd16) begin
                    sp_gth_q <= (sp_prod[W_PROD-1:W_PROD/2] > sp_thr_q[W_PROD-1:W_PROD/2]);
                    sp_eqh_q <= (sp_prod[W_PROD-1:W_PROD/2] == sp_thr_q[W_PROD-1:W_PROD/2]);
                    sp_gtl_q <= (sp_prod[W_PROD/2-1:0] > sp_thr_q[W_PROD/2-1:0]);
                end else begin
                    sp_m_q <= sp_m_q >> 1;
                    sp_a_q <= sp_m_q[1] ? {1'b0, sp_inc_q} : {W_SPHI{1'b0}};
                    sp_hi_q <= sp_sh >> 1;
                    sp_lo_q <= {sp_sh[0], sp_lo_q[W_GAP-1:1]};
                end
            end
            // R (r_y, part: above)
            r_wen_q <= q_wen_q;
            r_wc_q <= r_wc_d;
            r_v_q <= q_v_q;
            // B1
            p_inwin_q <= b_inwin_d;
            p_v_q <= r_v_q;
            // P
            b_inwin_q <= p_inwin_q;
            b_v_q <= p_v_q;
            // B2
            u_hi_q <= pos ? sf_hi : sn_hi;
            u_lo_q <= pos ? sf_lo[LH-1:0] : sn_lo[LH-1:0];
            u_c_q <= pos ? sf_lo[LH] : sn_lo[LH];
            u_ao_q <= pos ? sf_ao : sn_ao;
            u_v_q <= b_v_q;
            u_inwin_q <= b_inwin_q;
            e_q <= b_v_q && !done_d;
            tk_q <= p_v_q && !dec && !done_d && !stop0_d;
            c_fire_q <= dec;
            c_inwin_q <= u_inwin_q;
            c_live_q <= e_q;
            c_hic_q <= u_hic;
            c_lo_q <= u_lo_q;
            c_lt_q <= ut_lo;
            c_f_q <= pos;
            c_tm_q <= pos ? {(W_DIST-LH){1'b0}} : thr_q[W_DIST-1:LH];
            idx_p_q <= idx_l;
            adv_q <= adv;
            adv_g1_q <= adv && u_v_q;     // (adv implies each of these registers is 1)
            adv_g2_q <= adv && run_q;
            adv_i_q <= adv && ok_w_q;
            // (adv_q implies each of these registers is 1 in this call, too)
            mv_q <= {(adv || adv_q) && a_v_q, (adv || adv_q) && r_v_q};
            nx_p_q <= nx_l;
            nx2_p_q <= nx2_l;
            nx3_p_q <= nx3_l;
            nx4_p_q <= nx4_l;
            stop0_q <= stop0_d;
            done_q <= done_d;
            // B3
            if (c_live_q) dist_q <= dist_n;
            idx_o_q <= idx_l;
            done_o_q <= done_q;
            timer_q <= timer_d;
            nsp2_q <= nsp2_d;
            fc_q <= fc_d;
            fire_q <= fire;
            emit_q <= emit;
            pulse_q <= pulse_d;
            in_win_q <= c_inwin_q;
            overlap_q <= overlap;
            rate_over_q <= rate_over;
            spacing_err_q <= spacing_err;
            freq_err_q <= freq_err;
            ps_pulse_q <= ps_pulse;
        end
    end

    // counters and sticky flags: kept while enable = 0, cleared by an invalid configuration
    always @(posedge i_clk) begin
        if (rst_cfg) begin
            fire_cnt_q <= {W_FCNT{1'b0}};
            ovl_cnt_q <= {W_OVL{1'b0}};
            overlap_st_q <= 1'b0;
            rate_over_st_q <= 1'b0;
            spacing_st_q <= 1'b0;
            freq_st_q <= 1'b0;
            cfg_err_q <= !i_rst;
        end else if (!f_enable_q) begin
            ovl_cnt_q <= ovl_base;
            overlap_st_q <= overlap_st_q && !f_clear_q;
            rate_over_st_q <= rate_over_st_q && !f_clear_q;
            spacing_st_q <= spacing_st_q && !f_clear_q;
            freq_st_q <= freq_st_q && !f_clear_q;
            cfg_err_q <= 1'b0;
        end else begin
            fire_cnt_q <= fire_cnt_d;
            ovl_cnt_q <= ovl_d;
            overlap_st_q <= (overlap_st_q && !f_clear_q) || overlap;
            rate_over_st_q <= (rate_over_st_q && !f_clear_q) || rate_over;
            spacing_st_q <= (spacing_st_q && !f_clear_q) || spacing_err;
            freq_st_q <= (freq_st_q && !f_clear_q) || freq_err;
            cfg_err_q <= 1'b0;
        end
    end

    assign o_fire         = fire_q;
    assign o_emit         = emit_q;
    assign o_pulse        = pulse_q;
    assign o_in_win       = in_win_q;
    assign o_dist         = dist_q;
    assign o_idx          = idx_o_q;
    assign o_arr_done     = done_o_q;
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
    assign o_ps_count     = ps_cnt;      // a select of two registers by a register
    assign o_cfg_err      = cfg_err_q;

endmodule

`default_nettype wire
