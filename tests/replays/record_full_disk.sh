#!/usr/bin/env bash
# record_full_disk.sh ARCFIRE OUT_DIR
# Records a live session in a window (under xvfb-run -a, keys fed by xdotool) onto a disk that
# fills after a few seconds (ARCFIRE_WRITE_LIMIT, core/file_writer.h). The session says so on
# screen and in one log line naming the file and the reason, stops recording, and the file
# keeps whole lines only, so it replays up to the tick the line names.
# Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; it installs nothing.
set -u
arcfire="$(realpath "$1")"; out="$2"
source "$(dirname "$0")/live_window.sh"
require_tools record_full_disk
rm -rf "$out"; mkdir -p "$out"
rec="$out/full_disk_session.replay"

export ARCFIRE_WRITE_LIMIT=2500
play_recorded record_full_disk "$arcfire" "$rec" "$out/game.log" '
  for i in 1 2 3 4 5 6; do xdotool keydown w; sleep 0.3; xdotool keyup w; xdotool keydown s; sleep 0.3; xdotool keyup s; done
  sleep 0.5' || exit 1
unset ARCFIRE_WRITE_LIMIT

cat "$out/game.log"
fail() { echo "record_full_disk: $*"; exit 1; }
line=$(grep "cannot write" "$out/game.log")
[ "$(grep -c "cannot write" "$out/game.log")" -eq 1 ] || fail "expected one line about the failed write"
grep -q "^arcfire: $rec: cannot write: No space left on device; recording stopped, it replays up to tick [0-9]*$" <<<"$line" ||
  fail "the line does not name the file, the reason and the tick: $line"
! grep -q "arcfire: recorded" "$out/game.log" || fail "the session reported the recording as done"
[ "$(tail -c 1 "$rec" | od -An -c | tr -d ' ')" = '\n' ] || fail "the file ends in a cut line"
tick=$(sed -n 's/.*it replays up to tick \([0-9]*\)$/\1/p' <<<"$line")
"$arcfire" --headless --no-render --replay "$rec" --out "$out/replay" | tee "$out/replay.log"
[ "${PIPESTATUS[0]}" -eq 0 ] || fail "the recording does not replay"
grep -q "^final hash [0-9a-f]* at tick $tick$" "$out/replay.log" || fail "the replay does not end at tick $tick"
