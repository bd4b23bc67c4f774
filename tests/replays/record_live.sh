#!/usr/bin/env bash
# record_live.sh ARCFIRE OUT_DIR
# Records a live session in a window (under xvfb-run -a, keys fed by xdotool), kills the game
# mid-flight (a kill must leave a replayable file), then replays the recording headless: the
# hash lines the recorder wrote every second must all be reproduced.
# Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; it installs nothing.
set -u
arcfire="$(realpath "$1")"; out="$2"
for tool in xvfb-run xdotool; do
  if ! command -v "$tool" >/dev/null; then
    echo "record_live: $tool is not installed; skipping (.ci/run installs it: apt-get install xdotool xvfb)"
    exit 77
  fi
done
rm -rf "$out"; mkdir -p "$out"
rec="$out/live_session.replay"

# Inside the virtual display: start the game recording, wait for its window, fly a little.
xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
  arcfire="$1"; rec="$2"; log="$3"
  "$arcfire" --level tests/replays/levels/range.json --record "$rec" --size 640x360 >"$log" 2>&1 &
  pid=$!
  win=$(timeout 30 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
  if [ -z "$win" ]; then echo "record_live: no Arcfire window appeared"; kill $pid; cat "$log"; exit 1; fi
  xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
  sleep 1
  # X keysyms for the default bindings (assets/settings/bindings.json): W throttle up, T next
  # target, Up pitch, Shift_L afterburner, Tab switch weapon, Q roll.
  xdotool keydown w;       sleep 1.5; xdotool keyup w
  xdotool key t;           sleep 0.3
  xdotool keydown Up;      sleep 0.6; xdotool keyup Up
  xdotool keydown Shift_L; sleep 0.8; xdotool keyup Shift_L
  xdotool key Tab;         sleep 0.3
  xdotool keydown q;       sleep 0.5; xdotool keyup q
  sleep 1.5
  kill -TERM $pid; wait $pid
  exit 0
' _ "$arcfire" "$rec" "$out/game.log" || exit 1

[ -s "$rec" ] || { echo "record_live: no recording at $rec"; cat "$out/game.log"; exit 1; }
lines=$(grep -cE '^[0-9]+ (press|release|axis|command) ' "$rec")
hashes=$(grep -cE '^[0-9]+ hash ' "$rec")
echo "record_live: recorded $lines input lines and $hashes hash lines"
[ "$hashes" -ge 2 ] || { echo "record_live: expected a hash line every second of play"; cat "$rec"; exit 1; }
[ "$lines" -ge 1 ] || { echo "record_live: the key presses were not recorded"; cat "$rec"; exit 1; }
"$arcfire" --headless --no-render --replay "$rec" --out "$out/replay"
