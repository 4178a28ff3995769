#!/usr/bin/env bash
# Runs a libFuzzer target for a while:  tests/fuzz/run.sh [SECONDS=60] [TARGET=pipeline]
# TARGET: pipeline (G-code and everything the pipeline reads, fuzz_pipeline.cpp), dxf, 3b, curve or
# profile (one reader each, fuzz_<TARGET>.cpp).
# Builds with clang into build-fuzz/, starts from samples, the bad corpus and tests/fuzz/corpus,
# keeps new interesting inputs in build-fuzz/corpus-TARGET and crashers in tests/fuzz/crashers/.
# A crasher, once fixed, goes into tests/bad/ with its expected diagnostic on the first line
# (or into tests/fuzz/corpus/ when it is valid input), so CI replays it for ever.
set -euo pipefail
seconds="${1:-60}"
target="${2:-pipeline}"
cd "$(dirname "$0")/../.."
binary=kerf_fuzz
[[ "$target" != pipeline ]] && binary="kerf_fuzz_$target"
seeds=(samples samples/bad tests/bad tests/fuzz/corpus)
case "$target" in
  pipeline | dxf | 3b | curve) ;;
  profile) seeds+=(converter/machines tests/passes) ;;
  *) echo "run.sh: TARGET is pipeline, dxf, 3b, curve or profile, not '$target'" >&2; exit 2 ;;
esac
[[ "$target" == dxf && -d ../shared/realworld/dxf ]] && seeds+=(../shared/realworld/dxf)
CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKERF_BUILD_FUZZERS=ON \
  -DKERF_BUILD_BENCHMARKS=OFF -DKERF_SANITIZER=address,undefined >/dev/null
cmake --build build-fuzz --target "$binary" -j"$(nproc)"
mkdir -p "build-fuzz/corpus-$target" tests/fuzz/crashers
"build-fuzz/tests/$binary" "build-fuzz/corpus-$target" "${seeds[@]}" \
  -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix=tests/fuzz/crashers/ -print_final_stats=1
