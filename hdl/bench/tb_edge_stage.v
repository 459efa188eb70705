// Vector test bench of the edge stage alone (hdl/rtl/edge_stage.v): a case's expected gradient
// words (.out.hex, the gradient block's output) in, its expected edge beats (.edges.hex) out,
// beat for beat, with random input gaps and output back-pressure. tb_front.v checks the same
// beats behind the gradient block; this bench holds the edge stage to them on its own, so a
// fault there is found without the gradient block in the way. File formats: docs/gradient.md,
// "Golden vector files". Cases with resets are tb_front's (the stream after a reset needs it).
//
// Plusargs
//   +out=FILE +nout=N     gradient words in (with their tuser/tlast bits)
//   +edges=FILE +nedges=E expected edge beats
//   +threshold=T          cfg_threshold, grey levels
//   +seed=S +stall=P      P percent of clocks with an input gap and, independently, output
//                         back-pressure, from two xorshift32 generators seeded from S (0: none)
//   +corrupt_edge=K       flip bit 0 of expected edge beat K (fault injection)
// Exit status is non-zero ($fatal) on a mismatch, a missing or extra beat, a stuck stream or X
// on an output. The last line is "PASS n words, e edge beats".

`timescale 1ns/1ps
`default_nettype none
`include "gradient_word.vh"
`include "edge_beat.vh"

module tb_edge_stage;
    parameter MAX_WIDTH = 640;
    parameter DEPTH     = 2097152;              // beats per vector file (2^21)

    localparam OB       = `QT_VEC_OUT_BITS;
    localparam EB       = `QT_VEC_EDGE_BITS;
    localparam IDLE_MAX = 16 * MAX_WIDTH + 1000; // clocks without a handshake before failing
    localparam DRAIN    = 8 * MAX_WIDTH + 100;   // clocks watched for extra beats at the end

    reg [OB-1:0]     out_mem  [0:DEPTH-1];
    reg [EB-1:0]     edge_mem [0:DEPTH-1];
    reg [8*1024-1:0] out_file, edge_file;
    integer          nout, nedge, seed, stall, corrupt_e, threshold;

    reg         clk = 1'b0;
    reg         aresetn = 1'b0;
    reg  [31:0] s_tdata = 32'd0;
    reg  [1:0]  s_tuser = 2'b00;
    reg         s_tlast = 1'b0;
    reg         s_tvalid = 1'b0;
    reg         m_tready = 1'b0;
    wire        s_tready;
    wire [47:0] m_tdata;
    wire        m_tuser, m_tlast, m_tvalid;

    edge_stage #(.MAX_WIDTH(MAX_WIDTH)) dut (
        .aclk(clk), .aresetn(aresetn), .cfg_threshold(threshold[8:0]),
        .s_axis_tdata(s_tdata), .s_axis_tuser(s_tuser), .s_axis_tlast(s_tlast),
        .s_axis_tvalid(s_tvalid), .s_axis_tready(s_tready),
        .m_axis_tdata(m_tdata), .m_axis_tuser(m_tuser), .m_axis_tlast(m_tlast),
        .m_axis_tvalid(m_tvalid), .m_axis_tready(m_tready));

    always #5 clk = ~clk;

    // Two xorshift32 generators: input gaps and output back-pressure.
    reg [31:0] rin, rout;
    function [31:0] xorshift(input [31:0] v);
        reg [31:0] t;
        begin
            t = v ^ (v << 13);
            t = t ^ (t >> 17);
            xorshift = t ^ (t << 5);
        end
    endfunction

    integer k_in = 0, k_out = 0, idle = 0, cyc = 0, drained = 0;
    reg     offer;

    initial begin
        if (!$value$plusargs("out=%s", out_file)) $fatal(1, "tb_edge_stage: +out=FILE is required");
        if (!$value$plusargs("nout=%d", nout))    $fatal(1, "tb_edge_stage: +nout=N is required");
        if (!$value$plusargs("edges=%s", edge_file))
            $fatal(1, "tb_edge_stage: +edges=FILE is required");
        if (!$value$plusargs("nedges=%d", nedge)) $fatal(1, "tb_edge_stage: +nedges=E is required");
        if (!$value$plusargs("threshold=%d", threshold)) threshold = 40;
        if (!$value$plusargs("seed=%d", seed)) seed = 1;
        if (!$value$plusargs("stall=%d", stall)) stall = 0;
        if (!$value$plusargs("corrupt_edge=%d", corrupt_e)) corrupt_e = -1;
        if (nout < 0 || nout > DEPTH || nedge < 0 || nedge > DEPTH)
            $fatal(1, "tb_edge_stage: +nout/+nedges must be 0..%0d", DEPTH);
        if (threshold < 0 || threshold > 511) $fatal(1, "tb_edge_stage: +threshold must be 0..511");
        out_mem[nout > 0 ? nout - 1 : 0] = {OB{1'bx}};
        edge_mem[nedge > 0 ? nedge - 1 : 0] = {EB{1'bx}};
        if (nout > 0) $readmemh(out_file, out_mem, 0, nout - 1);
        if (nedge > 0) $readmemh(edge_file, edge_mem, 0, nedge - 1);
        if (nout > 0 && ^out_mem[nout - 1] === 1'bx)
            $fatal(1, "tb_edge_stage: %0s has fewer than %0d beats", out_file, nout);
        if (nedge > 0 && ^edge_mem[nedge - 1] === 1'bx)
            $fatal(1, "tb_edge_stage: %0s has fewer than %0d beats", edge_file, nedge);
        if (corrupt_e >= 0 && corrupt_e < nedge) edge_mem[corrupt_e][0] = ~edge_mem[corrupt_e][0];
        rin = 32'h9E3779B9 ^ seed;
        rout = 32'h7F4A7C15 ^ (seed * 3 + 1);
        if (rin == 0) rin = 1;
        if (rout == 0) rout = 1;
        repeat (4) @(posedge clk);
        aresetn <= 1'b1;
    end

    // Input: the next word offered unless a gap is drawn; held while not taken.
    always @(posedge clk) if (aresetn) begin
        cyc <= cyc + 1;
        rin = xorshift(rin);
        rout = xorshift(rout);
        if (s_tvalid && s_tready) k_in = k_in + 1;
        if (!s_tvalid || s_tready) begin
            offer = k_in < nout && (stall == 0 || rin % 100 >= stall);
            s_tvalid <= offer;
            s_tdata  <= offer ? out_mem[k_in][31:0] : 32'd0;
            s_tuser  <= offer ? {out_mem[k_in][`QT_VEC_OUT_EOF_BIT],
                                 out_mem[k_in][`QT_VEC_OUT_TUSER_BIT]} : 2'b00;
            s_tlast  <= offer ? out_mem[k_in][`QT_VEC_OUT_TLAST_BIT] : 1'b0;
        end
        m_tready <= stall == 0 || rout % 100 >= stall;
    end

    // Output: every beat against the next expected one.
    always @(posedge clk) if (aresetn) begin
        if (^{m_tvalid, s_tready} === 1'bx)
            $fatal(1, "tb_edge_stage: X on a handshake at clock %0d", cyc);
        if (m_tvalid && m_tready) begin
            if (^{m_tdata, m_tuser, m_tlast} === 1'bx)
                $fatal(1, "tb_edge_stage: X on the edge stream at clock %0d", cyc);
            if (k_out >= nedge)
                $fatal(1, "tb_edge_stage: extra edge beat %h at clock %0d", m_tdata, cyc);
            if ({m_tlast, m_tuser, m_tdata} !== edge_mem[k_out]) begin
                $display("MISMATCH edge=%0d got %h expected %h", k_out,
                         {m_tlast, m_tuser, m_tdata}, edge_mem[k_out]);
                $fatal(1, "tb_edge_stage: edge beat %0d differs", k_out);
            end
            k_out = k_out + 1;
            idle = 0;
        end else if (s_tvalid && s_tready) begin
            idle = 0;
        end else begin
            idle = idle + 1;
            if (idle > IDLE_MAX && k_out < nedge)
                $fatal(1, "tb_edge_stage: stuck at word %0d of %0d, edge beat %0d of %0d",
                       k_in, nout, k_out, nedge);
        end
        if (k_in >= nout && k_out >= nedge) begin
            drained = drained + 1;
            if (drained > DRAIN) begin
                $display("PASS %0d words, %0d edge beats", nout, nedge);
                $finish;
            end
        end
    end
endmodule

`default_nettype wire
