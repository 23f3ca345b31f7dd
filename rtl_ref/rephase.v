// rephase.v — referencing state machine: stage 1/2/3, points A, B, Z, C, phase adjustment d.
//
// Reference RTL of hls/rephase.h (DESIGN §4.5). One rising clock edge = one call of
// rephase::step(); the outputs after edge t are the out_t of call t (registers, and out_pos /
// homed as combinational functions of registers). Synchronous active-high reset =
// rephase::reset() (stage 1, forward, everything else 0).
//
// Per call, in the order of the C++ model:
//   1. paced' = paced + pstep; direction of the last real count; output phase counter ph.
//   2. stage machine: unhome/rehome -> stage 1 (adj0 = adj_tgt, no phase jump);
//      stage 1: rising switch edge (and !unhome) -> stage 2, A = paced', d from ph;
//      stage 2: Bresenham pair (q, num) keeps floor(d*tr/P) without a divider; tr < 0 -> stage 1;
//               tr == P -> stage 3, B, C, Z;
//      stage 3: homed, switch ignored.
//   3. ostep = pstep, or else sgn(adj_tgt' - adj) (adj follows adj_tgt one count per call).
//   4. mark = stage' == 3 && paced' in [B, C] (closed interval, either direction).
// Widths: positions 38 signed, d/num/ph 12 unsigned, q 13, tr 14 signed, stage 2.
// Latency: 1 call (pstep in, ostep/out_pos/mark out); extra counts +1 call.
`timescale 1ns / 1ps
`default_nettype none

module rephase (
    input  wire               i_clk,
    input  wire               i_rst,       // synchronous, active high: rephase::reset()
    input  wire signed [1:0]  i_pstep,     // paced count from the pacer: -1, 0, +1
    input  wire               i_sw,        // debounced reference switch level
    input  wire               i_sw_valid,  // its input_filter valid flag
    input  wire               i_rehome,    // register pulse: back to stage 1
    input  wire               i_unhome,    // laser error level: back to stage 1, no homing
    input  wire [12:0]        i_period,    // P (8..4096, multiple of 8)
    input  wire [12:0]        i_mark_len,  // C - B in counts (P/4..P)
    output wire signed [1:0]  o_ostep,     // output count: -1, 0, +1
    output wire signed [37:0] o_out_pos,   // paced + adj
    output wire               o_mark,      // reference mark
    output wire [1:0]         o_stage,     // 1, 2, 3
    output wire signed [37:0] o_a,         // point A
    output wire [11:0]        o_d,         // phase advance d in [0, P)
    output wire signed [37:0] o_b,         // point B
    output wire signed [37:0] o_c,         // point C (end of mark)
    output wire signed [37:0] o_z,         // point Z = B + dir * P/4
    output wire signed [37:0] o_adj,       // applied adjustment
    output wire               o_homed      // stage == 3
);

    // ---- fixed widths (hls: rephase_cfg, axis_widths) ----------------------------------------
    localparam integer W_POS = 38;        // positions
    localparam integer W_P   = 13;        // period and mark_len registers
    localparam integer W_PH  = 12;        // d, num, ph: 0..P-1
    localparam integer W_TR  = W_P + 1;   // travel beyond A, signed
    localparam integer W_SUM = W_P + 1;   // num + d < 2P, unsigned
    localparam integer W_DD  = W_P + 2;   // d before the modulo, signed

    // ---- registers ---------------------------------------------------------------------------
    reg [1:0]              stage_q;
    reg signed [W_POS-1:0] paced_q;
    reg                    fwd_last_q, sw_prev_q, sw_seen_q;
    reg signed [W_POS-1:0] a_q;
    reg                    fwd_q;
    reg [W_PH-1:0]         d_q;
    reg signed [W_TR-1:0]  tr_q;
    reg [W_PH-1:0]         num_q;
    reg [W_P-1:0]          q_q;        // floor(d*tr/P); kept as in hls/ (not an output)
    reg signed [W_POS-1:0] adj0_q, adj_tgt_q, adj_q;
    reg [W_PH-1:0]         ph_q;
    reg signed [W_POS-1:0] b_q, c_q, z_q;
    reg signed [1:0]       ostep_q;
    reg                    mark_q;

    reg [1:0]              stage_d;
    reg signed [W_POS-1:0] paced_d;
    reg                    fwd_last_d, sw_prev_d, sw_seen_d;
    reg signed [W_POS-1:0] a_d;
    reg                    fwd_d;
    reg [W_PH-1:0]         d_d;
    reg signed [W_TR-1:0]  tr_d;
    reg [W_PH-1:0]         num_d;
    reg [W_P-1:0]          q_d;
    reg signed [W_POS-1:0] adj0_d, adj_tgt_d, adj_d;
    reg [W_PH-1:0]         ph_d;
    reg signed [W_POS-1:0] b_d, c_d, z_d;
    reg signed [1:0]       ostep_d;
    reg                    mark_d;

    // phase counter modulo P: +1 wraps P-1 -> 0, -1 wraps 0 -> P-1
    function [W_PH-1:0] ph_step;
        input [W_PH-1:0] ph;
        input [1:0]      s;        // signed step, two's complement
        input [W_PH-1:0] p_last;
        begin
            if (!s[1] && s[0])
                ph_step = (ph == p_last) ? {W_PH{1'b0}} : ph + {{(W_PH-1){1'b0}}, 1'b1};
            else if (s[1])
                ph_step = (ph == {W_PH{1'b0}}) ? p_last : ph - {{(W_PH-1){1'b0}}, 1'b1};
            else
                ph_step = ph;
        end
    endfunction

    // combinational temporaries (part selects and extensions outside the always block)
    wire [W_PH-1:0]         p8       = i_period[W_P-1:3];                           // P/8
    wire [W_PH-1:0]         period_ph = i_period[W_PH-1:0];                         // P mod 2^12
    wire [W_PH-1:0]         p_last   = period_ph - {{(W_PH-1){1'b0}}, 1'b1};      // P-1
    wire signed [W_POS-1:0] period_x = $signed({{(W_POS-W_P){1'b0}}, i_period});
    wire signed [W_POS-1:0] mark_len_x = $signed({{(W_POS-W_P){1'b0}}, i_mark_len});
    wire signed [W_POS-1:0] p4_x     = $signed({{(W_POS-W_PH-1){1'b0}}, p8, 1'b0}); // 2 * P/8
    wire signed [W_DD-1:0]  period_dd = $signed({{(W_DD-W_P){1'b0}}, i_period});
    wire signed [W_DD-1:0]  p8_dd    = $signed({{(W_DD-W_PH){1'b0}}, p8});
    wire signed [W_TR-1:0]  period_tr = $signed({{(W_TR-W_P){1'b0}}, i_period});
    wire [W_SUM-1:0]        period_sum = {{(W_SUM-W_P){1'b0}}, i_period};
    wire [W_SUM-1:0]        num_sum  = {{(W_SUM-W_PH){1'b0}}, num_q};
    wire [W_SUM-1:0]        d_sum    = {{(W_SUM-W_PH){1'b0}}, d_q};
    wire                    rise     = i_sw && !sw_prev_q && sw_seen_q;
    wire                    pstep_nz = i_pstep != 2'sd0;
    wire                    pstep_fwd = !i_pstep[1];    // pstep > 0 when pstep != 0

    reg [W_PH-1:0]          ph_a;       // phase after the real count
    reg signed [W_DD-1:0]   ph_dd;      // ph_a extended for the d computation
    reg signed [W_DD-1:0]   dd;
    reg signed [1:0]        s, dq, dadj;
    reg [W_SUM-1:0]         sum;
    reg signed [W_POS-1:0]  lo, hi;

    always @* begin
        stage_d    = stage_q;
        a_d        = a_q;
        fwd_d      = fwd_q;
        d_d        = d_q;
        tr_d       = tr_q;
        num_d      = num_q;
        q_d        = q_q;
        adj0_d     = adj0_q;
        adj_tgt_d  = adj_tgt_q;
        adj_d      = adj_q;
        b_d        = b_q;
        c_d        = c_q;
        z_d        = z_q;
        dd         = {W_DD{1'b0}};
        s          = 2'sd0;
        dq         = 2'sd0;
        dadj       = 2'sd0;
        sum        = {W_SUM{1'b0}};

        // 1. real position and phase of the target output position
        paced_d    = paced_q + i_pstep;                        // signed: pstep sign-extended
        fwd_last_d = pstep_nz ? pstep_fwd : fwd_last_q;
        ph_a       = ph_step(ph_q, i_pstep, p_last);
        ph_d       = ph_a;
        ph_dd      = {{(W_DD-W_PH){1'b0}}, ph_a};

        // 2. stage machine
        if ((i_unhome || i_rehome) && stage_q != 2'd1) begin
            stage_d = 2'd1;
            adj0_d  = adj_tgt_q;                               // freeze: no phase jump
        end else if (stage_q == 2'd1) begin
            if (rise && !i_unhome) begin
                stage_d = 2'd2;
                a_d     = paced_d;
                fwd_d   = fwd_last_d;
                tr_d    = {W_TR{1'b0}};
                num_d   = {W_PH{1'b0}};
                q_d     = {W_P{1'b0}};
                // d = (7P/8 - ph_A) mod P forward, (ph_A - 3P/8) mod P backward
                if (fwd_last_d)
                    dd = period_dd - p8_dd - ph_dd;
                else
                    dd = ph_dd - p8_dd * 3;
                if (dd < 0)
                    d_d = dd + period_dd;                      // truncated to W_PH bits
                else
                    d_d = dd;
            end
        end else if (stage_q == 2'd2) begin
            s = fwd_q ? i_pstep : -i_pstep;                    // step in the homing direction
            if (s > 0) begin
                sum = num_sum + d_sum;
                if (sum >= period_sum) begin
                    num_d = sum - period_sum;                  // truncated to W_PH bits
                    dq    = 2'sd1;
                end else begin
                    num_d = sum;
                end
            end else if (s < 0 && tr_q > 0) begin
                if (num_q < d_q) begin
                    num_d = num_q + period_ph - d_q;
                    dq    = -2'sd1;
                end else begin
                    num_d = num_q - d_q;
                end
            end
            tr_d = tr_q + s;                                   // signed: s sign-extended
            q_d  = $signed(q_q) + dq;                          // modulo 2^W_P
            if (tr_d < 0) begin
                stage_d = 2'd1;                                // back past A: adjustment is 0
                tr_d    = {W_TR{1'b0}};
            end else begin
                dadj      = fwd_q ? dq : -dq;
                adj_tgt_d = adj_tgt_q + dadj;
                ph_d      = ph_step(ph_a, dadj, p_last);
                if (tr_d == period_tr) begin
                    stage_d = 2'd3;
                    adj0_d  = adj_tgt_d;
                    b_d     = fwd_q ? a_q + period_x : a_q - period_x;
                    c_d     = fwd_q ? b_d + mark_len_x : b_d - mark_len_x;
                    z_d     = fwd_q ? b_d + p4_x : b_d - p4_x;
                end
            end
        end
        sw_prev_d = i_sw;
        sw_seen_d = i_sw_valid;

        // 3. output step: the real count, or else the pending extra count
        ostep_d = i_pstep;
        if (!pstep_nz) begin
            if (adj_tgt_d > adj_q) ostep_d = 2'sd1;
            if (adj_tgt_d < adj_q) ostep_d = -2'sd1;
            adj_d = adj_q + ostep_d;
        end

        // 4. reference mark: a pure function of real position once homed
        lo     = fwd_d ? b_d : c_d;
        hi     = fwd_d ? c_d : b_d;
        mark_d = (stage_d == 2'd3) && (paced_d >= lo) && (paced_d <= hi);
    end

    always @(posedge i_clk) begin
        if (i_rst) begin
            stage_q    <= 2'd1;
            paced_q    <= {W_POS{1'b0}};
            fwd_last_q <= 1'b1;
            sw_prev_q  <= 1'b0;
            sw_seen_q  <= 1'b0;
            a_q        <= {W_POS{1'b0}};
            fwd_q      <= 1'b1;
            d_q        <= {W_PH{1'b0}};
            tr_q       <= {W_TR{1'b0}};
            num_q      <= {W_PH{1'b0}};
            q_q        <= {W_P{1'b0}};
            adj0_q     <= {W_POS{1'b0}};
            adj_tgt_q  <= {W_POS{1'b0}};
            adj_q      <= {W_POS{1'b0}};
            ph_q       <= {W_PH{1'b0}};
            b_q        <= {W_POS{1'b0}};
            c_q        <= {W_POS{1'b0}};
            z_q        <= {W_POS{1'b0}};
            ostep_q    <= 2'sd0;
            mark_q     <= 1'b0;
        end else begin
            stage_q    <= stage_d;
            paced_q    <= paced_d;
            fwd_last_q <= fwd_last_d;
            sw_prev_q  <= sw_prev_d;
            sw_seen_q  <= sw_seen_d;
            a_q        <= a_d;
            fwd_q      <= fwd_d;
            d_q        <= d_d;
            tr_q       <= tr_d;
            num_q      <= num_d;
            q_q        <= q_d;
            adj0_q     <= adj0_d;
            adj_tgt_q  <= adj_tgt_d;
            adj_q      <= adj_d;
            ph_q       <= ph_d;
            b_q        <= b_d;
            c_q        <= c_d;
            z_q        <= z_d;
            ostep_q    <= ostep_d;
            mark_q     <= mark_d;
        end
    end

    assign o_ostep   = ostep_q;
    assign o_out_pos = paced_q + adj_q;
    assign o_mark    = mark_q;
    assign o_stage   = stage_q;
    assign o_a       = a_q;
    assign o_d       = d_q;
    assign o_b       = b_q;
    assign o_c       = c_q;
    assign o_z       = z_q;
    assign o_adj     = adj_q;
    assign o_homed   = stage_q == 2'd3;

endmodule

`default_nettype wire
