#!/usr/bin/env bash
# Installs what Tessera needs, builds everything, and runs the whole test suite twice: an optimized
# build (unit tests, command-line tests, examples, downstream consumer of the installed package) and
# an AddressSanitizer + UndefinedBehaviorSanitizer build of the unit and command-line tests; then
# runs each fuzz target for 20 s.
set -euo pipefail
# ccache keys on paths relative to the checkout, so clones in other directories share its cache.
export CCACHE_BASEDIR="$(cd "$(dirname "$0")/.." && pwd)"
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
(cd build && ctest --output-on-failure -j"$jobs")

# -O1 -g1: line tables only, which keeps CGAL's translation units quick to assemble; no NDEBUG, so
# CGAL's and Tessera's preconditions are checked too.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DTESSERA_SANITIZE=ON \
  -DTESSERA_BUILD_EXAMPLES=OFF -DTESSERA_BUILD_BENCHMARKS=OFF
cmake --build build-asan -j"$jobs"
# fontconfig (used by cairo to draw picture titles) keeps its caches until exit by design.
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS="suppressions=$PWD/../tests/lsan.supp" ctest --output-on-failure -j"$jobs")

# Fuzz smoke: each libFuzzer target of fuzz/ for 20 s on its seed corpus (clang, ASan + UBSan).
bash scripts/fuzz.sh 20
