// error_map.v — position error mapping (reference RTL of hls/error_map.h, docs/ERROR_MAP.md).
//
// A correction table over equally spaced positions, linear interpolation between points, the
// correction delivered as whole output counts (corr) and as the change since the previous call
// (delta). Two banks of TBL_DEPTH = 1024 x 24-bit words with their own geometry (origin,
// spacing_log2 k, n_points); the even and the odd words are two RAMs of 2 x 512 x 24 bits (tble,
// tblo: the bank is the top address bit; the four arrays tbl<b>e / tbl<b>o of hls/error_map.h), so
// the two points T[i], T[i+1] of an interval are one read of each RAM, in the selected bank. The
// write port always writes the bank that is not selected in that call, delayed by W_DLY = 24
// calls (a first register, 22 calls in a 32 x 36 block RAM, its read register) so that it is done
// in the clock of a sample's reads: a RAM's read port (selected bank) and write port (other bank)
// never meet at one address, and a reload can never mix tables, even with two samples in flight.
// iCE40: each table RAM is six SB_RAM40_4K (1024 x 4), 12 in all, the delay line three
// (256 x 16); the table RAMs start at 0 (initial contents), as the C++ tables.
//
// The inputs are sampled once every S_MAP = 32 calls (phase counter ph, 0 after reset: the calls
// with ph = 0). One rising edge = one call of error_map::step(); for the sample call t (ph = 0):
//   A1 (t)      a_off[19:0] = (p + ~origin + 1)[19:0], its carry, p and ~origin >> 20, geometry
//               check, k (a_kc), last, flags, bank
//   A2 (t+1)    a_off[38:20] = the high halves + carry (19 bits from registers)
//   S  (t+2 .. t+21) while a_kc != 0: a_off[37:0] >>= 1, a_u = {a_off[0], a_u[19:1]}, a_kc -= 1
//   B  (every edge; the sample's at t+22) b_neg, b_hi = |a_off[37:10], b_i = a_off[9:0], b_u,
//               i >= last, i == last, (i + 1) / 2, (last + 1) / 2, u == 0: compares of registers
//   C  (every edge) clamp (above = !neg && (hi || i >= last)), i, u, inr: multiplexers into the
//               RAM addresses (i+1)/2 (even) and i/2 (odd)
//   R  (every edge) registered RAM reads (selected bank: the address's top bit); the write of 24
//               calls ago (other bank)
//   D  (every edge) d_e = even word, d_o = odd word, d_v = i odd ? 2^20 - u : u
//   M  ph = 26: load m_hi = 0, m_v = d_v, m_diff = d_o - d_e (25 bits), m_e = d_e + 128, flags;
//      ph = 27 .. 31, 0 .. 15: s = m_hi + (m_v[0] ? m_diff : 0) (26 bits), m_hi = s >>> 1,
//      m_b = s[0], m_v = m_v >> 1  (21 shift-and-add steps, LSB first)
//   G  ph = 16: corr = act ? (2 m_hi + m_e + m_b) >>> 8 : 0   (= floor((e 2^20 + diff v + 2^27) / 2^28))
//   H  every edge: output registers corr, delta = corr - corr_prev, active, in_range, cfg_err
// Latency: the inputs of a sample call t are reflected in the outputs after edge t+49 (L_MAP = 50)
// and held until edge t+80.
//
// i_rst (synchronous, active high) is error_map::reset(): the pipeline's control and output
// registers only, never the RAMs. The data registers of the stages are not reset: their values are
// only used while the stage's act flag (reset to 0) is 1. During a reset call the write port takes
// no new write (the C++ step() is not called in the safe state) but the writes already in the
// delay line still reach the RAM in their calls (its pointer is never reset; the C++ reset()
// performs them at once, and no sample reads the table before they have landed): a write of a
// running call is never lost.
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module error_map (
    input  wire                              i_clk,
    input  wire                              i_rst,      // synchronous, active high: error_map::reset()
    input  wire signed [`LX_W_POS-1:0]       i_p,        // uncorrected position (comp), output counts
    input  wire                              i_homed,    // rephase homed (registered status)
    input  wire                              i_map_en,
    input  wire                              i_bank_sel, // active bank of this call
    input  wire signed [`LX_W_POS-1:0]       i_origin0,  // bank 0 geometry
    input  wire [`LX_EM_W_K-1:0]             i_k0,
    input  wire [`LX_EM_W_N-1:0]             i_n0,
    input  wire signed [`LX_W_POS-1:0]       i_origin1,  // bank 1 geometry
    input  wire [`LX_EM_W_K-1:0]             i_k1,
    input  wire [`LX_EM_W_N-1:0]             i_n1,
    input  wire                              i_we,       // table write port: writes bank !bank_sel
    input  wire [`LX_EM_W_ADDR-1:0]          i_addr,
    input  wire signed [`LX_EM_W_CORR-1:0]   i_data,     // Q15.8 output counts
    output wire signed [`LX_EM_W_C-1:0]      o_corr,
    output wire signed [`LX_EM_W_CDELTA-1:0] o_delta,
    output wire                              o_active,
    output wire                              o_in_range,
    output wire                              o_clamped,
    output wire                              o_cfg_err
);

    // ---- fixed widths (hls: error_map_cfg) ---------------------------------------------------
    localparam integer TBL_DEPTH = 1 << `LX_EM_W_ADDR;
    localparam integer W_CORR    = `LX_EM_W_CORR;
    localparam [4:0]   K_MIN     = 5'd4;
    localparam [4:0]   K_MAX     = 5'd20;
    localparam integer W_ADDR    = `LX_EM_W_ADDR;
    localparam integer W_HADDR   = 9;
    localparam integer W_N       = `LX_EM_W_N;
    localparam integer W_OFF     = `LX_W_POS + 1;
    localparam integer W_FRAC    = 20;
    localparam integer W_V       = 21;
    localparam integer W_DIFF    = 25;
    localparam integer W_MHI     = 26;
    localparam integer W_ME      = 25;
    localparam integer W_G       = 27;
    localparam integer F         = 8;
    localparam [4:0]   PH_LOAD   = 5'd26;   // M's load: 26 calls after the sample call
    localparam [4:0]   PH_G      = 5'd16;   // G: 48 calls after it (mod S_MAP = 32)
    localparam integer N_STEP    = 21;  // W_V multiplier steps, calls 27 .. 47
    localparam integer W_C       = `LX_EM_W_C;
    localparam integer W_CDELTA  = `LX_EM_W_CDELTA;

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

    // ---- phase counter: ph = 0 marks a sample call ----------------------------------------------
    reg [4:0] ph;
    always @(posedge i_clk) begin
        if (i_rst) ph <= 5'd0;
        else       ph <= ph + 5'd1;   // wraps at S_MAP = 32
    end
    wire ph0 = ph == 5'd0;            // A1: the sample call
    wire ph1 = ph == 5'd1;            // A2

    // ---- stage A1 (ph = 0): the sample call's inputs, the low half of the subtract -----------
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

    // p - origin = p + ~origin + 1 in two halves: the low W_LO bits here (one 20-bit chain, the
    // carry registered), p and ~origin above them registered for A2. ~origin of the selected
    // bank: the bank multiplexer's LUT inverts for free (an inverted operand of a carry chain is
    // one more LUT per bit on the iCE40)
    localparam integer W_LO = 20;
    localparam integer W_HI = W_OFF - W_LO;   // 19
    wire [37:0]       ng_origin = i_bank_sel ? ~i_origin1 : ~i_origin0;
    wire [W_LO:0]     off_lo = {1'b0, i_p[W_LO-1:0]} + {1'b0, ng_origin[W_LO-1:0]} + {{W_LO{1'b0}}, 1'b1};
    wire [W_HI-1:0]   off_hi = a_phi + a_ohi + {{(W_HI-1){1'b0}}, a_c};   // A2, from registers

    // the offset register a_off: the low half written by A1, the high half by A2, then shifted
    // right one bit per call by S (the sign bit a_off[38] stays); a_kc counts the shifts still to
    // do (k of the sample; the RTL loads k unchecked: with an invalid geometry the sample is
    // inactive and S may run on until the next A1, which reloads everything); the bits shifted
    // out enter a_u from the top, so after k shifts a_u = (off mod 2^k) 2^(20-k)
    reg signed [W_OFF-1:0]  a_off;
    reg        [W_HI-1:0]   a_phi, a_ohi;
    reg                     a_c;
    reg        [4:0]        a_kc;
    reg        [W_FRAC-1:0] a_u;
    reg        [W_ADDR-1:0] na_last;   // ~last, last = n - 1 (the inversion of the decrement is
                                        // free; stage B's compare then has no inverted operand)
    reg                     a_bank, a_act, a_err;
    wire                    sh = a_kc != 5'd0 && !ph0 && !ph1;   // S: calls 2 .. 21 of the sample
    always @(posedge i_clk) begin
        if (ph0) begin
            a_off[W_LO-1:0] <= off_lo[W_LO-1:0];
            a_c    <= off_lo[W_LO];
            a_phi  <= {i_p[37], i_p[37:W_LO]};
            a_ohi  <= {ng_origin[37], ng_origin[37:W_LO]};
            a_kc   <= g_k;
            na_last <= ~n_m1[W_ADDR-1:0];
            a_bank <= i_bank_sel;
            a_u    <= {W_FRAC{1'b0}};
        end else if (ph1) begin
            a_off[W_OFF-1:W_LO] <= off_hi;
        end else if (sh) begin
            a_off <= {a_off[W_OFF-1], 1'b0, a_off[W_OFF-2:1]};
            a_u   <= {a_off[0], a_u[W_FRAC-1:1]};
            a_kc  <= a_kc - 5'd1;
        end
        if (i_rst) begin
            a_act <= 1'b0;
            a_err <= 1'b0;
        end else if (ph0) begin
            a_act <= i_map_en && i_homed && geom_ok;
            a_err <= i_map_en && !geom_ok;
        end
    end

    // ---- stage B (every call; the sample's in call t+22): the shifted offset's fields, the
    // compares with last, the even addresses, all from registers ---------------------------------
    wire [W_ADDR:0] ai_p1   = {1'b0, a_off[W_ADDR-1:0]} + {{W_ADDR{1'b0}}, 1'b1};
    // last + 1 = ~(~last - 1) (W_ADDR + 1 bits), from ~last without an inverted operand
    wire [W_ADDR:0] last_p1 = ~({1'b1, na_last} + {(W_ADDR+1){1'b1}});
    // i >= last: the carry of i + ~last + 1
    wire [W_ADDR:0] ge_s    = {1'b0, a_off[W_ADDR-1:0]} + {1'b0, na_last} + {{W_ADDR{1'b0}}, 1'b1};
    reg                      b_neg, b_hi, b_ge, b_eq, b_u0, b_bank, b_act, b_err;
    reg        [W_ADDR-1:0]  b_i, nb_last;                 // nb_last: ~last
    reg        [W_HADDR-1:0] b_ie, b_le;             // (i + 1) / 2, (last + 1) / 2
    reg        [W_FRAC-1:0]  b_u;
    always @(posedge i_clk) begin
        b_neg  <= a_off[W_OFF-1];
        b_hi   <= |a_off[W_OFF-2:W_ADDR];            // floor(off / 2^k) beyond every address
        b_i    <= a_off[W_ADDR-1:0];
        b_u    <= a_u;
        b_ge   <= ge_s[W_ADDR];
        b_eq   <= a_off[W_ADDR-1:0] == ~na_last;
        b_u0   <= a_u == {W_FRAC{1'b0}};
        b_ie   <= ai_p1[W_HADDR:1];
        b_le   <= last_p1[W_HADDR:1];
        nb_last <= na_last;
        b_bank <= a_bank;
        if (i_rst) begin
            b_act <= 1'b0;
            b_err <= 1'b0;
        end else begin
            b_act <= a_act;
            b_err <= a_err;
        end
    end

    // ---- stage C (every call): clamp (multiplexers only), the two RAM addresses (registered) ------
    wire                above  = !b_neg && (b_hi || b_ge);
    wire [W_ADDR-1:0]   ci     = b_neg ? {W_ADDR{1'b0}} : above ? ~nb_last : b_i;
    wire [W_FRAC-1:0]   cu     = (b_neg || above) ? {W_FRAC{1'b0}} : b_u;
    wire                cinr   = !b_neg && (!above || (!b_hi && b_eq && b_u0));
    wire [W_HADDR-1:0]  ea     = b_neg ? {W_HADDR{1'b0}} : above ? b_le : b_ie;   // (i+1)/2
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

    // ---- write port: delayed by W_DLY = 24 calls, to the clock of a sample's reads ---------------
    // w1 takes the call's write (to the bank not selected now; none in a reset call); a 32 x 36
    // block RAM holds it for 22 calls (write pointer wp, free-running and never reset, so the
    // writes in flight keep their calls across a reset; read pointer wp + 10 = wp - 22); the RAM's
    // read register wd is the write of call t - 24 in call t, performed into the table RAM in the
    // clock of stage R (read-first: the reads of that clock do not see it; other bank anyway).
    localparam integer W_WR = 1 + 1 + W_ADDR + W_CORR;   // we, bank, addr, data
    reg                     w1_we, w1_bank;
    reg        [W_ADDR-1:0] w1_addr;
    reg signed [W_CORR-1:0] w1_data;
    reg        [4:0]        wp;
    reg        [W_WR-1:0]   wd;
    reg                     wv;      // wd holds a delay-line word (0 in the power-up clock)
    always @(posedge i_clk) begin
        w1_bank <= !i_bank_sel;
        w1_addr <= i_addr;
        w1_data <= i_data;
        if (i_rst) w1_we <= 1'b0;
        else       w1_we <= i_we;
        wp <= wp + 5'd1;
        wv <= 1'b1;
    end
    wire [4:0]        rp      = wp + 5'd10;   // read slot: written 22 calls ago (mod 32)
    wire              wd_we   = wd[W_WR-1] && wv;
    wire              wd_bank = wd[W_WR-2];
    wire [W_ADDR-1:0] wd_addr = wd[W_CORR+W_ADDR-1:W_CORR];
    wire [W_CORR-1:0] wd_data = wd[W_CORR-1:0];
`ifndef FORMAL
    (* no_rw_check *) reg [W_WR-1:0] wdl [0:31];
    integer jj;
    initial begin
        // power-up values (FPGA flip-flops start at their configured value, 0): the never-reset
        // write pointer, no write in w1 before the first reset, and wv, which keeps the RAM's read
        // register (no initial value of its own: it is the block RAM's) from writing before it
        // has read a word of the zeroed delay line
        wp = 5'd0;
        w1_we = 1'b0;
        wv = 1'b0;
        for (jj = 0; jj < 32; jj = jj + 1) wdl[jj] = {W_WR{1'b0}};
    end
    always @(posedge i_clk) begin
        wdl[wp] <= {w1_we, w1_bank, w1_addr, w1_data};
        wd      <= wdl[rp];
    end
`else
    // formal: the write port reaches no property (the table RAMs are abstracted)
    always @(posedge i_clk) wd <= {W_WR{1'b0}};
`endif

    // ---- stage R (every call): one registered read of each RAM (selected bank), the delayed write
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
        if (wd_we && !wd_addr[0]) tble[{wd_bank, wd_addr[W_ADDR-1:1]}] <= wd_data;
    end
    always @(posedge i_clk) begin
        if (wd_we && wd_addr[0]) tblo[{wd_bank, wd_addr[W_ADDR-1:1]}] <= wd_data;
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

    // ---- M: sequenced multiply (d_o - d_e) * d_v, LSB first ------------------------------------------
    reg signed [W_MHI-1:0]  m_hi;
    reg                     m_b;
    reg        [W_V-1:0]    m_v;
    reg signed [W_DIFF-1:0] m_diff;
    reg signed [W_ME-1:0]   m_e;
    reg                     m_act, m_inr, m_err;
    wire [4:0]              m_j    = ph - (PH_LOAD + 5'd1);    // step index (mod 32)
    // M's two enables (load, step) are flip-flops, decoded in the call before from the next
    // phase, so the enables of its ~70 flip-flops do not wait for a phase subtract and compare
    wire [4:0]              ph_nx  = i_rst ? 5'd0 : ph + 5'd1;
    reg                     m_ld_q, m_step_q;                  // ph == PH_LOAD, m_j < N_STEP
    // m_j < N_STEP of the next call <=> ph_nx in 27 .. 31, 0 .. 15 (PH_LOAD + 1 .. PH_LOAD +
    // N_STEP mod 32), as bit logic: a subtract and a compare with a constant would be two carry
    // chains (the compare with an inverter per bit) behind the phase increment
    wire                    m_step_nx = !ph_nx[4] || (ph_nx[3] && (ph_nx[2] || (ph_nx[1] && ph_nx[0])));
    generate
        if (PH_LOAD != 5'd26 || N_STEP != 21) begin : g_bad_m_step
            error_map_m_step_nx_is_written_for_27_to_15 u_param_error ();
        end
    endgenerate
    always @(posedge i_clk) begin
        m_ld_q   <= ph_nx == PH_LOAD;
        m_step_q <= m_step_nx;
    end
    wire signed [W_MHI-1:0] m_add  = m_v[0] ? {m_diff[W_DIFF-1], m_diff} : {W_MHI{1'b0}};
    wire signed [W_MHI-1:0] m_s    = m_hi + m_add;
    always @(posedge i_clk) begin
        if (m_ld_q) begin
            m_hi   <= {W_MHI{1'b0}};
            m_b    <= 1'b0;
            m_v    <= d_v;
            m_diff <= {d_o[W_CORR-1], d_o} - {d_e[W_CORR-1], d_e};
            m_e    <= {d_e[W_CORR-1], d_e} + {{(W_ME-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            m_inr  <= d_inr;
        end else if (m_step_q) begin
            m_hi   <= m_s >>> 1;
            m_b    <= m_s[0];
            m_v    <= m_v >> 1;
        end
        if (i_rst) begin
            m_act <= 1'b0;
            m_err <= 1'b0;
        end else if (m_ld_q) begin
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
    // 3. a map switched off takes its correction back in full: after 82 calls in a row with
    //    map_en == 0 or homed == 0, corr == 0, delta == 0 and active == 0 (with 1., the deltas
    //    have returned exactly what they added).
    reg                f_init;
    initial f_init = 1'b0;
    reg signed [23:0]  f_sum;                          // the deltas of the calls before this one
    reg [6:0]          f_off;                          // calls in a row with the map off, saturating
    wire               f_offn = !i_map_en || !i_homed;
    wire [4:0]         f_sa = ph - 5'd1;               // calls since stage A1 (the sample call) - 1
    wire [4:0]         f_sb = ph - 5'd2, f_sc3 = ph - 5'd3, f_sr = ph - 5'd4, f_sd = ph - 5'd5;
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
            assert(m_ld_q == (ph == PH_LOAD) && m_step_q == (m_j < N_STEP));  // the decoded enables
            if (ph != PH_G + 5'd2) assert(delta_q == {W_CDELTA{1'b0}});
            // 3.
            if (f_off >= 7'd82) assert(corr_q == {W_C{1'b0}} && delta_q == {W_CDELTA{1'b0}} && !active_oq);
            // helper invariants: the activity pipeline behind the switched-off inputs (stage A1
            // takes the flags in the sample call only; B, C, R, D copy them every call)
            if (f_off >= 7'd1 + {2'b00, f_sa}) assert(!a_act);
            if (f_off >= 7'd2 + {2'b00, f_sb}) assert(!b_act);
            if (f_off >= 7'd3 + {2'b00, f_sc3}) assert(!c_act);
            if (f_off >= 7'd4 + {2'b00, f_sr}) assert(!r_act);
            if (f_off >= 7'd5 + {2'b00, f_sd}) assert(!d_act);
            if (f_off >= 7'd27 + {2'b00, f_sl}) assert(!m_act);
            if (f_off >= 7'd49 + {2'b00, f_sg}) assert(!g_act && g_corr == {W_C{1'b0}});
            if (f_off >= 7'd50 + {2'b00, f_sc}) assert(corr_q == {W_C{1'b0}});
            if (f_off >= 7'd82) assert(delta_q == {W_CDELTA{1'b0}} && !active_oq);
        end
    end
`endif

endmodule

`default_nettype wire
