// dds_sincos.v — position-in-period counter and quarter-wave sine/cosine table.
//
// Reference RTL of hls/dds_sincos.h (DESIGN §4.6). One rising clock edge = one call of
// dds_sincos::step(); o_sin / o_cos after edge t are the out_t of call t: the codes of the phase
// *before* the edge (registered table read), while the phase counter (q, r) moves by i_ostep.
// Synchronous active-high reset = dds_sincos::reset(): phase and outputs to 0; the table RAM
// keeps its contents.
//
// The phase ph = out_pos mod P is kept as quadrant q (2 bits) and offset r in [0, P/4), so no
// divider is needed for any P. Each edge reads the table twice, T[r] and T[P/4 - r] (two read
// ports: a true dual-port BRAM, or two copies), and the codes are mirrored into the quadrants:
//     q | sin        | cos
//     0 |  T[r]      |  T[P/4-r]
//     1 |  T[P/4-r]  | -T[r]
//     2 | -T[r]      | -T[P/4-r]
//     3 | -T[P/4-r]  |  T[r]
// T[P/4] is not stored: it is the amplitude input. At ph = P/8 both reads hit T[P/8].
//
// Pipeline form: the RAM read data are registered (BRAM output registers), together with the
// quadrant, the "r == 0" flag and the amplitude of the same edge; o_sin / o_cos are the quadrant
// mapping of those registers (combinational after registers), forced to 0 by the reset.
//
// Table write port (host side): a write at edge t is performed before the read of the same edge,
// as in hls/axis_core.h (write, then dds step, in one call): a read of the written address in the
// same edge returns the new word (write-first bypass).
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
    reg [W_TBL-1:0] tbl [0:TBL_DEPTH-1];
    // RAM contents at configuration time. This `initial` is the standard FPGA block-RAM
    // initialisation idiom (the bitstream carries the contents); it is the only initial block in
    // the synthesisable RTL.
    initial $readmemh(INIT_FILE, tbl);

    // ---- registers ---------------------------------------------------------------------------
    reg [1:0]       q_q;
    reg [W_R-1:0]   r_q;
    reg [W_TBL-1:0] t_dir_q, t_mir_q;   // registered table reads T[r], T[P/4 - r]
    reg [1:0]       rd_q_q;             // quadrant of the read
    reg             rd_r0_q;            // r == 0 at the read: the mirror word is amp
    reg [W_DAC-1:0] rd_amp_q;           // amplitude at the read
    reg             rd_valid_q;         // 0 after reset: codes are 0 (dds_sincos::reset())

    wire [W_R-1:0]    quarter  = i_period[W_R+1:2];      // P/4
    wire [W_R-1:0]    r_mirror = quarter - r_q;          // 1..P/4 (only read when r != 0)
    wire [W_ADDR-1:0] a_dir    = r_q[W_ADDR-1:0];        // r < P/4 <= 1024
    wire [W_ADDR-1:0] a_mir    = r_mirror[W_ADDR-1:0];

    // table port: write, and two registered reads with write-first bypass
    always @(posedge i_clk) begin
        if (i_tbl_we) tbl[i_tbl_addr] <= i_tbl_data;
        t_dir_q <= (i_tbl_we && i_tbl_addr == a_dir) ? i_tbl_data : tbl[a_dir];
        t_mir_q <= (i_tbl_we && i_tbl_addr == a_mir) ? i_tbl_data : tbl[a_mir];
    end

    // position-in-period counter
    wire          ostep_pos = !i_ostep[1] && i_ostep[0];   // ostep > 0
    wire          ostep_neg = i_ostep[1];                  // ostep < 0
    reg [1:0]     q_d;
    reg [W_R-1:0] r_d;
    always @* begin
        q_d = q_q;
        r_d = r_q;
        if (ostep_pos) begin
            if ({1'b0, r_q} == {1'b0, quarter} - {{W_R{1'b0}}, 1'b1}) begin
                r_d = {W_R{1'b0}};
                q_d = q_q + 2'd1;
            end else begin
                r_d = r_q + {{(W_R-1){1'b0}}, 1'b1};
            end
        end else if (ostep_neg) begin
            if (r_q == {W_R{1'b0}}) begin
                r_d = quarter - {{(W_R-1){1'b0}}, 1'b1};
                q_d = q_q - 2'd1;
            end else begin
                r_d = r_q - {{(W_R-1){1'b0}}, 1'b1};
            end
        end
    end

    always @(posedge i_clk) begin
        if (i_rst) begin
            q_q        <= 2'd0;
            r_q        <= {W_R{1'b0}};
            rd_q_q     <= 2'd0;
            rd_r0_q    <= 1'b0;
            rd_amp_q   <= {W_DAC{1'b0}};
            rd_valid_q <= 1'b0;
        end else begin
            q_q        <= q_d;
            r_q        <= r_d;
            rd_q_q     <= q_q;
            rd_r0_q    <= r_q == {W_R{1'b0}};
            rd_amp_q   <= i_amplitude;
            rd_valid_q <= 1'b1;
        end
    end

    // quadrant mapping of the registered reads
    wire [W_DAC-1:0] t_dir = {1'b0, t_dir_q};
    wire [W_DAC-1:0] t_mir = rd_r0_q ? rd_amp_q : {1'b0, t_mir_q};
    reg  [W_DAC-1:0] sin_v, cos_v;
    always @* begin
        case (rd_q_q)
            2'd0:    begin sin_v = t_dir;  cos_v = t_mir;  end
            2'd1:    begin sin_v = t_mir;  cos_v = -t_dir; end
            2'd2:    begin sin_v = -t_dir; cos_v = -t_mir; end
            default: begin sin_v = -t_mir; cos_v = t_dir;  end
        endcase
    end

    assign o_sin = rd_valid_q ? sin_v : {W_DAC{1'b0}};
    assign o_cos = rd_valid_q ? cos_v : {W_DAC{1'b0}};

endmodule

`default_nettype wire
