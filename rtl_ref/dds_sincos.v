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
// as in hls/axis_core.h (write, then dds step, in one call): the codes that read the written word
// at edge t see the new value.
`timescale 1ns / 1ps
`default_nettype none

module dds_sincos #(
    // INIT_FILE: $readmemh image of the table RAM at configuration time (1024 words of 17 bits,
    // the P = 256 / amp = 32767 table written by `lutgen --hex` or `laserax vectors`).
    // Must not be empty.
    parameter INIT_FILE = "dds_table_p256.hex"
) (
    input  wire               i_clk,
    input  wire               i_rst,        // synchronous, active high: dds_sincos::reset()
    input  wire signed [1:0]  i_ostep,      // output count: -1, 0, +1
    input  wire [12:0]        i_period,     // P (8..4096, multiple of 8)
    input  wire [17:0]        i_amplitude,  // amp = T[P/4]
    input  wire               i_tbl_we,     // table write enable
    input  wire [9:0]         i_tbl_addr,   // table write address
    input  wire [16:0]        i_tbl_data,   // table write data
    output wire signed [17:0] o_sin,        // sine code
    output wire signed [17:0] o_cos         // cosine code
);

    // ---- fixed widths (hls: dds_sincos_cfg, axis_widths) -------------------------------------
    localparam integer TBL_DEPTH = 1024;   // quarter-wave words (P_MAX / 4)
    localparam integer W_ADDR    = 10;     // table address
    localparam integer W_TBL     = 17;     // table word, unsigned
    localparam integer W_R       = 11;     // r and P/4 - r: 0..1024
    localparam integer W_DAC     = 18;     // sin/cos codes, signed

    generate
        if (INIT_FILE == "") begin : g_bad_init_file
            dds_sincos_PARAMETER_INIT_FILE_must_not_be_empty u_param_error ();
        end
    endgenerate

    // ---- table RAM ---------------------------------------------------------------------------
    (* no_rw_check *)   // a read of the address written in the same edge is replaced by the bypass
    reg [W_TBL-1:0] tbl [0:TBL_DEPTH-1];
    // RAM contents at configuration time. This `initial` is the standard FPGA block-RAM
    // initialisation idiom (the bitstream carries the contents); it is the only initial block in
    // the synthesisable RTL.
    initial $readmemh(INIT_FILE, tbl);

    // ---- registers ---------------------------------------------------------------------------
    reg [1:0]        q_q;
    reg [W_R-1:0]    r_q, rp1_q, rm1_q;  // phase offset r and its neighbours r + 1, r - 1
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

    wire [W_R-1:0] quarter = i_period[W_R+1:2];         // P/4
    wire [W_R-1:0] one     = {{(W_R-1){1'b0}}, 1'b1};

    // ---- phase counter and the next-phase read addresses -----------------------------------------
    wire ostep_pos = !i_ostep[1] && i_ostep[0];        // ostep > 0
    wire ostep_neg = i_ostep[1];                       // ostep < 0
    wire wrap_up   = rp1_q == quarter;                 // r == P/4 - 1
    wire at_0      = r_q == {W_R{1'b0}};
    wire s_inc     = ostep_pos && !wrap_up;
    wire s_wup     = ostep_pos && wrap_up;
    wire s_dec     = ostep_neg && !at_0;
    wire s_wdn     = ostep_neg && at_0;
    wire s_same    = !ostep_pos && !ostep_neg;
    wire [W_R-1:0] q_m1 = quarter - one;
    wire [1:0]     q_d   = s_wup ? q_q + 2'd1 : (s_wdn ? q_q - 2'd1 : q_q);
    wire [W_R-1:0] r_d   = ({W_R{s_same}} & r_q) | ({W_R{s_inc}} & rp1_q) | ({W_R{s_dec}} & rm1_q)
                         | ({W_R{s_wdn}} & q_m1);                                // s_wup: 0
    wire [W_R-1:0] rp1_d = ({W_R{s_same}} & rp1_q) | ({W_R{s_inc}} & (rp1_q + one)) | ({W_R{s_dec}} & r_q)
                         | ({W_R{s_wdn}} & quarter) | ({W_R{s_wup}} & one);
    wire [W_R-1:0] rm1_d = ({W_R{s_same}} & rm1_q) | ({W_R{s_inc}} & r_q) | ({W_R{s_dec}} & (rm1_q - one))
                         | ({W_R{s_wdn}} & (quarter - {{(W_R-2){1'b0}}, 2'd2})) | {W_R{s_wup}};
    // P/4 - r' (don't-care when r' = 0: the amplitude is used)
    wire [W_R-1:0] m_d   = ({W_R{s_same}} & (quarter - r_q)) | ({W_R{ostep_pos}} & (quarter - rp1_q))
                         | ({W_R{s_dec}} & (quarter - rm1_q)) | ({W_R{s_wdn}} & one);
    // reset: the phase-0 words (r' < P/4 <= 1024: the address is the low W_ADDR bits)
    wire [W_ADDR-1:0] a_dir = {W_ADDR{!i_rst}} & r_d[W_ADDR-1:0];
    wire [W_ADDR-1:0] a_mir = m_d[W_ADDR-1:0];
    wire              r0_d  = i_rst || r_d == {W_R{1'b0}};

    always @(posedge i_clk) begin
        if (i_tbl_we) tbl[i_tbl_addr] <= i_tbl_data;
        t_dir_q <= tbl[a_dir];
        t_mir_q <= tbl[a_mir];
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
    wire [W_TBL-1:0] w_dir  = wn_dir ? i_tbl_data : (wp_dir ? wp_data_q : t_dir_q);
    wire [W_TBL-1:0] w_mir  = wn_mir ? i_tbl_data : (wp_mir ? wp_data_q : t_mir_q);

    // ---- output stage: quadrant mapping of the read stage ----------------------------------------
    wire [W_DAC-1:0] t_dir = {1'b0, s1_dir_q};
    wire [W_DAC-1:0] t_mir = s1_mir_q;
    reg  [W_DAC-1:0] sin_v, cos_v;
    always @* begin
        case (s1_q_q)
            2'd0:    begin sin_v = t_dir;  cos_v = t_mir;  end
            2'd1:    begin sin_v = t_mir;  cos_v = -t_dir; end
            2'd2:    begin sin_v = -t_dir; cos_v = -t_mir; end
            default: begin sin_v = -t_mir; cos_v = t_dir;  end
        endcase
    end

    always @(posedge i_clk) begin
        if (i_rst) begin
            q_q        <= 2'd0;
            r_q        <= {W_R{1'b0}};
            rp1_q      <= one;
            rm1_q      <= {W_R{1'b1}};
            s1_q_q     <= 2'd0;
            s1_dir_q   <= {W_TBL{1'b0}};
            s1_mir_q   <= {W_DAC{1'b0}};
            s1_valid_q <= 1'b0;
            sin_q      <= {W_DAC{1'b0}};
            cos_q      <= {W_DAC{1'b0}};
        end else begin
            q_q        <= q_d;
            r_q        <= r_d;
            rp1_q      <= rp1_d;
            rm1_q      <= rm1_d;
            s1_q_q     <= q_q;
            s1_dir_q   <= w_dir;
            s1_mir_q   <= r0_q ? i_amplitude : {1'b0, w_mir};
            s1_valid_q <= 1'b1;
            sin_q      <= s1_valid_q ? sin_v : {W_DAC{1'b0}};
            cos_q      <= s1_valid_q ? cos_v : {W_DAC{1'b0}};
        end
    end

    assign o_sin = sin_q;
    assign o_cos = cos_q;

endmodule

`default_nettype wire
