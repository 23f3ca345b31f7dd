// encoder_counter.v — two 32-bit signed wrapping encoder counters with encoder simulation,
// reset now / at the next start trigger, wait-for-encoder and the sequenced 10 us correction.
//
// Reference RTL of hls/encoder_counter.h (docs/PSO_COUNTERS.md §3). One rising clock edge = one
// call of encoder_counter::step(); every output is a register holding the out_t of that call.
// Synchronous active-high reset = encoder_counter::reset() (all zero). A call with an invalid
// configuration (src 2/3, simulation rate above 2^30 on a simulated channel, corr_period < 33)
// resets every register and raises cfg_err for that call.
//
// Per channel c (registers before the edge; primes after it):
//   {carry, ph'} = ph + sim_inc;  sc' = carry      simulation phase, free running; the carry
//                                                  counts in the next call (sc, registered)
//   st     = src == 1 ? (sc ? (sim_down ? -1 : +1) : 0) : qstep
//   do_rst = (rst_req && !rst_on_trig) || (pending && trig)
//   pending' = (rst_req && rst_on_trig) || (pending && !trig)
//   cnt'   = do_rst ? 0 : load ? load_val : cnt + st   (32-bit wrap; a reset also clears ph', sc')
// Wait (two register stages: a counter that passes the value in call t gives reached in t + 2):
//   f_c' = parts of s32(cnt_c - val) (c = 0, 1: borrow, signs, equal), f_ok' = !wait_arm
//   reached = waiting && f_ok && (down ? s32(..)_ch < 0 : s32(..)_ch > 0), from f_ch
//   waiting' = wait_arm || (waiting && !reached)
//   ch, val, down latched by wait_arm.
// Correction: sample = timer + 1 >= corr_period (timer' = sample ? 0 : timer + 1). While the
//   product unit is idle (or in its last call) it loads hi = 2^23, lo = cnt (before the call),
//   m = scale, p = pos in every call; a sample call starts it (k' = 1), a sample while it runs is
//   dropped (only after corr_period was lowered live). Steps 0..31 follow in the next 32 calls
//   (step i: hi += lo[0] ? m : 0, then {hi, lo} >>>= 1; m is negated after step 30, so step 31
//   subtracts: two's complement multiplier); 33 calls after the sample
//   {hi, lo} = scale * cnt + 2^23 and corr' = {hi, lo}[63:24] + p, tick = 1.
//
// Timing (100 MHz on iCE40 HX8K): no multiplier, no add after an add in one clock. The
// simulation carry is registered before it counts (the 33-bit phase add ends in a register);
// the counter's next value is a 4:1 select of cnt + 1, cnt - 1, cnt - 2 (carry-select adds of
// the register) and the no-move value; the wait compares registers only, into flag registers
// (carry-select); the 33-bit shift-add and the 40-bit position add are carry-select; the
// sample decision (a 17-bit compare of an input) drives only k and the timer, never the
// enables of the product registers; the configuration check has no carry chain.
//
// Widths (encoder_counter_cfg): counters 32 signed, sim_inc Q0.32, scale Q8.24 signed, product
// 64, corr 40 signed, corr_period 16. Latency: a step (or a simulation carry of the previous
// call) in call t is in cnt of call t; a correction sampled in call s is in corr (with tick) in
// call s + 33; a counter that passes the awaited value in call t gives reached in call t + 2.
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module encoder_counter (
    input  wire                             i_clk,
    input  wire                             i_rst,          // synchronous, active high: encoder_counter::reset()
    // per-call inputs
    input  wire signed [`LX_W_STEP-1:0]     i_qstep0,       // quadrature step of counter 0 (-1, 0, +1)
    input  wire signed [`LX_W_STEP-1:0]     i_qstep1,       // quadrature step of counter 1
    input  wire                             i_trig,         // start trigger (pulse)
    input  wire signed [`LX_EC_W_POSIN-1:0] i_pos0,         // nominal output position 0, bits
    input  wire signed [`LX_EC_W_POSIN-1:0] i_pos1,         // nominal output position 1, bits
    // registers (encoder_counter_regs)
    input  wire [`LX_EC_W_SRC-1:0]          i_src0,         // 0 quadrature, 1 simulation (2, 3: cfg_err)
    input  wire [`LX_EC_W_SRC-1:0]          i_src1,
    input  wire [`LX_EC_W_INC-1:0]          i_sim_inc0,     // simulation rate, Q0.32 counts per clock (<= 2^30)
    input  wire [`LX_EC_W_INC-1:0]          i_sim_inc1,
    input  wire                             i_sim_down0,    // the simulation counts down
    input  wire                             i_sim_down1,
    input  wire signed [`LX_EC_W_SCALE-1:0] i_scale0,       // Q8.24 bits per count
    input  wire signed [`LX_EC_W_SCALE-1:0] i_scale1,
    input  wire                             i_rst_req0,     // pulse: reset request
    input  wire                             i_rst_req1,
    input  wire                             i_load0,        // pulse: preset the counter to load_val
    input  wire                             i_load1,
    input  wire signed [`LX_EC_W_CNT-1:0]   i_load_val0,
    input  wire signed [`LX_EC_W_CNT-1:0]   i_load_val1,
    input  wire                             i_rst_on_trig,  // reset requests wait for the next start trigger
    input  wire [`LX_EC_W_PER-1:0]          i_corr_period,  // correction period, calls (>= 32)
    input  wire                             i_wait_arm,     // pulse: arm wait-for-encoder
    input  wire                             i_wait_ch,      // 0: counter 0, 1: counter 1
    input  wire signed [`LX_EC_W_CNT-1:0]   i_wait_val,
    input  wire                             i_wait_down,    // 0: wait to overstep, 1: to understep
    // outputs (encoder_counter::out_t)
    output wire signed [`LX_EC_W_CNT-1:0]   o_cnt0,
    output wire signed [`LX_EC_W_CNT-1:0]   o_cnt1,
    output wire signed [`LX_W_STEP-1:0]     o_step0,        // count applied in this call
    output wire signed [`LX_W_STEP-1:0]     o_step1,
    output wire                             o_rst_done0,    // the counter was reset in this call
    output wire                             o_rst_done1,
    output wire                             o_rst_pending0, // waiting for a start trigger
    output wire                             o_rst_pending1,
    output wire signed [`LX_EC_W_CORR-1:0]  o_corr0,        // corrected output positions (held between ticks)
    output wire signed [`LX_EC_W_CORR-1:0]  o_corr1,
    output wire                             o_tick,         // corr updated in this call
    output wire                             o_waiting,
    output wire                             o_reached,      // pulse: the awaited counter passed the value
    output wire                             o_cfg_err
);

    // ---- fixed widths (hls: encoder_counter_cfg) -------------------------------------------
    localparam integer W_CNT    = `LX_EC_W_CNT;    // counters, signed, wrap
    localparam integer W_INC    = `LX_EC_W_INC;    // simulation rate, Q0.32
    localparam integer S_FRAC   = 24;              // scale fraction bits
    localparam integer W_SCALE  = `LX_EC_W_SCALE;  // scale, Q8.24 signed
    localparam integer W_PER    = `LX_EC_W_PER;    // correction period
    localparam integer W_CORR   = `LX_EC_W_CORR;   // W_SCALE + W_CNT - S_FRAC
    localparam integer W_ACC    = 33;              // W_SCALE + 1: upper half of the sequenced product
    localparam integer CORR_LAT = 33;              // = W_CNT + 1: calls from sample to corr
    localparam [5:0]       K_DONE   = CORR_LAT;   // step counter value of the add-p call
    localparam [W_ACC-1:0] HALF     = 33'd8388608; // 2^(S_FRAC-1): round half up

    // ---- registers ---------------------------------------------------------------------------
    reg signed [W_CNT-1:0]   cnt0_q, cnt1_q;
    reg        [W_INC-1:0]   ph0_q, ph1_q;
    reg                      sc0_q, sc1_q;     // simulation carry of the previous call
    reg                      pend0_q, pend1_q;
    reg signed [W_CORR-1:0]  corr0_q, corr1_q;
    reg signed [W_ACC-1:0]   hi0_q, hi1_q;     // sequenced product, upper half
    reg        [W_CNT-1:0]   lo0_q, lo1_q;     //   lower half
    reg signed [W_ACC-1:0]   m0_q, m1_q;       //   scale (negated for the last step)
    reg signed [W_CNT-1:0]   p0_q, p1_q;       //   sampled position
    reg        [5:0]         k_q;              //   0 idle, 1 + i: step i, 33: add p
    reg                      busy_q, done_q;   //   k_q in 1..32, k_q == 33
    reg        [W_PER-1:0]   timer_q;
    reg                      waiting_q, w_ch_q, w_down_q;
    reg        [3:0]         f0_q, f1_q;       // wait: parts of cnt_c - val of the previous call
    reg                      f_ok_q;           //   no arm in the previous call
    reg signed [W_CNT-1:0]   w_val_q;
    reg signed [1:0]         step0_q, step1_q;
    reg                      rst_done0_q, rst_done1_q, tick_q, reached_q, cfg_err_q;

    // ---- configuration check (encoder_counter_config_ok) -------------------------------------
    // sim_inc <= 2^30: bit 31 clear and (bit 30 clear or bits 29..0 clear)
    wire inc0_ok = !i_sim_inc0[31] && (!i_sim_inc0[30] || (i_sim_inc0[29:0] == 30'd0));
    wire inc1_ok = !i_sim_inc1[31] && (!i_sim_inc1[30] || (i_sim_inc1[29:0] == 30'd0));
    // corr_period >= CORR_LAT = 33 (no carry chain)
    wire per_ok  = (i_corr_period[W_PER-1:6] != 10'd0) || (i_corr_period[5] && (i_corr_period[4:0] != 5'd0));
    wire cfg_ok  = per_ok && !i_src0[1] && !i_src1[1] &&
                   (!i_src0[0] || inc0_ok) && (!i_src1[0] || inc1_ok);

    // carry-select W_ACC-bit add: low L bits, upper W_ACC - L bits for carry-in 0 and 1
    localparam integer L = 17;
    function [W_ACC-1:0] csel_add;
        input [W_ACC-1:0] a, b;
        reg [L:0]           lo;
        reg [W_ACC-L-1:0]   hi0;
        reg [W_ACC-L:0]     hi1;   // {a, 1} + {b, 1}: carry-in 1 through bit 0
        begin
            lo  = {1'b0, a[L-1:0]} + {1'b0, b[L-1:0]};
            hi0 = a[W_ACC-1:L] + b[W_ACC-1:L];
            hi1 = {a[W_ACC-1:L], 1'b1} + {b[W_ACC-1:L], 1'b1};
            csel_add = {lo[L] ? hi1[W_ACC-L:1] : hi0, lo[L-1:0]};
        end
    endfunction

    // the counter moves (cnt + 1, - 1, - 2: b a constant) as a three-part carry-select add (11,
    // 11, 10 bits): the longest carry chain is 11 bits; the upper part's carry-in is one LUT of
    // the lower and middle carries (with a constant b one of the middle carries is constant);
    // written for W_CNT = 32
    function [W_CNT-1:0] csel3;
        input [W_CNT-1:0] a, b;
        reg [11:0] lo;
        reg [11:0] m0;     // [11]: carry out with carry-in 0
        reg [12:0] m1;     // {a, 1} + {b, 1}: carry-in 1; [12] carry out
        reg [9:0]  h0;
        reg [10:0] h1;
        reg        cm;
        begin
            lo = {1'b0, a[10:0]} + {1'b0, b[10:0]};
            m0 = {1'b0, a[21:11]} + {1'b0, b[21:11]};
            m1 = {1'b0, a[21:11], 1'b1} + {1'b0, b[21:11], 1'b1};
            h0 = a[31:22] + b[31:22];
            h1 = {a[31:22], 1'b1} + {b[31:22], 1'b1};
            cm = lo[11] ? m1[12] : m0[11];
            csel3 = {cm ? h1[10:1] : h0, lo[11] ? m1[11:1] : m0[10:0], lo[10:0]};
        end
    endfunction

    // the same for the W_CORR-bit add of the position (20 + 20 bits)
    localparam integer LC = W_CORR / 2;
    function [W_CORR-1:0] csel_add40;
        input [W_CORR-1:0] a, b;
        reg [LC:0]           lo;
        reg [W_CORR-LC-1:0]  hi0;
        reg [W_CORR-LC:0]    hi1;
        begin
            lo  = {1'b0, a[LC-1:0]} + {1'b0, b[LC-1:0]};
            hi0 = a[W_CORR-1:LC] + b[W_CORR-1:LC];
            hi1 = {a[W_CORR-1:LC], 1'b1} + {b[W_CORR-1:LC], 1'b1};
            csel_add40 = {lo[LC] ? hi1[W_CORR-LC:1] : hi0, lo[LC-1:0]};
        end
    endfunction

    // ---- counting ----------------------------------------------------------------------------
    wire [W_INC:0] ph0_sum = {1'b0, ph0_q} + {1'b0, i_sim_inc0};
    wire [W_INC:0] ph1_sum = {1'b0, ph1_q} + {1'b0, i_sim_inc1};
    wire signed [1:0] sim0 = sc0_q ? (i_sim_down0 ? -2'sd1 : 2'sd1) : 2'sd0;
    wire signed [1:0] sim1 = sc1_q ? (i_sim_down1 ? -2'sd1 : 2'sd1) : 2'sd0;
    wire signed [1:0] st0  = i_src0[0] ? sim0 : i_qstep0;
    wire signed [1:0] st1  = i_src1[0] ? sim1 : i_qstep1;
    wire do_rst0 = (i_rst_req0 && !i_rst_on_trig) || (pend0_q && i_trig);
    wire do_rst1 = (i_rst_req1 && !i_rst_on_trig) || (pend1_q && i_trig);
    wire pend0_d = (i_rst_req0 && i_rst_on_trig) || (pend0_q && !i_trig);
    wire pend1_d = (i_rst_req1 && i_rst_on_trig) || (pend1_q && !i_trig);

    // cnt': the three moves cnt + 1, cnt - 1, cnt - 2 are three-part carry-select adds of the
    // register alone; the value without a move (reset 0, preset load_val or cnt) and a 2-bit code are
    // formed beside them from the inputs, and one 4:1 select follows
    wire [W_CNT-1:0] p0 = csel3(cnt0_q, 32'd1);
    wire [W_CNT-1:0] n0 = csel3(cnt0_q, 32'hffffffff);          // - 1
    wire [W_CNT-1:0] t0 = csel3(cnt0_q, 32'hfffffffe);          // - 2
    wire [W_CNT-1:0] p1 = csel3(cnt1_q, 32'd1);
    wire [W_CNT-1:0] n1 = csel3(cnt1_q, 32'hffffffff);
    wire [W_CNT-1:0] t1 = csel3(cnt1_q, 32'hfffffffe);
    wire [W_CNT-1:0] e0 = do_rst0 ? {W_CNT{1'b0}} : i_load0 ? i_load_val0 : cnt0_q;
    wire [W_CNT-1:0] e1 = do_rst1 ? {W_CNT{1'b0}} : i_load1 ? i_load_val1 : cnt1_q;
    wire             mv0 = !do_rst0 && !i_load0;   // the step applies
    wire             mv1 = !do_rst1 && !i_load1;
    // code: 0 no move (e), 1 +1, 2 -2, 3 -1 (= st when the step applies)
    wire [1:0]       code0 = mv0 ? st0 : 2'b00;
    wire [1:0]       code1 = mv1 ? st1 : 2'b00;
    // 4:1 select as AND-OR (a mux with the register as one leaf would become a flip-flop enable)
    function [W_CNT-1:0] sel4;
        input [1:0] code;
        input [W_CNT-1:0] e, p, t, n;
        begin
            sel4 = (e & {W_CNT{code == 2'b00}}) | (p & {W_CNT{code == 2'b01}}) |
                   (t & {W_CNT{code == 2'b10}}) | (n & {W_CNT{code == 2'b11}});
        end
    endfunction
    wire [W_CNT-1:0] cnt0_d = sel4(code0, e0, p0, t0, n0);
    wire [W_CNT-1:0] cnt1_d = sel4(code1, e1, p1, t1, n1);
    // (do_rst ? 0 : sum, as a mask: a LUT after the chain, not a second synchronous reset net
    // behind the configuration check)
    wire [W_INC-1:0] ph0_d  = ph0_sum[W_INC-1:0] & {W_INC{!do_rst0}};
    wire [W_INC-1:0] ph1_d  = ph1_sum[W_INC-1:0] & {W_INC{!do_rst1}};
    wire signed [1:0] step0_d = (do_rst0 || i_load0) ? 2'sd0 : st0;
    wire signed [1:0] step1_d = (do_rst1 || i_load1) ? 2'sd0 : st1;

    // ---- wait-for-encoder: two register stages --------------------------------------------
    // stage 1, per channel, from the registers: the parts of s32(cnt_c - val) as a carry-select
    // subtract (low-half borrow, upper-half sign without and with borrow-in) and cnt_c == val
    localparam integer H = W_CNT / 2;
    function [3:0] wparts;   // {borrow, sign without borrow, sign with borrow, equal}
        input [W_CNT-1:0] c, v;
        reg [H:0]   dlo;
        reg [H-1:0] dh0, dh1;
        begin
            dlo = {1'b0, c[H-1:0]} - {1'b0, v[H-1:0]};          // [H]: borrow
            dh0 = c[W_CNT-1:H] - v[W_CNT-1:H];                  // no borrow in
            dh1 = c[W_CNT-1:H] + ~v[W_CNT-1:H];                 // borrow in
            wparts = {dlo[H], dh0[H-1], dh1[H-1], c == v};
        end
    endfunction
    wire [3:0] fp0 = wparts(cnt0_q, w_val_q);
    wire [3:0] fp1 = wparts(cnt1_q, w_val_q);
    // stage 2: the parts of the previous call decide (unless an arm came between)
    wire [3:0] fw   = w_ch_q ? f1_q : f0_q;
    wire       fneg = fw[3] ? fw[1] : fw[2];        // s32(cnt_ch - val) < 0
    wire       fpos = !fneg && !fw[0];              // s32(cnt_ch - val) > 0
    wire reached_d = waiting_q && f_ok_q && (w_down_q ? fneg : fpos);
    wire waiting_d = i_wait_arm || (waiting_q && !reached_d);

    // ---- correction: sequenced product ---------------------------------------------------------
    wire sample = ({1'b0, timer_q} + 17'd1) >= {1'b0, i_corr_period};
    wire [W_PER-1:0] timer_inc = timer_q + 16'd1;
    // sample ? 0 : timer + 1, written as a mask: the 17-bit compare stays in the D logic of 16
    // flip-flops instead of becoming their (global-buffered) synchronous reset
    wire [W_PER-1:0] timer_d = timer_inc & {W_PER{!sample}};
    // busy_q = (k in 1..32), done_q = (k == 33): registered copies of the step counter's state
    wire done = done_q;
    wire busy = busy_q;
    // steps (busy): one 33-bit add per channel, hi + (lo[0] ? m : 0), as a carry-select adder
    // (17-bit low part; the upper 16 bits with carry-in 0 and 1, picked by the low carry)
    wire [W_ACC-1:0] y0 = lo0_q[0] ? m0_q : {W_ACC{1'b0}};
    wire [W_ACC-1:0] y1 = lo1_q[0] ? m1_q : {W_ACC{1'b0}};
    wire signed [W_ACC-1:0] s0 = csel_add(hi0_q, y0);
    wire signed [W_ACC-1:0] s1 = csel_add(hi1_q, y1);
    // done: {hi, lo} >> 24, low 40 bits, + p
    wire signed [W_CORR-1:0] q0 = {hi0_q[W_CNT-1:0], lo0_q[W_CNT-1:S_FRAC]};
    wire signed [W_CORR-1:0] q1 = {hi1_q[W_CNT-1:0], lo1_q[W_CNT-1:S_FRAC]};
    wire signed [W_CORR-1:0] corr0_d = csel_add40(q0, {{(W_CORR-W_CNT){p0_q[W_CNT-1]}}, p0_q});
    wire signed [W_CORR-1:0] corr1_d = csel_add40(q1, {{(W_CORR-W_CNT){p1_q[W_CNT-1]}}, p1_q});
    // done ? corr_d : corr, written as data (not as a flip-flop enable, which the synchronous
    // reset of an invalid configuration would have to pass through)
    wire [W_CORR-1:0] corr0_hold = corr0_q ^ ((corr0_q ^ corr0_d) & {W_CORR{done}});
    wire [W_CORR-1:0] corr1_hold = corr1_q ^ ((corr1_q ^ corr1_d) & {W_CORR{done}});
    wire negate = (k_q == 6'd31);   // m := -m after step 30 (k = 31): step 31 subtracts
    wire [5:0] k_d = busy ? k_q + 6'd1 : sample ? 6'd1 : 6'd0;
    wire busy_d = busy ? (k_q != K_DONE - 6'd1) : sample;
    wire done_d = busy && (k_q == K_DONE - 6'd1);

    always @(posedge i_clk) begin
        if (i_rst || !cfg_ok) begin
            cnt0_q <= {W_CNT{1'b0}};
            cnt1_q <= {W_CNT{1'b0}};
            ph0_q <= {W_INC{1'b0}};
            ph1_q <= {W_INC{1'b0}};
            sc0_q <= 1'b0;
            sc1_q <= 1'b0;
            pend0_q <= 1'b0;
            pend1_q <= 1'b0;
            corr0_q <= {W_CORR{1'b0}};
            corr1_q <= {W_CORR{1'b0}};
            k_q <= 6'd0;
            busy_q <= 1'b0;
            done_q <= 1'b0;
            timer_q <= {W_PER{1'b0}};
            waiting_q <= 1'b0;
            f0_q <= 4'd0;
            f1_q <= 4'd0;
            f_ok_q <= 1'b0;
            step0_q <= 2'sd0;
            step1_q <= 2'sd0;
            rst_done0_q <= 1'b0;
            rst_done1_q <= 1'b0;
            tick_q <= 1'b0;
            reached_q <= 1'b0;
            cfg_err_q <= !i_rst;
        end else begin
            cnt0_q <= cnt0_d;
            cnt1_q <= cnt1_d;
            ph0_q <= ph0_d;
            ph1_q <= ph1_d;
            sc0_q <= ph0_sum[W_INC] && !do_rst0;
            sc1_q <= ph1_sum[W_INC] && !do_rst1;
            pend0_q <= pend0_d;
            pend1_q <= pend1_d;
            corr0_q <= corr0_hold;
            corr1_q <= corr1_hold;
            k_q <= k_d;
            busy_q <= busy_d;
            done_q <= done_d;
            timer_q <= timer_d;
            waiting_q <= waiting_d;
            f0_q <= fp0;
            f1_q <= fp1;
            f_ok_q <= !i_wait_arm;
            step0_q <= step0_d;
            step1_q <= step1_d;
            rst_done0_q <= do_rst0;
            rst_done1_q <= do_rst1;
            tick_q <= done;
            reached_q <= reached_d;
            cfg_err_q <= 1'b0;
        end
    end

    // wait value registers: cleared by i_rst only. After an invalid-configuration call they are
    // unused until the next arm (waiting = 0, and the flags of the arm call are not valid), so the
    // configuration check stays out of their enables.
    always @(posedge i_clk) begin
        if (i_rst) begin
            w_ch_q <= 1'b0;
            w_down_q <= 1'b0;
            w_val_q <= {W_CNT{1'b0}};
        end else if (i_wait_arm) begin
            w_ch_q <= i_wait_ch;
            w_down_q <= i_wait_down;
            w_val_q <= i_wait_val;
        end
    end

    // product registers: cleared by i_rst only. They are don't-care while the unit is idle (k = 0,
    // also after an invalid-configuration call) and reloaded in every idle call, so the
    // configuration check stays out of their enables.
    always @(posedge i_clk) begin
        if (i_rst) begin
            hi0_q <= {W_ACC{1'b0}};
            hi1_q <= {W_ACC{1'b0}};
            lo0_q <= {W_CNT{1'b0}};
            lo1_q <= {W_CNT{1'b0}};
            m0_q <= {W_ACC{1'b0}};
            m1_q <= {W_ACC{1'b0}};
            p0_q <= {W_CNT{1'b0}};
            p1_q <= {W_CNT{1'b0}};
        end else begin
            if (!busy) begin   // idle or last call: the operands of a sample in this call
                hi0_q <= HALF;
                hi1_q <= HALF;
                lo0_q <= cnt0_q;
                lo1_q <= cnt1_q;
                m0_q <= {i_scale0[W_SCALE-1], i_scale0};
                m1_q <= {i_scale1[W_SCALE-1], i_scale1};
                p0_q <= i_pos0;
                p1_q <= i_pos1;
            end else begin
                hi0_q <= s0 >>> 1;
                hi1_q <= s1 >>> 1;
                lo0_q <= {s0[0], lo0_q[W_CNT-1:1]};
                lo1_q <= {s1[0], lo1_q[W_CNT-1:1]};
                if (negate) begin
                    m0_q <= -m0_q;
                    m1_q <= -m1_q;
                end
            end
        end
    end

    assign o_cnt0         = cnt0_q;
    assign o_cnt1         = cnt1_q;
    assign o_step0        = step0_q;
    assign o_step1        = step1_q;
    assign o_rst_done0    = rst_done0_q;
    assign o_rst_done1    = rst_done1_q;
    assign o_rst_pending0 = pend0_q;
    assign o_rst_pending1 = pend1_q;
    assign o_corr0        = corr0_q;
    assign o_corr1        = corr1_q;
    assign o_tick         = tick_q;
    assign o_waiting      = waiting_q;
    assign o_reached      = reached_q;
    assign o_cfg_err      = cfg_err_q;

endmodule

`default_nettype wire
