#!/usr/bin/env bash
# The rendering figures of the README in one run: headless picture of a ~1e6-triangle part at
# 1024x768 (context to PNG), kerf render of it end to end as a user runs it (it draws no piece
# narrower than a pixel), then the window's frame time on the same part under xvfb-run.
#   tests/bench/render_bench.sh [BUILD_DIR]
set -euo pipefail
build="${1:-build}"
part="$(mktemp --suffix=.nc)"
trap 'rm -f "$part"' EXIT
"$build/tests/kerf_bench_render" --repeat 3 --write "$part"
picture="$(mktemp --suffix=.png)"
trap 'rm -f "$part" "$picture"' EXIT
/usr/bin/time -f "kerf render end to end: %e s, %M KiB peak" "$build/viewer/kerf" render "$part" \
  --mesh-tolerance 0.002 --size 1024x768 -o "$picture" --timings 2>&1 | grep -E "^kerf"
xvfb-run -a -s "-screen 0 1280x800x24" "$build/viewer/kerf" view "$part" --mesh-tolerance 0.002 --size 1280x800 \
  --frames 60 --benchmark 2>&1 | grep "frame time"
xvfb-run -a -s "-screen 0 1280x800x24" "$build/viewer/kerf" view "$part" --mesh-tolerance 0.002 --size 1280x800 \
  --frames 60 --benchmark --coarse 2>&1 | grep "frame time"
