#!/usr/bin/env bash
# Installs what Tessera needs, builds it, and runs the main job on the built-in default input
# (a generated genus-2 surface), writing its results and pictures into ./tessera-demo.
set -euo pipefail
# ccache keys on paths relative to the checkout, so clones in other directories share its cache.
export CCACHE_BASEDIR="$(cd "$(dirname "$0")/.." && pwd)"
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --target tessera_cli -j"$jobs"
./build/tessera demo --out "${1:-tessera-demo}"
