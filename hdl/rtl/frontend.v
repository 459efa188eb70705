`timescale 1ns / 1ps
`default_nettype none

// The FPGA front end a hardware engineer drops in: camera pixels in on AXI4-Stream video
// (tuser = start of frame, tlast = end of line), the edge points the microcontroller's edge list
// takes out (edge_beat.vh), the gradient block (gradient.v) feeding the edge stage
// (edge_stage.v) through its AXI4-Stream output. Contract: docs/gradient.md ("The front end").
//
// Frames up to MAX_WIDTH x 2048 pixels (the edge point's coordinates have 11 bits): a
// cfg_height above 2048 is refused like a height of 0 (the start of frame is an error and the
// frame is dropped).

module frontend #(
    parameter MAX_WIDTH = 640                  // 1..2048 pixels per row
) (
    input  wire        aclk,
    input  wire        aresetn,                // synchronous, active low

    input  wire [15:0] cfg_height,             // rows per frame (1..2048), read at start of frame
    input  wire [8:0]  cfg_threshold,          // edge threshold, L1 magnitude, grey levels

    input  wire [7:0]  s_axis_tdata,           // pixel, grey levels
    input  wire        s_axis_tuser,           // start of frame
    input  wire        s_axis_tlast,           // end of line
    input  wire        s_axis_tvalid,
    output wire        s_axis_tready,

    output wire [47:0] m_axis_tdata,           // edge beat
    output wire        m_axis_tuser,           // a frame's first beat
    output wire        m_axis_tlast,           // a frame's trailer
    output wire        m_axis_tvalid,
    input  wire        m_axis_tready,

    output wire        error                   // one clock per framing error (input-timed)
);
    // The gradient stream between the two blocks (the benches watch it too).
    wire [31:0] g_tdata;
    wire [1:0]  g_tuser;
    wire        g_tlast, g_tvalid, g_tready;

    // The gradient block refuses a cfg_height above MAX_ROWS like 0.
    gradient #(.MAX_WIDTH(MAX_WIDTH), .MAX_ROWS(2048)) u_gradient (
        .aclk(aclk), .aresetn(aresetn), .cfg_height(cfg_height),
        .s_axis_tdata(s_axis_tdata), .s_axis_tuser(s_axis_tuser), .s_axis_tlast(s_axis_tlast),
        .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .m_axis_tdata(g_tdata), .m_axis_tuser(g_tuser), .m_axis_tlast(g_tlast),
        .m_axis_tvalid(g_tvalid), .m_axis_tready(g_tready), .error(error));

    edge_stage #(.MAX_WIDTH(MAX_WIDTH)) u_edges (
        .aclk(aclk), .aresetn(aresetn), .cfg_threshold(cfg_threshold),
        .s_axis_tdata(g_tdata), .s_axis_tuser(g_tuser), .s_axis_tlast(g_tlast),
        .s_axis_tvalid(g_tvalid), .s_axis_tready(g_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tuser(m_axis_tuser), .m_axis_tlast(m_axis_tlast),
        .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready));
endmodule

`default_nettype wire
