// Vector test bench of the gradient block (FRONT = 0: hdl/rtl/gradient.v alone) and of the FPGA
// front end (FRONT = 1: hdl/rtl/frontend.v, the gradient block feeding the edge stage). File
// formats: docs/gradient.md, "Golden vector files". With FRONT = 1 both streams are checked: the
// edge beats at the output and the gradient words on the link between the two blocks.
//
// Plusargs
//   +in=FILE +out=FILE    input / expected gradient vector files; +nin=N +nout=M beats in each
//   +edges=FILE +nedges=E expected edge beats (FRONT = 1)
//   +errors=E             expected number of error pulses
//   +threshold=T          cfg_threshold (FRONT = 1), grey levels
//   +seed=S +stall=P      P percent of clocks with an input gap and, independently, output
//                         back-pressure, from two xorshift32 generators seeded from S (0: none)
//   +corrupt=K            flip bit 0 of expected gradient beat K after loading (fault injection)
//   +corrupt_edge=K       flip bit 0 of expected edge beat K
//   +resets=FILE +nresets=N  reset points (.resets.hex, docs/gradient.md): before input beat
//                         in_beat the bench stops offering input, keeps the output side going for
//                         3..18 clocks (1 in 8 resets: up to 4*MAX_WIDTH+4, so that some flushes
//                         finish) so that the error pulses of every accepted beat have landed,
//                         checks the error count against the file, then holds aresetn low for
//                         1..8 clocks (xorshift) and goes on. Before a reset a block may emit any
//                         prefix of the segment's expected beats, no more; the first beat after
//                         it must be the next segment's first (a start of frame).
//   +lat_extra=K          (no stalls, no resets) every interior pixel's gradient word must leave
//                         exactly W + K clocks after the pixel was accepted
//   +trail_max=K          (FRONT = 1, no stalls, no resets) every frame's edge trailer must
//                         leave at most 2*W + K clocks after the frame's last pixel
//   +max_stalls=N         (no stalls) at most N clocks with a beat offered and not taken
//   +scramble_threshold=1 (FRONT = 1) cfg_threshold is T only in the clocks the gradient link
//                         offers a frame's first word (when the edge stage must read it) and a
//                         random other value in every other clock: a block that reads it at any
//                         other time gives other edges
//   +vary_threshold=1     (FRONT = 1) each frame's threshold is drawn from T and the frame's
//                         first word on the gradient link: 1 + ((word * 0x9E3779B1 + T) >> 25)
//                         (the soak generator's frame_threshold, hw_model/edge_model.h), set in
//                         the clocks the link offers that word and held until the next frame's
//                         (or scrambled in between, with +scramble_threshold=1)
// cfg_height is driven from a start-of-frame beat's height field when that beat is offered and
// held until the next one (a register, as software sets it).
// Exit status is non-zero ($fatal) on a mismatch, a missing or extra beat, a stuck stream, a
// wrong error count, X on an output or a failed latency or stall check. The last line is
// "PASS n beats, e edge beats, r resets, x errors, c cut" (c: expected beats, of either stream,
// a block had not emitted when a reset took it).

`timescale 1ns/1ps
`default_nettype none
`include "gradient_word.vh"
`include "edge_beat.vh"

module tb_front;
    parameter FRONT     = 1;
    parameter MAX_WIDTH = 640;
    parameter DEPTH     = 2097152;              // beats per vector file (2^21)
    parameter RDEPTH    = 65536;                // reset points

    localparam IB       = `QT_VEC_IN_BITS;
    localparam OB       = `QT_VEC_OUT_BITS;
    localparam EB       = `QT_VEC_EDGE_BITS;
    localparam RB       = `QT_VEC_RESET_BITS;
    localparam IDLE_MAX = 16 * MAX_WIDTH + 1000; // clocks without a handshake before failing
    localparam DRAIN    = 8 * MAX_WIDTH + 100;   // clocks watched for extra beats at the end
    localparam EDEPTH   = FRONT ? DEPTH : 1;

    reg [IB-1:0]      in_mem   [0:DEPTH-1];
    reg [OB-1:0]      out_mem  [0:DEPTH-1];
    reg [EB-1:0]      edge_mem [0:EDEPTH-1];
    reg [RB-1:0]      rs_mem   [0:RDEPTH-1];
    reg [8*1024-1:0]  in_file, out_file, edge_file, rs_file;
    integer           nin, nout, nedge, nerr, seed, stall, corrupt, corrupt_e, nres;
    integer           threshold, lat_extra, trail_max, max_stalls, scramble, vary;

    // ---------------------------------------------------------------- DUT
    reg         clk = 1'b0;
    reg         aresetn = 1'b0;
    reg  [7:0]  s_tdata  = 8'd0;
    reg         s_tuser  = 1'b0;
    reg         s_tlast  = 1'b0;
    reg         s_tvalid = 1'b0;
    reg  [15:0] cfg_height = 16'd0;
    reg  [8:0]  cfg_threshold = 9'd0;
    reg         m_tready = 1'b0;
    wire        s_tready, error;

    // The gradient stream (the DUT's output, or the front end's internal link) and the edges.
    wire [31:0] g_tdata;
    wire [1:0]  g_tuser;
    wire        g_tlast, g_tvalid, g_tready;
    wire [47:0] e_tdata;
    wire        e_tuser, e_tlast, e_tvalid;

    always #5 clk = ~clk;                       // 10 ns clock

    generate
        if (FRONT) begin : g_dut
            frontend #(.MAX_WIDTH(MAX_WIDTH)) dut (
                .aclk(clk), .aresetn(aresetn), .cfg_height(cfg_height),
                .cfg_threshold(cfg_threshold),
                .s_axis_tdata(s_tdata), .s_axis_tuser(s_tuser), .s_axis_tlast(s_tlast),
                .s_axis_tvalid(s_tvalid), .s_axis_tready(s_tready),
                .m_axis_tdata(e_tdata), .m_axis_tuser(e_tuser), .m_axis_tlast(e_tlast),
                .m_axis_tvalid(e_tvalid), .m_axis_tready(m_tready), .error(error));
            assign g_tdata  = dut.g_tdata;
            assign g_tuser  = dut.g_tuser;
            assign g_tlast  = dut.g_tlast;
            assign g_tvalid = dut.g_tvalid;
            assign g_tready = dut.g_tready;
        end else begin : g_dut
            gradient #(.MAX_WIDTH(MAX_WIDTH)) dut (
                .aclk(clk), .aresetn(aresetn), .cfg_height(cfg_height),
                .s_axis_tdata(s_tdata), .s_axis_tuser(s_tuser), .s_axis_tlast(s_tlast),
                .s_axis_tvalid(s_tvalid), .s_axis_tready(s_tready),
                .m_axis_tdata(g_tdata), .m_axis_tuser(g_tuser), .m_axis_tlast(g_tlast),
                .m_axis_tvalid(g_tvalid), .m_axis_tready(m_tready), .error(error));
            assign g_tready = m_tready;
            assign e_tdata  = 48'd0;
            assign e_tuser  = 1'b0;
            assign e_tlast  = 1'b0;
            assign e_tvalid = 1'b0;
        end
    endgenerate

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

    // The threshold between frames' first words: any other value (its own generator, so the
    // stall and reset patterns stay those of the seed). The link's signals are registers, so the
    // value set at the falling edge holds through the rising edge that may take the word.
    reg [31:0] rng_thr = 32'h6d2b79f5;
    reg [31:0] thr_hash;
    reg [8:0]  frame_thr;        // the value the frame on the link must see
    reg [8:0]  last_thr = 9'd0;  // the last frame's value (scrambling avoids it)
    always @(negedge clk) begin
        if (g_tvalid && g_tuser[0] && (vary != 0 || scramble != 0)) begin
            thr_hash  = g_tdata * 32'h9E3779B1 + threshold;
            frame_thr = vary != 0 ? 9'd1 + {2'b00, thr_hash[31:25]} : threshold[8:0];
            cfg_threshold <= frame_thr;
            last_thr = frame_thr;
        end else if (scramble != 0) begin
            rng_thr = xorshift32(rng_thr);
            cfg_threshold <= rng_thr[8:0] == last_thr ? ~rng_thr[8:0] : rng_thr[8:0];
        end
    end

    // ---------------------------------------------------------------- bookkeeping
    integer cyc;                 // clocks since the first reset release
    integer iidx;                // next input beat to offer
    integer oidx, eidx;          // next expected gradient / edge beat
    integer err_count;
    integer idle;                // clocks since the last handshake anywhere
    integer drain;               // clocks since everything expected was seen
    integer stalls;              // clocks with a beat offered and not taken
    reg     done;

    // Resets: rs_mem[ridx] is the next one; expected beats before seg_g / seg_e belong to the
    // current segment.
    integer ridx, seg_g, seg_e;
    integer quiet;               // > 0: input stopped before reset ridx, clocks left
    integer rclk;                // clocks of aresetn low left
    integer got_g, got_e;        // beats received
    integer cut;                 // expected beats not emitted before a reset took them
    integer r_prev_in, r_prev_out, r_prev_edge, r_prev_err, k;
    reg     after_g, after_e;    // no beat received on that stream since the last reset
    reg [RB-1:0] rs;

    // Expected gradient framing: position of beat oidx.
    integer ef, ex, ey, ew;      // frame (first is 0), column, row, width of that frame
    integer efe;                 // edge frame

    // Input framing, for latency: acceptance clock of (x, y mod 4) in the current input frame.
    integer fin, xin, yin, w_in;
    integer acc_time  [0:4*MAX_WIDTH-1];
    integer acc_frame [0:4*MAX_WIDTH-1];
    integer last_acc;            // acceptance clock of the last beat of the current frame row
    integer lat_min, lat_max, row_min, row_max, lat_w, slot, lat;
    integer ex_min, ex_max;      // latency minus the frame width
    integer tr_min, tr_max, tr_n; // trailer latency minus 2 * width
    integer frame_end_time [0:255];
    integer frame_width    [0:255];
    integer frames_ended;
    reg     row_has, lat_mixed;

    reg [OB-1:0] exp_beat, got_beat;
    reg [EB-1:0] exp_edge, got_edge;
    reg [IB-1:0] ib;

    initial begin
        if (!$value$plusargs("in=%s", in_file))   $fatal(1, "tb_front: +in=FILE is required");
        if (!$value$plusargs("out=%s", out_file)) $fatal(1, "tb_front: +out=FILE is required");
        if (!$value$plusargs("nin=%d", nin))      $fatal(1, "tb_front: +nin=N is required");
        if (!$value$plusargs("nout=%d", nout))    $fatal(1, "tb_front: +nout=M is required");
        nedge = 0;
        if (FRONT) begin
            if (!$value$plusargs("edges=%s", edge_file))
                $fatal(1, "tb_front: +edges=FILE is required with FRONT = 1");
            if (!$value$plusargs("nedges=%d", nedge))
                $fatal(1, "tb_front: +nedges=E is required with FRONT = 1");
        end
        if (!$value$plusargs("errors=%d", nerr))  nerr = 0;
        if (!$value$plusargs("threshold=%d", threshold)) threshold = 40;
        if (!$value$plusargs("seed=%d", seed))    seed = 1;
        if (!$value$plusargs("stall=%d", stall))  stall = 0;
        if (!$value$plusargs("corrupt=%d", corrupt)) corrupt = -1;
        if (!$value$plusargs("corrupt_edge=%d", corrupt_e)) corrupt_e = -1;
        if (!$value$plusargs("lat_extra=%d", lat_extra)) lat_extra = -1;
        if (!$value$plusargs("trail_max=%d", trail_max)) trail_max = -1;
        if (!$value$plusargs("max_stalls=%d", max_stalls)) max_stalls = -1;
        if (!$value$plusargs("scramble_threshold=%d", scramble)) scramble = 0;
        if (!$value$plusargs("vary_threshold=%d", vary)) vary = 0;
        nres = 0;
        if ($value$plusargs("resets=%s", rs_file)) begin
            if (!$value$plusargs("nresets=%d", nres))
                $fatal(1, "tb_front: +resets=FILE needs +nresets=N");
        end
        if (nin < 0 || nin > DEPTH || nout < 0 || nout > DEPTH || nedge < 0 || nedge > EDEPTH)
            $fatal(1, "tb_front: +nin/+nout/+nedges must be 0..%0d", DEPTH);
        if (nres < 0 || nres > RDEPTH)
            $fatal(1, "tb_front: +nresets must be 0..%0d", RDEPTH);
        if (threshold < 0 || threshold > 511)
            $fatal(1, "tb_front: +threshold must be 0..511");
        cfg_threshold = threshold;

        if (nin > 0) begin
            in_mem[nin - 1] = {IB{1'bx}};
            $readmemh(in_file, in_mem, 0, nin - 1);
            if (^in_mem[nin - 1] === 1'bx)
                $fatal(1, "tb_front: %0s has fewer than %0d beats", in_file, nin);
        end
        if (nout > 0) begin
            out_mem[nout - 1] = {OB{1'bx}};
            $readmemh(out_file, out_mem, 0, nout - 1);
            if (^out_mem[nout - 1] === 1'bx)
                $fatal(1, "tb_front: %0s has fewer than %0d beats", out_file, nout);
        end
        if (nedge > 0) begin
            edge_mem[nedge - 1] = {EB{1'bx}};
            $readmemh(edge_file, edge_mem, 0, nedge - 1);
            if (^edge_mem[nedge - 1] === 1'bx)
                $fatal(1, "tb_front: %0s has fewer than %0d beats", edge_file, nedge);
        end
        if (nres > 0) begin
            rs_mem[nres - 1] = {RB{1'bx}};
            $readmemh(rs_file, rs_mem, 0, nres - 1);
            if (^rs_mem[nres - 1] === 1'bx)
                $fatal(1, "tb_front: %0s has fewer than %0d reset points", rs_file, nres);
            // In stream order, within the files.
            r_prev_in = 0; r_prev_out = 0; r_prev_edge = 0; r_prev_err = 0;
            for (k = 0; k < nres; k = k + 1) begin
                rs = rs_mem[k];
                if (rs[`QT_VEC_RESET_IN_LSB +: 32] < r_prev_in || rs[`QT_VEC_RESET_IN_LSB +: 32] > nin ||
                    rs[`QT_VEC_RESET_OUT_LSB +: 32] < r_prev_out || rs[`QT_VEC_RESET_OUT_LSB +: 32] > nout ||
                    (FRONT && (rs[`QT_VEC_RESET_EDGE_LSB +: 32] < r_prev_edge ||
                               rs[`QT_VEC_RESET_EDGE_LSB +: 32] > nedge)) ||
                    rs[`QT_VEC_RESET_ERRORS_LSB +: 32] < r_prev_err ||
                    rs[`QT_VEC_RESET_ERRORS_LSB +: 32] > nerr)
                    $fatal(1, "tb_front: reset point %0d (%h) out of order or range", k, rs);
                r_prev_in = rs[`QT_VEC_RESET_IN_LSB +: 32];
                r_prev_out = rs[`QT_VEC_RESET_OUT_LSB +: 32];
                r_prev_edge = rs[`QT_VEC_RESET_EDGE_LSB +: 32];
                r_prev_err = rs[`QT_VEC_RESET_ERRORS_LSB +: 32];
            end
        end
        if (corrupt >= 0 && corrupt < nout)
            out_mem[corrupt][0] = ~out_mem[corrupt][0];
        if (corrupt_e >= 0 && corrupt_e < nedge)
            edge_mem[corrupt_e][0] = ~edge_mem[corrupt_e][0];

        rng_in  = xorshift32(32'h9e3779b9 ^ seed);
        rng_out = xorshift32(32'h7f4a7c15 ^ (seed * 3));
        rng_rst = xorshift32(32'h2545f491 ^ (seed * 5));
        if (rng_in == 0)  rng_in  = 32'h1;
        if (rng_out == 0) rng_out = 32'h2;
        if (rng_rst == 0) rng_rst = 32'h3;
        ridx = 0; quiet = 0; rclk = 0; got_g = 0; got_e = 0; cut = 0;
        after_g = 1'b0; after_e = 1'b0;
        seg_g = nres > 0 ? rs_mem[0][`QT_VEC_RESET_OUT_LSB +: 32] : nout;
        seg_e = nres > 0 && FRONT ? rs_mem[0][`QT_VEC_RESET_EDGE_LSB +: 32] : nedge;

        cyc = 0; iidx = 0; oidx = 0; eidx = 0; err_count = 0; idle = 0; drain = 0; stalls = 0;
        done = 1'b0;
        ef = -1; ex = 0; ey = 0; ew = 0; efe = -1;
        fin = -1; xin = 0; yin = 0; w_in = 0; last_acc = 0;
        lat_min = -1; lat_max = -1; row_min = -1; row_max = -1; row_has = 1'b0; lat_w = -1;
        ex_min = 0; ex_max = 0; lat_mixed = 1'b0;
        tr_min = 0; tr_max = 0; tr_n = 0; frames_ended = 0;

        repeat (4) @(posedge clk);
        aresetn <= 1'b1;
    end

    always @(posedge clk) begin
        if (aresetn && !done) begin
            cyc  = cyc + 1;
            idle = idle + 1;

            if (error === 1'b1)
                err_count = err_count + 1;
            else if (error !== 1'b0)
                $fatal(1, "tb_front: error output is %b at clock %0d", error, cyc);
            if (s_tready !== 1'b0 && s_tready !== 1'b1)
                $fatal(1, "tb_front: s_axis_tready is %b at clock %0d", s_tready, cyc);

            // ---- input side
            if (s_tvalid && !s_tready)
                stalls = stalls + 1;
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
                    if (yin == 0) w_in = xin + 1;
                    // A frame's last pixel, for the trailer's latency (well-formed streams).
                    if (yin + 1 == cfg_height && fin >= 0 && fin < 256) begin
                        frame_end_time[fin] = cyc;
                        frame_width[fin]    = w_in;
                    end
                    xin = 0; yin = yin + 1;
                end else begin
                    xin = xin + 1;
                end
                iidx = iidx + 1;
            end
            if (!(s_tvalid && !s_tready)) begin         // a pending beat must be held
                rng_in = xorshift32(rng_in);
                if (quiet == 0 && ridx < nres && iidx == rs_mem[ridx][`QT_VEC_RESET_IN_LSB +: 32]) begin
                    // Reset point: stop the input, let the error pulses land.
                    rng_rst = xorshift32(rng_rst);
                    if (rng_rst[31:29] == 3'd0)
                        quiet = 4 + rng_rst % (4 * MAX_WIDTH);
                    else
                        quiet = 4 + rng_rst % 16;
                end
                if (quiet == 0 && iidx < nin && (rng_in % 100) >= stall) begin
                    ib = in_mem[iidx];
                    s_tvalid <= 1'b1;
                    s_tdata  <= ib[7:0];
                    s_tuser  <= ib[`QT_VEC_IN_TUSER_BIT];
                    s_tlast  <= ib[`QT_VEC_IN_TLAST_BIT];
                    if (ib[`QT_VEC_IN_TUSER_BIT])
                        cfg_height <= ib[`QT_VEC_IN_HEIGHT_LSB +: 16];
                end else begin
                    s_tvalid <= 1'b0;
                end
            end

            // ---- the gradient stream
            if (g_tvalid === 1'bx || (g_tvalid === 1'b1 && g_tready === 1'b1 &&
                                      ^{g_tuser, g_tlast, g_tdata} === 1'bx))
                $fatal(1, "tb_front: X on the gradient stream at clock %0d", cyc);
            if (g_tvalid && g_tready) begin
                idle     = 0;
                got_beat = {g_tuser[1], g_tlast, g_tuser[0], g_tdata};
                if (oidx >= seg_g && ridx < nres) begin
                    $display("EXTRA beat=%0d got=%h (the segment before reset %0d ends at beat %0d)",
                             oidx, got_beat, ridx, seg_g);
                    $fatal(1, "tb_front: more gradient beats before reset %0d than expected", ridx);
                end
                if (oidx >= nout) begin
                    $display("EXTRA beat=%0d got=%h", oidx, got_beat);
                    $fatal(1, "tb_front: more than %0d gradient beats", nout);
                end
                exp_beat = out_mem[oidx];
                if (exp_beat[`QT_VEC_OUT_TUSER_BIT]) begin
                    ef = ef + 1; ex = 0; ey = 0;
                end
                if (got_beat !== exp_beat) begin
                    $display("MISMATCH beat=%0d frame=%0d x=%0d y=%0d expected=%h got=%h",
                             oidx, ef, ex, ey, exp_beat, got_beat);
                    if (nres > 0 && after_g)
                        $display("  the first beat after reset %0d", ridx - 1);
                    else if (nres > 0)
                        $display("  in the segment before reset %0d", ridx);
                    $fatal(1, "tb_front: gradient stream differs from %0s", out_file);
                end
                after_g = 1'b0;
                got_g = got_g + 1;

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

            // ---- the edge stream (FRONT = 1)
            if (e_tvalid === 1'bx || (e_tvalid === 1'b1 && m_tready === 1'b1 &&
                                      ^{e_tuser, e_tlast, e_tdata} === 1'bx))
                $fatal(1, "tb_front: X on the edge stream at clock %0d", cyc);
            if (e_tvalid && m_tready) begin
                idle     = 0;
                got_edge = {e_tlast, e_tuser, e_tdata};
                if (eidx >= seg_e && ridx < nres) begin
                    $display("EXTRA edge=%0d got=%h (the segment before reset %0d ends at beat %0d)",
                             eidx, got_edge, ridx, seg_e);
                    $fatal(1, "tb_front: more edge beats before reset %0d than expected", ridx);
                end
                if (eidx >= nedge) begin
                    $display("EXTRA edge=%0d got=%h", eidx, got_edge);
                    $fatal(1, "tb_front: more than %0d edge beats", nedge);
                end
                exp_edge = edge_mem[eidx];
                if (exp_edge[`QT_VEC_EDGE_TUSER_BIT])
                    efe = efe + 1;
                if (got_edge !== exp_edge) begin
                    $display("MISMATCH edge=%0d frame=%0d x=%0d y=%0d expected=%h got=%h",
                             eidx, efe, exp_edge[`QT_EP_X_LSB +: 11], exp_edge[`QT_EP_Y_LSB +: 11],
                             exp_edge, got_edge);
                    if (nres > 0 && after_e)
                        $display("  the first beat after reset %0d", ridx - 1);
                    else if (nres > 0)
                        $display("  in the segment before reset %0d", ridx);
                    $fatal(1, "tb_front: edge stream differs from %0s", edge_file);
                end
                if (exp_edge[`QT_VEC_EDGE_TLAST_BIT] && nres == 0 && efe >= 0 && efe < 256 &&
                    efe < fin + 1) begin
                    lat = cyc - frame_end_time[efe] - 2 * frame_width[efe];
                    if (tr_n == 0 || lat < tr_min) tr_min = lat;
                    if (tr_n == 0 || lat > tr_max) tr_max = lat;
                    tr_n = tr_n + 1;
                end
                after_e = 1'b0;
                got_e = got_e + 1;
                eidx = eidx + 1;
            end

            rng_out = xorshift32(rng_out);
            m_tready <= ((rng_out % 100) >= stall);

            // ---- reset point: every error pulse of the segment's beats has been counted
            // (they come 1 and 2 clocks after the beat); the expected output jumps to the next
            // segment, whose first beat must be the first each block emits after the reset.
            if (quiet > 0) begin
                quiet = quiet - 1;
                if (quiet == 0) begin
                    rs = rs_mem[ridx];
                    if (err_count != rs[`QT_VEC_RESET_ERRORS_LSB +: 32])
                        $fatal(1, "tb_front: %0d error pulses before reset %0d, expected %0d",
                               err_count, ridx, rs[`QT_VEC_RESET_ERRORS_LSB +: 32]);
                    cut = cut + (seg_g - oidx) + (FRONT ? seg_e - eidx : 0);
                    for (k = oidx; k < seg_g; k = k + 1)
                        if (out_mem[k][`QT_VEC_OUT_TUSER_BIT]) ef = ef + 1;
                    for (k = eidx; k < seg_e; k = k + 1)
                        if (edge_mem[k][`QT_VEC_EDGE_TUSER_BIT]) efe = efe + 1;
                    oidx = seg_g;
                    eidx = seg_e;
                    ridx = ridx + 1;
                    seg_g = ridx < nres ? rs_mem[ridx][`QT_VEC_RESET_OUT_LSB +: 32] : nout;
                    seg_e = ridx < nres && FRONT ? rs_mem[ridx][`QT_VEC_RESET_EDGE_LSB +: 32] : nedge;
                    rng_rst = xorshift32(rng_rst);
                    rclk = 1 + rng_rst % 8;
                    aresetn <= 1'b0;
                    s_tvalid <= 1'b0;
                    after_g = 1'b1;
                    after_e = 1'b1;
                    idle = 0;
                end
            end

            // ---- completion and liveness
            if (iidx >= nin && oidx >= nout && eidx >= nedge && ridx >= nres && quiet == 0) begin
                drain = drain + 1;
                if (drain > DRAIN) begin
                    if (err_count != nerr)
                        $fatal(1, "tb_front: %0d error pulses, expected %0d", err_count, nerr);
                    if (stall == 0 && nres == 0) begin
                        if (lat_min >= 0 && !lat_mixed)
                            $display("LATENCY min=%0d max=%0d width=%0d (width + %0d..%0d)",
                                     lat_min, lat_max, lat_w, ex_min, ex_max);
                        else if (lat_min >= 0)
                            $display("LATENCY min=%0d max=%0d width=mixed (width + %0d..%0d)",
                                     lat_min, lat_max, ex_min, ex_max);
                        else
                            $display("LATENCY none (no interior pixels)");
                        if (lat_extra >= 0 && (lat_min < 0 || ex_min != lat_extra ||
                                               ex_max != lat_extra))
                            $fatal(1, "tb_front: latency is not width + %0d for every interior pixel",
                                   lat_extra);
                        if (FRONT) begin
                            $display("TRAILER frames=%0d latency 2*width + %0d..%0d", tr_n,
                                     tr_min, tr_max);
                            if (trail_max >= 0 && (tr_n == 0 || tr_max > trail_max))
                                $fatal(1, "tb_front: trailer latency above 2*width + %0d",
                                       trail_max);
                        end
                        $display("STALLS %0d clocks with an input beat offered and not taken",
                                 stalls);
                        if (max_stalls >= 0 && stalls > max_stalls)
                            $fatal(1, "tb_front: %0d input stalls, at most %0d allowed", stalls,
                                   max_stalls);
                    end
                    $display("PASS %0d beats, %0d edge beats, %0d resets, %0d errors, %0d cut",
                             got_g, got_e, nres, err_count, cut);
                    done = 1'b1;
                    $finish;
                end
            end else if (idle > IDLE_MAX) begin
                if (oidx < nout && oidx < seg_g) begin
                    exp_beat = out_mem[oidx];
                    $display("MISSING beat=%0d expected=%h (frame %0d, input beat %0d of %0d)",
                             oidx, exp_beat, ef, iidx, nin);
                end
                if (eidx < nedge && eidx < seg_e) begin
                    exp_edge = edge_mem[eidx];
                    $display("MISSING edge=%0d expected=%h (input beat %0d of %0d)",
                             eidx, exp_edge, iidx, nin);
                end
                $fatal(1, "tb_front: no handshake for %0d clocks", IDLE_MAX);
            end
        end else if (!aresetn && rclk > 0) begin        // a reset point's aresetn: 1..8 clocks
            rclk = rclk - 1;
            if (rclk == 0)
                aresetn <= 1'b1;
        end
    end
endmodule

`default_nettype wire
