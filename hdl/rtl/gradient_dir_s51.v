`timescale 1ns / 1ps
`default_nettype none

// Direction bin, part 2 of 3 (gradient_direction.v): 3*hi, the upper bits of 51*hi, and
// 19*hi, combinational.

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

`default_nettype wire
