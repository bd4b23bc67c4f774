#!/usr/bin/env bash
# check_snapshot_failure.sh ARCFIRE OUT_DIR
# A snapshot that differs from its golden fails the replay (exit 1) and leaves the actual
# frame and a diff image in --out, named in the failure line.
set -u
arcfire="$1"; out="$2"
rm -rf "$out"
log="$("$arcfire" --headless --replay tests/replays/bad/snapshot_mismatch.replay --out "$out")"
code=$?
echo "$log"
[ "$code" -eq 1 ] || { echo "check_snapshot_failure: exit $code, expected 1"; exit 1; }
grep -q "^FAIL .*snapshot_mismatch.replay:8: tick 60: 60 snapshot view: .*wrote $out/view_actual.png and $out/view_diff.png" <<<"$log" ||
  { echo "check_snapshot_failure: no FAIL line naming both images"; exit 1; }
for f in view.png view_actual.png view_diff.png; do
  [ -s "$out/$f" ] || { echo "check_snapshot_failure: $out/$f missing"; exit 1; }
done
echo "ok: mismatch reported, actual and diff images written"
