// error_map.v — position error mapping (reference RTL of hls/error_map.h, docs/ERROR_MAP.md).
//
// A correction table over equally spaced positions, linear interpolation between points, the
// correction delivered as whole output counts (corr) and as the change since the previous call
// (delta). Two banks of 2048 x 24-bit words (two RAMs, tbl0 and tbl1, as the two arrays of
// hls/error_map.h) with their own geometry (origin, spacing_log2 k, n_points); the write port
// always writes the bank that is not selected in that call, so a reload can never mix tables and
// each RAM sees at most two accesses per edge (the two reads, or the write).
//
// Timing (one rising edge = one call of error_map::step()):
//   stage A (edge t):   off = p - origin, clamp to [0, (n-1) 2^k], i = off >> k,
//                       frac = off mod 2^k; the two RAM reads T[i], T[i+1] of the selected bank,
//                       frac, k and the flags are registered (t0_q, t1_q, frac_q, k_q, act_q,
//                       inr_q, err_q).
//   stage B (edge t+1): num = T[i] 2^k + (T[i+1] - T[i]) frac (46 bits, exact),
//                       corr = act ? floor(num / 2^(8+k) + 1/2) : 0, delta = corr - corr_prev:
//                       output registers.
// Latency: p presented before edge t is reflected in the outputs after edge t+1 (2 calls).
//
// i_rst (synchronous, active high) is error_map::reset(): the pipeline only, never the RAM. The
// write port is disabled in a reset call (the C++ step() is not called in the safe state).
`timescale 1ns / 1ps
`default_nettype none

module error_map (
    input  wire               i_clk,
    input  wire               i_rst,       // synchronous, active high: error_map::reset()
    input  wire signed [37:0] i_p,         // uncorrected position (comp), output counts
    input  wire               i_homed,     // rephase homed (registered status)
    input  wire               i_map_en,
    input  wire               i_bank_sel,  // active bank of this call
    input  wire signed [37:0] i_origin0,   // bank 0 geometry
    input  wire [4:0]         i_k0,
    input  wire [11:0]        i_n0,
    input  wire signed [37:0] i_origin1,   // bank 1 geometry
    input  wire [4:0]         i_k1,
    input  wire [11:0]        i_n1,
    input  wire               i_we,        // table write port: writes bank !bank_sel
    input  wire [10:0]        i_addr,
    input  wire signed [23:0] i_data,      // Q15.8 output counts
    output wire signed [16:0] o_corr,
    output wire signed [17:0] o_delta,
    output wire               o_active,
    output wire               o_in_range,
    output wire               o_clamped,
    output wire               o_cfg_err
);

    // ---- fixed widths (hls: error_map_cfg) ---------------------------------------------------
    localparam integer TBL_DEPTH = 2048;
    localparam integer W_CORR    = 24;
    localparam integer F         = 8;
    localparam [4:0]   K_MIN     = 5'd4;
    localparam [4:0]   K_MAX     = 5'd20;
    localparam integer W_ADDR    = 11;
    localparam integer W_OFF     = 39;
    localparam integer W_FRAC    = 20;
    localparam integer W_NUM     = 46;
    localparam integer W_C       = 17;
    localparam integer W_CDELTA  = 18;

    // ---- table RAM (not reset) ---------------------------------------------------------------
    reg signed [W_CORR-1:0] tbl0 [0:TBL_DEPTH-1];   // bank 0
    reg signed [W_CORR-1:0] tbl1 [0:TBL_DEPTH-1];   // bank 1

    // ---- registers ---------------------------------------------------------------------------
    wire signed [W_CORR-1:0]  t0_q, t1_q;   // T[i], T[i+1] (registered RAM outputs, bank mux)
    reg        [W_FRAC-1:0]   frac_q;
    reg        [4:0]          k_q;
    reg                       act_q, inr_q, err_q;
    reg signed [W_C-1:0]      corr_q;       // output corr (= corr of the previous call's output)
    reg signed [W_CDELTA-1:0] delta_q;
    reg                       active_oq, inr_oq, err_oq;

    // ---- stage B: interpolation of the stage A registers -------------------------------------
    wire signed [W_CORR:0]    diff    = {t1_q[W_CORR-1], t1_q} - {t0_q[W_CORR-1], t0_q};
    wire signed [W_FRAC:0]    frac_s  = {1'b0, frac_q};
    wire signed [W_NUM-1:0]   t0_x    = {{(W_NUM-W_CORR){t0_q[W_CORR-1]}}, t0_q};
    wire signed [W_NUM-1:0]   prod    = diff * frac_s;
    wire signed [W_NUM-1:0]   num     = (t0_x <<< k_q) + prod;
    wire        [5:0]         sh      = 6'd8 + {1'b0, k_q};
    wire signed [W_NUM-1:0]   half    = {{(W_NUM-1){1'b0}}, 1'b1} <<< (sh - 6'd1);
    wire signed [W_NUM-1:0]   rnd     = (num + half) >>> sh;
    wire signed [W_C-1:0]     c_next  = act_q ? rnd[W_C-1:0] : {W_C{1'b0}};
    wire signed [W_CDELTA-1:0] d_next = {c_next[W_C-1], c_next} - {corr_q[W_C-1], corr_q};

    // ---- stage A: geometry of the selected bank, clamp, addresses ----------------------------
    wire signed [37:0]        g_origin = i_bank_sel ? i_origin1 : i_origin0;
    wire        [4:0]         g_k      = i_bank_sel ? i_k1 : i_k0;
    wire        [11:0]        g_n      = i_bank_sel ? i_n1 : i_n0;
    wire                      geom_ok  = g_k >= K_MIN && g_k <= K_MAX && g_n >= 12'd2 && g_n <= 12'd2048;
    wire        [4:0]         k        = geom_ok ? g_k : K_MIN;
    wire        [11:0]        n_m1     = g_n - 12'd1;
    wire        [W_ADDR-1:0]  last_i   = geom_ok ? n_m1[W_ADDR-1:0] : {W_ADDR{1'b0}};
    wire signed [W_OFF-1:0]   off      = {i_p[37], i_p} - {g_origin[37], g_origin};
    wire signed [W_OFF-1:0]   last_off = {{(W_OFF-W_ADDR){1'b0}}, last_i} <<< k;
    wire signed [W_OFF-1:0]   off_sh   = off >>> k;
    wire signed [W_OFF-1:0]   mask     = ({{(W_OFF-1){1'b0}}, 1'b1} <<< k) - {{(W_OFF-1){1'b0}}, 1'b1};
    wire signed [W_OFF-1:0]   off_fr   = off & mask;
    wire                      below    = off < 0;
    wire                      above    = !below && off >= last_off;
    wire        [W_ADDR-1:0]  i0       = below ? {W_ADDR{1'b0}} : above ? last_i : off_sh[W_ADDR-1:0];
    wire        [W_FRAC-1:0]  frac     = (below || above) ? {W_FRAC{1'b0}} : off_fr[W_FRAC-1:0];
    wire                      inr      = below ? 1'b0 : above ? (off == last_off) : 1'b1;
    wire        [W_ADDR-1:0]  i1       = (i0 == last_i) ? i0 : i0 + {{(W_ADDR-1){1'b0}}, 1'b1};

    // RAMs: two registered reads of the selected bank, one write of the other bank
    always @(posedge i_clk) begin
        if (!i_rst && i_we && i_bank_sel) tbl0[i_addr] <= i_data;
    end
    always @(posedge i_clk) begin
        if (!i_rst && i_we && !i_bank_sel) tbl1[i_addr] <= i_data;
    end
    // registered reads (BRAM read registers with read enable: only the selected bank is read, so
    // the other RAM sees at most the write) and the bank they were taken for
    reg signed [W_CORR-1:0] rd0_0_q, rd0_1_q, rd1_0_q, rd1_1_q;
    reg                     rd_sel_q;
    always @(posedge i_clk) begin
        if (i_rst) begin
            rd0_0_q  <= {W_CORR{1'b0}};
            rd0_1_q  <= {W_CORR{1'b0}};
            rd1_0_q  <= {W_CORR{1'b0}};
            rd1_1_q  <= {W_CORR{1'b0}};
            rd_sel_q <= 1'b0;
        end else begin
            if (!i_bank_sel) begin
                rd0_0_q <= tbl0[i0];
                rd0_1_q <= tbl0[i1];
            end
            if (i_bank_sel) begin
                rd1_0_q <= tbl1[i0];
                rd1_1_q <= tbl1[i1];
            end
            rd_sel_q <= i_bank_sel;
        end
    end
    assign t0_q = rd_sel_q ? rd1_0_q : rd0_0_q;
    assign t1_q = rd_sel_q ? rd1_1_q : rd0_1_q;

    always @(posedge i_clk) begin
        if (i_rst) begin
            frac_q    <= {W_FRAC{1'b0}};
            k_q       <= K_MIN;
            act_q     <= 1'b0;
            inr_q     <= 1'b0;
            err_q     <= 1'b0;
            corr_q    <= {W_C{1'b0}};
            delta_q   <= {W_CDELTA{1'b0}};
            active_oq <= 1'b0;
            inr_oq    <= 1'b0;
            err_oq    <= 1'b0;
        end else begin
            // stage B (from the stage A registers of the previous call)
            corr_q    <= c_next;
            delta_q   <= d_next;
            active_oq <= act_q;
            inr_oq    <= act_q && inr_q;
            err_oq    <= err_q;
            // stage A
            frac_q    <= frac;
            k_q       <= k;
            act_q     <= i_map_en && i_homed && geom_ok;
            inr_q     <= inr;
            err_q     <= i_map_en && !geom_ok;
        end
    end

    assign o_corr     = corr_q;
    assign o_delta    = delta_q;
    assign o_active   = active_oq;
    assign o_in_range = inr_oq;
    assign o_clamped  = active_oq && !inr_oq;
    assign o_cfg_err  = err_oq;

endmodule

`default_nettype wire
