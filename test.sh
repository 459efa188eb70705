#!/usr/bin/env bash
# README command two: every test. Host Release and ASan+UBSan builds (Catch2, golden vectors,
# Icarus Verilog benches, yosys for the bounded proof of the HDL stream rules), the Cortex-M4
# (soft and hard float) and M3 firmware under qemu-system-arm, and the aarch64 build of the test
# suite under qemu-aarch64. opencv-doc and netpbm: the real photographs some tests composite
# boards onto (converted at build time; never needed at runtime).
set -euo pipefail
cd "$(dirname "$0")"
source platform/ensure_packages.sh
ensure_packages cmake make g++ catch2 iverilog gcc-arm-none-eabi libnewlib-arm-none-eabi \
    libstdc++-arm-none-eabi-newlib qemu-system-arm g++-aarch64-linux-gnu qemu-user \
    opencv-doc netpbm clang-format yosys
jobs=$(nproc)
for preset in host host-sanitize cortex-m4 cortex-m4f cortex-m3 aarch64-linux; do
    echo "=== $preset"
    cmake --preset "$preset" >/dev/null
    cmake --build --preset "$preset" -j"$jobs"
    ctest --preset "$preset" -j"$jobs"
done
