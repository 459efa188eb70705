// Bench of the register slice alone (hdl/rtl/axis_slice.v): a counting source that holds a beat
// offered and not taken, random input gaps, output back-pressure and resets; every beat out must
// be the next beat in (none lost, none doubled, none made up), a beat offered downstream and not
// taken must be held, and with no gaps and no back-pressure a beat must come out every clock.
// A reset drops the beats in flight: after it the next beat out is the next one taken in.
//
//   +seed=N            random seed (default 1)
//   +clocks=N          clocks of random traffic (default 200000)
//   +fault=K           check beat K out against a wrong value: the bench must fail (0: off)
//
// Exit status non-zero ($fatal) on any violation; the last line is "PASS ...".
`timescale 1ns/1ps
`default_nettype none

module tb_axis_slice;
    localparam W = 16;
    localparam STALL_PERCENT = 30;

    reg          clk = 1'b0, rst = 1'b1;
    reg  [W-1:0] s_data = 0;
    reg          s_valid = 1'b0, m_ready = 1'b0;
    wire         s_ready, m_valid;
    wire [W-1:0] m_data;

    axis_slice #(.W(W)) dut (
        .clk(clk), .rst(rst),
        .s_data(s_data), .s_valid(s_valid), .s_ready(s_ready),
        .m_data(m_data), .m_valid(m_valid), .m_ready(m_ready));

    always #5 clk = ~clk;

    integer seed = 1, clocks = 200000, fault = 0;
    integer n_in = 0, n_out = 0, n_resets = 0;
    reg [W-1:0] expect = 0;        // the next beat out
    reg [W-1:0] want;
    reg         taken = 1'b0;      // the source's beat was taken at the last rising edge
    reg         held = 1'b0;       // a beat was offered downstream and not taken last clock
    reg [W-1:0] held_data = 0;
    integer     gaps = STALL_PERCENT, pressure = STALL_PERCENT;
    integer     clk_n = 0;

    // At each rising edge: what the slice takes and gives, then the checks.
    always @(posedge clk) begin
        if (!rst) begin
            if (held && !(m_valid && m_data == held_data))
                $fatal(1, "tb_axis_slice: clock %0d: a beat offered and not taken was dropped or changed", clk_n);
            if (m_valid && m_ready) begin
                want = n_out + 1 == fault ? expect + 1'b1 : expect;
                if (m_data !== want)
                    $fatal(1, "tb_axis_slice: beat %0d out is %0d, want %0d", n_out + 1, m_data, want);
                expect <= expect + 1'b1;
                n_out = n_out + 1;
            end
            held <= m_valid && !m_ready;
            held_data <= m_data;
        end
        taken = s_valid && s_ready && !rst;   // read before the edge's updates land
        if (taken) n_in = n_in + 1;
    end

    // Between edges: the source and the sink draw their next move. The source holds a beat
    // offered and not taken; its data counts the beats taken.
    task drive;
        begin
            if (taken) s_data = s_data + 1'b1;
            if (taken || !s_valid) s_valid = ($urandom(seed) % 100) >= gaps;
            m_ready = ($urandom(seed) % 100) >= pressure;
        end
    endtask

    task do_reset;
        begin
            @(negedge clk);
            rst = 1'b1;
            s_valid = 1'b0;
            if (taken) s_data = s_data + 1'b1;
            @(negedge clk);
            rst = 1'b0;
            held = 1'b0;
            expect = s_data;   // the beats in flight are gone
            n_resets = n_resets + 1;
        end
    endtask

    integer i, before;
    initial begin
        if (!$value$plusargs("seed=%d", seed)) seed = 1;
        if (!$value$plusargs("clocks=%d", clocks)) clocks = 200000;
        if (!$value$plusargs("fault=%d", fault)) fault = 0;
        do_reset;
        for (i = 0; i < clocks; i = i + 1) begin
            @(negedge clk);
            clk_n = i;
            drive;
            if (($urandom(seed) % 4096) == 0) do_reset;
        end
        // Full throughput: no gaps, no back-pressure, a beat out every clock.
        gaps = 0;
        pressure = 0;
        for (i = 0; i < 8; i = i + 1) begin
            @(negedge clk);
            drive;
        end
        before = n_out;
        for (i = 0; i < 1000; i = i + 1) begin
            @(negedge clk);
            drive;
        end
        if (n_out - before != 1000)
            $fatal(1, "tb_axis_slice: %0d beats out in 1000 clocks without stalls, want 1000", n_out - before);
        $display("PASS %0d beats in, %0d out, %0d resets", n_in, n_out, n_resets);
        $finish;
    end
endmodule

`default_nettype wire
