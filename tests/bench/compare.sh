#!/usr/bin/env bash
# Kerf against its peers, each pair in one run, interleaved, R times (issue 13): prints min /
# median / max of both and the ratio of the medians. Figures, not tests: the machines are shared.
#   tests/bench/compare.sh BUILD_DIR [R]
# Pairs so far:
#   self-intersection of a star of long spikes (kerf_bench --shape star: Kerf's findSelfIntersections
#   as kerf check runs it) against CGAL's is_simple_2 (tests/bench/cgal_is_simple.cpp, built here
#   against Debian's libcgal-dev), 1e4, 1e5 and 1e6 vertices.
#   kerf check against LinuxCNC's rs274 -g (the standalone interpreter, Debian's linuxcnc-uspace)
#   on the 6.1 MB benchmark program (kerf_bench --blocks 200000 --write): wall time and peak
#   memory (GNU time), both reading, interpreting and (Kerf) checking the whole program; then Kerf
#   once on the same kind of program ten times as long, for the memory's slope (bytes per input
#   byte without the fixed amount).
#   kerf check against rs274 -g on a tangled walk (kerf_bench --shape crossing --blocks 200000
#   --write: random lines and arcs, R of both signs and I J up to nearly full turns, G90/G91
#   switching, crossing itself many thousands of times): the same pair on a program that is not
#   regular, and whose self-intersections must be reported, not only found. KERF_COMPARE_CROSSING=0 skips it.
#   kerf check of issue 13's 200 MB program (kerf_bench --shape spiral, 10 M modal X Y lines; no peer:
#   its target is 2 GB of memory), once: wall time and peak memory. KERF_COMPARE_SPIRAL=N sets the
#   lines (0 skips it).
#   kerf render of the render benchmark's part from its NC file (kerf_bench_render --write: read,
#   check, mesh 1,000,000 triangles, draw 1024x768 with OSMesa, PNG) against f3d drawing the same
#   mesh from a ready STL (kerf export, not timed) at 1024x768 under xvfb-run; f3d alone is timed
#   (inside xvfb-run, so the X server's start is not counted against it).
#   the 3D page of the render benchmark's part (kerf export part.nc -o part.html at the same 0.002 mm:
#   1,000,000 triangles exact, sent at the window's coarse level), in Debian's headless Chromium
#   (tests/browser/pages.mjs orbit, WebGL on SwiftShader, 1280x800): the page's size, the export's
#   wall time, and the frame rate of a scripted full turn of 120 frames; then once the exact million
#   triangles on the page (--page-triangles), 4 frames; no peer (no other tool makes such a page).
#   KERF_COMPARE_PAGE=0 skips it.
#   kerf check of a folder of 1,000 programs (the real corpus's programs and drawings copied in turn,
#   KERF_COMPARE_REALWORLD points at it; KERF_COMPARE_BATCH=0 skips it) in one call against 1,000
#   separate calls (issue 14): wall time.
# KERF_COMPARE_BASELINE=PATH: another build's kerf program (an earlier commit) timed in the same
# interleave on both check programs, for a change's before and after.
# KERF_COMPARE_STARS (a list of sizes, " " for none), KERF_COMPARE_RENDER=0, KERF_COMPARE_PAGE=0, KERF_COMPARE_READER=0,
# KERF_COMPARE_SPIRAL=0 and KERF_COMPARE_BATCH=0 leave pairs out.
set -euo pipefail
export LC_ALL=C  # $EPOCHREALTIME and awk with a decimal point, whatever the locale
if ((BASH_VERSINFO[0] < 5)); then
  echo "compare.sh: needs bash 5 or later (\$EPOCHREALTIME)" >&2
  exit 2
fi
build=${1:?usage: compare.sh BUILD_DIR [R]}
runs=${2:-5}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ ! -f /usr/include/CGAL/Polygon_2_algorithms.h ]]; then
  echo "compare.sh: CGAL is not installed (apt-get install libcgal-dev)" >&2
  exit 2
fi
g++ -std=c++17 -O2 -DNDEBUG "$here/cgal_is_simple.cpp" -o "$work/cgal_is_simple" -lgmp -lmpfr

stats() {  # min median max of the numbers on stdin, to $1 decimals (3 unless given)
  sort -g | awk -v d="${1:-3}" '{v[NR]=$1} END {f = "%." d "f"; printf f " " f " " f "\n", v[1], (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2), v[NR]}'
}
echo "# self-intersection (kerf_bench --shape star, Kerf's auto method) against CGAL is_simple_2"
for n in ${KERF_COMPARE_STARS:-10000 100000 1000000}; do
  : > "$work/kerf" && : > "$work/cgal"
  for ((r = 0; r < runs; ++r)); do
    "$build/tests/kerf_bench" --shape star --blocks "$n" --repeat 1 --sweeps auto |
      awk '/^self-intersection:/ {print $2}' >> "$work/kerf"
    "$work/cgal_is_simple" "$n" | awk '{print $3}' >> "$work/cgal"
  done
  # Both time the test alone to the microsecond: a 1e4 star takes 3 ms, a step of 1 ms a third of it.
  read -r kmin kmed kmax < <(stats 4 < "$work/kerf")
  read -r cmin cmed cmax < <(stats 4 < "$work/cgal")
  printf "star %8d vertices: kerf %s / %s / %s s   cgal is_simple_2 %s / %s / %s s   kerf/cgal %.2f\n" \
    "$n" "$kmin" "$kmed" "$kmax" "$cmin" "$cmed" "$cmax" "$(awk -v a="$kmed" -v b="$cmed" 'BEGIN {print a / b}')"
done

# clock OUT CMD...: appends the wall seconds of one run of CMD to OUT (stdout and stderr dropped),
# to the microsecond from bash's own clock ($EPOCHREALTIME) around the command alone. The clock
# read by starting `date`, and GNU time around the command, put those programs' start-up inside
# every figure (about 2.5 and 2 ms, a twentieth of a run of kerf check each, the same for both
# tools, so the ratio came out smaller than it is).
clock() {
  local out=$1 t0 t1
  shift
  t0=$EPOCHREALTIME
  "$@" > /dev/null 2>&1 || true
  t1=$EPOCHREALTIME
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.4f\n", b - a}' >> "$out"
}
# peak OUT CMD...: appends the peak memory (KiB, GNU time) of one run of CMD to OUT: runs of their
# own, interleaved with the timed ones.
peak() {
  local out=$1
  shift
  /usr/bin/time -f "%M" -o "$work/mem" "$@" > /dev/null 2>&1 || true
  tail -1 "$work/mem" >> "$out"
}
stats_pair() {  # label, file of "seconds KiB" lines -> "min / median / max s, median MiB"
  read -r a b c < <(cut -d' ' -f1 "$1" | stats)
  read -r _ m _ < <(cut -d' ' -f2 "$1" | stats)
  printf "%s / %s / %s s, %.0f MiB" "$a" "$b" "$c" "$(awk -v k="$m" 'BEGIN {print k / 1024}')"
}
if [[ "${KERF_COMPARE_RENDER:-1}" != 0 ]] && command -v f3d > /dev/null && command -v xvfb-run > /dev/null && [[ -x "$build/tests/kerf_bench_render" ]]; then
  echo "# kerf render from the NC file against f3d from a ready STL, 1,000,000 triangles, 1024x768"
  "$build/tests/kerf_bench_render" --repeat 1 --write "$work/part.nc" > /dev/null
  "$build/viewer/kerf" export "$work/part.nc" --mesh-tolerance 0.002 -o "$work/part.stl" 2> /dev/null
  : > "$work/kr" && : > "$work/fr"
  for ((r = 0; r < runs; ++r)); do
    /usr/bin/time -f "%e %M" -o "$work/t" "$build/viewer/kerf" render "$work/part.nc" --mesh-tolerance 0.002 \
      --size 1024x768 -o "$work/k.png" 2> /dev/null
    cat "$work/t" >> "$work/kr"
    xvfb-run -a -s "-screen 0 1280x800x24" /usr/bin/time -f "%e %M" -o "$work/t" f3d "$work/part.stl" \
      --output "$work/f.png" --resolution 1024,768 > /dev/null 2>&1
    cat "$work/t" >> "$work/fr"
  done
  printf "render: kerf %s   f3d %s   kerf/f3d %.2f\n" "$(stats_pair "$work/kr")" "$(stats_pair "$work/fr")" \
    "$(awk -v a="$(cut -d' ' -f1 "$work/kr" | stats | cut -d' ' -f2)" -v b="$(cut -d' ' -f1 "$work/fr" | stats | cut -d' ' -f2)" 'BEGIN {print a / b}')"
else
  echo "compare.sh: the picture pair is skipped (KERF_COMPARE_RENDER=0, or f3d or xvfb-run is not installed: apt-get install f3d xvfb)" >&2
fi

tools=${KERF_TEST_TOOLS:-/opt/kerf-test-tools}
if [[ "${KERF_COMPARE_PAGE:-1}" != 0 ]] && command -v chromium > /dev/null && [[ -d "$tools/node_modules/puppeteer-core" ]]; then
  echo "# the 3D page of the render benchmark's part (1,000,000 triangles at 0.002 mm), orbited in headless Chromium"
  [[ -f "$work/part.nc" ]] || "$build/tests/kerf_bench_render" --repeat 1 --write "$work/part.nc" > /dev/null
  : > "$work/pe" && : > "$work/pf"
  for ((r = 0; r < runs; ++r)); do
    /usr/bin/time -f "%e %M" -o "$work/t" "$build/viewer/kerf" export "$work/part.nc" --mesh-tolerance 0.002 \
      -o "$work/part.html" 2> "$work/export.log"
    cat "$work/t" >> "$work/pe"
    KERF_TEST_TOOLS="$tools" node "$here/../browser/pages.mjs" orbit "$work/part.html" 120 |
      awk -F'[:,}]' '{for (i = 1; i < NF; ++i) if ($i ~ /"fps"/) print $(i + 1)}' >> "$work/pf"
  done
  grep -o "wrote the 3D page.*" "$work/export.log" | sed 's/^/page: /'
  printf "page: %.1f MiB; export %s; orbit %s frames/s (min / median / max)\n" \
    "$(awk -v b="$(stat -c %s "$work/part.html")" 'BEGIN {print b / 1048576}')" "$(stats_pair "$work/pe")" \
    "$(stats 1 < "$work/pf" | sed 's/ / \/ /g')"
  # Once, what the budget spares the browser: the exact million triangles on the page.
  "$build/viewer/kerf" export "$work/part.nc" --mesh-tolerance 0.002 --page-triangles 2000000 -o "$work/exact.html" 2> /dev/null
  printf "page, exact (--page-triangles 2000000): %s\n" \
    "$(KERF_TEST_TOOLS="$tools" node "$here/../browser/pages.mjs" orbit "$work/exact.html" 4)"
else
  echo "compare.sh: the page is skipped (KERF_COMPARE_PAGE=0, or chromium or puppeteer-core is not installed: .ci/install-deps.sh --tests)" >&2
fi

if [[ "${KERF_COMPARE_READER:-1}" != 0 ]] && command -v rs274 > /dev/null; then
  echo "# kerf check against rs274 -g, 6.1 MB program (200,000 blocks): wall s, peak MiB"
  "$build/tests/kerf_bench" --blocks 200000 --write "$work/program.ngc" > /dev/null
  bytes=$(stat -c %s "$work/program.ngc")
  baseline=${KERF_COMPARE_BASELINE:-}
  : > "$work/kt" && : > "$work/km" && : > "$work/rt" && : > "$work/rm" && : > "$work/bt" && : > "$work/bm"
  for ((r = 0; r < runs; ++r)); do
    clock "$work/kt" "$build/viewer/kerf" check "$work/program.ngc"
    clock "$work/rt" rs274 -g "$work/program.ngc" /dev/null
    if [[ -n "$baseline" ]]; then clock "$work/bt" "$baseline" check "$work/program.ngc"; fi
    peak "$work/km" "$build/viewer/kerf" check "$work/program.ngc"
    peak "$work/rm" rs274 -g "$work/program.ngc" /dev/null
    if [[ -n "$baseline" ]]; then peak "$work/bm" "$baseline" check "$work/program.ngc"; fi
  done
  read -r kmin kmed kmax < <(stats 4 < "$work/kt")
  read -r rmin rmed rmax < <(stats 4 < "$work/rt")
  read -r _ kmem _ < <(stats < "$work/km")
  read -r _ rmem _ < <(stats < "$work/rm")
  printf "check %d bytes: kerf %s / %s / %s s, %.0f MiB   rs274 -g %s / %s / %s s, %.0f MiB   rs274/kerf %.1f   kerf bytes of memory per input byte %.1f\n" \
    "$bytes" "$kmin" "$kmed" "$kmax" "$(awk -v k="$kmem" 'BEGIN {print k / 1024}')" "$rmin" "$rmed" "$rmax" \
    "$(awk -v k="$rmem" 'BEGIN {print k / 1024}')" "$(awk -v a="$rmed" -v b="$kmed" 'BEGIN {print a / b}')" \
    "$(awk -v k="$kmem" -v b="$bytes" 'BEGIN {print k * 1024 / b}')"
  if [[ -n "$baseline" ]]; then
    read -r bmin bmed bmax < <(stats 4 < "$work/bt")
    read -r _ bmem _ < <(stats < "$work/bm")
    printf "  baseline %s: %s / %s / %s s, %.0f MiB   kerf/baseline %.2f\n" "$baseline" "$bmin" "$bmed" "$bmax" \
      "$(awk -v k="$bmem" 'BEGIN {print k / 1024}')" "$(awk -v a="$kmed" -v b="$bmed" 'BEGIN {print a / b}')"
  fi
  if [[ "${KERF_COMPARE_CROSSING:-1}" != 0 ]]; then
    "$build/tests/kerf_bench" --shape crossing --blocks 200000 --write "$work/crossing.ngc" > /dev/null
    cbytes=$(stat -c %s "$work/crossing.ngc")
    : > "$work/ct" && : > "$work/crt" && : > "$work/cbt"
    for ((r = 0; r < runs; ++r)); do
      clock "$work/ct" "$build/viewer/kerf" check "$work/crossing.ngc"
      clock "$work/crt" rs274 -g "$work/crossing.ngc" /dev/null
      if [[ -n "$baseline" ]]; then clock "$work/cbt" "$baseline" check "$work/crossing.ngc"; fi
    done
    read -r kmin kmed kmax < <(stats 4 < "$work/ct")
    read -r rmin rmed rmax < <(stats 4 < "$work/crt")
    printf "check %d bytes, crossing itself: kerf %s / %s / %s s   rs274 -g %s / %s / %s s   rs274/kerf %.1f\n" \
      "$cbytes" "$kmin" "$kmed" "$kmax" "$rmin" "$rmed" "$rmax" "$(awk -v a="$rmed" -v b="$kmed" 'BEGIN {print a / b}')"
    if [[ -n "$baseline" ]]; then
      read -r bmin bmed bmax < <(stats 4 < "$work/cbt")
      printf "  baseline: %s / %s / %s s   kerf/baseline %.2f\n" "$bmin" "$bmed" "$bmax" \
        "$(awk -v a="$kmed" -v b="$bmed" 'BEGIN {print a / b}')"
    fi
  fi
  # "Bytes per input byte plus a fixed amount": the slope between this program and one of the
  # same kind ten times as long, so no fixed cost (libraries, tables) is counted in it.
  "$build/tests/kerf_bench" --blocks 2000000 --write "$work/program10.ngc" > /dev/null
  bytes10=$(stat -c %s "$work/program10.ngc")
  /usr/bin/time -f "%e %M" -o "$work/t" "$build/viewer/kerf" check "$work/program10.ngc" > /dev/null
  read -r _ m10 < "$work/t"
  rm -f "$work/program10.ngc"
  printf "check %d bytes, once: %.0f MiB; bytes of memory per input byte between the two sizes %.2f\n" \
    "$bytes10" "$(awk -v k="$m10" 'BEGIN {print k / 1024}')" \
    "$(awk -v a="$kmem" -v b="$m10" -v x="$bytes" -v y="$bytes10" 'BEGIN {print (b - a) * 1024 / (y - x)}')"
else
  echo "compare.sh: the reader pair is skipped (KERF_COMPARE_READER=0, or rs274 is not installed: apt-get install linuxcnc-uspace)" >&2
fi

spiral=${KERF_COMPARE_SPIRAL:-10000000}
if [[ "$spiral" != 0 ]]; then
  echo "# kerf check of the spiral program ($spiral lines), once: wall s, peak memory"
  "$build/tests/kerf_bench" --shape spiral --blocks "$spiral" --write "$work/spiral.nc" > /dev/null
  bytes=$(stat -c %s "$work/spiral.nc")
  # An open path: one warning (K0605), exit 0.
  /usr/bin/time -f "%e %M" -o "$work/t" "$build/viewer/kerf" check "$work/spiral.nc" > /dev/null 2>&1
  read -r t m < "$work/t"
  printf "spiral %d bytes: kerf check %s s, %d KiB (%.2f GB)\n" "$bytes" "$t" "$m" "$(awk -v k="$m" 'BEGIN {print k * 1024 / 1e9}')"
fi

realworld=${KERF_COMPARE_REALWORLD:-$here/../../../shared/realworld}
if [[ "${KERF_COMPARE_BATCH:-1}" != 0 && -d "$realworld" ]]; then
  echo "# kerf check of a folder of 1,000 programs (the real corpus copied in turn): one call against 1,000 calls, wall s"
  mapfile -t sources < <(find "$realworld" -type f \( -iname '*.nc' -o -iname '*.ngc' -o -iname '*.iso' -o -iname '*.gcode' \
    -o -iname '*.dxf' \) | sort)
  mkdir -p "$work/batch"
  for ((i = 0; i < 1000; ++i)); do
    src=${sources[i % ${#sources[@]}]}
    cp "$src" "$work/batch/$(printf %04d "$i")_$(basename "$src")"
  done
  : > "$work/bt" && : > "$work/st"
  for ((r = 0; r < runs; ++r)); do
    # The folder holds programs with errors: GNU time then writes "Command exited with non-zero
    # status 1" before the figure, so the last line is the figure.
    /usr/bin/time -f "%e" -o "$work/t" "$build/viewer/kerf" check "$work/batch" --quiet > /dev/null 2>&1 || true
    tail -n 1 "$work/t" >> "$work/bt"
    start=$EPOCHREALTIME
    for f in "$work/batch"/*; do "$build/viewer/kerf" check "$f" --quiet > /dev/null 2>&1 || true; done
    awk -v a="$EPOCHREALTIME" -v b="$start" 'BEGIN {printf "%.3f\n", a - b}' >> "$work/st"
  done
  printf "batch of 1000 files: one call %s   1000 calls %s   one/many %.2f\n" "$(stats < "$work/bt" | tr ' ' '/')" \
    "$(stats < "$work/st" | tr ' ' '/')" \
    "$(awk -v a="$(stats < "$work/bt" | cut -d' ' -f2)" -v b="$(stats < "$work/st" | cut -d' ' -f2)" 'BEGIN {print a / b}')"
fi
