// Directed bench of the row limit: a start of frame whose cfg_height is above the block's
// MAX_ROWS is refused like a height of 0 (one error pulse, the beat dropped, nothing out), and a
// frame of exactly MAX_ROWS rows goes through whole. Two blocks: the gradient block with
// MAX_ROWS = 3 (4 and 65535 refused, 3 rows of 2 pixels accepted: 6 words, start and end of
// frame flagged), and the front end, whose MAX_ROWS is 2048, the edge point's 11-bit y (2049
// refused, 2048 rows of 1 pixel accepted: a flat frame gives its trailer alone, H - 1 = 2047).
// Exit status non-zero ($fatal) on any difference; the last line is "PASS".

`timescale 1ns/1ps
`default_nettype none

module tb_limits;
    reg clk = 1'b0;
    always #5 clk = ~clk;
    reg aresetn = 1'b0;

    // The source: one beat offered until it is taken.
    reg  [7:0]  s_tdata  = 8'd0;
    reg         s_tuser  = 1'b0, s_tlast = 1'b0, s_tvalid = 1'b0;
    reg  [15:0] cfg_height = 16'd0;
    wire        g_ready, f_ready;

    // The gradient block, MAX_ROWS = 3.
    wire [31:0] g_data;
    wire [1:0]  g_user;
    wire        g_last, g_valid, g_error;
    reg         use_front = 1'b0;   // which block the source feeds
    gradient #(.MAX_WIDTH(4), .MAX_ROWS(3)) u_gradient (
        .aclk(clk), .aresetn(aresetn), .cfg_height(cfg_height),
        .s_axis_tdata(s_tdata), .s_axis_tuser(s_tuser), .s_axis_tlast(s_tlast),
        .s_axis_tvalid(s_tvalid & ~use_front), .s_axis_tready(g_ready),
        .m_axis_tdata(g_data), .m_axis_tuser(g_user), .m_axis_tlast(g_last),
        .m_axis_tvalid(g_valid), .m_axis_tready(1'b1), .error(g_error));

    // The front end (its gradient block has MAX_ROWS = 2048).
    wire [47:0] f_data;
    wire        f_user, f_last, f_valid, f_error;
    frontend #(.MAX_WIDTH(2)) u_front (
        .aclk(clk), .aresetn(aresetn), .cfg_height(cfg_height), .cfg_threshold(9'd40),
        .s_axis_tdata(s_tdata), .s_axis_tuser(s_tuser), .s_axis_tlast(s_tlast),
        .s_axis_tvalid(s_tvalid & use_front), .s_axis_tready(f_ready),
        .m_axis_tdata(f_data), .m_axis_tuser(f_user), .m_axis_tlast(f_last),
        .m_axis_tvalid(f_valid), .m_axis_tready(1'b1), .error(f_error));

    wire ready = use_front ? f_ready : g_ready;
    wire valid = use_front ? f_valid : g_valid;
    wire err   = use_front ? f_error : g_error;

    integer beats = 0, errors = 0, eofs = 0, sofs = 0;
    reg [47:0] last_beat = 48'd0;
    always @(posedge clk) begin
        if (valid) begin
            beats = beats + 1;
            if (use_front) begin
                last_beat = f_data;
                sofs = sofs + f_user;
                eofs = eofs + f_last;
            end else begin
                sofs = sofs + g_user[0];
                eofs = eofs + g_user[1];
            end
        end
        if (err) errors = errors + 1;
    end

    // Offers one beat and waits until it is taken.
    task put(input [7:0] p, input sof, input eol);
        begin
            s_tdata <= p;
            s_tuser <= sof;
            s_tlast <= eol;
            s_tvalid <= 1'b1;
            @(posedge clk);
            while (!ready) @(posedge clk);
            s_tvalid <= 1'b0;
        end
    endtask

    task settle(input integer clocks);
        integer k;
        begin
            for (k = 0; k < clocks; k = k + 1) @(posedge clk);
        end
    endtask

    task clear;
        begin
            beats = 0;
            errors = 0;
            eofs = 0;
            sofs = 0;
        end
    endtask

    // A start of frame of `height`: refused (one error, nothing out) when refuse is 1.
    task refused(input [15:0] height, input [8*24-1:0] what);
        begin
            clear;
            cfg_height <= height;
            put(8'd10, 1'b1, 1'b0);
            settle(40);
            if (errors != 1 || beats != 0)
                $fatal(1, "tb_limits: %0s: height %0d gave %0d error pulses and %0d beats, want 1 and 0",
                       what, height, errors, beats);
        end
    endtask

    // A block that stops taking beats fails the bench instead of hanging it (the whole run
    // takes about 25 000 clocks).
    initial begin
        #2000000;
        $fatal(1, "tb_limits: still running after 200 000 clocks (a beat never taken?)");
    end

    integer r, c;
    initial begin
        settle(3);
        aresetn <= 1'b1;
        settle(2);

        // The gradient block: MAX_ROWS = 3.
        refused(16'd4, "gradient, MAX_ROWS + 1");
        refused(16'd65535, "gradient, 65535");
        clear;
        cfg_height <= 16'd3;
        for (r = 0; r < 3; r = r + 1)
            for (c = 0; c < 2; c = c + 1)
                put(8'd10 * (r + c + 1), r == 0 && c == 0, c == 1);
        settle(40);
        if (errors != 0 || beats != 6 || sofs != 1 || eofs != 1)
            $fatal(1, "tb_limits: gradient, 3 rows of 2: %0d errors, %0d words, %0d starts, %0d ends; want 0, 6, 1, 1",
                   errors, beats, sofs, eofs);

        // The front end: MAX_ROWS = 2048.
        use_front <= 1'b1;
        settle(2);
        refused(16'd2049, "front end, 2049 rows");
        clear;
        cfg_height <= 16'd2048;
        for (r = 0; r < 2048; r = r + 1)
            put(8'd77, r == 0, 1'b1);
        settle(80);
        if (errors != 0 || beats != 1 || !last_beat[47] || last_beat[21:11] != 11'd2047)
            $fatal(1, "tb_limits: front end, 2048 flat rows of 1: %0d errors, %0d beats, last %h; want 0, the trailer alone with H - 1 = 2047",
                   errors, beats, last_beat);
        $display("PASS");
        $finish;
    end
endmodule

`default_nettype wire
