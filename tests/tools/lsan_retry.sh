#!/bin/sh
# lsan_retry.sh COMMAND [ARG...]: runs COMMAND and passes on its standard output, standard error and
# exit status. When it failed only because LeakSanitizer's own stop-the-world tracer crashed at exit
# ("Tracer caught signal 11" then "LeakSanitizer has encountered a fatal error": an intermittent fault
# of the sanitizer runtime, seen with processes that keep threads, as Mesa's llvmpipe does; upstream
# google/sanitizers#1353), it runs COMMAND again, at most twice more, and passes on only the last
# run. Any other failure, a leak report included, is passed on at once. Each retry is logged to
# $KERF_LSAN_RETRY_LOG when that is set, so the flake's rate stays visible.
out=$(mktemp) || exit 125
err=$(mktemp) || { rm -f "$out"; exit 125; }
trap 'rm -f "$out" "$err"' EXIT
attempt=1
while :; do
  "$@" >"$out" 2>"$err"
  rc=$?
  # Both streams are searched: a CI run once showed the tracer's message and was not retried.
  if [ "$rc" -ne 0 ] && [ "$attempt" -lt 3 ] && cat "$out" "$err" | grep -q "^Tracer caught signal" &&
     cat "$out" "$err" | grep -q "LeakSanitizer has encountered a fatal error"; then
    if [ -n "${KERF_LSAN_RETRY_LOG:-}" ]; then
      echo "attempt $attempt of: $*" >>"$KERF_LSAN_RETRY_LOG"
    fi
    attempt=$((attempt + 1))
    continue
  fi
  cat "$out"
  cat "$err" >&2
  exit "$rc"
done
