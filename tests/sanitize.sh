#!/usr/bin/env bash
# The tests labelled "sanitizer" (the readers, the interpreter and the checks on every bad-input file,
# the fuzz corpus, the samples, the golden programs and every real program and drawing) in a Debug
# build under AddressSanitizer + UndefinedBehaviorSanitizer. Not part of .ci/run: on the 2-core CI
# machine this build alone takes 16 to 24 minutes, as long as the whole CI run is allowed to take
# (docs/architecture.md, "The CI build").
# The build compiles each source on its own (no unity batches), so it also finds a file that
# compiles only beside the others in its batch.
#   tests/sanitize.sh [BUILD_DIR]     (default build-asan; needs .ci/install-deps.sh --tests)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build-asan}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DKERF_WERROR=ON -DKERF_SANITIZER=address,undefined \
  -DCMAKE_UNITY_BUILD=OFF
cmake --build "$build" -j"$(nproc)" --target kerf_sanitizer_tests
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -L sanitizer
