// quad_decoder.v — 4x quadrature decoder for the laser's A/B lines plus the laser error line.
//
// Reference RTL of hls/quad_decoder.h (DESIGN §4.2). One rising clock edge = one call of
// quad_decoder::step(); every output is a register holding the out_t of that call. Synchronous
// active-high reset = quad_decoder::reset() (since = 65535, everything else 0).
//
// Each pin passes an input_filter #(W_GLITCH) (synchroniser + glitch filter, length glitch_n).
// The decoder acts on the filter outputs *of the same call* (the filters' o_*_d next-state
// ports), against the previous filtered levels pa/pb:
//   only A changed: +1 if A' != B' else -1      only B changed: +1 if A' == B' else -1
//   both changed:   illegal (no count, pulse + saturating counter)
// forward (+1) for (A,B) = 00 -> 10 -> 11 -> 01 (A leads B). No count before the filter is valid
// (primed) and none while the filtered laser error line is active. `clear` acts first; an event
// of the same call sets its flag again.
// Latency pin edge -> o_step: max(glitch_n,1) + 1 calls.
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module quad_decoder (
    input  wire                         i_clk,
    input  wire                         i_rst,         // synchronous, active high: quad_decoder::reset()
    input  wire                         i_a,           // laser A pin (asynchronous)
    input  wire                         i_b,           // laser B pin (asynchronous)
    input  wire                         i_lerr,        // laser error pin (asynchronous)
    input  wire [`LX_QD_W_GLITCH-1:0]   i_glitch_n,    // glitch filter length (W_GLITCH)
    input  wire [`LX_QD_W_SPACING-1:0]  i_min_spacing, // minimum edge spacing, clocks; 0 = off
    input  wire                         i_clear,       // register pulse: clears the sticky flags
    output wire signed [`LX_W_STEP-1:0] o_step,        // -1, 0, +1
    output wire signed [`LX_W_RAW-1:0]  o_raw_count,   // raw laser count N, wraps
    output wire                         o_illegal,     // pulse: both lines changed
    output wire                         o_ovs,         // pulse: edge closer than min_spacing
    output wire [`LX_QD_W_ERRCNT-1:0]   o_err_cnt,     // illegal transitions, saturating at 255
    output wire                         o_illegal_st,  // sticky
    output wire                         o_ovs_st,      // sticky
    output wire                         o_lerr,        // filtered laser error && primed
    output wire                         o_lerr_nx,     // look-ahead: the o_lerr of the next call (0 in a
                                                       // reset call; rephase registers it, DESIGN 4.5)
    output wire                         o_lerr_alarm,  // sticky while lerr
    output wire                         o_glitch_st    // sticky: the A or B filter suppressed a pulse
);

    // ---- fixed widths (hls: quad_decoder_cfg, axis_widths) ----------------------------------
    localparam integer W_GLITCH  = `LX_QD_W_GLITCH;   // glitch filter length register
    localparam integer W_SPACING = `LX_QD_W_SPACING;  // minimum edge spacing register, clocks
    localparam integer W_ERRCNT  = `LX_QD_W_ERRCNT;   // illegal transition counter
    localparam integer W_RAW     = `LX_W_RAW;         // raw laser count
    localparam integer W_RLO     = W_RAW / 2;         // its lower half (circuit only)
    localparam [W_SPACING-1:0] SINCE_MAX  = {W_SPACING{1'b1}};
    localparam [W_ERRCNT-1:0]  ERRCNT_MAX = {W_ERRCNT{1'b1}};

    // ---- the three pin filters -----------------------------------------------------------------
    wire fa_f, fa_valid, fa_glitch, fa_f_d, fa_valid_d, fa_glitch_d;
    wire fb_f, fb_valid, fb_glitch, fb_f_d, fb_valid_d, fb_glitch_d;
    wire fe_f, fe_valid, fe_glitch, fe_f_d, fe_valid_d, fe_glitch_d;

    input_filter #(.W_CNT(W_GLITCH)) u_fa (
        .i_clk(i_clk), .i_rst(i_rst), .i_pin(i_a), .i_n(i_glitch_n),
        .o_f(fa_f), .o_valid(fa_valid), .o_glitch(fa_glitch),
        .o_f_d(fa_f_d), .o_valid_d(fa_valid_d), .o_glitch_d(fa_glitch_d));
    input_filter #(.W_CNT(W_GLITCH)) u_fb (
        .i_clk(i_clk), .i_rst(i_rst), .i_pin(i_b), .i_n(i_glitch_n),
        .o_f(fb_f), .o_valid(fb_valid), .o_glitch(fb_glitch),
        .o_f_d(fb_f_d), .o_valid_d(fb_valid_d), .o_glitch_d(fb_glitch_d));
    input_filter #(.W_CNT(W_GLITCH)) u_fe (
        .i_clk(i_clk), .i_rst(i_rst), .i_pin(i_lerr), .i_n(i_glitch_n),
        .o_f(fe_f), .o_valid(fe_valid), .o_glitch(fe_glitch),
        .o_f_d(fe_f_d), .o_valid_d(fe_valid_d), .o_glitch_d(fe_glitch_d));

    // ---- registers -------------------------------------------------------------------------------
    reg                    pa_q, pb_q, primed_q;
    // the raw count is held in two halves (DESIGN 4.2: N wraps at 2^W_RAW; the split is only the
    // circuit): the upper half moves when the lower half wraps, told by two registered flags
    // (lower half all ones / all zeros), so no carry chain is longer than a half
    reg [W_RLO-1:0]        rlo_q;
    reg [W_RAW-W_RLO-1:0]  rhi_q;
    reg                    rlo_ones_q, rlo_zero_q;
    wire signed [W_RAW-1:0] raw_q = {rhi_q, rlo_q};
    reg [W_ERRCNT-1:0]     err_cnt_q;
    reg [W_SPACING:0]      nsp2_q;         // ~(since + 2) (DESIGN 4.2 `since`, offset by 2, inverted)
    reg                    illegal_st_q, ovs_st_q, lerr_alarm_q, glitch_st_q;
    reg signed [1:0]       step_q;
    reg                    illegal_q, ovs_q, lerr_q;

    reg                    pa_d, pb_d, primed_d;
    reg [W_RLO-1:0]        rlo_d;
    reg [W_RAW-W_RLO-1:0]  rhi_d;
    reg                    rlo_ones_d, rlo_zero_d;
    reg [W_ERRCNT-1:0]     err_cnt_d;
    reg [W_SPACING:0]      nsp2_d;
    reg                    illegal_st_d, ovs_st_d, lerr_alarm_d, glitch_st_d;
    reg signed [1:0]       step_d;
    reg                    illegal_d, ovs_d, lerr_d;

    reg                    da, db;
    wire [W_RLO-1:0]       rlo_inc = rlo_q + {{(W_RLO-1){1'b0}}, 1'b1};
    wire [W_RLO-1:0]       rlo_dec = rlo_q - {{(W_RLO-1){1'b0}}, 1'b1};
    wire [W_RAW-W_RLO-1:0] rhi_inc = rhi_q + {{(W_RAW-W_RLO-1){1'b0}}, 1'b1};
    wire [W_RAW-W_RLO-1:0] rhi_dec = rhi_q - {{(W_RAW-W_RLO-1){1'b0}}, 1'b1};
    // the next flags, from the register alone: lo + 1 is all ones iff lo == ~1 (all ones but
    // bit 0), lo - 1 is all zeros iff lo == 1
    wire                   rlo_m2  = rlo_q == {{(W_RLO-1){1'b1}}, 1'b0};
    wire                   rlo_p1  = rlo_q == {{(W_RLO-1){1'b0}}, 1'b1};
    reg                    close_q, close_d;   // DESIGN 4.2 `close`: since + 1 < min_spacing
    // `since` is kept as sp2 = since + 2 (65537 = since saturated at 65535), so that the overspeed
    // comparison of the next edge is one comparator on registers for both values since' can take:
    // since' = 0 after a step -> 1 < min_spacing; since' = since + 1 -> sp2 < min_spacing.
    // sp2 is held inverted (nsp2 = ~sp2), so sp2 < min_spacing is the carry out of
    // min_spacing + ~sp2 (W_SPACING + 1 bits) with no inverted operand in front of the chain (one
    // LUT per bit on the iCE40); a count is a decrement of nsp2
    localparam [W_SPACING:0] SP2_MAX  = {1'b0, SINCE_MAX} + {{(W_SPACING-1){1'b0}}, 2'd2};
    localparam [W_SPACING:0] NSP2_MAX = ~SP2_MAX;
    localparam [W_SPACING:0] NSP2_TWO = ~{{(W_SPACING-1){1'b0}}, 2'd2};
    // 1 < min_spacing as a test of min_spacing's bits above bit 0 (a compare with the constant
    // 1 is mapped to a carry chain with an inverter per bit on the iCE40)
    wire                   close_0   = (i_min_spacing >> 1) != {W_SPACING{1'b0}};
    wire [W_SPACING+1:0]   close_s   = {2'b00, i_min_spacing} + {1'b0, nsp2_q};
    wire                   close_inc = close_s[W_SPACING+1];

    always @* begin
        // clear acts first
        illegal_st_d = illegal_st_q;
        ovs_st_d     = ovs_st_q;
        glitch_st_d  = glitch_st_q;
        err_cnt_d    = err_cnt_q;
        lerr_alarm_d = lerr_alarm_q;
        if (i_clear) begin
            illegal_st_d = 1'b0;
            ovs_st_d     = 1'b0;
            glitch_st_d  = 1'b0;
            err_cnt_d    = {W_ERRCNT{1'b0}};
            if (!fe_f_d) lerr_alarm_d = 1'b0;
        end

        // decode against the previous filtered levels
        step_d    = 2'sd0;
        illegal_d = 1'b0;
        da        = fa_f_d != pa_q;
        db        = fb_f_d != pb_q;
        if (primed_q && !fe_f_d) begin
            if (da && db)
                illegal_d = 1'b1;
            else if (da)
                step_d = (fa_f_d != fb_f_d) ? 2'sd1 : -2'sd1;
            else if (db)
                step_d = (fa_f_d == fb_f_d) ? 2'sd1 : -2'sd1;
        end
        lerr_d   = primed_q && fe_f_d;
        pa_d     = fa_f_d;
        pb_d     = fb_f_d;
        primed_d = primed_q ? 1'b1 : fa_valid_d;

        // edge spacing
        ovs_d   = 1'b0;
        nsp2_d  = nsp2_q;
        close_d = 1'b0;                          // since stays 65535: 65536 < min_spacing never
        if (step_d != 2'sd0) begin
            ovs_d   = close_q;
            nsp2_d  = NSP2_TWO;
            close_d = close_0;
        end else if (nsp2_q != NSP2_MAX) begin
            nsp2_d  = nsp2_q - {{W_SPACING{1'b0}}, 1'b1};
            close_d = close_inc;
        end

        // events set their flags (after the clear)
        if (illegal_d) begin
            illegal_st_d = 1'b1;
            // (the increment of the register itself, the clear only selects: cleared and
            // counted in one call gives 1)
            if (i_clear) err_cnt_d = {{(W_ERRCNT-1){1'b0}}, 1'b1};
            else if (err_cnt_q != ERRCNT_MAX) err_cnt_d = err_cnt_q + {{(W_ERRCNT-1){1'b0}}, 1'b1};
        end
        if (ovs_d) ovs_st_d = 1'b1;
        if (fa_glitch_d || fb_glitch_d) glitch_st_d = 1'b1;
        if (lerr_d) lerr_alarm_d = 1'b1;
        // raw +- 1 are formed from the register alone (in parallel with the filter and step
        // logic); the step only selects: no carry chain after the step decision
        // (the halves: the upper one moves on a +1 from all ones or a -1 from all zeros)
        rlo_d      = rlo_q;
        rhi_d      = rhi_q;
        rlo_ones_d = rlo_ones_q;
        rlo_zero_d = rlo_zero_q;
        if (step_d == 2'sd1) begin
            rlo_d      = rlo_inc;
            rlo_ones_d = rlo_m2;
            rlo_zero_d = rlo_ones_q;
            if (rlo_ones_q) rhi_d = rhi_inc;
        end else if (step_d == -2'sd1) begin
            rlo_d      = rlo_dec;
            rlo_ones_d = rlo_zero_q;
            rlo_zero_d = rlo_p1;
            if (rlo_zero_q) rhi_d = rhi_dec;
        end
    end

    always @(posedge i_clk) begin
        if (i_rst) begin
            pa_q         <= 1'b0;
            pb_q         <= 1'b0;
            primed_q     <= 1'b0;
            rlo_q        <= {W_RLO{1'b0}};
            rhi_q        <= {(W_RAW-W_RLO){1'b0}};
            rlo_ones_q   <= 1'b0;
            rlo_zero_q   <= 1'b1;
            err_cnt_q    <= {W_ERRCNT{1'b0}};
            nsp2_q       <= NSP2_MAX;
            close_q      <= 1'b0;
            illegal_st_q <= 1'b0;
            ovs_st_q     <= 1'b0;
            lerr_alarm_q <= 1'b0;
            glitch_st_q  <= 1'b0;
            step_q       <= 2'sd0;
            illegal_q    <= 1'b0;
            ovs_q        <= 1'b0;
            lerr_q       <= 1'b0;
        end else begin
            pa_q         <= pa_d;
            pb_q         <= pb_d;
            primed_q     <= primed_d;
            rlo_q        <= rlo_d;
            rhi_q        <= rhi_d;
            rlo_ones_q   <= rlo_ones_d;
            rlo_zero_q   <= rlo_zero_d;
            err_cnt_q    <= err_cnt_d;
            nsp2_q       <= nsp2_d;
            close_q      <= close_d;
            illegal_st_q <= illegal_st_d;
            ovs_st_q     <= ovs_st_d;
            lerr_alarm_q <= lerr_alarm_d;
            glitch_st_q  <= glitch_st_d;
            step_q       <= step_d;
            illegal_q    <= illegal_d;
            ovs_q        <= ovs_d;
            lerr_q       <= lerr_d;
        end
    end

    assign o_step       = step_q;
    assign o_raw_count  = raw_q;
    assign o_illegal    = illegal_q;
    assign o_ovs        = ovs_q;
    assign o_err_cnt    = err_cnt_q;
    assign o_illegal_st = illegal_st_q;
    assign o_ovs_st     = ovs_st_q;
    assign o_lerr       = lerr_q;
    assign o_lerr_nx    = !i_rst && lerr_d;
    assign o_lerr_alarm = lerr_alarm_q;
    assign o_glitch_st  = glitch_st_q;

`ifdef FORMAL
    // ---- formal properties (read_verilog -formal; see docs/FORMAL.md) --------------------------
    // Checked after the first reset. The f_* registers record, at each edge, what the decoder
    // saw in that call; the asserts compare the outputs of the call with an independent decode:
    // the filtered (A,B) pair as a position on the cycle 00 -> 10 -> 11 -> 01 (index 0..3), the
    // move is the index difference mod 4 (1: +1, 3: -1, 2: illegal, 0: none).
    reg                    f_init, f_rst_p, f_en_p, f_clear_p, f_glitch_p, f_lnx_p;
    reg [1:0]              f_move_p;
    reg signed [W_RAW-1:0] f_raw_p, f_ref;
    reg [W_ERRCNT-1:0]     f_err_p;
    reg                    f_ill_st_p;
    initial f_init = 1'b0;

    // Edge spacing and laser error (DESIGN 4.2). f_dist is a plain reference of the spacing:
    // the number of calls from the call of the last counted edge to the present call (1 in the
    // call right after an edge), saturating at 2^17 - 1, and that value after reset ("no edge
    // yet": farther than any 16-bit min_spacing). It counts the edges of the reference decode
    // (f_edge: a legal move while counting), not the RTL's step. An edge is overspeed when its
    // spacing is below min_spacing of the previous call (the comparison is a register, `close`,
    // made one call early); min_spacing = 0 never flags.
    localparam [W_SPACING:0] F_DIST_MAX = {(W_SPACING+1){1'b1}};
    reg [W_SPACING:0]      f_dist;              // spacing an edge of the present call would have
    wire [W_SPACING:0]     f_sp2 = ~nsp2_q;     // since + 2 (the register holds it inverted)
    reg [W_SPACING-1:0]    f_ms_p;              // min_spacing of the previous call
    reg                    f_ovs_exp_p;         // the call was an edge closer than min_spacing
    reg                    f_ovs_st_p, f_fe_p, f_primed_p, f_alarm_p;

    function [1:0] f_idx;                       // position of (a,b) on the quadrature cycle
        input fa, fb;
        f_idx = {fb, fa ^ fb};                  // 00->0, 10->1, 11->2, 01->3
    endfunction

    wire [1:0] f_move = f_idx(fa_f_d, fb_f_d) - f_idx(pa_q, pb_q);
    // a counted edge of the reference decode: a legal move while counting is enabled
    wire       f_edge = primed_q && !fe_f_d && (f_move == 2'd1 || f_move == 2'd3);

    always @(posedge i_clk) begin
        if (i_rst) f_init <= 1'b1;
        f_rst_p    <= i_rst;
        f_en_p     <= primed_q && !fe_f_d;
        f_move_p   <= f_move;
        f_clear_p  <= i_clear;
        f_glitch_p <= fa_glitch_d || fb_glitch_d;
        f_raw_p    <= raw_q;
        f_err_p    <= err_cnt_q;
        f_ill_st_p <= illegal_st_q;
        f_ovs_st_p <= ovs_st_q;
        f_fe_p     <= fe_f_d;
        f_primed_p <= primed_q;
        f_alarm_p  <= lerr_alarm_q;
        f_lnx_p    <= o_lerr_nx;
        f_ms_p     <= i_min_spacing;
        // the call is an edge closer than min_spacing (of the previous call)
        f_ovs_exp_p <= f_edge && (f_dist < {1'b0, f_ms_p});
        // reference spacing: 1 in the call after a counted edge, + 1 per call, saturating
        if (i_rst)
            f_dist <= F_DIST_MAX;
        else if (f_edge)
            f_dist <= {{W_SPACING{1'b0}}, 1'b1};
        else if (f_dist != F_DIST_MAX)
            f_dist <= f_dist + 1'b1;
        // tiny reference counter: +1 / -1 on legal moves while counting is enabled
        if (i_rst)
            f_ref <= {W_RAW{1'b0}};
        else if (primed_q && !fe_f_d && f_move == 2'd1)
            f_ref <= f_ref + 1;
        else if (primed_q && !fe_f_d && f_move == 2'd3)
            f_ref <= f_ref - 1;
    end

    always @* begin
        if (f_init && !f_rst_p) begin
            // the position is the reference counter, always
            assert(raw_q == f_ref);
            // the wrap flags of the lower half are those of the register
            assert(rlo_ones_q == (&rlo_q));
            assert(rlo_zero_q == !(|rlo_q));
            // each call: the step is the decoded move, the raw count moves by exactly it
            assert(raw_q == f_raw_p + {{(W_RAW-2){step_q[1]}}, step_q});
            if (f_en_p && f_move_p == 2'd1) assert(step_q == 2'sd1 && !illegal_q);
            if (f_en_p && f_move_p == 2'd3) assert(step_q == -2'sd1 && !illegal_q);
            if (!f_en_p || f_move_p == 2'd0) assert(step_q == 2'sd0 && !illegal_q);
            // illegal transition (both lines changed): flag, sticky flag, no count
            if (f_en_p && f_move_p == 2'd2) begin
                assert(illegal_q && illegal_st_q);
                assert(step_q == 2'sd0 && raw_q == f_raw_p);
            end
            // error counter: +1 per illegal transition, saturating at 255, cleared by clear
            if (f_clear_p)
                assert(err_cnt_q == {{(W_ERRCNT-1){1'b0}}, illegal_q});
            else if (illegal_q)
                assert(err_cnt_q == ((f_err_p == ERRCNT_MAX) ? ERRCNT_MAX : f_err_p + 1'b1));
            else
                assert(err_cnt_q == f_err_p);
            // sticky illegal flag: set by the event, held until clear
            assert(illegal_st_q == (illegal_q || (f_ill_st_p && !f_clear_p)));
            if (f_glitch_p) assert(glitch_st_q);
            // edge spacing: the overspeed pulse exactly when the call counted an edge whose
            // spacing (calls since the previous counted edge) is below min_spacing of the
            // previous call; the edge is counted all the same (a step of +1 or -1, by which
            // the raw count moves, as in every call)
            assert(ovs_q == f_ovs_exp_p);
            if (ovs_q) assert(step_q == 2'sd1 || step_q == -2'sd1);
            // sticky overspeed flag: set by the event, held until clear (the event wins)
            assert(ovs_st_q == (ovs_q || (f_ovs_st_p && !f_clear_p)));
            // laser error: while the filtered line is high no count, no illegal or overspeed
            // event, the position holds
            if (f_fe_p) assert(step_q == 2'sd0 && !illegal_q && !ovs_q && raw_q == f_raw_p);
            // the laser error output is the filtered line once primed
            assert(lerr_q == (f_primed_p && f_fe_p));
            // laser error alarm: set in every call with a laser error, held otherwise; a clear
            // resets it only in a call whose filtered line is low
            assert(lerr_alarm_q == (lerr_q || (f_alarm_p && !(f_clear_p && !f_fe_p))));
        end
        if (f_init) begin
            assert(lerr_q == f_lnx_p);   // the look-ahead is the next call's lerr (resets too)
            assert(illegal_st_q || !illegal_q);
            assert(ovs_st_q || !ovs_q);
            assert(lerr_alarm_q || !lerr_q);
            // no laser error alarm before the filters are primed (so a clear in a call whose
            // filtered line is high never finds an alarm that this call does not set again)
            if (lerr_alarm_q) assert(primed_q);
            // the decoder tracks the filtered levels in every call (also during a laser error
            // and before priming): when counting resumes it starts from the present levels
            assert(pa_q == fa_f && pb_q == fb_f);
            // counting starts when the A filter is valid (primed = valid of the A filter)
            assert(primed_q == fa_valid);
            // helper invariants (induction): since (kept as sp2 = since + 2) and the
            // registered comparison close follow the reference spacing
            assert(f_sp2 == ((f_dist > {1'b0, SINCE_MAX}) ? SP2_MAX : f_dist + 1'b1));
            assert(close_q == (f_dist < {1'b0, f_ms_p}));
        end
    end
`endif

endmodule

`default_nettype wire
