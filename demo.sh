#!/usr/bin/env bash
# README command one: build the CLI and run the demo on its built-in synthetic scene.
# Pictures go to demo_out/ (open the .png files).
set -euo pipefail
cd "$(dirname "$0")"
source platform/ensure_packages.sh
ensure_packages cmake make g++ catch2
cmake --preset host >/dev/null
cmake --build --preset host --target quadtrack -j"$(nproc)" >/dev/null
./build/host/platform/cli/quadtrack demo --out demo_out
