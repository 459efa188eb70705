#!/usr/bin/env bash
# Synthesis and place-and-route of hdl/rtl/gradient.v (MAX_WIDTH 640) for two iCE40 devices with a
# 100 MHz clock constraint. Prints one line per device: logic cells, block RAMs, Fmax.
#
#   bash hdl/synth/ice40.sh [BUILD_DIR]      (default: a new temporary directory)
#
# Tools: yosys (synth_ice40 -abc9, the direction submodules mapped separately and flattened
# afterwards: about 10 LCs fewer than flattening first), nextpnr-ice40. The UP5K SG48 package has 39 I/O pins and
# the block has 67 ports, so on UP5K it is placed inside a wrapper that feeds s_height from
# m_tdata[15:0] (which then need no pins) and leaves no logic of its own; the block is
# synthesised on its own first, so its netlist does not depend on the wrapper. HX8K CT256 takes
# the block's ports directly.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
hdl=$(cd "$here/.." && pwd)
out=${1:-$(mktemp -d "${TMPDIR:-/tmp}/qt_ice40.XXXXXX")}
mkdir -p "$out"
freq=100          # MHz
seed=1            # nextpnr placement seed, fixed for reproducible figures

for tool in yosys nextpnr-ice40; do
    command -v "$tool" >/dev/null || { echo "ice40.sh: $tool not found" >&2; exit 1; }
done

src=("$hdl/rtl/gradient.v" "$hdl/rtl/gradient_direction.v")

# No latches anywhere in the design (elaborated RTL).
yosys -q -l "$out/latch_check.log" -p "read_verilog -I$hdl/rtl ${src[*]}; hierarchy -top gradient;
    chparam -set MAX_WIDTH 640 gradient; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr" \
    >/dev/null || { echo "ice40.sh: latch check failed, see $out/latch_check.log" >&2; exit 1; }

cat > "$out/gradient_up5k_sg48.v" <<'VERILOG'
// Pin-count wrapper for UP5K SG48 (see ice40.sh): no logic, only wiring.
module gradient_up5k_sg48 (
    input  wire        clk, rst,
    input  wire [7:0]  s_tdata,
    input  wire        s_tuser, s_tlast, s_tvalid,
    output wire        s_tready,
    output wire [15:0] m_tdata_hi,
    output wire        m_tuser, m_tlast, m_tvalid,
    input  wire        m_tready,
    output wire        error
);
    wire [31:0] m_tdata;
    gradient u_gradient (
        .clk(clk), .rst(rst), .s_tdata(s_tdata), .s_tuser(s_tuser), .s_tlast(s_tlast),
        .s_tvalid(s_tvalid), .s_tready(s_tready), .s_height(m_tdata[15:0]),
        .m_tdata(m_tdata), .m_tuser(m_tuser), .m_tlast(m_tlast), .m_tvalid(m_tvalid),
        .m_tready(m_tready), .error(error));
    assign m_tdata_hi = m_tdata[31:16];
endmodule
VERILOG

# device  yosys -device  nextpnr device/package  top
run() {
    local name=$1 ydev=$2 pnr=$3 top=$4
    local wrap=""
    [ "$top" = gradient ] || wrap="read_verilog $out/$top.v; hierarchy -top $top; flatten;"
    yosys -q -l "$out/$name.yosys.log" -p "read_verilog -I$hdl/rtl ${src[*]};
        chparam -set MAX_WIDTH 640 gradient;
        synth_ice40 -top gradient -abc9 -device $ydev -noflatten;
        flatten;
        $wrap
        check -assert;
        write_json $out/$name.json" >/dev/null \
        || { echo "ice40.sh: yosys failed for $name, see $out/$name.yosys.log" >&2; exit 1; }
    # shellcheck disable=SC2086
    nextpnr-ice40 $pnr --json "$out/$name.json" --freq $freq --seed $seed --timing-allow-fail \
        --asc "$out/$name.asc" -l "$out/$name.nextpnr.log" -q >/dev/null 2>&1 \
        || { echo "ice40.sh: nextpnr failed for $name, see $out/$name.nextpnr.log" >&2; exit 1; }
    local log=$out/$name.nextpnr.log
    local lc ram fmax
    lc=$(grep -P '^Info:\s+ICESTORM_LC:' "$log" | tail -1 | awk '{print $3 $4}')
    ram=$(grep -P '^Info:\s+ICESTORM_RAM:' "$log" | tail -1 | awk '{print $3 $4}')
    fmax=$(grep 'Max frequency for clock' "$log" | tail -1 | sed -E 's/.*: ([0-9.]+ MHz) \((PASS|FAIL).*/\1 (\2 at '"$freq"' MHz)/')
    printf '%-12s LCs %-10s RAM %-6s Fmax %s\n' "$name" "$lc" "$ram" "$fmax"
}

run UP5K-SG48  u  "--up5k --package sg48"  gradient_up5k_sg48
run HX8K-CT256 hx "--hx8k --package ct256" gradient
echo "ice40.sh: logs and netlists in $out" >&2
