// tb_common.vh — shared body of the golden-vector testbenches (included inside each tb module).
//
// The including module declares: N_MAX, ROW_BITS, TB_NAME, `vec`, `row`, i_clk, i_rst and the
// tasks apply_inputs (row -> DUT inputs), idle_inputs (all inputs 0) and check_outputs (one
// `check` per output column of the row).
//
// Timing (one row = one call of the C++ model = one rising edge):
//   i_rst = 1 for RESET_EDGES edges with idle inputs;
//   for k = 0 .. rows-1: at the falling edge, release i_rst and apply row k's inputs;
//                        1 ns after the next rising edge, compare row k's outputs.
// So row 0 is the first call after reset, as in tools/common/vectors.cpp.

    localparam integer RESET_EDGES = 3;
    localparam integer MAX_SHOWN   = 10;   // mismatch lines printed

    integer errors;
    integer rows;
    integer k;
    reg [8*1024-1:0] vec_path;
    reg [8*1024-1:0] vcd_path;

    // sign extension of the low `bits` bits of v (for printing)
    function signed [63:0] sext64;
        input [63:0]  v;
        input integer bits;
        begin
            sext64 = $signed(v << (64 - bits)) >>> (64 - bits);
        end
    endfunction

    // compares one output column; X/Z in the DUT output count as a mismatch
    task check;
        input [8*24-1:0] name;
        input [63:0]     exp_v;
        input [63:0]     got_v;
        input integer    bits;
        input            is_signed;
        reg   [63:0]     mask, e, g;
        begin
            mask = (bits >= 64) ? {64{1'b1}} : (({{63{1'b0}}, 1'b1} << bits) - 64'd1);
            e = exp_v & mask;
            g = got_v & mask;
            if (e !== g) begin
                errors = errors + 1;
                if (errors <= MAX_SHOWN) begin
                    if (is_signed)
                        $display("cycle %0d signal %0s: expected %0d got %0d", k, name, sext64(e, bits),
                                 sext64(g, bits));
                    else
                        $display("cycle %0d signal %0s: expected %0d got %0d", k, name, e, g);
                end
                if (errors == MAX_SHOWN) $display("(further mismatches not shown)");
            end
        end
    endtask

    initial begin
        i_clk = 1'b0;
        forever #5 i_clk = ~i_clk;
    end

    initial begin
        errors = 0;
        k = 0;
        if (!$value$plusargs("vectors=%s", vec_path)) begin
            $display("FAIL %0s: no +vectors=PATH given", TB_NAME);
            $finish;
        end
        rows = N_MAX;
        if ($value$plusargs("rows=%d", rows)) begin
            if (rows < 1 || rows > N_MAX) begin
                $display("FAIL %0s: +rows=%0d outside 1..N_MAX=%0d", TB_NAME, rows, N_MAX);
                $finish;
            end
        end
        $readmemh(vec_path, vec);
        if ($value$plusargs("vcd=%s", vcd_path)) begin
            $dumpfile(vcd_path);
            $dumpvars(0);
        end

        i_rst = 1'b1;
        idle_inputs;
        repeat (RESET_EDGES) @(posedge i_clk);
        for (k = 0; k < rows; k = k + 1) begin
            @(negedge i_clk);
            row = vec[k];
            if (^row === 1'bx) begin
                $display("FAIL %0s: vector row %0d missing or unreadable in %0s", TB_NAME, k, vec_path);
                $finish;
            end
            i_rst = 1'b0;
            apply_inputs;
            @(posedge i_clk);
            #1;
            check_outputs;
        end

        if (errors == 0)
            $display("PASS %0s: %0d rows, 0 mismatches", TB_NAME, rows);
        else
            $display("FAIL %0s: %0d mismatches in %0d rows", TB_NAME, errors, rows);
        $finish;
    end
