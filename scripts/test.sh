#!/usr/bin/env bash
# Installs what Tessera needs, checks the formatting, builds everything, and runs the whole test
# suite twice: an optimized build (unit tests, command-line tests, examples, downstream consumer of
# the installed package) and an AddressSanitizer + UndefinedBehaviorSanitizer build of the unit
# tests; then runs each fuzz target for 20 s.
set -euo pipefail
# ccache keys on paths relative to the checkout, so clones in other directories share its cache.
export CCACHE_BASEDIR="$(cd "$(dirname "$0")/.." && pwd)"
# and leaves the working directory out of the hash of builds with debug information (the sanitizer
# build's -g1), which would otherwise tie its entries to one clone's path.
export CCACHE_NOHASHDIR=true
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)

# The tree is formatted with clang-format (.clang-format at the root); a file that is not fails here.
find include src tests examples benchmarks fuzz \( -name '*.h' -o -name '*.cpp' \) -print0 |
  xargs -0 clang-format --dry-run --Werror

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
(cd build && ctest --output-on-failure -j"$jobs")

# -O0 -g1: line tables only. With the sanitizers, -O1 doubles the compile time of CGAL's translation
# units (210 s against 110 s for tests/fields/features.cpp) for a test run 3-4 times shorter (2.4
# minutes at -O1 on one core): the build is what costs. No NDEBUG, so CGAL's and Tessera's
# preconditions are checked too. The unit tests only: the command-line tool's ten CGAL translation
# units would add half again to this build for argument parsing over the same library calls; its
# error paths run in the optimized build above, and its readers under the sanitizers in the fuzzers.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -g1" \
  -DTESSERA_SANITIZE=ON -DTESSERA_BUILD_CLI=OFF \
  -DTESSERA_BUILD_EXAMPLES=OFF -DTESSERA_BUILD_BENCHMARKS=OFF
cmake --build build-asan -j"$jobs"
# fontconfig (used by cairo to draw picture titles) keeps its caches until exit by design.
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS="suppressions=$PWD/../tests/lsan.supp" ctest --output-on-failure -j"$jobs")

# Fuzz smoke: each libFuzzer target of fuzz/ for 20 s on its seed corpus (clang, ASan + UBSan).
bash scripts/fuzz.sh 20
