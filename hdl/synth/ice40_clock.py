# Timing constraint of the iCE40 runs (nextpnr-ice40 --pre-pack): the one clock, aclk, at
# 100 MHz (10 ns), the target for 720p60 (74.25 MHz pixel clock) with margin.
ctx.addClock("aclk", 100)
