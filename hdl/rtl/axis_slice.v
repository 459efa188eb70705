`timescale 1ns / 1ps
`default_nettype none

// AXI4-Stream register slice (skid buffer): two registers, full throughput, and no
// combinational path from m_ready to s_ready (s_ready is a flip-flop's output) nor from s_valid
// or s_data to the m_ side. The block in front of it stalls on ~s_ready alone.
//
//   main  (m_data, m_valid): the beat offered downstream
//   skid  (k_data, k_valid): a beat taken while main was stalled; s_ready is ~k_valid
//
// Verified with the blocks: hdl/formal/ (the stream rules under any m_ready), the benches.

module axis_slice #(
    parameter W = 8                     // data bits, tuser and tlast included
) (
    input  wire         clk,
    input  wire         rst,            // synchronous, active high

    input  wire [W-1:0] s_data,
    input  wire         s_valid,
    output wire         s_ready,

    output reg  [W-1:0] m_data,
    output reg          m_valid,
    input  wire         m_ready
);
    reg [W-1:0] k_data;
    reg         k_valid;

    assign s_ready = ~k_valid;

    wire m_load = ~m_valid | m_ready;   // main is empty or its beat is being taken

    always @(posedge clk) begin
        if (rst) begin
            m_valid <= 1'b0;
            k_valid <= 1'b0;
        end else if (m_load) begin
            m_valid <= k_valid | s_valid;   // s_valid counts only when s_ready (k empty)
            k_valid <= 1'b0;
        end else if (s_valid) begin
            k_valid <= 1'b1;                // main stalled: park the beat (s_ready was 1)
        end
    end

    always @(posedge clk) begin
        if (m_load)
            m_data <= k_valid ? k_data : s_data;
        if (~k_valid)
            k_data <= s_data;
    end
endmodule

`default_nettype wire
