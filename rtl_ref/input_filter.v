// input_filter.v — two-flop synchroniser plus stability (glitch) filter for one asynchronous pin.
//
// Reference RTL of hls/input_filter.h (DESIGN §4.1). One rising clock edge = one call of
// input_filter::step(); the output registers after edge t hold the out_t returned by call t for
// the inputs presented before edge t. Synchronous active-high reset = input_filter::reset().
//
//   glitch = valid && s2 == f && cnt != 0                 (registers before the edge)
//   !valid:      fill == 2 ? (f' = s2, valid' = 1) : fill' = fill + 1
//   s2 == f:     cnt' = 0
//   ready:       f' = s2, cnt' = 0;  else cnt' = cnt + 1
//   ready' = cnt' + 1 >= max(N,1)   (the pass decision of the next edge, with this edge's N)
//   s2' = s1, s1' = pin
//
// o_f / o_valid / o_glitch are registers. o_f_d / o_valid_d / o_glitch_d are the values those
// registers take at the coming edge (their D inputs): a parent block that, like quad_decoder,
// uses the filter output *of the same call* reads these.
// Latency pin -> o_f: max(N,1) + 1 calls (DESIGN §4.1); o_valid is first 1 after call 2.
`timescale 1ns / 1ps
`default_nettype none

module input_filter #(
    // W_CNT: width of the filter length register i_n and of the stability counter
    // (hls: input_filter<W_CNT>; 8 for the A/B/LERR pins, 16 for the switch debounce).
    // Legal range 1..32.
    parameter integer W_CNT = 8
) (
    input  wire             i_clk,
    input  wire             i_rst,      // synchronous, active high: input_filter::reset()
    input  wire             i_pin,      // asynchronous pin level
    input  wire [W_CNT-1:0] i_n,        // filter length N (0 and 1 both: pass after 1 call)
    output wire             o_f,        // filtered level
    output wire             o_valid,    // the synchroniser holds a real sample
    output wire             o_glitch,   // pulse: a change shorter than max(N,1) was suppressed
    output wire             o_f_d,      // next value of o_f (D input of its register)
    output wire             o_valid_d,  // next value of o_valid
    output wire             o_glitch_d  // next value of o_glitch
);

    // ---- elaboration-time parameter check (a missing module stops elaboration) -------------
    generate
        if (W_CNT < 1 || W_CNT > 32) begin : g_bad_w_cnt
            input_filter_PARAMETER_W_CNT_must_be_1_to_32 u_param_error ();
        end
    endgenerate

    // ---- registers -------------------------------------------------------------------------
    reg             s1_q, s2_q, f_q, valid_q, glitch_q, ready_q;
    reg             take_q;     // this call loads f from s2 if s2 != f: valid ? ready : fill == 2
    // the stability counter cnt of hls/input_filter.h is kept as ~(cnt + 2) (nc2, W_CNT + 1 bits:
    // cnt < max(N,1) <= 2^W_CNT - 1, so cnt + 2 <= 2^W_CNT): cnt + 2 is the value the pass compare
    // needs, and held inverted it meets i_n in a carry chain without an inverted operand (which
    // costs a LUT per bit on the iCE40); the count is a decrement of nc2
    reg [W_CNT:0]   nc2_q;
    reg             cnz_q;      // nc2 != ~2 (cnt != 0), kept beside nc2 so the glitch test is one LUT
    reg [1:0]       fill_q;

    reg             s1_d, s2_d, f_d, valid_d, glitch_d, ready_d, take_d;
    reg [W_CNT:0]   nc2_d;
    reg             cnz_d;
    reg [1:0]       fill_d;

    // Pass decision of the next edge (DESIGN 4.1 `ready`), with this edge's N: cnt' + 1 >= max(N,1).
    // cnt' is 0 (-> 1 >= max(N,1)) or cnt + 1 (-> cnt + 2 >= max(N,1)); both compares are formed
    // from the registers and i_n in parallel with the filter logic, which only selects.
    // max(N,1) <= 1 <=> N <= 1, and (cnt + 2 >= 2) max(N,1) <= cnt + 2 <=> N <= cnt + 2 <=>
    // !(N > cnt + 2) <=> no carry out of N + ~(cnt + 2) (W_CNT + 1 bits): the compare takes i_n
    // and the register nc2 = ~(cnt + 2) as they are (one chain, no add or inverter before it)
    localparam [W_CNT:0] C2_ZERO  = 2;          // cnt + 2 of cnt = 0
    localparam [W_CNT:0] NC2_ZERO = ~C2_ZERO;   // nc2 of cnt = 0
    // N <= 1 as a zero test of N's bits above bit 0 (a compare with the constant 1 is mapped to a
    // carry chain with an inverter per bit of N on the iCE40)
    wire             rdy_0   = (i_n >> 1) == {W_CNT{1'b0}};
    wire [W_CNT+1:0] n_gt_s  = {2'b00, i_n} + {1'b0, nc2_q};
    wire             rdy_inc = !n_gt_s[W_CNT+1];

    always @* begin
        s1_d     = i_pin;
        s2_d     = s1_q;
        valid_d  = valid_q;
        nc2_d    = nc2_q;
        cnz_d    = cnz_q;
        fill_d   = fill_q;
        glitch_d = valid_q && (s2_q == f_q) && cnz_q;
        if (!valid_q) begin
            if (fill_q == 2'd2) begin
                valid_d = 1'b1;          // first sample: f loaded (take), not filtered
            end else begin
                fill_d = fill_q + 2'd1;
            end
        end else if (s2_q == f_q) begin
            nc2_d = NC2_ZERO;
            cnz_d = 1'b0;
        end else if (ready_q) begin
            nc2_d = NC2_ZERO;            // f loaded (take)
            cnz_d = 1'b0;
        end else begin
            nc2_d = nc2_q - 1'b1;        // ~(c2 + 1); cnt + 1 < max(N(t-1),1) <= 2^W_CNT - 1: fits
            cnz_d = 1'b1;                // c2 >= 2, so c2 + 1 >= 3
        end
        ready_d = (valid_q && s2_q != f_q && !ready_q) ? rdy_inc : rdy_0;
        // the branches above that load f, as one register: f_d is then take ? s2 : f (one LUT
        // from flip-flops), so the decoder that reads f_d in the same call starts early
        take_d  = valid_d ? ready_d : (fill_d == 2'd2);
        f_d     = take_q ? s2_q : f_q;
    end

    always @(posedge i_clk) begin
        if (i_rst) begin
            s1_q     <= 1'b0;
            s2_q     <= 1'b0;
            f_q      <= 1'b0;
            valid_q  <= 1'b0;
            glitch_q <= 1'b0;
            ready_q  <= 1'b0;
            take_q   <= 1'b0;
            nc2_q    <= NC2_ZERO;
            cnz_q    <= 1'b0;
            fill_q   <= 2'd0;
        end else begin
            s1_q     <= s1_d;
            s2_q     <= s2_d;
            f_q      <= f_d;
            valid_q  <= valid_d;
            glitch_q <= glitch_d;
            ready_q  <= ready_d;
            take_q   <= take_d;
            nc2_q    <= nc2_d;
            cnz_q    <= cnz_d;
            fill_q   <= fill_d;
        end
    end

    assign o_f        = f_q;
    assign o_valid    = valid_q;
    assign o_glitch   = glitch_q;
    // Next-state values (meaningful while i_rst is low; a parent shares the reset).
    assign o_f_d      = f_d;
    assign o_valid_d  = valid_d;
    assign o_glitch_d = glitch_d;

`ifdef FORMAL
    // helper invariant (read_verilog -formal, docs/FORMAL.md): take is the register form of the
    // load condition of the branches above, in every state reached after a reset
    reg f_init_if;
    initial f_init_if = 1'b0;
    always @(posedge i_clk) if (i_rst) f_init_if <= 1'b1;
    // c2 = cnt + 2 stays in [2, 2^W_CNT]: it counts only while !ready, and !ready says that the
    // last count left it below N <= 2^W_CNT - 1; before the first sample it holds its reset value
    localparam [W_CNT:0] C2_MAX = {1'b1, {W_CNT{1'b0}}};   // 2^W_CNT
    wire       [W_CNT:0] f_c2 = ~nc2_q;                     // cnt + 2
    always @* if (f_init_if) begin
        assert(take_q == (valid_q ? ready_q : (fill_q == 2'd2)));
        assert(f_c2 >= C2_ZERO && f_c2 <= C2_MAX);
        assert(cnz_q == (f_c2 != C2_ZERO));
        if (!valid_q) assert(f_c2 == C2_ZERO);
        if (!ready_q) assert(f_c2 < C2_MAX);
    end
`endif

endmodule

`default_nettype wire
