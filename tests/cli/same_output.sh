#!/usr/bin/env bash
# same_output.sh GOLDEN -- COMMAND...
# Runs COMMAND; passes when it exits 0 and its stdout is GOLDEN byte for byte. On a difference
# it prints the diff (golden first); after an intended change, write COMMAND's output to GOLDEN.
set -u
golden="$1"; shift 2
out="$(mktemp)"
"$@" >"$out"
got=$?
if [ "$got" -ne 0 ]; then echo "exit code $got, expected 0"; rm -f "$out"; exit 1; fi
if ! diff -u "$golden" "$out"; then
  echo "the output differs from $golden (lines with - are the golden's, + the program's)"
  rm -f "$out"; exit 1
fi
rm -f "$out"
echo "ok: the output is $golden"
