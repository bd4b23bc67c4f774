#!/usr/bin/env bash
# record_live.sh ARCFIRE OUT_DIR
# Records a live session in a window (under xvfb-run -a, keys fed by xdotool), kills the game
# mid-flight (a kill must leave a replayable file), then replays the recording headless: the
# hash lines the recorder wrote every second must all be reproduced.
# Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; it installs nothing.
set -u
arcfire="$(realpath "$1")"; out="$2"
source "$(dirname "$0")/live_window.sh"
require_tools record_live
rm -rf "$out"; mkdir -p "$out"
rec="$out/live_session.replay"

# X keysyms for the default bindings (assets/settings/bindings.json): W throttle up, T next
# target, Up pitch, Shift_L afterburner, Tab switch weapon, Q roll.
play_recorded record_live "$arcfire" "$rec" "$out/game.log" '
  xdotool keydown w;       sleep 1.5; xdotool keyup w
  xdotool key t;           sleep 0.3
  xdotool keydown Up;      sleep 0.6; xdotool keyup Up
  xdotool keydown Shift_L; sleep 0.8; xdotool keyup Shift_L
  xdotool key Tab;         sleep 0.3
  xdotool keydown q;       sleep 0.5; xdotool keyup q
  sleep 1.5' || exit 1

[ -s "$rec" ] || { echo "record_live: no recording at $rec"; cat "$out/game.log"; exit 1; }
lines=$(grep -cE '^[0-9]+ (press|release|axis|command) ' "$rec")
hashes=$(grep -cE '^[0-9]+ hash ' "$rec")
echo "record_live: recorded $lines input lines and $hashes hash lines"
[ "$hashes" -ge 2 ] || { echo "record_live: expected a hash line every second of play"; cat "$rec"; exit 1; }
[ "$lines" -ge 1 ] || { echo "record_live: the key presses were not recorded"; cat "$rec"; exit 1; }
"$arcfire" --headless --no-render --replay "$rec" --out "$out/replay"
