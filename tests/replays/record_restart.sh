#!/usr/bin/env bash
# record_restart.sh ARCFIRE OUT_DIR
# Records a live session in a window (under xvfb-run -a, keys fed by xdotool), restarts the
# level from the pause menu mid-recording, flies on, then replays the file headless. A restart
# stops the recording (the window says so and the log names the tick); the file must end with
# `end` at that tick and replay with every hash it wrote.
# Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; it installs nothing.
set -u
arcfire="$(realpath "$1")"; out="$2"
for tool in xvfb-run xdotool; do
  if ! command -v "$tool" >/dev/null; then
    echo "record_restart: $tool is not installed; skipping (apt-get install xdotool xvfb)"
    exit 77
  fi
done
rm -rf "$out"; mkdir -p "$out"
rec="$out/restarted_session.replay"

xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
  arcfire="$1"; rec="$2"; log="$3"
  "$arcfire" --level tests/replays/levels/range.json --record "$rec" --size 640x360 >"$log" 2>&1 &
  pid=$!
  win=$(timeout 30 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
  if [ -z "$win" ]; then echo "record_restart: no Arcfire window appeared"; kill $pid; cat "$log"; exit 1; fi
  xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
  sleep 1
  # Default bindings: W throttle up, T next target, Escape menu; the menu is Resume, Restart, ...
  xdotool keydown w; sleep 1.2; xdotool keyup w
  xdotool key t;     sleep 1.2
  xdotool key Escape; sleep 0.5
  xdotool key Down;   sleep 0.3
  xdotool key Return; sleep 0.5
  xdotool keydown w; sleep 1.0; xdotool keyup w
  sleep 0.5
  kill -TERM $pid; wait $pid
  exit 0
' _ "$arcfire" "$rec" "$out/game.log" || exit 1

cat "$out/game.log"
[ -s "$rec" ] || { echo "record_restart: no recording at $rec"; exit 1; }
stopped=$(sed -n 's/.*stopped by the restart; it replays up to tick \([0-9]*\).*/\1/p' "$out/game.log")
[ -n "$stopped" ] || { echo "record_restart: the restart did not report the end of the recording"; exit 1; }
last=$(tail -n 1 "$rec")
[ "$last" = "$stopped end" ] || { echo "record_restart: expected '$stopped end' as the last line, found '$last'"; exit 1; }
grep -qE '^[0-9]+ axis throttle ' "$rec" || { echo "record_restart: the throttle was not recorded"; cat "$rec"; exit 1; }
"$arcfire" --headless --no-render --replay "$rec" --out "$out/replay"
