#!/usr/bin/env bash
# record_reload.sh ARCFIRE OUT_DIR
# Records a live session in a window (under xvfb-run -a, keys fed by xdotool) onto an existing
# recording, with a second arcfire trying to record to the same file (refused with one line,
# exit 2, by the lock), then edits the level mid-recording. The hot reload stops the recording
# (session_recorder.h says why it is not continued as a segment): the window says so, the file
# ends with `end` at the tick the log names and replays with every hash it wrote; the earlier
# recording, kept as NAME.bak during the first second, is gone once the session had it.
# Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; it installs nothing.
set -u
arcfire="$(realpath "$1")"; out="$(realpath -m "$2")"
source "$(dirname "$0")/live_window.sh"
require_tools record_reload
rm -rf "$out"; mkdir -p "$out"
rec="$out/reloaded_session.replay"
cp tests/replays/levels/range.json "$out/range.json"
echo "an earlier recording" >"$rec"

export LEVEL="$out/range.json" SECOND="$out/second"
play_recorded record_reload "$arcfire" "$rec" "$out/game.log" '
  xdotool keydown w; sleep 1.2; xdotool keyup w
  timeout 20 "$arcfire" --level "$level" --record "$rec" --size 320x180 >/dev/null 2>"$SECOND.err"; echo $? >"$SECOND.code"
  xdotool key t; sleep 1.0
  touch "$level"; sleep 1.5
  xdotool keydown w; sleep 0.8; xdotool keyup w
  sleep 0.5' || exit 1

cat "$out/game.log"
fail() { echo "record_reload: $*"; exit 1; }
[ "$(cat "$SECOND.code")" = 2 ] || fail "the second arcfire exited $(cat "$SECOND.code"), expected 2: $(cat "$SECOND.err")"
[ "$(grep -c '' "$SECOND.err")" -eq 1 ] && grep -q "another arcfire (pid [0-9]*) is recording to this file" "$SECOND.err" ||
  fail "the second arcfire was not refused with one line: $(cat "$SECOND.err")"
[ ! -e "$rec.bak" ] || fail "$rec.bak is still there after the session recorded its first second"
[ ! -e "$rec.lock" ] || fail "$rec.lock is left behind"
stopped=$(sed -n 's/.*stopped by the reload of changed files; it replays up to tick \([0-9]*\).*/\1/p' "$out/game.log")
[ -n "$stopped" ] || fail "the hot reload did not report the end of the recording"
last=$(tail -n 1 "$rec")
[ "$last" = "$stopped end" ] || fail "expected '$stopped end' as the last line, found '$last'"
"$arcfire" --headless --no-render --replay "$rec" --out "$out/replay"
