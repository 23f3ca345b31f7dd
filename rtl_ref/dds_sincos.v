// dds_sincos.v — position-in-period counter and quarter-wave sine/cosine table.
//
// Reference RTL of hls/dds_sincos.h (DESIGN §4.6). One rising clock edge = one call of
// dds_sincos::step(); o_sin / o_cos after edge t are the out_t of call t: the codes of the phase
// before edge t-1 (two stages), while the phase counter (q, r) moves by i_ostep.
// Synchronous active-high reset = dds_sincos::reset(): phase and both stages to 0; the table RAM
// keeps its contents.
//
// The phase ph = out_pos mod P is kept as quadrant q (2 bits) and offset r in [0, P/4), so no
// divider is needed for any P. The table is read twice per edge, T[r] and T[P/4 - r] (two read
// ports: a true dual-port BRAM, or two copies), and the codes are mirrored into the quadrants:
//     q | sin        | cos
//     0 |  T[r]      |  T[P/4-r]
//     1 |  T[P/4-r]  | -T[r]
//     2 | -T[r]      | -T[P/4-r]
//     3 | -T[P/4-r]  |  T[r]
// T[P/4] is not stored: it is the amplitude input. At ph = P/8 both reads hit T[P/8].
//
// Pipeline form (DESIGN §4.6 "Hardware form"): three register levels, none with logic of note
// in front of it:
//   edge t    the RAM reads the words of the phase *after* this edge, (q', r'), at the addresses
//             r' and P/4 - r' (P/4 of edge t: hls/dds_sincos.h models it with qtr_prev_); the
//             addresses are selected from candidates formed from registers (r, r + 1, r - 1 are
//             all kept) and the period, so the step decision only selects;
//   edge t+1  read stage (= the C++ s1_/c1_ of call t+1): the read data, with the write-first
//             bypass of the writes of edges t and t+1 (the RAM read is read-first), the mirror
//             word replaced by the amplitude of edge t+1 when r' = 0, and the quadrant q';
//   edge t+2  output stage: quadrant mapping and negation, into o_sin / o_cos.
// So the codes after edge t+2 are those of the phase before call t+1, as the C++ model specifies.
//
// Table write port (host side): a write at edge t is performed before the read of the same edge,
// as in hls/laserax_top.h (write, then dds step, in one call): the codes that read the written word
// at edge t see the new value.
`timescale 1ns / 1ps
`default_nettype none
`include "laserax_widths.vh"

module dds_sincos #(
    // INIT_FILE: $readmemh image of the table RAM at configuration time (1024 words of 17 bits,
    // the P = 256 / amp = 32767 table written by `lutgen --hex` or `laserax vectors`).
    // Must not be empty.
    parameter INIT_FILE = "dds_table_p256.hex",
    // WRITE_BYPASS: 1 (default, the block of hls/dds_sincos.h): a table write and the step in one
    // call, and a read of a word written in this or the previous call, see the new word (the RAM
    // is read-first; muxes on the read data). 0: no bypass, for a parent that never reads a word
    // in the call of its write or the call after it (laserax_top: the call of a write and the
    // next are safe-state calls, DESIGN 4.6), which saves the muxes and the delayed write port.
    // Legal values 0, 1.
    parameter integer WRITE_BYPASS = 1
) (
    input  wire                         i_clk,
    input  wire                         i_rst,       // synchronous, active high: dds_sincos::reset()
    input  wire signed [`LX_W_STEP-1:0] i_ostep,     // output count: -1, 0, +1
    input  wire [`LX_W_P-1:0]           i_period,    // P (8..4096, multiple of 8)
    // P/4 - 1 in 11 bits (i_period[12:2] - 1, wrapping), formed by the caller from the same
    // period value (the top: in its register stage), so no decrement of P sits in front of the
    // phase counter's select and the RAM read address. It must equal that of i_period in every
    // call (the testbench forms it from the period column).
    input  wire [`LX_DDS_W_R-1:0]       i_qtr_m1,
    input  wire [`LX_DDS_W_AMP-1:0]     i_amplitude, // amp = T[P/4]
    input  wire                         i_tbl_we,    // table write enable
    input  wire [`LX_W_TBL_ADDR-1:0]    i_tbl_addr,  // table write address
    input  wire [`LX_W_TBL-1:0]         i_tbl_data,  // table write data
    output wire signed [`LX_W_DAC-1:0]  o_sin,       // sine code
    output wire signed [`LX_W_DAC-1:0]  o_cos,       // cosine code
    // DAC range guard support (not part of the C++ model; the top's guard, DESIGN 4.7): the
    // magnitude bound for the codes formed in this call (they leave through o_sin / o_cos after
    // the edge) and, registered with them, whether |o_sin| / |o_cos| exceeds it. |code| is the
    // table word (or the amplitude) the quadrant selects, so the compare runs on the read-stage
    // registers beside the negation instead of after the output register. Exact while the
    // words are below 2^17 (always: 17-bit table words, amplitude <= 2^17 - 1 in every running
    // call of the top). An all-ones bound never flags (the block testbench's idle value).
    input  wire [`LX_W_DAC-1:0]         i_clip_hi,
    output wire                         o_sin_over,
    output wire                         o_cos_over
`ifdef FORMAL
    ,
    input  wire [`LX_W_TBL-1:0] f_i_rd_dir, // formal only: the table RAM abstracted (see the
    input  wire [`LX_W_TBL-1:0] f_i_rd_mir  //   FORMAL block): its two read data, free values
`endif
);

    // ---- fixed widths (hls: dds_sincos_cfg, axis_widths) -------------------------------------
    localparam integer TBL_DEPTH = 1 << `LX_W_TBL_ADDR;  // quarter-wave words (P_MAX / 4)
    localparam integer W_ADDR    = `LX_W_TBL_ADDR;       // table address
    localparam integer W_TBL     = `LX_W_TBL;            // table word, unsigned
    localparam integer W_R       = `LX_DDS_W_R;          // r and P/4 - r: 0..1024
    localparam integer W_DAC     = `LX_W_DAC;            // sin/cos codes, signed

    generate
        if (INIT_FILE == "") begin : g_bad_init_file
            dds_sincos_PARAMETER_INIT_FILE_must_not_be_empty u_param_error ();
        end
        if (WRITE_BYPASS != 0 && WRITE_BYPASS != 1) begin : g_bad_write_bypass
            dds_sincos_PARAMETER_WRITE_BYPASS_must_be_0_or_1 u_param_error ();
        end
    endgenerate

    // ---- table RAM ---------------------------------------------------------------------------
    // (the formal proof replaces the RAM by free read data constrained at one witness address:
    // see the FORMAL block at the end; simulation and synthesis never define FORMAL)
`ifndef FORMAL
    (* no_rw_check *)   // a read of the address written in the same edge is replaced by the bypass
    reg [W_TBL-1:0] tbl [0:TBL_DEPTH-1];
    // RAM contents at configuration time. This `initial` is the standard FPGA block-RAM
    // initialisation idiom (the bitstream carries the contents); it is the only initial block in
    // the synthesisable RTL.
    initial $readmemh(INIT_FILE, tbl);
`endif

    // ---- registers ---------------------------------------------------------------------------
    reg [1:0]        q_q;
    reg [W_R-1:0]    r_q, rp1_q, rm1_q;  // phase offset r and its neighbours r + 1, r - 1
    reg [W_R-1:0]    nr_q;               // ~r
    reg              wrap_q;             // r + 1 == P/4 of the previous call (the up count wraps)
    reg [W_TBL-1:0]  t_dir_q, t_mir_q;   // RAM read data (read-first), next-phase addresses
    reg [W_ADDR-1:0] a_dir_q, a_mir_q;   // their addresses
    reg              r0_q;               // r' == 0 at that read: the mirror word is the amplitude
    reg              wp_we_q;            // the write of the previous edge (bypass of the read stage)
    reg [W_ADDR-1:0] wp_addr_q;
    reg [W_TBL-1:0]  wp_data_q;
    reg [1:0]        s1_q_q;             // read stage: quadrant, direct and mirror words, valid
    reg [W_TBL-1:0]  s1_dir_q;
    reg [W_DAC-1:0]  s1_mir_q;
    reg              s1_valid_q;
    reg [W_DAC-1:0]  sin_q, cos_q;       // output stage
    reg              sin_over_q, cos_over_q;

    wire [W_R-1:0] quarter = i_period[W_R+1:2];         // P/4
    wire [W_R-1:0] one     = {{(W_R-1){1'b0}}, 1'b1};

    // ---- phase counter and the next-phase read addresses -----------------------------------------
    wire ostep_pos = !i_ostep[1] && i_ostep[0];        // ostep > 0
    wire ostep_neg = i_ostep[1];                       // ostep < 0
    wire wrap_up   = wrap_q;                           // r == P/4 - 1 (P of the previous call)
    wire at_0      = r_q == {W_R{1'b0}};
    wire s_inc     = ostep_pos && !wrap_up;
    wire s_wup     = ostep_pos && wrap_up;
    wire s_dec     = ostep_neg && !at_0;
    wire s_wdn     = ostep_neg && at_0;
    wire s_same    = !ostep_pos && !ostep_neg;
    wire [W_R-1:0] q_m1 = i_qtr_m1;                    // P/4 - 1
    // P/4 - 2: P/4 - 1 with bit 0 cleared (P/4 - 1 is odd: P is a multiple of 8), no decrement
    wire [W_R-1:0] q_m2 = {q_m1[W_R-1:1], 1'b0};
    wire [1:0]     q_d   = s_wup ? q_q + 2'd1 : (s_wdn ? q_q - 2'd1 : q_q);
    wire [W_R-1:0] r_d   = ({W_R{s_same}} & r_q) | ({W_R{s_inc}} & rp1_q) | ({W_R{s_dec}} & rm1_q)
                         | ({W_R{s_wdn}} & q_m1);                                // s_wup: 0
    wire [W_R-1:0] rp1_d = ({W_R{s_same}} & rp1_q) | ({W_R{s_inc}} & (rp1_q + one)) | ({W_R{s_dec}} & r_q)
                         | ({W_R{s_wdn}} & quarter) | ({W_R{s_wup}} & one);
    wire [W_R-1:0] rm1_d = ({W_R{s_same}} & rm1_q) | ({W_R{s_inc}} & r_q) | ({W_R{s_dec}} & (rm1_q - one))
                         | ({W_R{s_wdn}} & q_m2) | {W_R{s_wup}};
    // r' + 1 == P/4, registered for the next call's up count: equalities of registers with P/4 and
    // P/4 - 1 beside the candidates (r + 1 + 1 == P/4 is r + 1 == P/4 - 1), selected by the step
    wire           wrap_d = (s_same && wrap_q) || (s_inc && rp1_q == q_m1) || (s_dec && r_q == quarter)
                          || s_wdn;   // (after the up wrap r' + 1 = 1 < P/4: P >= 8)
    // P/4 - r' (don't-care when r' = 0: the amplitude is used)
    // P/4 - (r + 1) = P/4 + ~r: from the register nr = ~r kept beside r (rp1 = r + 1 mod 2^W_R
    // always), so no inverted operand sits in front of that chain (one LUT per bit on the iCE40)
    wire [W_R:0]   m_same = {1'b0, quarter} + {1'b0, nr_q} + {{W_R{1'b0}}, 1'b1};   // P/4 - r
    // P/4 - (r - 1) = (P/4 + 1) + ~r + 1, with P/4 + 1 = P/4 with bit 0 set (P/4 is even: P is a
    // multiple of 8), so no inverted operand (~(r - 1)) sits in front of that chain either
    wire [W_R:0]   m_dec  = {1'b0, quarter[W_R-1:1], 1'b1} + {1'b0, nr_q} + {{W_R{1'b0}}, 1'b1};
    wire [W_R-1:0] m_d   = ({W_R{s_same}} & m_same[W_R-1:0]) | ({W_R{ostep_pos}} & (quarter + nr_q))
                         | ({W_R{s_dec}} & m_dec[W_R-1:0]) | ({W_R{s_wdn}} & one);
    // reset: the phase-0 words (r' < P/4 <= 1024: the address is the low W_ADDR bits)
    wire [W_ADDR-1:0] a_dir = {W_ADDR{!i_rst}} & r_d[W_ADDR-1:0];
    wire [W_ADDR-1:0] a_mir = m_d[W_ADDR-1:0];
    wire              r0_d  = i_rst || r_d == {W_R{1'b0}};

    always @(posedge i_clk) begin
`ifdef FORMAL
        t_dir_q <= f_i_rd_dir;
        t_mir_q <= f_i_rd_mir;
`else
        if (i_tbl_we) tbl[i_tbl_addr] <= i_tbl_data;
        t_dir_q <= tbl[a_dir];
        t_mir_q <= tbl[a_mir];
`endif
    end
    always @(posedge i_clk) begin
        a_dir_q   <= a_dir;
        a_mir_q   <= a_mir;
        r0_q      <= r0_d;
        wp_we_q   <= i_tbl_we;
        wp_addr_q <= i_tbl_addr;
        wp_data_q <= i_tbl_data;
    end

    // ---- read stage: the words of the phase before this edge (q_q, r_q), write-first -----------
    wire             wn_dir = i_tbl_we && i_tbl_addr == a_dir_q;   // a write of this edge
    wire             wn_mir = i_tbl_we && i_tbl_addr == a_mir_q;
    wire             wp_dir = wp_we_q && wp_addr_q == a_dir_q;     // a write of the previous edge
    wire             wp_mir = wp_we_q && wp_addr_q == a_mir_q;
    wire [W_TBL-1:0] w_dir  = (WRITE_BYPASS == 0) ? t_dir_q : wn_dir ? i_tbl_data : (wp_dir ? wp_data_q : t_dir_q);
    wire [W_TBL-1:0] w_mir  = (WRITE_BYPASS == 0) ? t_mir_q : wn_mir ? i_tbl_data : (wp_mir ? wp_data_q : t_mir_q);

    // ---- output stage: quadrant mapping of the read stage ----------------------------------------
    wire [W_DAC-1:0] t_dir = {1'b0, s1_dir_q};
    wire [W_DAC-1:0] t_mir = s1_mir_q;
    wire             gt_dir = t_dir > i_clip_hi;     // the magnitudes against the bound
    wire             gt_mir = t_mir > i_clip_hi;
    // quadrant mapping as one conditional negation each, (x ^ {neg}) + neg: the word select and
    // the inversion are one LUT in front of the chain, the carry-in is the sign, so the chain
    // ends in the output register (no multiplexer behind a negation)
    //     q | sin        | cos
    //     0 |  T[r]      |  T[P/4-r]
    //     1 |  T[P/4-r]  | -T[r]
    //     2 | -T[r]      | -T[P/4-r]
    //     3 | -T[P/4-r]  |  T[r]
    wire             sin_neg = s1_q_q[1];
    wire             cos_neg = s1_q_q[1] ^ s1_q_q[0];
    wire [W_DAC-1:0] sin_x   = (s1_q_q[0] ? t_mir : t_dir) ^ {W_DAC{sin_neg}};
    wire [W_DAC-1:0] cos_x   = (s1_q_q[0] ? t_dir : t_mir) ^ {W_DAC{cos_neg}};
    wire [W_DAC-1:0] sin_v   = sin_x + {{(W_DAC-1){1'b0}}, sin_neg};
    wire [W_DAC-1:0] cos_v   = cos_x + {{(W_DAC-1){1'b0}}, cos_neg};

    always @(posedge i_clk) begin
        if (i_rst) begin
            q_q        <= 2'd0;
            r_q        <= {W_R{1'b0}};
            nr_q       <= {W_R{1'b1}};
            rp1_q      <= one;
            rm1_q      <= {W_R{1'b1}};
            wrap_q     <= 1'b0;                  // P/4 of the reset call read as 0: r + 1 != 0
            s1_q_q     <= 2'd0;
            s1_dir_q   <= {W_TBL{1'b0}};
            s1_mir_q   <= {W_DAC{1'b0}};
            s1_valid_q <= 1'b0;
            sin_q      <= {W_DAC{1'b0}};
            cos_q      <= {W_DAC{1'b0}};
            sin_over_q <= 1'b0;
            cos_over_q <= 1'b0;
        end else begin
            q_q        <= q_d;
            r_q        <= r_d;
            nr_q       <= ~r_d;
            rp1_q      <= rp1_d;
            rm1_q      <= rm1_d;
            wrap_q     <= wrap_d;
            s1_q_q     <= q_q;
            s1_dir_q   <= w_dir;
            s1_mir_q   <= r0_q ? i_amplitude : {1'b0, w_mir};
            s1_valid_q <= 1'b1;
            sin_q      <= s1_valid_q ? sin_v : {W_DAC{1'b0}};
            cos_q      <= s1_valid_q ? cos_v : {W_DAC{1'b0}};
            // sin takes the direct word in quadrants 0 and 2, the mirror word in 1 and 3
            sin_over_q <= s1_valid_q && (s1_q_q[0] ? gt_mir : gt_dir);
            cos_over_q <= s1_valid_q && (s1_q_q[0] ? gt_dir : gt_mir);
        end
    end

    assign o_sin = sin_q;
    assign o_cos = cos_q;
    assign o_sin_over = sin_over_q;
    assign o_cos_over = cos_over_q;

`ifdef FORMAL
    // ---- formal properties (read_verilog -formal; see docs/FORMAL.md) --------------------------
    // Table RAM abstraction: the RAM is replaced by the free read data f_i_rd_dir / f_i_rd_mir.
    // One witness word is tracked: f_w is a free constant address (any value, never changes) and
    // f_tw the content of word f_w (any initial content, then the writes to f_w). A read of
    // address f_w returns f_tw before the write of the same edge (read-first, as the RAM); a read
    // of any other address returns anything, the same word on both ports when they read the
    // same address. Every property below that names a table word names
    // f_w, so it holds for every address and every table content / write sequence.
    // The period is a free constant (f_per) under the assumption 8 <= P <= 4096, P % 8 == 0.
    reg [12:0]       f_per;       // P (no initial value: any, then kept)
    reg [W_ADDR-1:0] f_w;         // witness address (any, kept)
    reg [W_TBL-1:0]  f_tw;        // table word f_w (after the writes of the last edge)
    reg [W_TBL-1:0]  f_tw_p;      //   before the last edge
    reg              f_init;      // a reset has been seen
    reg              f_v1, f_v2;  // the read stage / the output stage holds the codes of a phase
    reg [12:0]       f_ph, f_ph1, f_ph2;  // reference phase after the last edge, 1 and 2 edges back
    reg [1:0]        f_q1, f_q2;  // (q, r) of the RTL counter 1 and 2 edges back
    reg [W_R-1:0]    f_r1, f_r2;
    reg [W_DAC-1:0]  f_amp1, f_amp2;  // amplitude input of the last / last but one edge
    initial f_init = 1'b0;

    wire [12:0] f_p8   = {3'b000, f_per[12:3]};             // P/8
    wire [12:0] f_qtr  = {2'b00, quarter};
    // the reference phase counter: (ph + ostep) mod P, computed on the whole phase
    wire [12:0] f_ph_n = i_rst ? 13'd0 :
                         ostep_pos ? ((f_ph + 13'd1 == f_per) ? 13'd0 : f_ph + 13'd1) :
                         ostep_neg ? ((f_ph == 13'd0) ? f_per - 13'd1 : f_ph - 13'd1) : f_ph;
    // q * P/4 + r of the RTL counter
    wire [12:0] f_qr   = (q_q == 2'd0) ? {2'b00, r_q} :
                         (q_q == 2'd1) ? f_qtr + {2'b00, r_q} :
                         (q_q == 2'd2) ? {f_qtr[11:0], 1'b0} + {2'b00, r_q} :
                                         {f_qtr[11:0], 1'b0} + f_qtr + {2'b00, r_q};
    wire [W_R-1:0] f_w_x = {1'b0, f_w};
    // the output stage: the words of the phase two edges back, where they are known
    wire             f_d_kn = f_r2 == f_w_x;                               // direct word = f_tw_p
    wire             f_m_kn = f_r2 == {W_R{1'b0}} || quarter - f_r2 == f_w_x;
    wire [W_DAC-1:0] f_dw   = {1'b0, f_tw_p};
    wire [W_DAC-1:0] f_mw   = (f_r2 == {W_R{1'b0}}) ? f_amp2 : {1'b0, f_tw_p};

    always @(posedge i_clk) begin
        f_per  <= f_per;
        f_w    <= f_w;
        f_tw_p <= f_tw;
        if (i_tbl_we && i_tbl_addr == f_w) f_tw <= i_tbl_data;
        if (i_rst) f_init <= 1'b1;
        f_v1   <= !i_rst && f_init;
        f_v2   <= !i_rst && f_v1;
        f_ph   <= f_ph_n;
        f_ph1  <= f_ph;
        f_ph2  <= f_ph1;
        f_q1   <= q_q;
        f_q2   <= f_q1;
        f_r1   <= r_q;
        f_r2   <= f_r1;
        f_amp1 <= i_amplitude;
        f_amp2 <= f_amp1;
    end

    always @* begin
        // legal inputs: a constant legal period, ostep in {-1, 0, +1}
        assume(i_period == f_per);
        assume(i_qtr_m1 == f_per[12:2] - 11'd1);
        assume(f_per >= 13'd8 && f_per <= 13'd4096 && f_per[2:0] == 3'b000);
        assume(i_ostep != -2'sd2);
        // the RAM: a read of the witness address returns its content (before this edge's write)
        if (a_dir == f_w) assume(f_i_rd_dir == f_tw);
        if (a_mir == f_w) assume(f_i_rd_mir == f_tw);
        // and the two ports read one word when they read one address
        if (a_dir == a_mir) assume(f_i_rd_dir == f_i_rd_mir);
        // "T[P/8] > 0": the word at P/8 is never 0 (only this assumption is about the contents)
        if ({3'b000, f_w} == f_p8) assume(f_tw != {W_TBL{1'b0}});

        if (f_init) begin
            // 1. the phase counter: ph in [0, P), moves by ostep mod P (reference f_ph), kept as
            //    q * P/4 + r with r in [0, P/4) and the neighbours r + 1, r - 1 exact
            assert(f_ph < f_per);
            assert(r_q < quarter);
            assert(f_qr == f_ph);
            assert(rp1_q == r_q + one);
            assert(nr_q == ~r_q);                     // the inverted copy of r
            assert(rm1_q == r_q - one);
            assert(wrap_q == (rp1_q == quarter));       // the registered wrap test (P constant)
            // helper invariants: the addresses read at the last edge are those of (q_q, r_q)
            assert(a_dir_q == r_q[W_ADDR-1:0]);
            assert(r0_q == (r_q == {W_R{1'b0}}));
            if (r_q != {W_R{1'b0}}) assert({1'b0, a_mir_q} == quarter - r_q);
            // the RAM abstraction: data read at the last edge, the write of the last edge
            if (a_dir_q == f_w) assert(t_dir_q == f_tw_p);
            if (a_mir_q == f_w) assert(t_mir_q == f_tw_p);
            assert(f_tw == ((wp_we_q && wp_addr_q == f_w) ? wp_data_q : f_tw_p));
            if (a_dir_q == a_mir_q) assert(t_dir_q == t_mir_q);
            // 2. read stage: quadrant and words of the phase before the last edge, with the
            //    table as it is after the last edge (write-first), the amplitude at r = 0
            assert(s1_valid_q == f_v1);
            if (f_v1) begin
                assert(s1_q_q == f_q1);
                if (f_r1 == f_w_x) assert(s1_dir_q == f_tw);
                if (f_r1 == {W_R{1'b0}}) assert(s1_mir_q == f_amp1);
                else if (quarter - f_r1 == f_w_x) assert(s1_mir_q == {1'b0, f_tw});
                // (helper: at r = P/8 both words are the same read)
                if (f_r1 != {W_R{1'b0}} && quarter - f_r1 == f_r1) assert(s1_mir_q == {1'b0, s1_dir_q});
            end
            // 3. output stage: the codes of the phase two edges back (ph2 = q2 * P/4 + r2):
            //    the quadrant mapping of T[r2] and T[P/4 - r2] (amp at r2 = 0), table words as
            //    they were after the previous edge; zero until the first phase reaches it
            if (!f_v2) assert(sin_q == {W_DAC{1'b0}} && cos_q == {W_DAC{1'b0}});
            if (f_v2) begin
                if (f_d_kn) begin
                    case (f_q2)
                        2'd0:    assert(sin_q == f_dw);
                        2'd1:    assert(cos_q == -f_dw);
                        2'd2:    assert(sin_q == -f_dw);
                        default: assert(cos_q == f_dw);
                    endcase
                end
                if (f_m_kn) begin
                    case (f_q2)
                        2'd0:    assert(cos_q == f_mw);
                        2'd1:    assert(sin_q == f_mw);
                        2'd2:    assert(cos_q == -f_mw);
                        default: assert(sin_q == -f_mw);
                    endcase
                end
                // 4. the P/8 points, for any table content: sin == cos at P/8 (and > 0 when
                //    T[P/8] > 0: the witness is P/8), sin == -cos at 3P/8, sin == cos at 5P/8,
                //    cos == -sin at 7P/8
                if (f_ph2 == f_p8) begin
                    assert(sin_q == cos_q);
                    if ({3'b000, f_w} == f_p8) assert(!sin_q[W_DAC-1] && sin_q != {W_DAC{1'b0}});
                end
                if (f_ph2 == f_qtr + f_p8)                        assert(sin_q == -cos_q);
                if (f_ph2 == {f_qtr[11:0], 1'b0} + f_p8)          assert(sin_q == cos_q);
                if (f_ph2 == {f_qtr[11:0], 1'b0} + f_qtr + f_p8)  assert(cos_q == -sin_q);
                assert(f_ph2 == ((f_q2 == 2'd0) ? {2'b00, f_r2} :
                                 (f_q2 == 2'd1) ? f_qtr + {2'b00, f_r2} :
                                 (f_q2 == 2'd2) ? {f_qtr[11:0], 1'b0} + {2'b00, f_r2} :
                                                  {f_qtr[11:0], 1'b0} + f_qtr + {2'b00, f_r2}));
            end
            if (f_v1) assert(f_ph1 == ((f_q1 == 2'd0) ? {2'b00, f_r1} :
                                       (f_q1 == 2'd1) ? f_qtr + {2'b00, f_r1} :
                                       (f_q1 == 2'd2) ? {f_qtr[11:0], 1'b0} + {2'b00, f_r1} :
                                                        {f_qtr[11:0], 1'b0} + f_qtr + {2'b00, f_r1}) &&
                             f_r1 < quarter);
            if (f_v2) assert(f_r2 < quarter);
        end
    end
`endif

endmodule

`default_nettype wire
