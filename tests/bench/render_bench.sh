#!/usr/bin/env bash
# The rendering figures of the README in one run: headless picture of a ~1e6-triangle part at
# 1024x768 (context to PNG), then the window's frame time on the same part under xvfb-run.
#   tests/bench/render_bench.sh [BUILD_DIR]
set -euo pipefail
build="${1:-build}"
part="$(mktemp --suffix=.nc)"
trap 'rm -f "$part"' EXIT
"$build/tests/kerf_bench_render" --repeat 3 --write "$part"
xvfb-run -a -s "-screen 0 1280x800x24" "$build/viewer/kerf" view "$part" --mesh-tolerance 0.002 --size 1280x800 \
  --frames 60 --benchmark 2>&1 | grep "frame time"
xvfb-run -a -s "-screen 0 1280x800x24" "$build/viewer/kerf" view "$part" --mesh-tolerance 0.002 --size 1280x800 \
  --frames 60 --benchmark --coarse 2>&1 | grep "frame time"
