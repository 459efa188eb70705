#!/usr/bin/env bash
# Synthesis and place-and-route of the gradient block (hdl/rtl/gradient.v) and the front end
# (hdl/rtl/frontend.v: gradient + edge stage) for iCE40 UP5K and HX8K, MAX_WIDTH 640 (and the
# gradient block at 1280 on HX8K: what a 1280-wide line costs), against the clock constraint in
# ice40_clock.py (aclk 100 MHz). Each placement runs over SEEDS seeds; one line per block and
# device: logic cells, block RAMs, Fmax min / median over the seeds. The tool versions first.
#
#   bash hdl/synth/ice40.sh [BUILD_DIR]      (default: a new temporary directory)
#   SEEDS="1 2 3" (default) the nextpnr placement seeds
#
# yosys synth_ice40 -abc9, nextpnr-ice40. The UP5K SG48 package has 39 I/O pins, fewer than the
# blocks' ports, so on UP5K each block sits in a wrapper with no logic of its own that feeds the
# cfg_* registers from low bits of m_axis_tdata (which then need no pins); HX8K CT256 takes the
# ports directly.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
hdl=$(cd "$here/.." && pwd)
out=${1:-$(mktemp -d "${TMPDIR:-/tmp}/qt_ice40.XXXXXX")}
mkdir -p "$out"
seeds=${SEEDS:-1 2 3}

for tool in yosys nextpnr-ice40; do
    command -v "$tool" >/dev/null || { echo "ice40.sh: $tool not found" >&2; exit 1; }
done
echo "tools: $(yosys -V | head -1); $(nextpnr-ice40 --version 2>&1 | head -1)"
echo "seeds: $seeds; constraint: aclk 100 MHz (hdl/synth/ice40_clock.py)"

rtl=$hdl/rtl
src=("$rtl/frontend.v" "$rtl/gradient.v" "$rtl/edge_stage.v" "$rtl/axis_slice.v"
     "$rtl/gradient_dir_fold.v" "$rtl/gradient_dir_s51.v" "$rtl/gradient_dir_bin.v"
     "$rtl/gradient_direction.v")

# No latches anywhere in the design (elaborated RTL).
yosys -q -l "$out/latch_check.log" -p "read_verilog -I$rtl ${src[*]}; hierarchy -top frontend;
    proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr" \
    >/dev/null || { echo "ice40.sh: latch check failed, see $out/latch_check.log" >&2; exit 1; }

cat > "$out/wrappers.v" <<'VERILOG'
// Pin-count wrappers for UP5K SG48 (see ice40.sh): no logic, only wiring.
module gradient_sg48 (
    input  wire aclk, aresetn, input wire [7:0] s_tdata, input wire s_tuser, s_tlast, s_tvalid,
    output wire s_tready, output wire [15:0] m_tdata_hi, output wire [1:0] m_tuser,
    output wire m_tlast, m_tvalid, input wire m_tready, output wire error);
    wire [31:0] m_tdata;
    gradient #(.MAX_WIDTH(640)) u (.aclk(aclk), .aresetn(aresetn), .cfg_height(m_tdata[15:0]),
        .s_axis_tdata(s_tdata), .s_axis_tuser(s_tuser), .s_axis_tlast(s_tlast),
        .s_axis_tvalid(s_tvalid), .s_axis_tready(s_tready), .m_axis_tdata(m_tdata),
        .m_axis_tuser(m_tuser), .m_axis_tlast(m_tlast), .m_axis_tvalid(m_tvalid),
        .m_axis_tready(m_tready), .error(error));
    assign m_tdata_hi = m_tdata[31:16];
endmodule
module frontend_sg48 (
    input  wire aclk, aresetn, input wire [7:0] s_tdata, input wire s_tuser, s_tlast, s_tvalid,
    output wire s_tready, output wire [15:0] m_tdata_hi, output wire m_tuser, m_tlast, m_tvalid,
    input wire m_tready, output wire error);
    wire [47:0] m_tdata;
    frontend #(.MAX_WIDTH(640)) u (.aclk(aclk), .aresetn(aresetn), .cfg_height(m_tdata[15:0]),
        .cfg_threshold(m_tdata[24:16]), .s_axis_tdata(s_tdata), .s_axis_tuser(s_tuser),
        .s_axis_tlast(s_tlast), .s_axis_tvalid(s_tvalid), .s_axis_tready(s_tready),
        .m_axis_tdata(m_tdata), .m_axis_tuser(m_tuser), .m_axis_tlast(m_tlast),
        .m_axis_tvalid(m_tvalid), .m_axis_tready(m_tready), .error(error));
    assign m_tdata_hi = m_tdata[47:32];
endmodule
VERILOG

# name  block  MAX_WIDTH  yosys -device  nextpnr device/package  wrapper ("" for none)
run() {
    local name=$1 block=$2 width=$3 ydev=$4 pnr=$5 wrap=$6
    local top=$block json=$out/$name.json
    local read="read_verilog -I$rtl ${src[*]}; chparam -set MAX_WIDTH $width $block;"
    if [ -n "$wrap" ]; then
        top=$wrap
        read="read_verilog -I$rtl ${src[*]} $out/wrappers.v;"
    fi
    yosys -q -l "$out/$name.yosys.log" -p "$read
        synth_ice40 -top $top -abc9 -device $ydev; check -assert; write_json $json" >/dev/null \
        || { echo "ice40.sh: yosys failed for $name, see $out/$name.yosys.log" >&2; exit 1; }
    local fmaxes=() lc="" ram="" seed log
    for seed in $seeds; do
        log=$out/$name.s$seed.nextpnr.log
        # shellcheck disable=SC2086
        nextpnr-ice40 $pnr --json "$json" --pre-pack "$here/ice40_clock.py" --seed "$seed" \
            --timing-allow-fail --asc "$out/$name.s$seed.asc" -l "$log" -q >/dev/null 2>&1 \
            || { echo "ice40.sh: nextpnr failed for $name seed $seed, see $log" >&2; exit 1; }
        lc=$(grep -P '^Info:\s+ICESTORM_LC:' "$log" | tail -1 | awk '{print $3 $4}')
        ram=$(grep -P '^Info:\s+ICESTORM_RAM:' "$log" | tail -1 | awk '{print $3 $4}')
        fmaxes+=("$(grep 'Max frequency for clock' "$log" | tail -1 |
                    sed -E 's/.*: ([0-9.]+) MHz.*/\1/')")
    done
    local sorted n
    mapfile -t sorted < <(printf '%s\n' "${fmaxes[@]}" | sort -g)
    n=${#sorted[@]}
    printf '%-22s LCs %-10s RAM %-6s Fmax min %s median %s MHz (%d seeds)\n' "$name" "$lc" \
        "$ram" "${sorted[0]}" "${sorted[$((n / 2))]}" "$n"
}

run gradient-640-UP5K  gradient 640  u  "--up5k --package sg48"  gradient_sg48
run gradient-640-HX8K  gradient 640  hx "--hx8k --package ct256" ""
run gradient-1280-HX8K gradient 1280 hx "--hx8k --package ct256" ""
run frontend-640-UP5K  frontend 640  u  "--up5k --package sg48"  frontend_sg48
run frontend-640-HX8K  frontend 640  hx "--hx8k --package ct256" ""
echo "ice40.sh: logs and netlists in $out" >&2
