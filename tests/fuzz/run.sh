#!/usr/bin/env bash
# Runs the libFuzzer target for a while:  tests/fuzz/run.sh [SECONDS=60]
# Builds with clang into build-fuzz/, starts from samples, the bad corpus and tests/fuzz/corpus,
# keeps new interesting inputs in build-fuzz/corpus and crashers in tests/fuzz/crashers/.
# A crasher, once fixed, goes into tests/bad/ with its expected diagnostic on the first line
# (or into tests/fuzz/corpus/ when it is valid input), so CI replays it for ever.
set -euo pipefail
seconds="${1:-60}"
cd "$(dirname "$0")/../.."
CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKERF_BUILD_FUZZERS=ON \
  -DKERF_BUILD_BENCHMARKS=OFF -DKERF_SANITIZER=address,undefined >/dev/null
cmake --build build-fuzz --target kerf_fuzz -j"$(nproc)"
mkdir -p build-fuzz/corpus tests/fuzz/crashers
build-fuzz/tests/kerf_fuzz build-fuzz/corpus samples samples/bad tests/bad tests/fuzz/corpus \
  -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix=tests/fuzz/crashers/ -print_final_stats=1
