`timescale 1ns / 1ps
`default_nettype none

// Direction bin of a gradient (docs/gradient.md, "Direction"), combinational.
//
// Split in three parts, a file each, so that hdl/rtl/gradient.v can put pipeline registers
// between them:
//   gradient_dir_fold: |gx|, |gy| folded into lo = min, hi = max, swap = (|gy| > |gx|)
//   gradient_dir_s51:  3*hi, the upper bits of 51*hi, and 19*hi
//   gradient_dir_bin:  the two sector compares (256*lo <= 51*hi, 256*lo <= 171*hi) and
//                      quadrant mapping to the bin
// gradient_direction is exactly the three in a row, so the exhaustive test of
// gradient_direction (hdl/bench/tb_direction.v) covers the logic used in the pipeline.

module gradient_direction (
    input  wire signed [8:0] gx,
    input  wire signed [8:0] gy,
    output wire        [3:0] dir
);
    wire [7:0]  lo, hi;
    wire        swap;
    wire [5:0]  m51h;
    wire [12:0] m19;

    gradient_dir_fold u_fold (.gx(gx), .gy(gy), .lo(lo), .hi(hi), .swap(swap));
    gradient_dir_s51  u_s51  (.hi(hi), .m51h(m51h), .m19(m19));
    gradient_dir_bin  u_bin  (.lo(lo), .m19(m19), .m51h(m51h), .swap(swap),
                              .negx(gx[8]), .negy(gy[8]), .dir(dir));
endmodule

`default_nettype wire
