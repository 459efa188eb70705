`timescale 1ns / 1ps

// Direction bin of a gradient (docs/gradient.md, "Direction"), combinational.
//
// Split in three parts so that hdl/rtl/gradient.v can put pipeline registers between them:
//   gradient_dir_fold: |gx|, |gy| folded into lo = min, hi = max, swap = (|gy| > |gx|)
//   gradient_dir_s51:  3*hi, the upper bits of 51*hi, and 19*hi
//   gradient_dir_bin:  the two sector compares (256*lo <= 51*hi, 256*lo <= 171*hi) and
//                      quadrant mapping to the bin
// gradient_direction is exactly the three in a row, so the exhaustive test of
// gradient_direction (hdl/bench/tb_direction.v) covers the logic used in the pipeline.

module gradient_dir_fold (
    input  wire signed [8:0] gx,     // grey levels, -255..255
    input  wire signed [8:0] gy,     // grey levels, -255..255
    output wire        [7:0] lo,     // min(|gx|, |gy|)
    output wire        [7:0] hi,     // max(|gx|, |gy|)
    output wire              swap    // |gy| > |gx|: reflect the sector into 45..90 degrees
);
    // |v| = v < 0 ? ~(v - 1) : v. Adding the sign bit replicated (0 or -1) needs no inverted
    // carry operand, so each magnitude is one carry chain.
    wire [8:0] tx = gx + {9{gx[8]}};
    wire [8:0] ty = gy + {9{gy[8]}};
    wire [7:0] ax = tx[7:0] ^ {8{gx[8]}};   // |v| <= 255 for the specified input range
    wire [7:0] ay = ty[7:0] ^ {8{gy[8]}};

    // ay > ax as the borrow of ax - ay: one carry chain (a comparison operator is mapped onto a
    // ripple of LUTs instead, eight levels deep).
    wire [8:0] d_xy = {1'b0, ax} - {1'b0, ay};
    assign swap = d_xy[8];
    assign lo   = swap ? ax : ay;
    assign hi   = swap ? ay : ax;
endmodule

module gradient_dir_s51 (
    input  wire [7:0]  hi,
    output wire [5:0]  m51h,         // floor(51*hi / 256), for gradient_dir_bin's first compare
    output wire [12:0] m19           // 19*hi <= 4845, for gradient_dir_bin's 171*hi
);
    // Products of the rule, factored to share a term (shifts and adds only):
    //   51*hi = 17*(3*hi),  171*hi = 9*(19*hi) with 19*hi = 16*hi + 3*hi.
    wire [9:0]  hi3 = {1'b0, hi, 1'b0} + {2'b0, hi};                // 3*hi   <= 765
    wire [13:0] m51 = {hi3, 4'b0} + {4'b0, hi3};                    // 51*hi  <= 13005
    assign m19  = {1'b0, hi, 4'b0} + {3'b0, hi3};
    assign m51h = m51[13:8];
endmodule

module gradient_dir_bin (
    input  wire [7:0]  lo,
    input  wire [12:0] m19,          // 19*hi (gradient_dir_s51)
    input  wire [5:0]  m51h,         // floor(51*hi / 256) (gradient_dir_s51)
    input  wire        swap,
    input  wire        negx,         // gx < 0
    input  wire        negy,         // gy < 0
    output reg  [3:0]  dir           // bin 0..15, 22.5 degrees per bin
);
    // 256*lo <= k*hi  <=>  lo <= floor(k*hi / 256), so only the upper byte is compared.
    wire [15:0] m171 = {m19, 3'b0} + {3'b0, m19};                   // 171*hi <= 43605
    wire le171 = (lo <= m171[15:8]);             // sector 0 or 1
    wire le51  = ({2'b0, lo} <= m51h);           // sector 0 (implies le171)

    // bin = s, 8 - s, 8 + s or (16 - s) mod 16 by quadrant, s = sector reflected when swap;
    // written out as a table so that it maps onto a few LUTs instead of 4-bit adders.
    always @* begin
        case ({negx, negy, swap, le51, le171})
            //  gx<0 gy<0 swap le51 le171      s
            5'b0_0_0_1_1, 5'b0_0_0_1_0: dir = 4'd0;    // 0
            5'b0_0_0_0_1:               dir = 4'd1;    // 1
            5'b0_0_0_0_0, 5'b0_0_1_0_0: dir = 4'd2;    // 2
            5'b0_0_1_0_1:               dir = 4'd3;    // 3
            5'b0_0_1_1_1, 5'b0_0_1_1_0: dir = 4'd4;    // 4
            5'b1_0_0_1_1, 5'b1_0_0_1_0: dir = 4'd8;    // 8 - 0
            5'b1_0_0_0_1:               dir = 4'd7;    // 8 - 1
            5'b1_0_0_0_0, 5'b1_0_1_0_0: dir = 4'd6;    // 8 - 2
            5'b1_0_1_0_1:               dir = 4'd5;    // 8 - 3
            5'b1_0_1_1_1, 5'b1_0_1_1_0: dir = 4'd4;    // 8 - 4
            5'b1_1_0_1_1, 5'b1_1_0_1_0: dir = 4'd8;    // 8 + 0
            5'b1_1_0_0_1:               dir = 4'd9;    // 8 + 1
            5'b1_1_0_0_0, 5'b1_1_1_0_0: dir = 4'd10;   // 8 + 2
            5'b1_1_1_0_1:               dir = 4'd11;   // 8 + 3
            5'b1_1_1_1_1, 5'b1_1_1_1_0: dir = 4'd12;   // 8 + 4
            5'b0_1_0_1_1, 5'b0_1_0_1_0: dir = 4'd0;    // 16 - 0
            5'b0_1_0_0_1:               dir = 4'd15;   // 16 - 1
            5'b0_1_0_0_0, 5'b0_1_1_0_0: dir = 4'd14;   // 16 - 2
            5'b0_1_1_0_1:               dir = 4'd13;   // 16 - 3
            default:                    dir = 4'd12;   // 16 - 4
        endcase
    end
endmodule

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
