`timescale 1ns / 1ps
`default_nettype none

// Stream rules of the gradient block's output, as properties for a bounded proof (yosys-smtbmc;
// hdl/formal/run.sh). The input side is left free but for the AXI4-Stream source rule (a beat
// offered and not taken is held) and a reset in the first clock; cfg_height is free at every
// clock. Proven for every reachable state within the depth:
//   - a beat offered and not taken is held: tvalid stays, tdata, tuser and tlast unchanged;
//   - start of frame (tuser[0]) exactly on the first beat of a frame (the first after reset or
//     after an end of frame);
//   - end of frame (tuser[1]) only on a tlast beat;
//   - every row of a frame ends with tlast at the same column as its first row (one tlast per
//     row, whole rows only);
//   - after a reset no beat is offered until an input beat has been taken (a reset forgets
//     every pending row and flush);
//   - the first frame after a reset, when no error is raised, ends after exactly the rows that
//     cfg_height held when its first word was taken (the height is read once, at that word,
//     however it changes later).
module stream_props #(
    parameter MAX_WIDTH = 4                 // pixels per row: small, so the depth covers rows
) (
    input wire       aclk,
    input wire       aresetn,
    input wire [15:0] cfg_height,
    input wire [7:0] s_tdata,
    input wire       s_tuser,
    input wire       s_tlast,
    input wire       s_tvalid,
    input wire       m_tready
);
    wire        s_tready, error;
    wire [31:0] m_tdata;
    wire [1:0]  m_tuser;
    wire        m_tlast, m_tvalid;

    gradient #(.MAX_WIDTH(MAX_WIDTH)) dut (
        .aclk(aclk), .aresetn(aresetn), .cfg_height(cfg_height),
        .s_axis_tdata(s_tdata), .s_axis_tuser(s_tuser), .s_axis_tlast(s_tlast),
        .s_axis_tvalid(s_tvalid), .s_axis_tready(s_tready),
        .m_axis_tdata(m_tdata), .m_axis_tuser(m_tuser), .m_axis_tlast(m_tlast),
        .m_axis_tvalid(m_tvalid), .m_axis_tready(m_tready), .error(error));

`ifdef FORMAL
    reg first = 1'b1;                       // the first clock: reset
    always @(posedge aclk) first <= 1'b0;
    always @(*) if (first) assume(!aresetn);

    // The source holds a beat it offered until it is taken (outside reset).
    reg        p_valid = 1'b0, p_tuser = 1'b0, p_tlast = 1'b0, p_rst = 1'b1;
    reg [7:0]  p_tdata = 8'd0;
    always @(posedge aclk) begin
        p_valid <= s_tvalid & ~s_tready;
        p_tdata <= s_tdata;
        p_tuser <= s_tuser;
        p_tlast <= s_tlast;
        p_rst   <= ~aresetn;
    end
    always @(*)
        if (aresetn && !p_rst && p_valid)
            assume(s_tvalid && s_tdata == p_tdata && s_tuser == p_tuser && s_tlast == p_tlast);

    // The output side: what the sink saw. And since the last reset: an input beat taken; the
    // first frame's height at its first word (0: not started); rows of the first frame taken at
    // the output; an error raised.
    reg        q_stall = 1'b0;              // a beat was offered and not taken last clock
    reg [34:0] q_beat  = 35'd0;
    reg        in_frame = 1'b0;             // a frame's first beat was taken, not its last
    reg [15:0] col = 16'd0;                 // column of the next beat in its row
    reg [15:0] width = 16'd0;               // columns of the frame's first row (0: not known)
    reg        s_seen  = 1'b0;
    reg [15:0] h_first = 16'd0;
    reg [15:0] rows_out = 16'd0;
    reg        out_done = 1'b0, err_seen = 1'b0;

    wire       take = m_tvalid & m_tready;
    wire       s_take = s_tvalid & s_tready;

    always @(posedge aclk) begin
        if (!aresetn) begin
            q_stall  <= 1'b0;
            in_frame <= 1'b0;
            col      <= 16'd0;
            width    <= 16'd0;
            s_seen   <= 1'b0;
            h_first  <= 16'd0;
            rows_out <= 16'd0;
            out_done <= 1'b0;
            err_seen <= 1'b0;
        end else begin
            q_stall <= m_tvalid & ~m_tready;
            q_beat  <= {m_tuser, m_tlast, m_tdata};
            if (take) begin
                in_frame <= ~m_tuser[1];
                if (m_tlast) begin
                    col <= 16'd0;
                    if (width == 16'd0 || m_tuser[0])
                        width <= col + 16'd1;
                end else begin
                    col <= col + 16'd1;
                end
                if (m_tuser[0] && !m_tlast)
                    width <= 16'd0;
            end
            if (s_take) s_seen <= 1'b1;
            if (s_take && s_tuser && h_first == 16'd0 && cfg_height != 16'd0)
                h_first <= cfg_height;
            if (take && m_tlast && !out_done) begin
                rows_out <= rows_out + 16'd1;
                if (m_tuser[1]) out_done <= 1'b1;
            end
            if (error) err_seen <= 1'b1;
        end
    end

    always @(posedge aclk) begin
        if (aresetn && !first && !p_rst) begin
            // Nothing out before something came in since the reset.
            if (!s_seen)
                assert(!m_tvalid);
            // The first frame's end after the rows its first word's height gave.
            if (take && m_tuser[1] && !out_done && !err_seen && !error)
                assert(rows_out + 16'd1 == h_first);
            // Held while stalled.
            if (q_stall)
                assert(m_tvalid && {m_tuser, m_tlast, m_tdata} == q_beat);
            if (m_tvalid) begin
                // Start of frame exactly on a frame's first beat.
                assert(m_tuser[0] == !in_frame);
                // End of frame only at an end of line.
                if (m_tuser[1])
                    assert(m_tlast);
                // Rows after the first end at the first row's last column, and none runs on.
                if (in_frame && width != 16'd0) begin
                    assert(col < width);
                    assert(m_tlast == (col == width - 16'd1));
                end
                assert(col < MAX_WIDTH);
            end
        end
    end
`endif
endmodule

`default_nettype wire
