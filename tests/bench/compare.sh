#!/usr/bin/env bash
# Kerf against its peers, each pair in one run, interleaved, R times (issue 13): prints min /
# median / max of both and the ratio of the medians. Figures, not tests: the machines are shared.
#   tests/bench/compare.sh BUILD_DIR [R]
# Pairs so far:
#   self-intersection of a star of long spikes (kerf_bench --shape star: Kerf's findSelfIntersections
#   as kerf check runs it) against CGAL's is_simple_2 (tests/bench/cgal_is_simple.cpp, built here
#   against Debian's libcgal-dev), 1e4, 1e5 and 1e6 vertices.
# [Not yet: rs274 -g on a 6 MB program, f3d on a 1e6-triangle mesh.]
set -euo pipefail
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

stats() {  # min median max of the numbers on stdin
  sort -g | awk '{v[NR]=$1} END {printf "%.3f %.3f %.3f\n", v[1], (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2), v[NR]}'
}
for n in 10000 100000 1000000; do
  : > "$work/kerf" && : > "$work/cgal"
  for ((r = 0; r < runs; ++r)); do
    "$build/tests/kerf_bench" --shape star --blocks "$n" --repeat 1 |
      awk '/^self-intersection:/ {print $2}' >> "$work/kerf"
    "$work/cgal_is_simple" "$n" | awk '{print $3}' >> "$work/cgal"
  done
  read -r kmin kmed kmax < <(stats < "$work/kerf")
  read -r cmin cmed cmax < <(stats < "$work/cgal")
  printf "star %8d vertices: kerf %s / %s / %s s   cgal is_simple_2 %s / %s / %s s   kerf/cgal %.2f\n" \
    "$n" "$kmin" "$kmed" "$kmax" "$cmin" "$cmed" "$cmax" "$(awk -v a="$kmed" -v b="$cmed" 'BEGIN {print a / b}')"
done
