#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) and runs each for SECONDS (default 20) on a
# scratch copy of its seed corpus in fuzz/corpus/. A crash, a hang over 10 s or more than 2 GiB of
# memory fails the run and leaves the input in build-fuzz/artifacts-FORMAT/.
set -euo pipefail
seconds=${1:-20}
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1" -DTESSERA_FUZZ=ON -DTESSERA_BUILD_CLI=OFF \
  -DTESSERA_BUILD_TESTS=OFF -DTESSERA_BUILD_EXAMPLES=OFF -DTESSERA_BUILD_BENCHMARKS=OFF >/dev/null
formats=(off obj ply stl image cutting)
export UBSAN_OPTIONS="suppressions=$PWD/fuzz/ubsan.supp:print_stacktrace=1:halt_on_error=1"
cmake --build build-fuzz -j"$jobs" --target "${formats[@]/#/fuzz_read_}"
for format in "${formats[@]}"; do
  corpus=build-fuzz/corpus-$format artifacts=build-fuzz/artifacts-$format
  rm -rf "$corpus" "$artifacts" && mkdir -p "$corpus" "$artifacts"
  cp fuzz/corpus/"$format"/* "$corpus"/
  echo "fuzz_read_$format: ${seconds} s"
  # A fixed seed makes the smoke a regression check (the same mutations on every run, so a failure
  # means the code or the corpus changed); the 10-minute runs in doc/reliability.md explore.
  build-fuzz/fuzz/fuzz_read_"$format" "$corpus" -seed=1 -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -artifact_prefix="$artifacts/" -print_final_stats=1 2>&1 |
    grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ *DONE)|ERROR|SUMMARY" || true
  # libFuzzer writes an artifact for every crash, timeout or out-of-memory it finds.
  if compgen -G "$artifacts/*" >/dev/null; then
    echo "fuzz_read_$format found a failing input: $(ls "$artifacts")" >&2
    exit 1
  fi
done
