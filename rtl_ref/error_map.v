// error_map.v — position error mapping (reference RTL of hls/error_map.h, docs/ERROR_MAP.md).
//
// A correction table over equally spaced positions, linear interpolation between points, the
// correction delivered as whole output counts (corr) and as the change since the previous call
// (delta). Two banks of TBL_DEPTH = 1024 x 24-bit words with their own geometry (origin,
// spacing_log2 k, n_points); the even and the odd words are two RAMs of 2 x 512 x 24 bits (tble,
// tblo: the bank is the top address bit; the four arrays tbl<b>e / tbl<b>o of hls/error_map.h), so
// the two points T[i], T[i+1] of an interval are one read of each RAM, in the selected bank. The
// write port always writes the bank that is not selected in that call, delayed by three registers
// (w1..w3) so that it is done in the same clock as that call's reads: a RAM's read port (selected
// bank) and write port (other bank) never meet at one address, and a reload can never mix tables.
// iCE40: each RAM is six SB_RAM40_4K (1024 x 4), 12 in all; the RAMs start at 0 (initial
// contents), as the C++ tables.
//
// The inputs are sampled once every S_MAP = 32 calls (phase counter ph, 0 after reset: the calls
// with ph = 0); stages A .. D run every call (one rising edge = one call of error_map::step(),
// stage X of call t at edge t + (X - A)), the multiplier takes the sample's operands from D:
//   A  a_off = p - origin (39 bits, carry-select halves), geometry check, k, last, flags, bank;
//      w1 = the write port
//   B  b_neg, b_hi (off >= 2^(k+10)), b_i = off[k+9:k], b_u = off[k-1:0] left-aligned to 20 bits
//   C  clamp (above = !neg && (hi || i >= last)), i, u, inr; the RAM addresses (i+1)/2 (even)
//      and i/2 (odd) registered
//   R  registered RAM reads (selected bank: the address's top bit); the write of w3 (other bank)
//   D  d_e = even word, d_o = odd word, d_v = i odd ? 2^20 - u : u
//   M  ph = 5: load m_hi = 0, m_v = d_v, m_diff = d_o - d_e (25 bits), m_e = d_e + 128, flags;
//      ph = 6 .. 26: s = m_hi + (m_v[0] ? m_diff : 0) (26 bits), m_hi = s >>> 1, m_b = s[0],
//      m_v = m_v >> 1  (21 shift-and-add steps, LSB first)
//   G  ph = 27: corr = act ? (2 m_hi + m_e + m_b) >>> 8 : 0   (= floor((e 2^20 + diff v + 2^27) / 2^28))
//   H  every edge: output registers corr, delta = corr - corr_prev, active, in_range, cfg_err
// Latency: the inputs of a sample call t are reflected in the outputs after edge t+28 (L_MAP = 29)
// and held until edge t+59.
//
// i_rst (synchronous, active high) is error_map::reset(): the pipeline's control and output
// registers only, never the RAM. The data registers of the stages are not reset: their values are
// only used while the stage's act flag (reset to 0) is 1. During a reset call the write port takes
// no new write (the C++ step() is not called in the safe state) but the writes already in w1..w3
// still reach the RAM (the C++ reset() performs them): a write of a running call is never lost.
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
    input  wire [10:0]        i_n0,
    input  wire signed [37:0] i_origin1,   // bank 1 geometry
    input  wire [4:0]         i_k1,
    input  wire [10:0]        i_n1,
    input  wire               i_we,        // table write port: writes bank !bank_sel
    input  wire [9:0]         i_addr,
    input  wire signed [23:0] i_data,      // Q15.8 output counts
    output wire signed [16:0] o_corr,
    output wire signed [17:0] o_delta,
    output wire               o_active,
    output wire               o_in_range,
    output wire               o_clamped,
    output wire               o_cfg_err
);

    // ---- fixed widths (hls: error_map_cfg) ---------------------------------------------------
    localparam integer TBL_DEPTH = 1024;
    localparam integer W_CORR    = 24;
    localparam [4:0]   K_MIN     = 5'd4;
    localparam [4:0]   K_MAX     = 5'd20;
    localparam integer W_ADDR    = 10;
    localparam integer W_HADDR   = 9;
    localparam integer W_N       = 11;
    localparam integer W_OFF     = 39;
    localparam integer W_FRAC    = 20;
    localparam integer W_V       = 21;
    localparam integer W_DIFF    = 25;
    localparam integer W_MHI     = 26;
    localparam integer W_ME      = 25;
    localparam integer W_G       = 27;
    localparam integer F         = 8;
    localparam [4:0]   PH_LOAD   = 5'd5;
    localparam [4:0]   PH_G      = 5'd27;
    localparam integer W_C       = 17;
    localparam integer W_CDELTA  = 18;

    // ---- table RAMs (not reset): even and odd words, both banks in one RAM each ------------------
    // tble[{b, j}] = T_b[2j], tblo[{b, j}] = T_b[2j + 1]: the bank is the top address bit, so the
    // read port (selected bank) and the write port (the other bank, delayed to the clock of the
    // reads) of one RAM never meet at one address, and the words of the selected bank come out of
    // the RAM without a bank multiplexer. no_rw_check tells Yosys so; without it, it adds an
    // address comparator and a bypass multiplexer for a collision that cannot happen (measured:
    // 2 ns of the read-address path).
    (* no_rw_check *) reg signed [W_CORR-1:0] tble [0:TBL_DEPTH-1];
    (* no_rw_check *) reg signed [W_CORR-1:0] tblo [0:TBL_DEPTH-1];
    // Power-up contents 0, as the C++ tables (block RAM initial contents on the iCE40). At the
    // held end of a table (i = n - 1, u = 0) the word of the other RAM is read but multiplied by
    // 0 (or cancelled, ERROR_MAP.md §4); it may lie beyond the loaded words, so it must not be X.
`ifndef FORMAL
    integer ii;
    initial begin
        for (ii = 0; ii < TBL_DEPTH; ii = ii + 1) begin
            tble[ii] = {W_CORR{1'b0}};
            tblo[ii] = {W_CORR{1'b0}};
        end
    end
`endif

    // ---- stage A: geometry of the selected bank, registered subtract -------------------------
    wire        [4:0]         g_k      = i_bank_sel ? i_k1 : i_k0;
    wire        [W_N-1:0]     g_n      = i_bank_sel ? i_n1 : i_n0;
    // geometry check of each bank as plain logic (no carry chains), then the bank multiplexer:
    // 4 <= k <= 20 and 2 <= n <= 1024
    wire k0_ok = (i_k0[4] ? (i_k0[3:0] <= 4'd4) : (i_k0[3:2] != 2'b00));
    wire k1_ok = (i_k1[4] ? (i_k1[3:0] <= 4'd4) : (i_k1[3:2] != 2'b00));
    wire n0_ok = i_n0[10] ? (i_n0[9:0] == 10'd0) : (i_n0[9:1] != 9'd0);
    wire n1_ok = i_n1[10] ? (i_n1[9:0] == 10'd0) : (i_n1[9:1] != 9'd0);
    wire                      geom_ok  = i_bank_sel ? (k1_ok && n1_ok) : (k0_ok && n0_ok);
    wire        [W_N-1:0]     n_m1     = g_n - 11'd1;

    reg signed [W_OFF-1:0]  a_off;
    reg        [4:0]        a_k;
    reg        [W_ADDR-1:0] a_last;
    reg                     a_bank, a_act, a_err;
    // write port, delayed to stage R
    reg                     w1_we, w1_bank, w2_we, w2_bank, w3_we, w3_bank;
    reg        [W_ADDR-1:0] w1_addr, w2_addr, w3_addr;
    reg signed [W_CORR-1:0] w1_data, w2_data, w3_data;

    // p - origin = p + ~origin + 1 as a carry-select add: the low 20 bits and both candidates of
    // the high 19 bits (carry 0 / 1) side by side, then the select (two 20-bit carry chains instead
    // of one of 39). ~origin of the selected bank: the bank multiplexer's LUT inverts for free (an
    // inverted operand of a carry chain is one more LUT per bit on the iCE40)
    localparam integer W_LO = 20;
    wire [37:0]             ng_origin = i_bank_sel ? ~i_origin1 : ~i_origin0;
    wire [W_LO:0]           off_lo  = {1'b0, i_p[W_LO-1:0]} + {1'b0, ng_origin[W_LO-1:0]} + {{W_LO{1'b0}}, 1'b1};  // [W_LO]: no borrow
    wire [W_OFF-W_LO-1:0]   p_hi    = {i_p[37], i_p[37:W_LO]};
    wire [W_OFF-W_LO-1:0]   no_hi   = {ng_origin[37], ng_origin[37:W_LO]};
    wire [W_OFF-W_LO-1:0]   off_hi0 = p_hi + no_hi;                            // p_hi - o_hi - 1
    wire [W_OFF-W_LO-1:0]   off_hi1 = p_hi + no_hi + {{(W_OFF-W_LO-1){1'b0}}, 1'b1};  // p_hi - o_hi
    always @(posedge i_clk) begin
        a_off  <= {off_lo[W_LO] ? off_hi1 : off_hi0, off_lo[W_LO-1:0]};
        // with an invalid geometry the sample is inactive (a_act = 0) and k, last are not used:
        // they are taken raw here (the C++ model substitutes K_MIN / 0 to keep its shifts defined)
        a_k    <= g_k;
        a_last <= n_m1[W_ADDR-1:0];
        a_bank <= i_bank_sel;
        w1_bank <= !i_bank_sel;
        w1_addr <= i_addr;
        w1_data <= i_data;
        w2_we   <= w1_we;
        w2_bank <= w1_bank;
        w2_addr <= w1_addr;
        w2_data <= w1_data;
        w3_we   <= w2_we;
        w3_bank <= w2_bank;
        w3_addr <= w2_addr;
        w3_data <= w2_data;
        if (i_rst) begin
            a_act <= 1'b0;
            a_err <= 1'b0;
            w1_we <= 1'b0;
        end else begin
            a_act <= i_map_en && i_homed && geom_ok;
            a_err <= i_map_en && !geom_ok;
            w1_we <= i_we;
        end
    end

    // ---- stage B: split the offset (field selects by k, no compare) --------------------------
    // suffix OR of the offset's magnitude bits: sor[j] = |a_off[37:j]; b_hi = sor[k + 10]
    wire [W_OFF-1:0] sor;
    assign sor[W_OFF-1] = 1'b0;
    genvar gj;
    generate
        for (gj = W_OFF - 2; gj >= 0; gj = gj - 1) begin : g_sor
            assign sor[gj] = sor[gj+1] | a_off[gj];
        end
    endgenerate
    wire [31:0]       sor_hi = {{(32-W_OFF+W_ADDR){1'b0}}, sor[W_OFF-1:W_ADDR]};  // [k] = |a_off[37:k+10]
    // i = off[k+9:k] and u = off[k-1:0] << (20 - k) are the fields [29:20] and [19:0] of
    // {off[29:0], 20 zeros} >> k (k <= K_MAX = 20 while active): one shifter for both fields
    wire [W_ADDR+2*W_FRAC-1:0] off_w  = {a_off[W_ADDR+W_FRAC-1:0], {W_FRAC{1'b0}}};
    wire [W_ADDR+2*W_FRAC-1:0] off_sw = off_w >> a_k;
    wire [W_ADDR-1:0]          off_sh = off_sw[W_ADDR+W_FRAC-1:W_FRAC];
    wire [W_FRAC-1:0]          u_sh   = off_sw[W_FRAC-1:0];
    // even-RAM address (last + 1) / 2 of the clamp candidate last (that of i is formed in C)
    wire [W_ADDR:0]   last_p1 = {1'b0, a_last} + {{W_ADDR{1'b0}}, 1'b1};

    reg                     b_neg, b_hi, b_bank, b_act, b_err;
    reg        [W_ADDR-1:0] b_i, b_last;
    reg        [W_HADDR-1:0] b_laste;             // (last + 1) / 2
    reg        [W_FRAC-1:0] b_u;
    always @(posedge i_clk) begin
        b_neg  <= a_off[W_OFF-1];
        b_hi   <= sor_hi[a_k];
        b_i    <= off_sh[W_ADDR-1:0];
        b_laste <= last_p1[W_HADDR:1];
        b_u    <= u_sh;
        b_last <= a_last;
        b_bank <= a_bank;
        if (i_rst) begin
            b_act <= 1'b0;
            b_err <= 1'b0;
        end else begin
            b_act <= a_act;
            b_err <= a_err;
        end
    end

    // ---- stage C: clamp, the two RAM addresses (registered) --------------------------------------
    wire                above  = !b_neg && (b_hi || b_i >= b_last);
    wire [W_ADDR-1:0]   ci     = b_neg ? {W_ADDR{1'b0}} : above ? b_last : b_i;
    wire [W_FRAC-1:0]   cu     = (b_neg || above) ? {W_FRAC{1'b0}} : b_u;
    wire                cinr   = !b_neg && (!above || (!b_hi && b_i == b_last && b_u == {W_FRAC{1'b0}}));
    wire [W_ADDR:0]     bi_p1  = {1'b0, b_i} + {{W_ADDR{1'b0}}, 1'b1};   // beside the compare
    wire [W_HADDR-1:0]  ea     = b_neg ? {W_HADDR{1'b0}} : above ? b_laste : bi_p1[W_HADDR:1];  // (i+1)/2
    wire [W_HADDR-1:0]  oa     = ci[W_ADDR-1:1];

    reg [W_HADDR-1:0] c_ea, c_oa;
    reg               c_lsb, c_bank, c_act, c_inr, c_err;
    reg [W_FRAC-1:0]  c_u;
    always @(posedge i_clk) begin
        c_ea   <= ea;
        c_oa   <= oa;
        c_lsb  <= ci[0];
        c_u    <= cu;
        c_bank <= b_bank;
        c_inr  <= cinr;
        if (i_rst) begin
            c_act <= 1'b0;
            c_err <= 1'b0;
        end else begin
            c_act <= b_act;
            c_err <= b_err;
        end
    end

    // ---- stage R: one registered read of each RAM (selected bank), the delayed write ----------
    reg signed [W_CORR-1:0] rd_e, rd_o;   // registered RAM outputs
`ifdef FORMAL
    // formal: the table contents are free (the properties below hold for any table); every read
    // returns an arbitrary word
    (* anyseq *) wire signed [W_CORR-1:0] f_rd_e, f_rd_o;
    always @(posedge i_clk) begin
        rd_e <= f_rd_e;
        rd_o <= f_rd_o;
    end
`else
    always @(posedge i_clk) begin
        rd_e <= tble[{c_bank, c_ea}];
        rd_o <= tblo[{c_bank, c_oa}];
    end
    always @(posedge i_clk) begin
        if (w3_we && !w3_addr[0]) tble[{w3_bank, w3_addr[W_ADDR-1:1]}] <= w3_data;
    end
    always @(posedge i_clk) begin
        if (w3_we && w3_addr[0]) tblo[{w3_bank, w3_addr[W_ADDR-1:1]}] <= w3_data;
    end
`endif

    reg              r_lsb, r_act, r_inr, r_err;
    reg [W_FRAC-1:0] r_u;
    always @(posedge i_clk) begin
        r_lsb  <= c_lsb;
        r_u    <= c_u;
        r_inr  <= c_inr;
        if (i_rst) begin
            r_act <= 1'b0;
            r_err <= 1'b0;
        end else begin
            r_act <= c_act;
            r_err <= c_err;
        end
    end

    // ---- stage D: the words of the selected bank, orientation (the difference is formed by the M
    // load). v = lsb ? 2^20 - u : u as one adder: (u ^ {lsb}) + lsb, 20 bits and the carry into
    // bit 20
    wire signed [W_CORR-1:0] we_m = rd_e;
    wire signed [W_CORR-1:0] wo_m = rd_o;
    wire        [W_V-1:0]    v_d  = {1'b0, r_u ^ {W_FRAC{r_lsb}}} + {{(W_V-1){1'b0}}, r_lsb};
    reg signed [W_CORR-1:0] d_e, d_o;
    reg        [W_V-1:0]    d_v;
    reg                     d_act, d_inr, d_err;
    always @(posedge i_clk) begin
        d_e    <= we_m;
        d_o    <= wo_m;
        d_v    <= v_d;
        d_inr  <= r_inr;
        if (i_rst) begin
            d_act <= 1'b0;
            d_err <= 1'b0;
        end else begin
            d_act <= r_act;
            d_err <= r_err;
        end
    end

    // ---- phase counter: ph = 0 marks a sample call ----------------------------------------------
    reg [4:0] ph;
    always @(posedge i_clk) begin
        if (i_rst) ph <= 5'd0;
        else       ph <= ph + 5'd1;   // wraps at S_MAP = 32
    end

    // ---- M: sequenced multiply (d_o - d_e) * d_v, LSB first ------------------------------------------
    reg signed [W_MHI-1:0]  m_hi;
    reg                     m_b;
    reg        [W_V-1:0]    m_v;
    reg signed [W_DIFF-1:0] m_diff;
    reg signed [W_ME-1:0]   m_e;
    reg                     m_act, m_inr, m_err;
    wire                    m_step = ph > PH_LOAD && ph < PH_G;
    wire signed [W_MHI-1:0] m_add  = m_v[0] ? {m_diff[W_DIFF-1], m_diff} : {W_MHI{1'b0}};
    wire signed [W_MHI-1:0] m_s    = m_hi + m_add;
    always @(posedge i_clk) begin
        if (ph == PH_LOAD) begin
            m_hi   <= {W_MHI{1'b0}};
            m_b    <= 1'b0;
            m_v    <= d_v;
            m_diff <= {d_o[W_CORR-1], d_o} - {d_e[W_CORR-1], d_e};
            m_e    <= {d_e[W_CORR-1], d_e} + {{(W_ME-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            m_inr  <= d_inr;
        end else if (m_step) begin
            m_hi   <= m_s >>> 1;
            m_b    <= m_s[0];
            m_v    <= m_v >> 1;
        end
        if (i_rst) begin
            m_act <= 1'b0;
            m_err <= 1'b0;
        end else if (ph == PH_LOAD) begin
            m_act <= d_act;
            m_err <= d_err;
        end
    end

    // ---- stage G: round the sample's product (ph = PH_G), held otherwise ----------------------------
    wire signed [W_G-1:0] g_x = {m_hi, 1'b0} + {{(W_G-W_ME){m_e[W_ME-1]}}, m_e} + {{(W_G-1){1'b0}}, m_b};
    reg signed [W_C-1:0] g_corr;
    reg                  g_act, g_inr, g_err;
    always @(posedge i_clk) begin
        if (ph == PH_G) g_inr <= m_inr;
        if (i_rst) begin
            g_corr <= {W_C{1'b0}};
            g_act  <= 1'b0;
            g_err  <= 1'b0;
        end else if (ph == PH_G) begin
            g_corr <= m_act ? g_x[F+W_C-1:F] : {W_C{1'b0}};
            g_act  <= m_act;
            g_err  <= m_err;
        end
    end

    // ---- stage H: output registers ---------------------------------------------------------------
    reg signed [W_C-1:0]      corr_q;
    reg signed [W_CDELTA-1:0] delta_q;
    reg                       active_oq, inr_oq, err_oq;
    always @(posedge i_clk) begin
        if (i_rst) begin
            corr_q    <= {W_C{1'b0}};
            delta_q   <= {W_CDELTA{1'b0}};
            active_oq <= 1'b0;
            inr_oq    <= 1'b0;
            err_oq    <= 1'b0;
        end else begin
            corr_q    <= g_corr;
            delta_q   <= {g_corr[W_C-1], g_corr} - {corr_q[W_C-1], corr_q};
            active_oq <= g_act;
            inr_oq    <= g_act && g_inr;
            err_oq    <= g_err;
        end
    end

    assign o_corr     = corr_q;
    assign o_delta    = delta_q;
    assign o_active   = active_oq;
    assign o_in_range = inr_oq;
    assign o_clamped  = active_oq && !inr_oq;
    assign o_cfg_err  = err_oq;

`ifdef FORMAL
    // ---- formal properties (read_verilog -formal; see docs/FORMAL.md) --------------------------
    // For any table contents, any positions and any register values:
    // 1. conservation: the deltas since reset add up to corr in every call (the pacer receives
    //    exactly the correction; the delta form loses or adds nothing);
    // 2. corr changes at most once per S_MAP = 32 calls, in a fixed call of the phase (delta is
    //    non-zero only with ph == PH_G + 2);
    // 3. a map switched off takes its correction back in full: after 64 calls in a row with
    //    map_en == 0 or homed == 0, corr == 0, delta == 0 and active == 0 (with 1., the deltas
    //    have returned exactly what they added).
    reg                f_init;
    initial f_init = 1'b0;
    reg signed [23:0]  f_sum;                          // the deltas of the calls before this one
    reg [6:0]          f_off;                          // calls in a row with the map off, saturating
    wire               f_offn = !i_map_en || !i_homed;
    wire [4:0]         f_sl = ph - (PH_LOAD + 5'd1);   // calls since M was loaded
    wire [4:0]         f_sg = ph - (PH_G + 5'd1);      // calls since stage G was loaded
    wire [4:0]         f_sc = ph - (PH_G + 5'd2);      // calls since corr took stage G's value
    always @(posedge i_clk) begin
        if (i_rst) begin
            f_init <= 1'b1;
            f_sum  <= 24'sd0;
            f_off  <= 7'd0;
        end else begin
            f_sum  <= f_sum + {{(24-W_CDELTA){delta_q[W_CDELTA-1]}}, delta_q};
            f_off  <= !f_offn ? 7'd0 : (f_off == 7'd127 ? f_off : f_off + 7'd1);
        end
    end
    always @* begin
        if (f_init) begin
            // 1.
            assert(f_sum + {{(24-W_CDELTA){delta_q[W_CDELTA-1]}}, delta_q} == {{(24-W_C){corr_q[W_C-1]}}, corr_q});
            // 2. (and its helper: the stage-G value reaches corr one call after it is formed)
            if (ph != PH_G + 5'd1) assert(g_corr == corr_q);
            if (ph != PH_G + 5'd2) assert(delta_q == {W_CDELTA{1'b0}});
            // 3.
            if (f_off >= 7'd64) assert(corr_q == {W_C{1'b0}} && delta_q == {W_CDELTA{1'b0}} && !active_oq);
            // helper invariants: the activity pipeline behind the switched-off inputs
            if (f_off >= 7'd1) assert(!a_act);
            if (f_off >= 7'd2) assert(!b_act);
            if (f_off >= 7'd3) assert(!c_act);
            if (f_off >= 7'd4) assert(!r_act);
            if (f_off >= 7'd5) assert(!d_act);
            if (f_off >= 7'd6 + {2'b00, f_sl}) assert(!m_act);
            if (f_off >= 7'd28 + {2'b00, f_sg}) assert(!g_act && g_corr == {W_C{1'b0}});
            if (f_off >= 7'd29 + {2'b00, f_sc}) assert(corr_q == {W_C{1'b0}});
            if (f_off >= 7'd61) assert(delta_q == {W_CDELTA{1'b0}} && !active_oq);
        end
    end
`endif

endmodule

`default_nettype wire
