#!/usr/bin/env bash
# Instructions `kerf check` executes on the benchmark programs, counted by valgrind's callgrind
# (every thread summed): figures that do not move from run to run on a shared machine (issue 58).
# Prints the total and, inclusive, the pipeline's phases: reading and parsing (readForMachine),
# interpreting (interpretForMachine), the checks and the summary (runChecks), and within the
# checks the self-intersection sweep.
#   tests/bench/count_instructions.sh BUILD_DIR [PROGRAM...]
# Without programs: the 6.1 MB benchmark program (kerf_bench --blocks 200000 --write) and the
# crossing program (kerf_bench --shape crossing --blocks 200000 --write), generated here.
# KERF=path/to/kerf counts another build's program (an earlier commit's) on the same files.
# kerf runs on one thread (KERF_THREADS=1): the total is the same work, and each phase's count is
# then its own (with two, a worker thread's share lands outside the phase that started it, and
# differently from run to run on a busy machine).
set -euo pipefail
export LC_ALL=C
build=${1:?usage: count_instructions.sh BUILD_DIR [PROGRAM...]}
shift
kerf=${KERF:-$build/viewer/kerf}
command -v valgrind > /dev/null || { echo "count_instructions.sh: valgrind is not installed" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
programs=("$@")
if ((${#programs[@]} == 0)); then
  "$build/tests/kerf_bench" --blocks 200000 --write "$work/benchmark.nc" > /dev/null
  "$build/tests/kerf_bench" --shape crossing --blocks 200000 --write "$work/crossing.nc" > /dev/null
  programs=("$work/benchmark.nc" "$work/crossing.nc")
fi

millions() { awk '{printf "%.0f M", $1 / 1e6}'; }
# The inclusive count of the first function whose name holds $2, in callgrind_annotate's output $1.
phase() { awk -v f="$2" 'index($0, f) && $1 ~ /^[0-9,]+$/ {gsub(",", "", $1); print $1; exit}' "$1"; }

for program in "${programs[@]}"; do
  out="$work/callgrind.out"
  rm -f "$out"*
  KERF_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$out" "$kerf" check "$program" > /dev/null 2>&1 || true
  callgrind_annotate --inclusive=yes --threshold=100 "$out" > "$work/annotated" 2> /dev/null
  total=$(awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1; exit}' "$work/annotated")
  printf "%s: %s" "$(basename "$program")" "$(echo "$total" | millions)"
  for p in readForMachine interpretForMachine runChecks findSelfIntersections; do
    n=$(phase "$work/annotated" "$p")
    [[ -n "$n" ]] && printf ", %s %s" "$p" "$(echo "$n" | millions)"
  done
  printf "\n"
done
