#!/usr/bin/env bash
# check_replay.sh EXIT_CODE ARCFIRE ARGS...
# Runs one replay and checks its exit code and output contract: exit 0 and 1 end stdout with
# `final hash HEX at tick N` (exit 1 also prints a FAIL line); exit 2 prints exactly one
# stderr line `path:line:col: message`.
set -u
want="$1"; shift
out="$(mktemp)"; err="$(mktemp)"
trap 'rm -f "$out" "$err"' EXIT
"$@" >"$out" 2>"$err"
got=$?
cat "$out"
if [ "$got" -ne "$want" ]; then
  echo "check_replay: exit code $got, expected $want"; cat "$err"; exit 1
fi
if [ "$want" -eq 2 ]; then
  lines=$(grep -c '' "$err")
  if [ "$lines" -ne 1 ] || ! grep -Eq '\.replay:[0-9]+:[0-9]+: ' "$err"; then
    echo "check_replay: expected one 'path:line:col: message' line on stderr, got:"; cat "$err"; exit 1
  fi
  echo "ok: exit 2: $(cat "$err")"; exit 0
fi
last="$(tail -n 1 "$out")"
if ! grep -Eq '^final hash [0-9a-f]{16} at tick [0-9]+$' <<<"$last"; then
  echo "check_replay: last line is '$last', expected 'final hash HEX at tick N'"; exit 1
fi
if [ "$want" -eq 1 ] && ! grep -q '^FAIL ' "$out"; then
  echo "check_replay: exit 1 without a FAIL line"; exit 1
fi
exit 0
