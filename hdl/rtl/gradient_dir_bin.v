`timescale 1ns / 1ps
`default_nettype none

// Direction bin, part 3 of 3 (gradient_direction.v): the two sector compares
// (256*lo <= 51*hi, 256*lo <= 171*hi) and the quadrant mapping to the bin, combinational.

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

`default_nettype wire
