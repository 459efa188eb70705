// Vector test bench for hdl/rtl/gradient.v (file formats: docs/gradient.md, "Golden vector files").
//
// Plusargs
//   +in=FILE +out=FILE   input / expected-output vector files
//   +nin=N +nout=M       beats in each file
//   +errors=E            expected number of error pulses
//   +seed=S +stall=P     P percent of clocks with an input gap and, independently, output
//                        back-pressure, from two xorshift32 generators seeded from S (0: none)
//   +corrupt=K           flip bit 0 of expected beat K after loading (fault injection)
//   +resets=FILE +nresets=N  reset points (the soak's .resets.hex, docs/gradient.md): before
//                        input beat in_beat the bench stops offering input, keeps the output
//                        side going for 3..18 clocks (1 in 8 resets: up to 2*MAX_WIDTH+2) so
//                        that the error pulses of every accepted beat have landed, checks the
//                        error count against the file, then holds rst for 1..8 clocks (xorshift)
//                        and goes on. Before a reset the block may emit any prefix of the
//                        segment's expected beats, no more; the first beat after it must be
//                        expected beat out_beat (a start of frame).
// Exit status is non-zero ($fatal) on a mismatch, a missing or extra beat, a stuck stream or a
// wrong error count. With +stall=0 and no resets the latency from a pixel's acceptance to the
// output of its own gradient word is reported over interior pixels (x = 1..W-2, rows with a
// successor row). With resets the last line is "PASS n beats, r resets, e errors, c cut".

`timescale 1ns/1ps
`include "gradient_word.vh"

module tb_gradient;
    parameter MAX_WIDTH = 640;
    parameter DEPTH     = 2097152;              // beats per vector file (2^21)
    parameter RDEPTH    = 65536;                // reset points

    localparam IB       = `QT_VEC_IN_BITS;
    localparam OB       = `QT_VEC_OUT_BITS;
    // Reset points: {in_beat[31:0], out_beat[31:0], errors[31:0]} (hw_model/vector_format.h).
    localparam RB       = 96;
    localparam IDLE_MAX = 8 * MAX_WIDTH + 1000; // clocks without a handshake before failing
    localparam DRAIN    = 4 * MAX_WIDTH + 100;  // clocks watched for extra beats at the end

    reg [IB-1:0]      in_mem  [0:DEPTH-1];
    reg [OB-1:0]      out_mem [0:DEPTH-1];
    reg [RB-1:0]      rs_mem  [0:RDEPTH-1];
    reg [8*1024-1:0]  in_file, out_file, rs_file;
    integer           nin, nout, nerr, seed, stall, corrupt, nres;

    // ---------------------------------------------------------------- DUT
    reg         clk = 1'b0;
    reg         rst = 1'b1;
    reg  [7:0]  s_tdata  = 8'd0;
    reg         s_tuser  = 1'b0;
    reg         s_tlast  = 1'b0;
    reg         s_tvalid = 1'b0;
    reg  [15:0] s_height = 16'd0;
    reg         m_tready = 1'b0;
    wire        s_tready;
    wire [31:0] m_tdata;
    wire        m_tuser, m_tlast, m_tvalid, error;

    always #5 clk = ~clk;                       // 10 ns clock

    gradient #(.MAX_WIDTH(MAX_WIDTH)) dut (
        .clk(clk), .rst(rst),
        .s_tdata(s_tdata), .s_tuser(s_tuser), .s_tlast(s_tlast), .s_tvalid(s_tvalid),
        .s_tready(s_tready), .s_height(s_height),
        .m_tdata(m_tdata), .m_tuser(m_tuser), .m_tlast(m_tlast), .m_tvalid(m_tvalid),
        .m_tready(m_tready), .error(error));

    // ---------------------------------------------------------------- stimulus randomness
    reg [31:0] rng_in, rng_out, rng_rst;

    function [31:0] xorshift32;
        input [31:0] v;
        reg   [31:0] t;
        begin
            t = v ^ (v << 13);
            t = t ^ (t >> 17);
            xorshift32 = t ^ (t << 5);
        end
    endfunction

    // ---------------------------------------------------------------- bookkeeping
    integer cyc;                 // clocks since reset release
    integer iidx, oidx;          // next input beat to offer, next expected output beat
    integer err_count;
    integer idle;                // clocks since the last handshake on either side
    integer drain;               // clocks since the last expected beat was seen
    reg     done;

    // Resets: rs_mem[ridx] is the next one; the expected beats before seg_end belong to the
    // current segment.
    integer ridx, seg_end;
    integer quiet;               // > 0: input stopped before reset ridx, clocks left
    integer rclk;                // clocks of rst left
    integer got;                 // output beats received
    integer cut;                 // expected beats the block did not emit before a reset took it
    integer r_prev_in, r_prev_out, r_prev_err, k;
    reg     after_rst;           // no beat received since the last reset
    reg [RB-1:0] rs;

    // Expected-output framing: position of beat oidx.
    integer ef, ex, ey, ew;      // frame (first is 0), column, row, width of that frame

    // Input framing, for latency: acceptance clock of (x, y mod 4) in the current input frame.
    integer fin, xin, yin;
    integer acc_time  [0:4*MAX_WIDTH-1];
    integer acc_frame [0:4*MAX_WIDTH-1];
    integer lat_min, lat_max, row_min, row_max, lat_w, slot, lat;
    integer ex_min, ex_max;      // latency minus the frame width
    reg     row_has, lat_mixed;

    reg [OB-1:0] exp_beat, got_beat;
    reg [IB-1:0] ib;

    initial begin
        if (!$value$plusargs("in=%s", in_file))   $fatal(1, "tb_gradient: +in=FILE is required");
        if (!$value$plusargs("out=%s", out_file)) $fatal(1, "tb_gradient: +out=FILE is required");
        if (!$value$plusargs("nin=%d", nin))      $fatal(1, "tb_gradient: +nin=N is required");
        if (!$value$plusargs("nout=%d", nout))    $fatal(1, "tb_gradient: +nout=M is required");
        if (!$value$plusargs("errors=%d", nerr))  nerr = 0;
        if (!$value$plusargs("seed=%d", seed))    seed = 1;
        if (!$value$plusargs("stall=%d", stall))  stall = 0;
        if (!$value$plusargs("corrupt=%d", corrupt)) corrupt = -1;
        nres = 0;
        if ($value$plusargs("resets=%s", rs_file)) begin
            if (!$value$plusargs("nresets=%d", nres))
                $fatal(1, "tb_gradient: +resets=FILE needs +nresets=N");
        end
        if (nin < 0 || nin > DEPTH || nout < 0 || nout > DEPTH)
            $fatal(1, "tb_gradient: +nin/+nout must be 0..%0d", DEPTH);
        if (nres < 0 || nres > RDEPTH)
            $fatal(1, "tb_gradient: +nresets must be 0..%0d", RDEPTH);

        if (nin > 0) begin
            in_mem[nin - 1] = {IB{1'bx}};
            $readmemh(in_file, in_mem, 0, nin - 1);
            if (^in_mem[nin - 1] === 1'bx)
                $fatal(1, "tb_gradient: %0s has fewer than %0d beats", in_file, nin);
        end
        if (nout > 0) begin
            out_mem[nout - 1] = {OB{1'bx}};
            $readmemh(out_file, out_mem, 0, nout - 1);
            if (^out_mem[nout - 1] === 1'bx)
                $fatal(1, "tb_gradient: %0s has fewer than %0d beats", out_file, nout);
        end
        if (nres > 0) begin
            rs_mem[nres - 1] = {RB{1'bx}};
            $readmemh(rs_file, rs_mem, 0, nres - 1);
            if (^rs_mem[nres - 1] === 1'bx)
                $fatal(1, "tb_gradient: %0s has fewer than %0d reset points", rs_file, nres);
            // The points must be in stream order, within the files, and every non-empty
            // segment must begin with a start of frame.
            r_prev_in = 0; r_prev_out = 0; r_prev_err = 0;
            for (k = 0; k < nres; k = k + 1) begin
                rs = rs_mem[k];
                if (rs[95:64] < r_prev_in || rs[95:64] > nin || rs[63:32] < r_prev_out ||
                    rs[63:32] > nout || rs[31:0] < r_prev_err || rs[31:0] > nerr)
                    $fatal(1, "tb_gradient: reset point %0d (%h) out of order or range", k, rs);
                r_prev_in = rs[95:64]; r_prev_out = rs[63:32]; r_prev_err = rs[31:0];
            end
        end
        for (k = 0; k < nres; k = k + 1) begin
            rs = rs_mem[k];
            if (rs[63:32] < nout && out_mem[rs[63:32]][`QT_VEC_OUT_TUSER_BIT] !== 1'b1 &&
                (k + 1 == nres || rs_mem[k + 1][63:32] != rs[63:32]))
                $fatal(1, "tb_gradient: expected beat %0d after reset %0d is no start of frame",
                       rs[63:32], k);
        end
        if (corrupt >= 0 && corrupt < nout)
            out_mem[corrupt][0] = ~out_mem[corrupt][0];

        rng_in  = xorshift32(32'h9e3779b9 ^ seed);
        rng_out = xorshift32(32'h7f4a7c15 ^ (seed * 3));
        rng_rst = xorshift32(32'h2545f491 ^ (seed * 5));
        if (rng_in == 0)  rng_in  = 32'h1;
        if (rng_out == 0) rng_out = 32'h2;
        if (rng_rst == 0) rng_rst = 32'h3;
        ridx = 0; quiet = 0; rclk = 0; got = 0; cut = 0; after_rst = 1'b0;
        seg_end = nres > 0 ? rs_mem[0][63:32] : nout;

        cyc = 0; iidx = 0; oidx = 0; err_count = 0; idle = 0; drain = 0; done = 1'b0;
        ef = -1; ex = 0; ey = 0; ew = 0;
        fin = -1; xin = 0; yin = 0;
        lat_min = -1; lat_max = -1; row_min = -1; row_max = -1; row_has = 1'b0; lat_w = -1;
        ex_min = 0; ex_max = 0; lat_mixed = 1'b0;

        repeat (4) @(posedge clk);
        rst <= 1'b0;
    end

    always @(posedge clk) begin
        if (!rst && !done) begin
            cyc  = cyc + 1;
            idle = idle + 1;

            if (error === 1'b1)
                err_count = err_count + 1;
            else if (error !== 1'b0)
                $fatal(1, "tb_gradient: error output is %b at clock %0d", error, cyc);

            // ---- input side
            if (s_tvalid && s_tready) begin
                idle = 0;
                if (s_tuser) begin
                    fin = fin + 1; xin = 0; yin = 0;
                end
                if (xin < MAX_WIDTH) begin
                    slot = (yin % 4) * MAX_WIDTH + xin;
                    acc_time[slot]  = cyc;
                    acc_frame[slot] = fin;
                end
                if (s_tlast) begin
                    xin = 0; yin = yin + 1;
                end else begin
                    xin = xin + 1;
                end
                iidx = iidx + 1;
            end
            if (!(s_tvalid && !s_tready)) begin         // a pending beat must be held
                rng_in = xorshift32(rng_in);
                if (quiet == 0 && ridx < nres && iidx == rs_mem[ridx][95:64]) begin
                    // Reset point: stop the input, let the error pulses land.
                    rng_rst = xorshift32(rng_rst);
                    if (rng_rst[31:29] == 3'd0)
                        quiet = 4 + rng_rst % (2 * MAX_WIDTH);
                    else
                        quiet = 4 + rng_rst % 16;
                end
                if (quiet == 0 && iidx < nin && (rng_in % 100) >= stall) begin
                    ib = in_mem[iidx];
                    s_tvalid <= 1'b1;
                    s_tdata  <= ib[7:0];
                    s_tuser  <= ib[`QT_VEC_IN_TUSER_BIT];
                    s_tlast  <= ib[`QT_VEC_IN_TLAST_BIT];
                    s_height <= ib[`QT_VEC_IN_HEIGHT_LSB +: 16];
                end else begin
                    s_tvalid <= 1'b0;
                end
            end

            // ---- output side
            if (m_tvalid === 1'bx || (m_tvalid === 1'b1 && m_tready === 1'b1 &&
                                      ^{m_tlast, m_tuser, m_tdata} === 1'bx))
                $fatal(1, "tb_gradient: X on the output stream at clock %0d", cyc);
            if (m_tvalid && m_tready) begin
                idle     = 0;
                got_beat = {m_tlast, m_tuser, m_tdata};
                if (oidx >= seg_end && ridx < nres) begin
                    $display("EXTRA beat=%0d got=%h (the segment before reset %0d ends at beat %0d)",
                             oidx, got_beat, ridx, seg_end);
                    $fatal(1, "tb_gradient: more output beats before reset %0d than expected", ridx);
                end
                if (oidx >= nout) begin
                    $display("EXTRA beat=%0d got=%h", oidx, got_beat);
                    $fatal(1, "tb_gradient: more than %0d output beats", nout);
                end
                exp_beat = out_mem[oidx];
                if (exp_beat[`QT_VEC_OUT_TUSER_BIT]) begin
                    ef = ef + 1; ex = 0; ey = 0;
                end
                if (got_beat !== exp_beat) begin
                    $display("MISMATCH beat=%0d frame=%0d x=%0d y=%0d expected=%h got=%h",
                             oidx, ef, ex, ey, exp_beat, got_beat);
                    if (nres > 0 && after_rst)
                        $display("  the first beat after reset %0d", ridx - 1);
                    else if (nres > 0)
                        $display("  in the segment before reset %0d", ridx);
                    $fatal(1, "tb_gradient: output differs from %0s", out_file);
                end
                after_rst = 1'b0;
                got = got + 1;

                // Latency of interior pixels, committed once the row is known not to be the last.
                if (ex == 0) begin
                    if (ey >= 2 && row_has) begin
                        if (lat_min < 0 || row_min - ew < ex_min) ex_min = row_min - ew;
                        if (lat_min < 0 || row_max - ew > ex_max) ex_max = row_max - ew;
                        if (lat_min < 0 || row_min < lat_min) lat_min = row_min;
                        if (row_max > lat_max) lat_max = row_max;
                        if (lat_w >= 0 && lat_w != ew) lat_mixed = 1'b1;
                        lat_w = ew;
                    end
                    row_has = 1'b0;
                end
                if (nres == 0 && ey >= 1 && ex >= 1 && ex <= ew - 2 && ex < MAX_WIDTH) begin
                    slot = (ey % 4) * MAX_WIDTH + ex;
                    if (acc_frame[slot] === fin) begin
                        lat = cyc - acc_time[slot];
                        if (!row_has || lat < row_min) row_min = lat;
                        if (!row_has || lat > row_max) row_max = lat;
                        row_has = 1'b1;
                    end
                end

                if (exp_beat[`QT_VEC_OUT_TLAST_BIT]) begin
                    if (ey == 0) ew = ex + 1;
                    ex = 0; ey = ey + 1;
                end else begin
                    ex = ex + 1;
                end
                oidx = oidx + 1;
            end
            rng_out = xorshift32(rng_out);
            m_tready <= ((rng_out % 100) >= stall);

            // ---- reset point: every error pulse of the segment's beats has been counted
            // (they come 1 and 2 clocks after the beat); the expected output jumps to the next
            // segment, whose first beat must be the first the block emits after the reset.
            if (quiet > 0) begin
                quiet = quiet - 1;
                if (quiet == 0) begin
                    rs = rs_mem[ridx];
                    if (err_count != rs[31:0])
                        $fatal(1, "tb_gradient: %0d error pulses before reset %0d, expected %0d",
                               err_count, ridx, rs[31:0]);
                    cut = cut + (seg_end - oidx);
                    for (k = oidx; k < seg_end; k = k + 1)
                        if (out_mem[k][`QT_VEC_OUT_TUSER_BIT]) ef = ef + 1;
                    oidx = seg_end;
                    ridx = ridx + 1;
                    seg_end = ridx < nres ? rs_mem[ridx][63:32] : nout;
                    rng_rst = xorshift32(rng_rst);
                    rclk = 1 + rng_rst % 8;
                    rst <= 1'b1;
                    after_rst = 1'b1;
                    idle = 0;
                end
            end

            // ---- completion and liveness
            if (iidx >= nin && oidx >= nout && ridx >= nres && quiet == 0) begin
                drain = drain + 1;
                if (drain > DRAIN) begin
                    if (err_count != nerr)
                        $fatal(1, "tb_gradient: %0d error pulses, expected %0d", err_count, nerr);
                    if (stall == 0 && nres == 0) begin
                        if (lat_min >= 0 && !lat_mixed)
                            $display("LATENCY min=%0d max=%0d width=%0d (width + %0d..%0d)",
                                     lat_min, lat_max, lat_w, ex_min, ex_max);
                        else if (lat_min >= 0)
                            $display("LATENCY min=%0d max=%0d width=mixed (width + %0d..%0d)",
                                     lat_min, lat_max, ex_min, ex_max);
                        else
                            $display("LATENCY none (no interior pixels)");
                    end
                    if (nres > 0)
                        $display("PASS %0d beats, %0d resets, %0d errors, %0d cut", got, nres,
                                 err_count, cut);
                    else
                        $display("PASS %0d beats", oidx);
                    done = 1'b1;
                    $finish;
                end
            end else if (idle > IDLE_MAX) begin
                if (oidx < nout) begin
                    exp_beat = out_mem[oidx];
                    if (exp_beat[`QT_VEC_OUT_TUSER_BIT])
                        $display("MISSING beat=%0d frame=%0d x=0 y=0 expected=%h (input beat %0d of %0d)",
                                 oidx, ef + 1, exp_beat, iidx, nin);
                    else
                        $display("MISSING beat=%0d frame=%0d x=%0d y=%0d expected=%h (input beat %0d of %0d)",
                                 oidx, ef, ex, ey, exp_beat, iidx, nin);
                end
                $fatal(1, "tb_gradient: no handshake for %0d clocks", IDLE_MAX);
            end
        end else if (rst && rclk > 0) begin             // a reset point's rst: 1..8 clocks
            rclk = rclk - 1;
            if (rclk == 0)
                rst <= 1'b0;
        end
    end
endmodule
