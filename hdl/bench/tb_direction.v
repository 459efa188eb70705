// Exhaustive check of gradient_direction against a reference table.
//
// +table=FILE: one hex digit per line, gx = -255..255 outer, gy = -255..255 inner
// (written by `qt_vectors --direction-table FILE`). Exit status non-zero on any mismatch.

`timescale 1ns/1ps
`default_nettype none

module tb_direction;
    localparam N = 511 * 511;           // (gx, gy) pairs

    reg  [3:0]        table_mem [0:N-1];
    reg  [8*1024-1:0] table_file;
    reg  signed [8:0] gx, gy;
    wire [3:0]        dir;
    integer           i, j, k, errors;

    gradient_direction dut (.gx(gx), .gy(gy), .dir(dir));

    initial begin
        if (!$value$plusargs("table=%s", table_file))
            $fatal(1, "tb_direction: +table=FILE is required");
        for (k = 0; k < N; k = k + 1)
            table_mem[k] = 4'bxxxx;
        $readmemh(table_file, table_mem, 0, N - 1);
        if (^table_mem[N - 1] === 1'bx)
            $fatal(1, "tb_direction: table shorter than %0d entries", N);

        errors = 0;
        k = 0;
        for (i = -255; i <= 255; i = i + 1) begin
            for (j = -255; j <= 255; j = j + 1) begin
                gx = i;
                gy = j;
                #1;
                if (dir !== table_mem[k]) begin
                    if (errors < 20)
                        $display("MISMATCH gx=%0d gy=%0d expected=%h got=%h",
                                 i, j, table_mem[k], dir);
                    errors = errors + 1;
                end
                k = k + 1;
            end
        end
        if (errors != 0)
            $fatal(1, "tb_direction: %0d of %0d pairs differ", errors, N);
        $display("PASS %0d pairs", N);
        $finish;
    end
endmodule

`default_nettype wire
