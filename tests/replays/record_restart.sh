#!/usr/bin/env bash
# record_restart.sh ARCFIRE OUT_DIR
# Records a live session in a window (under xvfb-run -a, keys fed by xdotool), restarts the
# level from the pause menu mid-recording, flies on, then replays the file headless. A restart
# stops the recording (the window says so and the log names the tick); the file must end with
# `end` at that tick and replay with every hash it wrote.
# Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; it installs nothing.
set -u
arcfire="$(realpath "$1")"; out="$2"
source "$(dirname "$0")/live_window.sh"
require_tools record_restart
rm -rf "$out"; mkdir -p "$out"
rec="$out/restarted_session.replay"

# Default bindings: W throttle up, T next target, Escape menu; the menu is Resume, Restart, ...
play_recorded record_restart "$arcfire" "$rec" "$out/game.log" '
  xdotool keydown w; sleep 1.2; xdotool keyup w
  xdotool key t;     sleep 1.2
  xdotool key Escape; sleep 0.5
  xdotool key Down;   sleep 0.3
  xdotool key Return; sleep 0.5
  xdotool keydown w; sleep 1.0; xdotool keyup w
  sleep 0.5' || exit 1

cat "$out/game.log"
[ -s "$rec" ] || { echo "record_restart: no recording at $rec"; exit 1; }
stopped=$(sed -n 's/.*stopped by the restart; it replays up to tick \([0-9]*\).*/\1/p' "$out/game.log")
[ -n "$stopped" ] || { echo "record_restart: the restart did not report the end of the recording"; exit 1; }
last=$(tail -n 1 "$rec")
[ "$last" = "$stopped end" ] || { echo "record_restart: expected '$stopped end' as the last line, found '$last'"; exit 1; }
grep -qE '^[0-9]+ axis throttle ' "$rec" || { echo "record_restart: the throttle was not recorded"; cat "$rec"; exit 1; }
"$arcfire" --headless --no-render --replay "$rec" --out "$out/replay"
