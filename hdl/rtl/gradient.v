`timescale 1ns / 1ps
`default_nettype none

// Streaming gradient (central differences, replicated borders), one pixel per clock, on
// AXI4-Stream video: s_axis_tuser = start of frame, s_axis_tlast = end of line, aresetn.
// Contract: docs/gradient.md; bit-accurate model: hw_model/gradient_model.h.
//
// Output frames are always whole: every output row ends with tlast, the frame's last beat
// carries m_axis_tuser[1] (end of frame), and when the input breaks off (a framing error after
// row 0) the row in progress is completed with fill words (bit 31 set, all else 0) and ends
// the frame. A register slice (axis_slice) drives the output: m_axis_tready reaches nothing
// but the slice, and s_axis_tready is a function of flip-flops only.
//
// Pipeline (stages S1..S4 advance together on `adv`: the register slice has room)
//   S0  beat classification and framing state; line memory read (input column x, or the tail's
//       column t).
//   S1  two paths. Write path: every accepted pixel is written back as {p(x,y-1), p(x,y)}
//       ({p, p} in row 0). Window path: a column (the accepted beat's, or the tail's) whose
//       read data {p(x,y-2), p(x,y-1)} and pixel form column x, shifted into the window. The
//       window holds column C = x-1 and its left neighbour; with column x as right neighbour
//       they give gx, gy of word (x-1, y-1). The word of the last column W-1 follows in the
//       next clock with C as its own right neighbour; the column at x = 0 that may enter in
//       that clock emits nothing, so input and output keep one beat per clock.
//   S2  gx, gy; magnitude fold (gradient_dir_fold). A fill column becomes a fill word here.
//   S3  lo, hi; 3*hi, then 51*hi and 19*hi (gradient_dir_s51), lo + hi.
//   S3b the two sector compares and the direction bin (gradient_dir_bin).
//   S4  output word, into the register slice.
// Latency without stalls: a pixel's word leaves W + 7 clocks after the pixel was accepted
// (one row plus one pixel for its right and lower neighbours, five stages, the slice).
//
// The tail. A frame's last output row is emitted after its last input beat: the flush re-reads
// the line memory for W clocks (the lower neighbour replicated); a frame broken off after row 0
// emits the rest of its output row as fill words. The tail has its own column counter t and
// runs while the next frame's row 0 arrives: row 0 only writes the memory (at column x <= t, so
// the flush reads every column before it is overwritten), and emits nothing. s_axis_tready
// drops only when the next frame reaches its row 1 before the tail is done (a frame narrower
// than the one before, by the difference), and for one clock after a one-row frame whose flush
// had to wait for the tail before it.
//
// Line memory: MAX_WIDTH x 16 bit, {p(x,y-1), p(x,y)} at address x; its depth is the width (no
// power-of-two rounding). A read never meets the write of the same address in one clock: the
// only case, column 0 of a one-pixel-wide frame read right after it was written, waits a clock
// (one-pixel-wide frames go at half rate).

`include "gradient_word.vh"

module gradient #(
    parameter MAX_WIDTH  = 640,                // pixels per row, upper bound of the learnt width
    parameter PIXEL_BITS = 8,                  // grey level bits; the word's fields need 8
    parameter MAX_ROWS   = 65535               // a cfg_height above it is refused like 0
) (
    input  wire                  aclk,
    input  wire                  aresetn,      // synchronous, active low

    input  wire [15:0]           cfg_height,   // rows per frame, a register: read when a start
                                               // of frame is accepted (0: frames refused)

    input  wire [PIXEL_BITS-1:0] s_axis_tdata, // pixel, grey levels
    input  wire                  s_axis_tuser, // start of frame
    input  wire                  s_axis_tlast, // end of line
    input  wire                  s_axis_tvalid,
    output wire                  s_axis_tready,

    output wire [31:0]           m_axis_tdata, // gradient word, layout in gradient_word.vh
    output wire [1:0]            m_axis_tuser, // [0] start of frame, [1] end of frame
    output wire                  m_axis_tlast, // end of line
    output wire                  m_axis_tvalid,
    input  wire                  m_axis_tready,

    output reg                   error         // one clock per framing error (input-timed)
);

    // Parameters checked at elaboration: an instance of a module that does not exist stops
    // Icarus and yosys with its name in the message.
    generate
        if (MAX_WIDTH < 1 || MAX_WIDTH > 65535) begin : g_check_width
            gradient_MAX_WIDTH_must_be_1_to_65535 u_bad_max_width ();
        end
        if (PIXEL_BITS != 8) begin : g_check_pixel
            gradient_PIXEL_BITS_must_be_8 u_bad_pixel_bits ();
        end
        if (MAX_ROWS < 1 || MAX_ROWS > 65535) begin : g_check_rows
            gradient_MAX_ROWS_must_be_1_to_65535 u_bad_max_rows ();
        end
    endgenerate

    localparam XW = (MAX_WIDTH < 2) ? 1 : $clog2(MAX_WIDTH);   // column index bits
    localparam [XW-1:0] MAXM2 = (MAX_WIDTH < 2) ? 0 : MAX_WIDTH - 2;
    localparam RW = $clog2(MAX_ROWS + 1);                      // row counter bits

    wire rst = ~aresetn;

    // ------------------------------------------------------------------------------------
    // S0: framing state
    // ------------------------------------------------------------------------------------
    reg          rdy;         // out of reset for a clock: s_axis_tready may rise
    reg          active;      // a frame is in progress and its beats are accepted
    reg          learn;       // current row is row 0 (width not yet known)
    reg          first;       // the next emitting row is output row 0 (carries start of frame)
    reg          err_hold;    // second error pulse of a beat that had two errors
    reg [XW-1:0] x;           // column of the next beat
    reg          x_zero;      // x == 0
    reg [XW-1:0] wm1;         // W - 1, learnt at the end of row 0
    reg [XW-1:0] wm2;         // W - 2 (modulo 2^XW), learnt with it: x + 1 == W - 1 is
                              // x == wm2, with no adder in front of the comparison
    reg          w_one;       // W == 1
    reg          x_last;      // x == W - 1 (rows >= 1)
    reg          x_max;       // x == MAX_WIDTH - 1
    reg [RW-1:0] rows;        // rows of the frame not yet completed, including the current one
    reg          rows_one;    // rows == 1

    reg          tail;        // the tail runs: a column a clock (flush or fill)
    reg          t_fill;      // the tail completes a row with fill words
    reg          t_first;     // the tail's row is output row 0
    reg [XW-1:0] t;           // the tail's column
    reg          t_zero;      // t == 0
    reg [XW-1:0] t_wm1;       // W - 1 of the tail's frame
    reg          t_end;       // t == t_wm1 (while the tail runs), kept a step ahead
    reg          pending;     // a one-row frame's flush waits for the tail before it

    // The pipeline advances while the register slice's skid is empty (a flip-flop: no logic
    // between it and the ~200 enables it drives; a bubble in S4 is not used to catch up).
    wire         slice_ready;
    wire adv = slice_ready;

    // Input held: during reset and the clock after, while S4 cannot move, for a two-error
    // beat's second pulse, while a flush waits, and while a tail runs and the frame has
    // reached its row 1 (whose words would come before the tail's).
    // And for a clock when a row of a one-pixel-wide frame would read column 0 while the
    // beat before is written there (wz): the block RAM cannot give the data being written.
    reg          wz;          // S1 writes column 0 in this clock
    // The tail waits with it (and the input with the tail, which must keep ahead of row 0).
    //   rd0_wait = wz & ((x_zero & active & ~learn) | (tail & t_zero & ~t_fill))
    //   s_axis_tready = rdy & adv & ~err_hold & ~pending & ~(tail & active & ~learn) &
    //                   ~rd0_wait
    //   t_step = adv & tail & ~rd0_wait
    // All but adv is a function of flip-flops; it is kept in flip-flops made from those
    // registers' next values (in_go, t_go below), and so are the parts of push_in that come
    // from the state (go_t, go_n): push_in, which enables ~60 flip-flops, is then two gates
    // from the flip-flops instead of five or six (timing on iCE40). The expressions they
    // stand for are checked in simulation and asserted in the bounded proof (below).
    reg          in_go;       // s_axis_tready but for adv
    reg          t_go;        // tail & ~rd0_wait
    // push_in of a beat without tuser, but for adv and tvalid, by its tlast:
    reg          go_t;        // in_go & active & (learn | x_last)
    reg          go_n;        // in_go & active & (learn ? ~x_max : ~x_last)
    assign s_axis_tready = adv & in_go;

    wire acc = s_axis_tvalid & s_axis_tready;

    // A start-of-frame beat is column 0 of row 0 whatever the current state; the registers
    // that take its column are cleared by their synchronous reset instead. The comparisons of
    // the column and row counters are kept in flip-flops (x_last, x_max, rows_one), made a beat
    // ahead, so that none is in the path from s_axis_tready to the state.
    wire          sof      = s_axis_tuser;
    wire          xb_zero  = sof | x_zero;
    // A height above MAX_ROWS is refused like 0; a frame is started only with a height it
    // accepts, so the row counter needs RW bits.
    wire [RW-1:0] rows_b   = sof ? cfg_height[RW-1:0] : rows;
    wire [RW-1:0] rows_n   = rows_b - {{(RW-1){1'b0}}, s_axis_tlast};
    wire          h_zero   = (cfg_height == 16'd0) || (cfg_height > MAX_ROWS);
    wire          last_row = sof ? (cfg_height == 16'd1) : rows_one;
    wire          at_wm1   = x_last;
    wire          at_max   = sof ? (MAX_WIDTH == 1) : x_max;

    wire start    = sof & ~h_zero;
    wire cont     = ~sof & active;
    wire in_row0  = start | (cont & learn);
    wire in_row   = cont & ~learn;
    // in_row0 of a beat that enters the pipeline (push_in: a start of frame then has a height,
    // another beat an active frame), without the height's comparison. The registers loaded
    // while no tail runs take it too: only their load in the clock a tail starts counts, and
    // that clock has push_in, a fill (fill_wb) or pending.
    wire row0_p   = sof | learn;
    wire ok_row0  = s_axis_tlast | ~at_max;            // row 0 must end by column MAX_WIDTH-1
    wire ok_row   = (s_axis_tlast == at_wm1);          // rows >= 1 must end exactly at W-1
    wire good     = (in_row0 & ok_row0) | (in_row & ok_row);
    wire err_sof  = sof & active;                      // frame ended early
    wire err_zero = sof & h_zero;                      // zero height, beat dropped
    wire err_len  = (in_row0 & ~ok_row0) | (in_row & ~ok_row);
    wire err_any  = err_sof | err_zero | err_len;
    wire err_two  = err_sof & (err_zero | err_len);   // err_len here only if MAX_WIDTH == 1

    // Accepted pixel enters the pipeline: acc & good, from go_t and go_n. Kept as three
    // signals (keep: synthesis would fold them into a deeper tree), so that push_in is two
    // gates from the flip-flops.
    wire good_sof = ~h_zero & (s_axis_tlast | (MAX_WIDTH != 1));
    (* keep *) wire p_row;                             // push_in of a beat without tuser
    (* keep *) wire p_sof;                             // push_in of a start of frame
    (* keep *) wire push_in;
    assign p_row   = adv & (s_axis_tlast ? go_t : go_n);
    assign p_sof   = adv & in_go & good_sof;
    assign push_in = s_axis_tvalid & (sof ? p_sof : p_row);
    // Tail requests: the frame's last beat (flush), or an error once row 0 is complete (fill
    // from the column of the word in progress: x - 1, or 0 at a row start).
    wire req_flush = push_in & s_axis_tlast & last_row;
    wire req_fill  = acc & active & ~learn & (sof | ~ok_row);
    wire go_now    = (req_flush | req_fill) & ~tail;   // else (one-row frame) pending
    wire t_step    = adv & t_go;                       // the tail's column enters S1

    wire [XW-1:0] rd_addr = tail ? t : x;

    // Column counter: cleared after the last column, 1 after a start-of-frame beat. The clear
    // and the load map onto the flip-flops' synchronous reset.
    wire [XW-1:0] x_inc = x + 1'b1;
    wire [XW-1:0] x_dec = x - 1'b1;

    always @(posedge aclk) begin
        if (rst || (push_in && s_axis_tlast))
            x[0] <= 1'b0;
        else if (push_in)
            x[0] <= sof | x_inc[0];
    end

    generate
        if (XW > 1) begin : g_xhi
            always @(posedge aclk) begin
                if (rst || (push_in && (s_axis_tlast || sof)))
                    x[XW-1:1] <= {(XW-1){1'b0}};
                else if (push_in)
                    x[XW-1:1] <= x_inc[XW-1:1];
            end
        end
    endgenerate

    // Next values (without reset) of the registers in_go, t_go, go_t and go_n are made from.
    wire active_nx   = push_in ? ~(s_axis_tlast & last_row) : (active & ~(acc & err_any));
    wire learn_nx    = push_in ? (row0_p & ~s_axis_tlast) : learn;
    wire x_zero_nx   = push_in ? s_axis_tlast : x_zero;
    wire wz_nx       = adv ? (push_in & xb_zero) : wz;
    wire err_hold_nx = acc & err_two;
    // x after this beat: 0 after an end of line (the last column when W == 1), else x + 1 (1
    // after a start of frame).
    wire x_last_nx   = ~push_in ? x_last :
                       s_axis_tlast ? (row0_p ? xb_zero : w_one) : (~sof & (x == wm2));
    wire x_max_nx    = ~push_in ? x_max :
                       s_axis_tlast ? (MAX_WIDTH == 1) :
                       (sof ? (MAX_WIDTH == 2) : (MAX_WIDTH >= 2 && x == MAXM2));

    always @(posedge aclk) begin
        if (rst) begin
            rdy      <= 1'b0;
            active   <= 1'b0;
            learn    <= 1'b0;
            first    <= 1'b0;
            err_hold <= 1'b0;
            error    <= 1'b0;
            wz       <= 1'b0;
            x_zero   <= 1'b1;
        end else begin
            rdy      <= 1'b1;
            wz       <= wz_nx;
            error    <= (acc & err_any) | err_hold;
            err_hold <= err_hold_nx;
            active   <= active_nx;
            learn    <= learn_nx;
            x_zero   <= x_zero_nx;
            x_last   <= x_last_nx;
            x_max    <= x_max_nx;

            if (push_in) begin
                rows     <= rows_n;
                rows_one <= (rows_n == {{(RW-1){1'b0}}, 1'b1});
                if (sof)
                    first <= 1'b1;
                else if (s_axis_tlast & ~learn)
                    first <= 1'b0;
                if (s_axis_tlast & row0_p) begin
                    // A mask rather than sof ? 0 : x, so that synthesis does not share one
                    // multiplexer with s1_wx (which then uses its flip-flops' reset).
                    wm1   <= x & {XW{~sof}};
                    wm2   <= sof ? {XW{1'b1}} : x_dec;
                    w_one <= xb_zero;
                end
            end
        end
    end

    // The tail: started by a request when none runs, else (a one-row frame's flush arriving
    // while a tail runs, or on the start-of-frame beat that asks for the fill of the frame
    // before) one clock after that tail ends. While no tail runs, its registers follow the
    // values a tail started now would take, so that only `tail` and `pending` hang on the
    // acceptance of the beat.
    wire          fill_wb  = ~pending & active & ~learn & (sof | ~ok_row);
    wire          skip_wb  = fill_wb & ~x_zero;             // the fill starts at x - 1

    wire pending_nx = (req_flush & (tail | req_fill)) | (pending & tail);
    wire tail_nx    = go_now | (pending & ~tail) | (tail & ~(t_step & t_end));
    wire t_fill_nx  = tail ? t_fill : fill_wb;
    wire t_zero_nx  = tail ? (t_zero & ~t_step) : (~skip_wb | (x == 1));

    always @(posedge aclk) begin
        if (rst) begin
            tail    <= 1'b0;
            pending <= 1'b0;
        end else begin
            pending <= pending_nx;
            tail    <= tail_nx;
        end
    end

    // in_go, t_go, go_t and go_n from the next values (see s_axis_tready); rdy's next value
    // is 1.
    wire rd0_wait_nx = wz_nx & ((x_zero_nx & active_nx & ~learn_nx) |
                                (tail_nx & t_zero_nx & ~t_fill_nx));

    wire in_go_nx    = ~err_hold_nx & ~pending_nx & ~(tail_nx & active_nx & ~learn_nx) &
                       ~rd0_wait_nx;

    always @(posedge aclk) begin
        if (rst) begin
            in_go <= 1'b0;
            t_go  <= 1'b0;
            go_t  <= 1'b0;
            go_n  <= 1'b0;
        end else begin
            in_go <= in_go_nx;
            t_go  <= tail_nx & ~rd0_wait_nx;
            go_t  <= in_go_nx & active_nx & (learn_nx | x_last_nx);
            go_n  <= in_go_nx & active_nx & (learn_nx ? ~x_max_nx : ~x_last_nx);
        end
    end

`ifndef SYNTHESIS
    // in_go, t_go, go_t, go_n, push_in, t_end and row0_p equal the expressions they stand
    // for, from the first reset on: checked in simulation (the benches stop on a difference),
    // and asserted in the bounded proof (hdl/formal/).
    reg          chk_go = 1'b0;
    wire         rd0_wait = wz & ((x_zero & active & ~learn) | (tail & t_zero & ~t_fill));
    wire         go_same  = (in_go === (rdy & ~err_hold & ~pending & ~(tail & active & ~learn) &
                                        ~rd0_wait)) && (t_go === (tail & ~rd0_wait)) &&
                            (go_t === (in_go & active & (learn | x_last))) &&
                            (go_n === (in_go & active & (learn ? ~x_max : ~x_last))) &&
                            (push_in === (acc & good)) && (!tail || t_end === (t == t_wm1)) &&
                            (!push_in || row0_p === in_row0);
    always @(posedge aclk) begin
`ifdef FORMAL
        if (chk_go)
            assert(go_same);
`else
        if (chk_go && !go_same) begin
            $display("gradient: in_go, t_go, go_t, go_n or t_end differ from their expressions",
                     " at %0t", $time);
            $fatal(1);
        end
`endif
        if (rst)
            chk_go <= 1'b1;
    end
`endif

    wire [XW-1:0] t_inc = t + 1'b1;

    always @(posedge aclk) begin
        if (~tail) begin
            t_fill  <= fill_wb;
            // Flush: output row H-1, output row 0 when the request comes in row 0 (or from a
            // one-row frame's pending flush). Fill: the row in progress, output row 0 while
            // input row 1 arrives (first still set).
            t_first <= pending | (fill_wb ? first : row0_p);
            t_wm1   <= (pending | fill_wb | ~row0_p) ? wm1 : (x & {XW{~sof}});
            t       <= skip_wb ? x_dec : {XW{1'b0}};
            t_zero  <= ~skip_wb | (x == 1);
            // t == t_wm1 for those values: a fill from x - 1 is never at its row's end
            // (x <= W - 1 in rows >= 1); else t = 0, and t_wm1 = 0 when W == 1 or, for a
            // one-row frame's flush, when this beat is in column 0.
            t_end   <= ~skip_wb & ((pending | fill_wb | ~row0_p) ? w_one : xb_zero);
        end else if (t_step) begin
            t      <= t_inc;
            t_zero <= 1'b0;
            t_end  <= (t_inc == t_wm1);
        end
    end

    // ------------------------------------------------------------------------------------
    // Line memory, read at S0, written at S1
    // ------------------------------------------------------------------------------------
    (* no_rw_check *)
    reg  [15:0]   line_mem [0:MAX_WIDTH-1];     // {p(x,y-1), p(x,y)} after row y (row 0: {p, p})
    reg  [15:0]   q;                            // read data, {p(x,y-2), p(x,y-1)}
    wire          wr_en;
    wire [XW-1:0] wr_addr;
    wire [15:0]   wr_data;

    always @(posedge aclk) begin
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
    // S1: write path and window path
    // ------------------------------------------------------------------------------------
    reg          s1_we;       // write path: a pixel to write back
    reg [7:0]    s1_p;        // its pixel p(x,y)
    reg [XW-1:0] s1_wx;       // its address
    reg          s1_wrow0;    // it is in row 0: written as {p, p}
    reg          s1_cv;       // window path: a column
    reg          s1_row0;     // column of row 0: emits nothing
    reg          s1_flush;    // flush column: no new pixel, lower neighbour replicated
    reg          s1_fill;     // fill column: a fill word, no data
    reg          s1_x0;       // column 0
    reg          s1_last;     // column W-1
    reg          s1_eof;      // the frame's last column
    reg          s1_first;    // column of output row 0 (start of frame on its column 0)

    always @(posedge aclk) begin
        if (rst) begin
            s1_we <= 1'b0;
            s1_cv <= 1'b0;
        end else if (adv) begin
            s1_we <= push_in;
            s1_cv <= t_step | push_in;
        end
    end

    always @(posedge aclk) begin
        if (adv) begin
            s1_p     <= s_axis_tdata[7:0];
            s1_wx    <= sof ? {XW{1'b0}} : x;
            s1_wrow0 <= row0_p;
            s1_row0  <= ~t_step & row0_p;
            s1_flush <= t_step & ~t_fill;
            s1_fill  <= t_step & t_fill;
            s1_x0    <= t_step ? t_zero : xb_zero;
            s1_last  <= t_step ? t_end : s_axis_tlast;
            s1_eof   <= t_step & t_end;
            s1_first <= t_step ? t_first : first;
        end
    end

    // Window: column C = {c_up, c_ctr, c_dn} and its left neighbour c_left. The subtrahends
    // c_up and c_left are stored inverted: a - b = a + ~b + 1 then needs no inverters in front
    // of the carry chain.
    reg [7:0] c_up_n, c_ctr, c_dn, c_left_n;
    reg       c_tuser;    // C is column 0 of output row 0
    reg       c_pend;     // C is column W-1 of an emitting row and its word is still due
    reg       c_eof;      // C is the frame's last column

    wire [7:0]  n_ctr = q[7:0];                        // p(x,y-1)
    wire [7:0]  n_up  = q[15:8];                       // p(x,y-2)
    wire [7:0]  n_dn  = s1_flush ? n_ctr : s1_p;       // p(x,y), bottom border replicated

    assign wr_en   = adv & s1_we;
    assign wr_addr = s1_wx;
    assign wr_data = {s1_wrow0 ? s1_p : n_ctr, s1_p};  // row 0: p(x,-1) = p(x,0), top border

    // Word for C: due when the next column of the same row arrives (right = its centre) or,
    // for the last column, in the clock after it entered (right = C's own centre).
    wire       w_col  = s1_cv & ~s1_fill;               // a column for the window
    wire       e_norm = w_col & ~s1_row0 & ~s1_x0;
    wire       e_fill = s1_cv & s1_fill;
    wire [7:0] right  = c_pend ? c_ctr : n_ctr;
    wire [8:0] gx_n   = {1'b0, right} + {1'b1, c_left_n} + 9'd1;   // right - left
    wire [8:0] gy_n   = {1'b0, c_dn}  + {1'b1, c_up_n}   + 9'd1;   // dn - up

    // ------------------------------------------------------------------------------------
    // S2: gx, gy (or a fill word)
    // ------------------------------------------------------------------------------------
    reg       s2_valid, s2_tuser, s2_tlast, s2_eof, s2_fill;
    reg [8:0] s2_gx, s2_gy;

    always @(posedge aclk) begin
        if (rst) begin
            c_pend   <= 1'b0;
            s2_valid <= 1'b0;
        end else if (adv) begin
            s2_valid <= e_norm | c_pend | e_fill;
            s2_tuser <= e_fill ? (s1_x0 & s1_first) : c_tuser;
            s2_tlast <= e_fill ? s1_last : c_pend;
            s2_eof   <= e_fill ? s1_eof : (c_pend & c_eof);
            s2_fill  <= e_fill;
            s2_gx    <= gx_n;
            s2_gy    <= gy_n;
            if (w_col) begin
                c_up_n   <= ~n_up;
                c_ctr    <= n_ctr;
                c_dn     <= n_dn;
                c_left_n <= ~(s1_x0 ? n_ctr : c_ctr);
                c_tuser  <= s1_x0 & s1_first;
                c_pend   <= s1_last & ~s1_row0;
                c_eof    <= s1_eof;
            end else begin
                c_pend   <= 1'b0;
            end
        end
    end

    wire [7:0] f_lo, f_hi;
    wire       f_swap;

    gradient_dir_fold u_fold (.gx(s2_gx), .gy(s2_gy), .lo(f_lo), .hi(f_hi), .swap(f_swap));

    // ------------------------------------------------------------------------------------
    // S3: lo, hi
    // ------------------------------------------------------------------------------------
    reg       s3_valid, s3_tuser, s3_tlast, s3_eof, s3_fill, s3_swap;
    reg [8:0] s3_gx, s3_gy;
    reg [7:0] s3_lo, s3_hi;

    always @(posedge aclk) begin
        if (rst) begin
            s3_valid <= 1'b0;
        end else if (adv) begin
            s3_valid <= s2_valid;
            s3_tuser <= s2_tuser;
            s3_tlast <= s2_tlast;
            s3_eof   <= s2_eof;
            s3_fill  <= s2_fill;
            s3_gx    <= s2_gx;
            s3_gy    <= s2_gy;
            s3_lo    <= f_lo;
            s3_hi    <= f_hi;
            s3_swap  <= f_swap;
        end
    end

    wire [5:0]  d_m51h;
    wire [12:0] d_m19;

    gradient_dir_s51 u_s51 (.hi(s3_hi), .m51h(d_m51h), .m19(d_m19));

    // ------------------------------------------------------------------------------------
    // S3b: 51*hi (its upper bits) and 19*hi; magnitude lo + hi
    // ------------------------------------------------------------------------------------
    reg        s3b_valid, s3b_tuser, s3b_tlast, s3b_eof, s3b_fill, s3b_swap;
    reg [5:0]  s3b_m51h;
    reg [8:0]  s3b_gx, s3b_gy, s3b_mag;
    reg [7:0]  s3b_lo;
    reg [12:0] s3b_m19;

    always @(posedge aclk) begin
        if (rst) begin
            s3b_valid <= 1'b0;
        end else if (adv) begin
            s3b_valid <= s3_valid;
            s3b_tuser <= s3_tuser;
            s3b_tlast <= s3_tlast;
            s3b_eof   <= s3_eof;
            s3b_fill  <= s3_fill;
            s3b_swap  <= s3_swap;
            s3b_m51h  <= d_m51h;
            s3b_gx    <= s3_gx;
            s3b_gy    <= s3_gy;
            s3b_mag   <= {1'b0, s3_lo} + {1'b0, s3_hi};    // |gx| + |gy|
            s3b_lo    <= s3_lo;
            s3b_m19   <= d_m19;
        end
    end

    wire [3:0] dir;

    gradient_dir_bin u_bin (.lo(s3b_lo), .m19(s3b_m19), .m51h(s3b_m51h), .swap(s3b_swap),
                            .negx(s3b_gx[8]), .negy(s3b_gy[8]), .dir(dir));

    reg [31:0] word;
    always @* begin
        word = 32'd0;
        word[`QT_GW_GX_LSB  +: `QT_GW_GX_BITS ] = s3b_gx;
        word[`QT_GW_GY_LSB  +: `QT_GW_GY_BITS ] = s3b_gy;
        word[`QT_GW_MAG_LSB +: `QT_GW_MAG_BITS] = s3b_mag;
        word[`QT_GW_DIR_LSB +: `QT_GW_DIR_BITS] = dir;
    end

    // ------------------------------------------------------------------------------------
    // S4: output word, then the register slice
    // ------------------------------------------------------------------------------------
    reg        s4_v;
    reg [31:0] s4_word;
    reg        s4_tuser, s4_tlast, s4_eof;

    always @(posedge aclk) begin
        if (rst) begin
            s4_v <= 1'b0;
        end else if (adv) begin
            s4_v     <= s3b_valid;
            // The fill word: bit 31 alone (flip-flop set/reset rather than a multiplexer).
            s4_word  <= s3b_fill ? (32'd1 << `QT_GW_FILL_BIT) : word;
            s4_tuser <= s3b_tuser;
            s4_tlast <= s3b_tlast;
            s4_eof   <= s3b_eof;
        end
    end

    axis_slice #(.W(35)) u_slice (
        .clk(aclk), .rst(rst),
        .s_data({s4_eof, s4_tuser, s4_tlast, s4_word}), .s_valid(s4_v), .s_ready(slice_ready),
        .m_data({m_axis_tuser[1], m_axis_tuser[0], m_axis_tlast, m_axis_tdata}),
        .m_valid(m_axis_tvalid), .m_ready(m_axis_tready));
endmodule

`default_nettype wire
