#!/bin/sh
# The pre-commit hook definition (.pre-commit-hooks.yaml), run by pre-commit itself (Debian's
# package pre-commit): in a scratch git repository, a clean program passes and a program with an
# error fails the hook with its file:line:col diagnostic.
#   precommit_test.sh SOURCE KERF_DIR WORK
set -eu
source=$1 kerfdir=$2 work=$3
rm -rf "$work" && mkdir -p "$work/repo"
export PATH="$kerfdir:$PATH" PRE_COMMIT_HOME="$work/cache" HOME="$work"
cd "$work/repo"
git init -q . && git config user.email t@example.invalid && git config user.name test
cp "$source/samples/punch_outline.nc" good.nc
printf 'G21 G90\nG92 X0 Y0\nG02 X10 Y0 R4\nM30\n' > bad.NC
echo 'not a program' > notes.md
git add good.nc bad.NC notes.md
# The hook on the clean file alone: passes.
pre-commit try-repo "$source" kerf-check --files good.nc notes.md > "$work/good.log" 2>&1 || {
  cat "$work/good.log"; echo "FAIL: the hook should pass a clean program"; exit 1; }
# With the bad one: fails, and says where.
if pre-commit try-repo "$source" kerf-check --files good.nc bad.NC > "$work/bad.log" 2>&1; then
  cat "$work/bad.log"; echo "FAIL: the hook should fail a program with an error"; exit 1
fi
grep -q "bad.NC:3:12: error: .*\[K0302\]" "$work/bad.log" || {
  cat "$work/bad.log"; echo "FAIL: the hook should print the error at bad.NC:3:12"; exit 1; }
echo "pre-commit hook: a clean program passes, an error fails at its line"
