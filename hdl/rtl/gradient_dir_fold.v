`timescale 1ns / 1ps
`default_nettype none

// Direction bin, part 1 of 3 (gradient_direction.v): |gx|, |gy| folded into lo = min,
// hi = max and swap = (|gy| > |gx|), combinational.

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

`default_nettype wire
