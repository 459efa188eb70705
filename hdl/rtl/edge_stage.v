`timescale 1ns / 1ps
`default_nettype none

// The edge stage: gradient words in (the gradient block's AXI4-Stream output), edge points out
// (edge_beat.vh): L1 magnitude threshold, non-maximum suppression along the direction bin and
// the parabolic sub-pixel offset, one word per clock. Contract: docs/gradient.md ("The front
// end"); bit-accurate model: hw_model/edge_model.h; core's edge stage
// (core/lines/edge_stage.h) gives the same points.
//
// Input: a stream as gradient.v emits it: frames from tuser[0] (start) to tuser[1] (end, on a
// tlast beat), rows of one width W <= MAX_WIDTH ending with tlast, fill words (bit 31) marking a
// frame whose input broke off. Output: each frame's points in raster order, then its trailer
// (W - 1, H - 1, broken); tuser on a frame's first beat, tlast on its
// trailer. Every point at or above cfg_threshold goes out with its magnitude: which ones the
// microcontroller's edge list keeps is its business.
//
// Decision: pixel (x, y) is an edge when m >= threshold, 2m (odd bins; m for even ones) is
// greater than the magnitude ahead along its direction and not less than the one behind. The
// eight neighbours form a ring n0..n7 (n_k at k * 45 degrees from +x towards +y); bin d looks
// ahead at n_j, j = d / 2, plus n_{j+1} when d is odd, and behind at n_{j+4} (+ n_{j+5}).
// With k = j mod 4 and swap = j >= 4: P = n_k (+ n_{k+1}), Q = n_{k+4} (+ n_{k+5}), ahead/behind
// = P/Q, or Q/P when swap. Offset: q = floor((8 |behind - ahead| + floor(D / 2)) / D),
// D = 2m' - ahead - behind (m' = 2m or m), restoring division in four steps; delta = -q when
// behind > ahead else q, limited to -8..7. Outside the frame magnitudes are 0.
//
// Pipeline (advancing together on `adv`)
//   E0  input beat or tail column; line memory read at x (or t).
//   E1  read data {A = m(x,y-2), C = m, d(x,y-1)} with the word B = m, d(x,y) form column x
//       (rows >= 1; the flush's columns have B = 0); written back as {C.m, B}, row 0 as {0, B}.
//       The column shifts into the window L, M, R; M's decision is made in the clock after.
//       A row's last column, once in R, is shifted on by the next column or, if none comes, by
//       an empty column (close), so every pixel is decided whatever follows.
//   E2  window: left (zero at column 0), M, right (zero at column W-1); sides sp = P + P2 and
//       sq = Q + Q2.  E3  s_p = m' - sp, s_q = m' - sq.  E4  the test; D = s_p + s_q,
//       N = |s_p - s_q|.  E5  R0 = 8N + D/2, 3D.  E6  first radix-4 digit of R0 / D.
//       E7  second digit, delta.  O  the beat (x and y from counters, or the trailer), the
//       output register.
// The trailer goes out with the frame's last decision when that pixel is no edge, else in the
// next clock; when that clock brings the next frame's first decision too, the pipeline holds
// for one clock (its only input stall besides back-pressure and the tail below).
//
// The tail: after a frame's last word, its last row is decided by re-reading the memory for W
// columns with B = 0 (the lower neighbour outside). It runs while the next frame's row 0
// arrives (written at columns <= t, so no column is overwritten before it is read);
// s_axis_tready drops when the next frame reaches row 1 first, or for a one-row frame whose
// tail waits for the one before.
//
// Line memory: MAX_WIDTH x 23 bits {A, C.m, C.d, C.ok}, as two memories of 16 and 7 bits so
// that each maps onto whole block RAMs (iCE40: 3 + 2 at 640); depth as the width needs. A read
// never meets the write of the same address in one clock: the only case, column 0 of a
// one-word-wide frame read right after it was written, waits a clock (such frames go at half
// rate).

`include "gradient_word.vh"
`include "edge_beat.vh"

module edge_stage #(
    parameter MAX_WIDTH = 640                 // words per row, upper bound of the learnt width
) (
    input  wire        aclk,
    input  wire        aresetn,               // synchronous, active low

    input  wire [8:0]  cfg_threshold,         // L1 magnitude, grey levels; a register, read
                                              // when a frame's first word is accepted

    input  wire [31:0] s_axis_tdata,          // gradient word (gradient_word.vh)
    input  wire [1:0]  s_axis_tuser,          // [0] start of frame, [1] end of frame
    input  wire        s_axis_tlast,          // end of row
    input  wire        s_axis_tvalid,
    output wire        s_axis_tready,

    output wire [47:0] m_axis_tdata,          // edge beat (edge_beat.vh)
    output wire        m_axis_tuser,          // a frame's first beat
    output wire        m_axis_tlast,          // a frame's trailer
    output wire        m_axis_tvalid,
    input  wire        m_axis_tready
);

    generate
        if (MAX_WIDTH < 1 || MAX_WIDTH > 2048) begin : g_check_width
            edge_stage_MAX_WIDTH_must_be_1_to_2048 u_bad_max_width ();   // x has 11 bits
        end
    endgenerate

    localparam XW = (MAX_WIDTH < 2) ? 1 : $clog2(MAX_WIDTH);
    localparam CW = `QT_EP_COORD_BITS;                      // 11

    wire rst = ~aresetn;

    // ------------------------------------------------------------------------------------
    // E0: framing and the tail
    // ------------------------------------------------------------------------------------
    reg          rdy, active, learn, broken;
    reg [XW-1:0] x, wm1;
    reg          x_zero;
    reg [8:0]    thr;         // the frame's threshold
    reg          tail, pending, t_zero, t_broken;
    reg [XW-1:0] t, t_wm1;
    reg          w_one;       // wm1 == 0
    reg          t_end;       // t == t_wm1 (while the tail runs), kept a step ahead

    (* keep *) wire adv;      // E1 .. E10 advance (O free and no trailer hold)

    // Also held for a clock when a row of a one-word-wide frame would read column 0 while the
    // word before is written there (wz): the block RAM cannot give the data being written.
    reg  wz;                  // E1 writes column 0 in this clock
    // The tail waits with it (and the input with the tail, which must keep ahead of row 0).
    //   rd0_wait = wz & ((x_zero & active & ~learn) | (tail & t_zero))
    //   s_axis_tready = rdy & adv & ~pending & ~(tail & active & ~learn) & ~rd0_wait
    //   t_step = tail & adv & ~rd0_wait
    // All but adv is a function of flip-flops: kept in two flip-flops made from those
    // registers' next values (in_go, t_go below), as in gradient.v (timing: adv, with the
    // output's m_axis_tready in front of it, is then the last gate before the enables).
    reg  in_go;               // s_axis_tready but for adv
    reg  t_go;                // tail & ~rd0_wait
    assign s_axis_tready = adv & in_go;
    wire t_step = adv & t_go;                           // the tail's column enters E1

    wire       sof   = s_axis_tuser[0];
    // A word of a frame is taken: s_axis_tvalid & s_axis_tready & (sof | active). Kept as two
    // signals (keep: synthesis would fold them into a deeper tree): the part from flip-flops,
    // then one gate with adv, the signal with the most logic in front of it.
    (* keep *) wire w_ok;
    (* keep *) wire take;
    assign w_ok = s_axis_tvalid & in_go & (sof | active);
    assign take = adv & w_ok;
    wire       row0  = sof | learn;
    wire       fill  = s_axis_tdata[`QT_GW_FILL_BIT];
    wire [8:0] b_mag = s_axis_tdata[`QT_GW_MAG_LSB +: 9];
    wire [3:0] b_dir = s_axis_tdata[`QT_GW_DIR_LSB +: 4];
    // The threshold test of each word, with its frame's threshold, kept in the line memory
    // beside it (so the tail needs no threshold of its own).
    wire       b_ok  = (b_mag >= (sof ? cfg_threshold : thr));
    wire       req   = take & s_axis_tuser[1];           // the frame's last word: its tail
    wire       go    = req & ~tail;
    wire [XW-1:0] col = x & {XW{~sof}};

    wire [XW-1:0] rd_addr = tail ? t : x;

    // Next values (without reset) of the registers in_go and t_go are made from.
    wire active_nx = take ? ~s_axis_tuser[1] : active;
    wire learn_nx  = take ? (row0 & ~s_axis_tlast) : learn;
    wire x_zero_nx = take ? s_axis_tlast : x_zero;
    wire wz_nx     = adv ? (take & (sof | x_zero)) : wz;

    always @(posedge aclk) begin
        if (rst) begin
            rdy    <= 1'b0;
            active <= 1'b0;
            learn  <= 1'b0;
            wz     <= 1'b0;
            x      <= {XW{1'b0}};
            x_zero <= 1'b1;
        end else begin
            rdy    <= 1'b1;
            wz     <= wz_nx;
            active <= active_nx;
            learn  <= learn_nx;
            x_zero <= x_zero_nx;
            if (take) begin
                broken <= (broken & ~sof) | fill;
                x      <= s_axis_tlast ? {XW{1'b0}} : col + 1'b1;
            end
            // Loaded from the word at the input while it may be taken (w_ok), taken in this
            // clock or not: a word not taken is offered again (and adv alone has held it, so
            // w_ok stays), the last load is the one of the clock it is taken, and nothing
            // reads these registers meanwhile. So adv is not in their enables (timing).
            // thr: the frame's threshold, read for the frame's other words only.
            if (w_ok & sof)
                thr <= cfg_threshold;
            // W - 1: the column of row 0's last word, from every word of row 0 (read once
            // row 0 is complete, or while pending, when no word may be taken).
            if (w_ok & row0) begin
                wm1   <= col;
                w_one <= sof | x_zero;
            end
        end
    end

    // The tail: started by the frame's last word when none runs, else (a one-row frame behind
    // a tail) when that one ends. While no tail runs, its registers follow the values a tail
    // started now would take, so that only `tail` and `pending` hang on the word's acceptance.
    // pending: a one-row frame behind a tail.
    wire pending_nx = tail & (req | pending);
    wire tail_nx    = go | (pending & ~tail) | (tail & ~(t_step & t_end));
    wire t_zero_nx  = ~tail | (t_zero & ~t_step);

    always @(posedge aclk) begin
        if (rst) begin
            tail    <= 1'b0;
            pending <= 1'b0;
        end else begin
            pending <= pending_nx;
            tail    <= tail_nx;
        end
    end

    // in_go and t_go from the next values (see s_axis_tready); rdy's next value is 1.
    wire rd0_wait_nx = wz_nx & ((x_zero_nx & active_nx & ~learn_nx) | (tail_nx & t_zero_nx));

    always @(posedge aclk) begin
        if (rst) begin
            in_go <= 1'b0;
            t_go  <= 1'b0;
        end else begin
            in_go <= ~pending_nx & ~(tail_nx & active_nx & ~learn_nx) & ~rd0_wait_nx;
            t_go  <= tail_nx & ~rd0_wait_nx;
        end
    end

`ifndef SYNTHESIS
    // in_go, t_go and t_end equal the expressions they stand for (from the first reset on);
    // the benches stop on a difference.
    reg  chk_go = 1'b0;
    wire rd0_wait = wz & ((x_zero & active & ~learn) | (tail & t_zero));
    wire go_same  = (in_go === (rdy & ~pending & ~(tail & active & ~learn) & ~rd0_wait)) &&
                    (t_go === (tail & ~rd0_wait)) && (!tail || t_end === (t == t_wm1));
    always @(posedge aclk) begin
        if (chk_go && !go_same) begin
            $display("edge_stage: in_go, t_go or t_end differ from their expressions at %0t",
                     $time);
            $fatal(1);
        end
        if (rst)
            chk_go <= 1'b1;
    end
`endif

    wire [XW-1:0] t_inc = t + 1'b1;

    always @(posedge aclk) begin
        if (~tail) begin
            t        <= {XW{1'b0}};
            t_zero   <= 1'b1;
            t_wm1    <= (pending | ~row0) ? wm1 : col;
            t_broken <= pending ? broken : ((broken & ~sof) | fill);
            t_end    <= (pending | ~row0) ? w_one : (sof | x_zero);
        end else if (t_step) begin
            t      <= t_inc;
            t_zero <= 1'b0;
            t_end  <= (t_inc == t_wm1);
        end
    end

    // ------------------------------------------------------------------------------------
    // Line memory: {A[8:0], C.m[8:0], C.d[3:0], C.ok} at [22:14], [13:5], [4:1], [0]
    // ------------------------------------------------------------------------------------
    (* no_rw_check *)
    reg  [15:0]   mem_lo [0:MAX_WIDTH-1];
    (* no_rw_check *)
    reg  [6:0]    mem_hi [0:MAX_WIDTH-1];
    reg  [15:0]   q_lo;
    reg  [6:0]    q_hi;
    wire          wr_en;
    wire [XW-1:0] wr_addr;
    wire [22:0]   wr_data;

    always @(posedge aclk) begin
        if (wr_en) begin
            mem_lo[wr_addr] <= wr_data[15:0];
            mem_hi[wr_addr] <= wr_data[22:16];
        end
        if (adv) begin
            q_lo <= mem_lo[rd_addr];
            q_hi <= mem_hi[rd_addr];
`ifndef SYNTHESIS
            if (wr_en && wr_addr == rd_addr) begin
                q_lo <= 16'bx;                  // collision: undefined in the block RAM
                q_hi <= 7'bx;
            end
`endif
        end
    end

    // ------------------------------------------------------------------------------------
    // E1: column assembly, write-back, window shift
    // ------------------------------------------------------------------------------------
    reg          e1_we, e1_wrow0, e1_cv, e1_tail, e1_first, e1_last, e1_final, e1_broken, e1_bok;
    reg [XW-1:0] e1_wx;
    reg [8:0]    e1_bm;
    reg [3:0]    e1_bd;

    always @(posedge aclk) begin
        if (rst) begin
            e1_we <= 1'b0;
            e1_cv <= 1'b0;
        end else if (adv) begin
            e1_we <= take;
            e1_cv <= t_step | (take & ~row0);         // rows >= 1 and the tail: decisions
        end
    end

    always @(posedge aclk) begin
        if (adv) begin
            e1_wx     <= col;
            e1_wrow0  <= row0;
            e1_bm     <= b_mag;
            e1_bd     <= b_dir;
            e1_bok    <= b_ok;
            e1_tail   <= t_step;
            e1_first  <= t_step ? t_zero : x_zero;
            e1_last   <= t_step ? t_end : s_axis_tlast;
            e1_final  <= t_step & t_end;
            e1_broken <= t_broken;
        end
    end

    wire [22:0] rd    = {q_hi, q_lo};
    wire [8:0]  n_a   = rd[22:14];                       // m(x, y-2)
    wire [8:0]  n_cm  = rd[13:5];                        // m(x, y-1)
    wire [3:0]  n_cd  = rd[4:1];                         // d(x, y-1)
    wire        n_ok  = rd[0];                           // m(x, y-1) >= threshold
    wire [8:0]  n_b   = e1_tail ? 9'd0 : e1_bm;          // m(x, y); the flush: outside

    assign wr_en   = adv & e1_we;
    assign wr_addr = e1_wx;
    assign wr_data = {e1_wrow0 ? 9'd0 : n_cm, e1_bm, e1_bd, e1_bok};

    // Window columns: a (above), c (centre) and b (below) magnitudes; M and R also keep the
    // centre's direction, threshold check and flags.
    reg [8:0] l_a, l_c, l_b, m_a, m_c, m_b, r_a, r_c, r_b;
    reg [3:0] m_d, r_d;
    reg       m_ok, r_ok;
    reg       m_dec, m_first, m_last, m_final, m_broken;
    reg       r_dec, r_first, r_last, r_final, r_broken;
    reg       e2_go;          // the window shifted: decide M

    wire close = r_dec & r_last & ~e1_cv;                // move a row's last column on
    wire shift = e1_cv | close;

    always @(posedge aclk) begin
        if (rst) begin
            e2_go <= 1'b0;
            m_dec <= 1'b0;
            r_dec <= 1'b0;
        end else if (adv) begin
            e2_go <= shift;
            if (shift) begin
                m_dec <= r_dec;
                r_dec <= e1_cv;
            end
        end
    end

    always @(posedge aclk) begin
        if (adv && shift) begin
            // L: M, or zero when the column becoming M is column 0 (the left border).
            l_a <= r_first ? 9'd0 : m_a;
            l_c <= r_first ? 9'd0 : m_c;
            l_b <= r_first ? 9'd0 : m_b;
            {m_a, m_c, m_b, m_d, m_ok} <= {r_a, r_c, r_b, r_d, r_ok};
            {m_first, m_last, m_final, m_broken} <= {r_first, r_last, r_final, r_broken};
            {r_a, r_c, r_b, r_d, r_ok} <= {n_a, n_cm, n_b, n_cd, n_ok};
            {r_first, r_last, r_final, r_broken} <= {e1_first & e1_cv, e1_last & e1_cv,
                                                     e1_final & e1_cv, e1_broken & e1_cv};
        end
    end

    // ------------------------------------------------------------------------------------
    // E2: the ring, its two sides summed: sp = P (+ P2), sq = Q (+ Q2)
    // ------------------------------------------------------------------------------------
    wire [8:0] ra = m_last ? 9'd0 : r_a;                 // right border: outside is 0
    wire [8:0] rc = m_last ? 9'd0 : r_c;
    wire [8:0] rb = m_last ? 9'd0 : r_b;
    wire [8:0] n0 = rc, n1 = rb, n2 = m_b, n3 = l_b, n4 = l_c, n5 = l_a, n6 = m_a, n7 = ra;
    wire [1:0] k    = m_d[2:1];
    wire       odd  = m_d[0];

    // P1, P2 = n_k, n_{k+1} of (n0 .. n4) and Q1, Q2 = n_{k+4}, n_{k+5} of (n4 .. n7, n0): a
    // two-step shift by k (2, then 1), two-input selections only.
    wire [8:0] pa0 = k[1] ? n2 : n0, pa1 = k[1] ? n3 : n1, pa2 = k[1] ? n4 : n2;
    wire [8:0] qa0 = k[1] ? n6 : n4, qa1 = k[1] ? n7 : n5, qa2 = k[1] ? n0 : n6;
    wire [8:0] p1 = k[0] ? pa1 : pa0, p2 = k[0] ? pa2 : pa1;
    wire [8:0] q1 = k[0] ? qa1 : qa0, q2 = k[0] ? qa2 : qa1;
    wire [9:0] sp = {1'b0, p1} + {1'b0, p2 & {9{odd}}};
    wire [9:0] sq = {1'b0, q1} + {1'b0, q2 & {9{odd}}};

    // Decision-slot flags travel with every stage: slot (a pixel decided), last (of its row),
    // final (of its frame), broken (the frame's, on its final pixel).
    reg       e3_slot, e3_cand, e3_last, e3_final, e3_broken, e3_swap;
    reg [9:0] e3_sp, e3_sq, e3_mm;
    reg [3:0] e3_d;

    always @(posedge aclk) begin
        if (rst)
            e3_slot <= 1'b0;
        else if (adv)
            e3_slot <= e2_go & m_dec;
    end

    always @(posedge aclk) begin
        if (adv) begin
            {e3_cand, e3_last, e3_final, e3_broken} <= {m_ok, m_last, m_final, m_broken};
            e3_swap <= m_d[3];
            e3_sp   <= sp;
            e3_sq   <= sq;
            e3_mm   <= odd ? {m_c, 1'b0} : {1'b0, m_c};      // 2m for odd bins
            e3_d    <= m_d;
        end
    end

    // ------------------------------------------------------------------------------------
    // E3: the centre against each side, s_p = m' - sp and s_q = m' - sq; the test (ahead = sp,
    // behind = sq; swapped for bins 8..15): greater than ahead, not less than behind;
    // D = s_p + s_q = 2m' - ahead - behind; behind - ahead = s_p - s_q (swapped: s_q - s_p),
    // N = |sp - sq|. Two carry chains in a row at most.
    // ------------------------------------------------------------------------------------
    wire [10:0] s_p = {1'b0, e3_mm} - {1'b0, e3_sp};
    wire [10:0] s_q = {1'b0, e3_mm} - {1'b0, e3_sq};
    wire [10:0] d_pq = {1'b0, e3_sq} - {1'b0, e3_sp};         // s_p - s_q
    wire [10:0] d_qp = {1'b0, e3_sp} - {1'b0, e3_sq};         // s_q - s_p
    wire        p_gt = ~s_p[10] & (s_p[9:0] != 10'd0);
    wire        q_gt = ~s_q[10] & (s_q[9:0] != 10'd0);
    wire        is_edge = e3_slot & e3_cand & (e3_swap ? (q_gt & ~s_p[10]) : (p_gt & ~s_q[10]));
    wire [10:0] den = s_p + s_q;                              // <= 2040 on an edge

    reg        e4_slot, e4_edge, e4_neg, e4_last, e4_final, e4_broken;
    reg [9:0]  e4_n;                                          // <= 1020 on an edge
    reg [10:0] e4_den;
    reg [8:0]  e4_m;
    reg [3:0]  e4_d;

    always @(posedge aclk) begin
        if (rst)
            e4_slot <= 1'b0;
        else if (adv)
            e4_slot <= e3_slot;
    end

    always @(posedge aclk) begin
        if (adv) begin
            {e4_last, e4_final, e4_broken} <= {e3_last, e3_final, e3_broken};
            e4_edge <= is_edge;
            // behind > ahead: the offset is negative
            e4_neg  <= e3_swap ? (~d_qp[10] & (d_qp != 11'd0)) : (~d_pq[10] & (d_pq != 11'd0));
            e4_n    <= d_pq[10] ? d_qp[9:0] : d_pq[9:0];
            e4_den  <= den;
            e4_m    <= e3_d[0] ? e3_mm[9:1] : e3_mm[8:0];    // m, from m' (no copy of m)
            e4_d    <= e3_d;
        end
    end

    // ------------------------------------------------------------------------------------
    // E4: R0 = 8N + floor(D/2) <= 8.5 D
    // ------------------------------------------------------------------------------------
    reg        e5_slot, e5_edge, e5_neg, e5_last, e5_final, e5_broken;
    reg [13:0] e5_r;
    reg [10:0] e5_den;
    reg [8:0]  e5_m;
    reg [3:0]  e5_d;

    always @(posedge aclk) begin
        if (rst)
            e5_slot <= 1'b0;
        else if (adv)
            e5_slot <= e4_slot;
    end

    always @(posedge aclk) begin
        if (adv) begin
            {e5_edge, e5_neg, e5_last, e5_final, e5_broken} <=
                {e4_edge, e4_neg, e4_last, e4_final, e4_broken};
            e5_r   <= {e4_n, 3'b000} + {4'b0000, e4_den[10:1]};
            e5_den <= e4_den;
            e5_m   <= e4_m;
            e5_d   <= e4_d;
        end
    end

    // ------------------------------------------------------------------------------------
    // E5: quotient q = floor(R0 / D) <= 8 in two radix-4 digits. First digit: 2 when
    // R0 >= 8D (q = 8), 1 when R0 >= 4D, else 0; the remainder R1 < 4D. And 3D.
    // ------------------------------------------------------------------------------------
    wire [14:0] t8 = {1'b0, e5_r} - {1'b0, e5_den, 3'b000};
    wire [14:0] t4 = {1'b0, e5_r} - {2'b00, e5_den, 2'b00};

    reg        e6_slot, e6_edge, e6_neg, e6_last, e6_final, e6_broken;
    reg [1:0]  e6_hi;
    reg [12:0] e6_r;
    reg [10:0] e6_den;
    reg [12:0] e6_den3;
    reg [8:0]  e6_m;
    reg [3:0]  e6_d;

    always @(posedge aclk) begin
        if (rst)
            e6_slot <= 1'b0;
        else if (adv)
            e6_slot <= e5_slot;
    end

    always @(posedge aclk) begin
        if (adv) begin
            {e6_edge, e6_neg, e6_last, e6_final, e6_broken} <=
                {e5_edge, e5_neg, e5_last, e5_final, e5_broken};
            e6_hi   <= ~t8[14] ? 2'd2 : ~t4[14] ? 2'd1 : 2'd0;
            e6_r    <= ~t8[14] ? t8[12:0] : ~t4[14] ? t4[12:0] : e5_r[12:0];
            e6_den  <= e5_den;
            e6_den3 <= {2'b00, e5_den} + {1'b0, e5_den, 1'b0};
            e6_m    <= e5_m;
            e6_d    <= e5_d;
        end
    end

    // E6: second digit: 3, 2, 1 or 0 as R1 >= 3D, 2D, D; delta = -q or q, limited to -8..7
    // (q <= 8).
    wire [13:0] u3 = {1'b0, e6_r} - {1'b0, e6_den3};
    wire [13:0] u2 = {1'b0, e6_r} - {1'b0, e6_den, 1'b0};
    wire [13:0] u1 = {1'b0, e6_r} - {3'b000, e6_den};
    wire [1:0]  lo_digit = ~u3[13] ? 2'd3 : ~u2[13] ? 2'd2 : ~u1[13] ? 2'd1 : 2'd0;
    wire [3:0]  q6 = {e6_hi, lo_digit};
    // 0 - q6, written bit by bit: gates, where the subtraction would be a carry chain behind the
    // compares' (timing).
    wire [3:0]  q6_neg = {q6[3] ^ (|q6[2:0]), q6[2] ^ (|q6[1:0]), q6[1] ^ q6[0], q6[0]};

    reg        e7_slot, e7_edge, e7_last, e7_final, e7_broken;
    reg [3:0]  e7_delta;
    reg [8:0]  e7_m;
    reg [3:0]  e7_d;

    always @(posedge aclk) begin
        if (rst)
            e7_slot <= 1'b0;
        else if (adv)
            e7_slot <= e6_slot;
    end

    always @(posedge aclk) begin
        if (adv) begin
            {e7_edge, e7_last, e7_final, e7_broken} <= {e6_edge, e6_last, e6_final, e6_broken};
            e7_delta <= e6_neg ? q6_neg : (q6[3] ? 4'd7 : q6);
            e7_m     <= e6_m;
            e7_d     <= e6_d;
        end
    end

    // ------------------------------------------------------------------------------------
    // O: the output register. Counters give each decided pixel its x and y; the trailer
    // closes a frame.
    // ------------------------------------------------------------------------------------
    wire z_slot  = e7_slot;
    wire z_edge  = e7_edge;
    wire z_final = e7_final;

    reg [CW-1:0] xo, yo;
    reg          sof_due, tr_pend, tr_broken, hold;
    reg          o_v;
    reg [49:0]   o_beat;                                  // {tuser, tlast, beat}

    // O takes a beat when it is empty or its beat is being taken: the only place m_axis_tready
    // goes (the gradient block's register slice keeps it from the front end's input). `hold`
    // (the trailer first, the pixel behind it waits) is a flip-flop: tr_pend and z_slot of the
    // next clock.
    (* keep *) wire o_ready;  // kept (with adv, take): one gate each, not a deeper tree
    assign o_ready = ~o_v | m_axis_tready;
    assign adv   = o_ready & ~hold;

    wire        trailer  = tr_pend | (z_slot & z_final & ~z_edge);
    wire        o_valid  = tr_pend | (z_slot & (z_edge | z_final));
    wire        tr_next  = o_ready ? (~trailer & z_slot & z_final) : tr_pend;
    wire        slot_next = adv ? e6_slot : z_slot;

    always @(posedge aclk) begin
        if (rst) begin
            o_v     <= 1'b0;
            xo      <= {CW{1'b0}};
            yo      <= {CW{1'b0}};
            sof_due <= 1'b1;
            tr_pend <= 1'b0;
            hold    <= 1'b0;
        end else begin
            tr_pend <= tr_next;
            hold    <= tr_next & slot_next;
            if (o_ready) begin
                o_v <= o_valid;
                // A trailer: {1, broken, 0, W - 1, H - 1}; a point: {0, 0, m, the packed point}.
                o_beat[49] <= sof_due;
                o_beat[48] <= trailer;
                o_beat[47] <= trailer;
                o_beat[46] <= trailer & (tr_pend ? tr_broken : e7_broken);
                o_beat[45:22] <= trailer ? 24'd0 : {6'd0, e7_m, e7_delta, 2'b00, e7_d};
                o_beat[21:0]  <= {yo, xo};
                if (o_valid)
                    sof_due <= trailer;
                if (trailer) begin
                    xo <= {CW{1'b0}};
                    yo <= {CW{1'b0}};
                end else if (z_slot) begin
                    if (z_final) begin
                        tr_broken <= e7_broken;           // counters kept for the trailer
                    end else begin
                        xo <= e7_last ? {CW{1'b0}} : xo + 1'b1;
                        yo <= e7_last ? yo + 1'b1 : yo;
                    end
                end
            end
        end
    end

    assign {m_axis_tuser, m_axis_tlast, m_axis_tdata} = o_beat;
    assign m_axis_tvalid = o_v;
endmodule

`default_nettype wire
