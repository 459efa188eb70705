`timescale 1ns / 1ps

// Streaming gradient (central differences, replicated borders), one pixel per clock.
// Contract: docs/gradient.md; bit-accurate model: hw_model/gradient_model.h.
//
// Pipeline (all stages advance together on `adv`: output register empty or being taken)
//   S0  beat classification and framing state; line memory read at column x.
//   S1  read data {p(x,y-2), p(x,y-1)} plus the new pixel p(x,y) form column x; it is written
//       back as {p(x,y-1), p(x,y)} and shifted into the window. The window holds column
//       C = x-1 and its left neighbour; with column x as right neighbour they give gx, gy of
//       word (x-1, y-1). The word of the last column W-1 follows in the next clock with C as
//       its own right neighbour; the beat at x = 0 that may arrive in that clock emits nothing,
//       so input and output keep one beat per clock.
//   S2  gx, gy; magnitude fold (gradient_dir_fold).
//   S3  lo, hi, 3*hi; direction bin (gradient_dir_bin) and magnitude lo + hi.
//   S4  output register.
// Latency without stalls: a pixel's word leaves W + 5 clocks after the pixel was accepted
// (one row plus one pixel for its right and lower neighbours, four register stages).
//
// Line memory: one MAX_WIDTH x 16 bit memory, {p(x,y-1), p(x,y)} at address x. Row 0 writes
// {p, p}, so row 1 sees its upper neighbour replicated. After the last row the block reads the
// memory once more for W clocks with s_tready low (the flush) and uses p(x,H-1) as its own
// lower neighbour. With W == 1 every column reads the address written in the clock before;
// that word is taken from the window registers (s1_fwd) instead of the memory.

`include "gradient_word.vh"

module gradient #(
    parameter MAX_WIDTH = 640                  // pixels per row, upper bound of the learnt width
) (
    input  wire        clk,
    input  wire        rst,                    // synchronous, active high

    input  wire [7:0]  s_tdata,                // pixel, grey levels
    input  wire        s_tuser,                // start of frame
    input  wire        s_tlast,                // end of row
    input  wire        s_tvalid,
    output wire        s_tready,
    input  wire [15:0] s_height,               // rows, sampled with the start-of-frame beat

    output reg  [31:0] m_tdata,                // gradient word, layout in gradient_word.vh
    output reg         m_tuser,                // word (0,0)
    output reg         m_tlast,                // last word of a row
    output reg         m_tvalid,
    input  wire        m_tready,

    output reg         error                   // one clock per framing error
);
    function integer clog2;
        input integer v;
        integer r;
        begin
            r = 0;
            while ((1 << r) < v)
                r = r + 1;
            clog2 = r;
        end
    endfunction

    localparam XW = (MAX_WIDTH < 2) ? 1 : clog2(MAX_WIDTH);   // column index bits

    // ------------------------------------------------------------------------------------
    // S0: framing state
    // ------------------------------------------------------------------------------------
    reg          active;      // a frame is in progress and its beats are accepted
    reg          learn;       // current row is row 0 (width not yet known)
    reg          flush;       // emitting the last row; input held off
    reg          first;       // the next emitting row is output row 0 (carries m_tuser)
    reg          err_hold;    // second error pulse of a beat that had two errors
    reg [XW-1:0] x;           // column of the next beat (flush: column being re-read)
    reg          x_zero;      // x == 0
    reg [XW-1:0] wm1;         // W - 1, learnt at the end of row 0
    reg          w_one;       // W == 1
    reg [15:0]   rows;        // rows of the frame not yet completed, including the current one

    wire adv = ~m_tvalid | m_tready;

    assign s_tready = adv & ~flush & ~err_hold & ~rst;

    wire acc = s_tvalid & s_tready;

    // A start-of-frame beat is column 0 of row 0 whatever the current state. It still reads
    // at x (row 0 does not use the read data); the registers that take its column are cleared
    // by their synchronous reset instead. During the flush no beat is taken and x addresses
    // the column being re-read.
    wire          sof      = s_tuser & ~flush;
    wire          xb_zero  = sof | x_zero;
    wire [15:0]   rows_b   = sof ? s_height : rows;
    wire          h_zero   = (s_height == 16'd0);
    wire          last_row = (rows_b == 16'd1);
    wire          at_wm1   = (x == wm1);
    wire          at_max   = sof ? (MAX_WIDTH == 1) : (x == MAX_WIDTH - 1);

    wire start    = s_tuser & ~h_zero;
    wire cont     = ~s_tuser & active;
    wire in_row0  = start | (cont & learn);
    wire in_row   = cont & ~learn;
    wire ok_row0  = s_tlast | ~at_max;                 // row 0 must end by column MAX_WIDTH-1
    wire ok_row   = (s_tlast == at_wm1);               // rows >= 1 must end exactly at W-1
    wire good     = (in_row0 & ok_row0) | (in_row & ok_row);
    wire err_sof  = s_tuser & active;                  // frame ended early
    wire err_zero = s_tuser & h_zero;                  // zero height, beat dropped
    wire err_len  = (in_row0 & ~ok_row0) | (in_row & ~ok_row);
    wire err_any  = err_sof | err_zero | err_len;
    wire err_two  = err_sof & (err_zero | err_len);   // err_len here only if MAX_WIDTH == 1

    wire push_in  = acc & good;                        // accepted pixel enters the pipeline
    wire push_fl  = adv & flush;                       // flush column enters the pipeline
    wire step     = push_in | push_fl;
    wire x_clr    = flush ? at_wm1 : s_tlast;          // last column of the row

    wire [XW-1:0] rd_addr = x;

    // Column counter: cleared after the last column, 1 after a start-of-frame beat. The clear
    // and the load map onto the flip-flops' synchronous reset.
    wire [XW-1:0] x_inc = x + 1'b1;

    always @(posedge clk) begin
        if (rst || (step && x_clr))
            x[0] <= 1'b0;
        else if (step)
            x[0] <= sof | x_inc[0];
    end

    generate
        if (XW > 1) begin : g_xhi
            always @(posedge clk) begin
                if (rst || (step && (x_clr || sof)))
                    x[XW-1:1] <= {(XW-1){1'b0}};
                else if (step)
                    x[XW-1:1] <= x_inc[XW-1:1];
            end
        end
    endgenerate

    always @(posedge clk) begin
        if (rst) begin
            active   <= 1'b0;
            learn    <= 1'b0;
            flush    <= 1'b0;
            first    <= 1'b0;
            err_hold <= 1'b0;
            error    <= 1'b0;
            x_zero   <= 1'b1;
        end else begin
            error    <= (acc & err_any) | err_hold;
            err_hold <= acc & err_two;

            if (step)
                x_zero <= x_clr;
            if (push_in) begin
                rows   <= rows_b - {15'd0, s_tlast};
                learn  <= in_row0 & ~s_tlast;
                active <= ~(s_tlast & last_row);
                flush  <= s_tlast & last_row;
                if (start)
                    first <= 1'b1;
                else if (s_tlast & in_row)
                    first <= 1'b0;
                if (s_tlast & in_row0) begin
                    // A mask rather than sof ? 0 : x, so that synthesis does not share one
                    // multiplexer with s1_x (which then uses its flip-flops' reset): 10 LCs.
                    wm1   <= x & {XW{~sof}};
                    w_one <= xb_zero;
                end
            end else if (acc & err_any) begin
                active <= 1'b0;                        // frame abandoned
            end else if (push_fl & at_wm1) begin
                flush  <= 1'b0;
            end
        end
    end

    // ------------------------------------------------------------------------------------
    // Line memory, read at S0, written at S1
    // ------------------------------------------------------------------------------------
    // Depth rounded up to a power of two: 1024 x 16 maps onto four 1024 x 4 block RAMs with no
    // read multiplexer. A read colliding with the write (same address, same clock) happens
    // only when W == 1 and its data is then not used (s1_fwd), so no collision logic is needed.
    (* no_rw_check *)
    reg  [15:0]   line_mem [0:(1 << XW) - 1];   // {p(x,y-1), p(x,y)} after row y (row 0: hi unused)
    reg  [15:0]   q;                            // read data, {p(x,y-2), p(x,y-1)}
    wire          wr_en;
    wire [XW-1:0] wr_addr;
    wire [15:0]   wr_data;

    always @(posedge clk) begin
        if (wr_en)
            line_mem[wr_addr] <= wr_data;
        if (adv) begin
            q <= line_mem[rd_addr];
`ifndef SYNTHESIS
            if (wr_en && wr_addr == rd_addr)
                q <= 16'bx;                     // collision: undefined in the block RAM
`endif
        end
    end

    // ------------------------------------------------------------------------------------
    // S1: column assembly and window
    // ------------------------------------------------------------------------------------
    reg          s1_valid;
    reg [7:0]    s1_p;        // pixel p(x,y)
    reg [XW-1:0] s1_x;        // write-back address
    reg          s1_row0;     // column of row 0: emits nothing
    reg          s1_flush;    // flush column: no new pixel, lower neighbour replicated
    reg          s1_x0;       // column 0
    reg          s1_last;     // column W-1
    reg          s1_first;    // column of output row 0 (m_tuser on its column 0)
    reg          s1_fwd;      // read collided with the previous column's write (W == 1)

    always @(posedge clk) begin
        if (rst)
            s1_valid <= 1'b0;
        else if (adv)
            s1_valid <= step;
    end

    always @(posedge clk) begin
        if (adv) begin
            s1_p     <= s_tdata;
            s1_x     <= sof ? {XW{1'b0}} : x;
            s1_row0  <= ~flush & in_row0;
            s1_flush <= flush;
            s1_x0    <= xb_zero;
            s1_last  <= x_clr;
            s1_first <= first;
            // Consecutive columns share an address only when W == 1 (rows >= 1 and the flush
            // read address 0 every column); the word just written is then taken from the window.
            s1_fwd   <= s1_valid & w_one;
        end
    end

    // Window: column C = {c_up, c_ctr, c_dn} and its left neighbour c_left. The subtrahends
    // c_up and c_left are stored inverted: a - b = a + ~b + 1 then needs no inverters in front
    // of the carry chain.
    reg [7:0] c_up_n, c_ctr, c_dn, c_left_n;
    reg       c_tuser;    // C is column 0 of output row 0
    reg       c_pend;     // C is column W-1 of an emitting row and its word is still due

    wire [7:0] n_ctr = s1_fwd ? c_dn  : q[7:0];        // p(x,y-1)
    wire [7:0] n_up  = s1_fwd ? c_ctr : q[15:8];       // p(x,y-2)
    wire [7:0] n_dn  = s1_flush ? n_ctr : s1_p;        // p(x,y), bottom border replicated
    wire [7:0] w_hi  = s1_row0 ? s1_p : n_ctr;         // row 0: p(x,-1) = p(x,0), top border

    assign wr_en   = adv & s1_valid;
    assign wr_addr = s1_x;
    assign wr_data = {w_hi, s1_p};

    // Word for C: due when the next column of the same row arrives (right = its centre) or,
    // for the last column, in the clock after it entered (right = C's own centre).
    wire       e_norm = s1_valid & ~s1_row0 & ~s1_x0;
    wire [7:0] right  = c_pend ? c_ctr : n_ctr;
    wire [8:0] gx_n   = {1'b0, right} + {1'b1, c_left_n} + 9'd1;   // right - left
    wire [8:0] gy_n   = {1'b0, c_dn}  + {1'b1, c_up_n}   + 9'd1;   // dn - up

    // ------------------------------------------------------------------------------------
    // S2: gx, gy
    // ------------------------------------------------------------------------------------
    reg       s2_valid, s2_tuser, s2_tlast;
    reg [8:0] s2_gx, s2_gy;

    always @(posedge clk) begin
        if (rst) begin
            c_pend   <= 1'b0;
            s2_valid <= 1'b0;
        end else if (adv) begin
            s2_valid <= e_norm | c_pend;
            s2_tuser <= c_tuser;
            s2_tlast <= c_pend;
            s2_gx    <= gx_n;
            s2_gy    <= gy_n;
            if (s1_valid) begin
                c_up_n  <= ~n_up;
                c_ctr   <= w_hi;                   // = n_ctr except in row 0 (no word)
                c_dn    <= n_dn;
                c_left_n <= ~(s1_x0 ? n_ctr : c_ctr);
                c_tuser <= s1_x0 & s1_first;
                c_pend  <= s1_last & ~s1_row0;
            end else begin
                c_pend  <= 1'b0;
            end
        end
    end

    wire [7:0] f_lo, f_hi;
    wire       f_swap;
    wire [9:0] f_hi3;

    gradient_dir_fold u_fold (.gx(s2_gx), .gy(s2_gy), .lo(f_lo), .hi(f_hi), .swap(f_swap),
                              .hi3(f_hi3));

    // ------------------------------------------------------------------------------------
    // S3: lo, hi
    // ------------------------------------------------------------------------------------
    reg       s3_valid, s3_tuser, s3_tlast, s3_swap;
    reg [8:0] s3_gx, s3_gy;
    reg [7:0] s3_lo, s3_hi;
    reg [9:0] s3_hi3;

    always @(posedge clk) begin
        if (rst) begin
            s3_valid <= 1'b0;
        end else if (adv) begin
            s3_valid <= s2_valid;
            s3_tuser <= s2_tuser;
            s3_tlast <= s2_tlast;
            s3_gx    <= s2_gx;
            s3_gy    <= s2_gy;
            s3_lo    <= f_lo;
            s3_hi    <= f_hi;
            s3_swap  <= f_swap;
            s3_hi3   <= f_hi3;
        end
    end

    wire [3:0] dir;
    wire [8:0] mag = {1'b0, s3_lo} + {1'b0, s3_hi};    // |gx| + |gy|

    gradient_dir_bin u_bin (.lo(s3_lo), .hi(s3_hi), .hi3(s3_hi3), .swap(s3_swap),
                            .negx(s3_gx[8]), .negy(s3_gy[8]), .dir(dir));

    reg [31:0] word;
    always @* begin
        word = 32'd0;
        word[`QT_GW_GX_LSB  +: `QT_GW_GX_BITS ] = s3_gx;
        word[`QT_GW_GY_LSB  +: `QT_GW_GY_BITS ] = s3_gy;
        word[`QT_GW_MAG_LSB +: `QT_GW_MAG_BITS] = mag;
        word[`QT_GW_DIR_LSB +: `QT_GW_DIR_BITS] = dir;
    end

    // ------------------------------------------------------------------------------------
    // S4: output register
    // ------------------------------------------------------------------------------------
    always @(posedge clk) begin
        if (rst) begin
            m_tvalid <= 1'b0;
        end else if (adv) begin
            m_tvalid <= s3_valid;
            m_tdata  <= word;
            m_tuser  <= s3_tuser;
            m_tlast  <= s3_tlast;
        end
    end
endmodule
