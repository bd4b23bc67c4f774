#!/usr/bin/env bash
# expect.sh EXIT_CODE REGEX -- COMMAND...
# Runs COMMAND; passes when it exits with EXIT_CODE and, for a non-zero code, its stderr is one
# line matching REGEX (a bad-input error must be a single clear line).
set -u
want="$1"; regex="$2"; shift 3
err="$(mktemp)"
"$@" >/dev/null 2>"$err"
got=$?
lines=$(grep -c '' "$err")
msg="$(cat "$err")"
rm -f "$err"
if [ "$got" -ne "$want" ]; then echo "exit code $got, expected $want; stderr: $msg"; exit 1; fi
if [ "$want" -ne 0 ]; then
  if [ "$lines" -ne 1 ]; then echo "expected one error line, got $lines: $msg"; exit 1; fi
  if ! grep -Eq -- "$regex" <<<"$msg"; then echo "stderr '$msg' does not match '$regex'"; exit 1; fi
fi
echo "ok: exit $got: $msg"
