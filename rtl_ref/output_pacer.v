// output_pacer.v — rate limiter for the compensated count stream.
//
// Reference RTL of hls/output_pacer.h (DESIGN §4.4). One rising clock edge = one call of
// output_pacer::step(); every output is a register holding the out_t of that call.
// Synchronous active-high reset = output_pacer::reset() (all zero).
//
//   emit     = (timer == 0 && backlog != 0) ? sgn(backlog) : 0     (registers before the edge)
//   backlog' = backlog + delta - emit
//   paced'   = paced + emit
//   timer'   = emit != 0 ? M - 1 : max(timer - 1, 0)
//   ovs      = |backlog'| > thr (pulse); ovs_st cleared by clear, set by ovs (event wins)
// Widths: backlog 40 signed, timer 16, paced 38 signed. Latency: delta in at call t, the first
// count leaves at call t+1.
`timescale 1ns / 1ps
`default_nettype none

module output_pacer (
    input  wire               i_clk,
    input  wire               i_rst,     // synchronous, active high: output_pacer::reset()
    input  wire signed [38:0] i_delta,   // comp(t) - comp(t-1) from the multiplier
    input  wire [15:0]        i_pace_m,  // M: at least M calls between two emitted counts
    input  wire [31:0]        i_thr,     // backlog alarm threshold
    input  wire               i_clear,   // register pulse: clears ovs_st (unless ovs)
    output wire signed [1:0]  o_pstep,   // emitted count: -1, 0, +1
    output wire signed [37:0] o_paced,   // paced position
    output wire signed [39:0] o_backlog, // counts still to emit
    output wire               o_ovs,     // pulse: |backlog| > thr
    output wire               o_ovs_st   // sticky
);

    // ---- fixed widths (hls: output_pacer_cfg, axis_widths) -----------------------------------
    localparam integer W_PACE    = 16;   // M register
    localparam integer W_THR     = 32;   // backlog alarm threshold
    localparam integer W_POS     = 38;   // paced position
    localparam integer W_DELTA   = 39;   // input delta
    localparam integer W_BACKLOG = 40;   // backlog, signed

    // ---- registers ---------------------------------------------------------------------------
    reg signed [W_BACKLOG-1:0] backlog_q;
    reg        [W_PACE-1:0]    timer_q;
    reg signed [W_POS-1:0]     paced_q;
    reg                        ovs_st_q;
    reg signed [1:0]           pstep_q;
    reg                        ovs_q;

    // ---- next state --------------------------------------------------------------------------
    wire                       emit_nz = (timer_q == {W_PACE{1'b0}}) && (backlog_q != {W_BACKLOG{1'b0}});
    wire signed [1:0]          emit    = emit_nz ? (backlog_q[W_BACKLOG-1] ? -2'sd1 : 2'sd1) : 2'sd0;
    wire signed [W_BACKLOG-1:0] emit_x  = {{(W_BACKLOG-2){emit[1]}}, emit};
    wire signed [W_BACKLOG-1:0] delta_x = {{(W_BACKLOG-W_DELTA){i_delta[W_DELTA-1]}}, i_delta};
    wire signed [W_BACKLOG-1:0] bl      = backlog_q + delta_x - emit_x;
    wire        [W_PACE-1:0]   timer_d = emit_nz ? i_pace_m - {{(W_PACE-1){1'b0}}, 1'b1}
                                       : (timer_q != {W_PACE{1'b0}}) ? timer_q - {{(W_PACE-1){1'b0}}, 1'b1}
                                       : {W_PACE{1'b0}};
    wire signed [W_POS-1:0]    paced_d = paced_q + {{(W_POS-2){emit[1]}}, emit};
    wire        [W_BACKLOG-1:0] mag    = bl[W_BACKLOG-1] ? -bl : bl;   // |backlog'|, unsigned
    wire                       ovs_d   = mag > {{(W_BACKLOG-W_THR){1'b0}}, i_thr};
    wire                       ovs_st_d = ovs_d || (ovs_st_q && !i_clear);

    always @(posedge i_clk) begin
        if (i_rst) begin
            backlog_q <= {W_BACKLOG{1'b0}};
            timer_q   <= {W_PACE{1'b0}};
            paced_q   <= {W_POS{1'b0}};
            ovs_st_q  <= 1'b0;
            pstep_q   <= 2'sd0;
            ovs_q     <= 1'b0;
        end else begin
            backlog_q <= bl;
            timer_q   <= timer_d;
            paced_q   <= paced_d;
            ovs_st_q  <= ovs_st_d;
            pstep_q   <= emit;
            ovs_q     <= ovs_d;
        end
    end

    assign o_pstep   = pstep_q;
    assign o_paced   = paced_q;
    assign o_backlog = backlog_q;
    assign o_ovs     = ovs_q;
    assign o_ovs_st  = ovs_st_q;

`ifdef FORMAL
    // ---- formal properties (read_verilog -formal; see docs/FORMAL.md) --------------------------
    // Checked after the first reset. The f_* registers record what the pacer saw in each call.
    // Conservation (backlog + paced = sum of the deltas) is checked in the harness
    // rtl_ref/formal/fv_output_pacer.v, which tracks the input sum.
    reg                   f_init, f_rst_p, f_clear_p, f_ovs_st_p;
    reg [W_THR-1:0]       f_thr_p;
    reg [W_PACE:0]        f_m;      // M in force at the last emitted count (0 read as 2^16)
    reg [W_PACE+1:0]      f_since;  // calls since the last emitted count, saturating
    initial f_init = 1'b0;

    localparam [W_PACE+1:0] F_SINCE_MAX = {(W_PACE+2){1'b1}};
    wire [W_PACE:0] f_m_now = (i_pace_m == {W_PACE{1'b0}}) ? {1'b1, {W_PACE{1'b0}}}
                                                            : {1'b0, i_pace_m};
    // |backlog| computed independently, one bit wider
    wire [W_BACKLOG:0] f_mag = backlog_q[W_BACKLOG-1] ? ({1'b0, ~backlog_q} + 1'b1)
                                                      : {1'b0, backlog_q};

    always @(posedge i_clk) begin
        if (i_rst) f_init <= 1'b1;
        f_rst_p    <= i_rst;
        f_clear_p  <= i_clear;
        f_ovs_st_p <= ovs_st_q;
        f_thr_p    <= i_thr;
        if (i_rst) begin
            f_since <= F_SINCE_MAX;
            f_m     <= {(W_PACE+1){1'b0}};
        end else if (emit_nz) begin
            f_since <= {{(W_PACE+1){1'b0}}, 1'b1};
            f_m     <= f_m_now;
        end else if (f_since != F_SINCE_MAX) begin
            f_since <= f_since + 1'b1;
        end
    end

    always @* begin
        if (f_init && !f_rst_p) begin
            // alarm exactly when |backlog| > threshold (threshold of the same call)
            assert(ovs_q == (f_mag > {{(W_BACKLOG-W_THR+1){1'b0}}, f_thr_p}));
            assert(ovs_st_q == (ovs_q || (f_ovs_st_p && !f_clear_p)));
        end
        if (f_init) begin
            // at most one count per M calls: a count leaves only M or more calls after the
            // previous one (M as set at the previous count)
            if (emit_nz) assert(f_since >= {1'b0, f_m});
            // the count has the sign of the backlog
            if (emit_nz) assert(emit == (backlog_q[W_BACKLOG-1] ? -2'sd1 : 2'sd1));
            // helper invariant (induction): the timer is what is left of the gap
            assert(timer_q == ((f_since >= {1'b0, f_m}) ? {W_PACE{1'b0}}
                                                         : (f_m - f_since[W_PACE:0])));
            if (!f_rst_p) assert(pstep_q == 2'sd0 || f_since == {{(W_PACE+1){1'b0}}, 1'b1});
        end
    end
`endif

endmodule

`default_nettype wire
