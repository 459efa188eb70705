#!/usr/bin/env bash
# README command two: every test. Host Release and ASan+UBSan builds (Catch2, golden vectors,
# Icarus Verilog benches, yosys for the bounded proof of the HDL stream rules), the Cortex-M4
# (soft and hard float) and M3 firmware under qemu-system-arm, and the aarch64 build of the test
# suite under qemu-aarch64. opencv-doc and netpbm: the real photographs some tests composite
# boards onto (converted at build time; never needed at runtime); ccache: repeated builds.
# Tests labelled long (the full-frame HDL runs with stalls, the deep proof, the [slow] cases
# under qemu-aarch64) are left to `bash bench.sh long`. Ends with one line per preset: build and
# test seconds, the slowest tests.
set -euo pipefail
cd "$(dirname "$0")"
source platform/ensure_packages.sh
ensure_packages cmake make g++ catch2 iverilog gcc-arm-none-eabi libnewlib-arm-none-eabi \
    libstdc++-arm-none-eabi-newlib qemu-system-arm g++-aarch64-linux-gnu qemu-user \
    opencv-doc netpbm clang-format yosys ccache
jobs=$(nproc)
summary=()
start=$SECONDS
for preset in host host-sanitize cortex-m4 cortex-m4f cortex-m3 aarch64-linux; do
    echo "=== $preset"
    t0=$SECONDS
    cmake --preset "$preset" >/dev/null
    cmake --build --preset "$preset" -j"$jobs"
    t1=$SECONDS
    log="build/$preset/ctest.log"
    ctest --preset "$preset" -j"$jobs" | tee "$log"
    # ctest prints "Test #N: NAME ....   Passed   1.23 sec"; the three slowest, seconds.
    slowest=$(sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: (.*[^ .]) \.+ *Passed +([0-9.]+) sec$/\2 \1/p' "$log" |
        sort -rn | awk 'NR <= 3 { s = $1; $1 = ""; printf "%s%s %.0f s", sep, substr($0, 2, 40), s; sep = ", " }')
    summary+=("$(printf '%-14s build %4d s  tests %4d s  slowest: %s' "$preset" $((t1 - t0)) \
        $((SECONDS - t1)) "$slowest")")
done
echo "=== time, seconds (wall clock, $jobs jobs)"
printf '%s\n' "${summary[@]}"
echo "total $((SECONDS - start)) s"
