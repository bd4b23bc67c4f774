#!/bin/bash
# frame_times.sh ARCFIRE OUT: a live duel in a window under xvfb-run with --frame-times, quit
# from the pause menu after a few seconds as a player would (Esc, down to Quit, Enter). It must
# exit 0, print the percentile line, and leave a CSV with a header and a line per frame.
set -u
arcfire="$1"; out="$2"
source "$(dirname "$0")/../replays/live_window.sh"
require_tools cli_frame_times
mkdir -p "$(dirname "$out")"
rm -f "$out.csv" "$out.log"
xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
  arcfire="$1"; out="$2"
  "$arcfire" --level levels/duel.json --size 640x360 --frame-times "$out.csv" >"$out.log" 2>&1 &
  pid=$!
  win=$(timeout 30 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
  if [ -z "$win" ]; then echo "cli_frame_times: no Arcfire window appeared"; kill $pid; cat "$out.log"; exit 1; fi
  xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
  sleep 3
  xdotool key Escape; sleep 0.5
  for i in 1 2 3 4 5; do xdotool key Down; sleep 0.2; done
  xdotool key Return
  for i in $(seq 1 100); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
  if kill -0 $pid 2>/dev/null; then echo "cli_frame_times: Quit in the pause menu did not end the game"; kill $pid; exit 1; fi
  wait $pid
' _ "$arcfire" "$out" || { cat "$out.log" 2>/dev/null; exit 1; }
grep -E "^arcfire: [0-9]+ frames in [0-9.]+ s: p50 [0-9.]+ ms, p99 [0-9.]+ ms, worst [0-9.]+ ms" "$out.log" ||
  { echo "cli_frame_times: no percentile line"; cat "$out.log"; exit 1; }
grep -E "^arcfire: median frame [0-9.]+ ms: render [0-9.]+ ms \(opaque [0-9.]+, particles [0-9.]+, post [0-9.]+, hud [0-9.]+\), the rest [0-9.]+ ms" "$out.log" ||
  { echo "cli_frame_times: no median frame line"; cat "$out.log"; exit 1; }
head -1 "$out.csv" | grep -qx "time_s,frame_ms,tick,particles_drawn,budgeted_layers,half_res,render_opaque_ms,render_particles_ms,render_post_ms,render_hud_ms" ||
  { echo "cli_frame_times: bad CSV header"; head -2 "$out.csv"; exit 1; }
rows=$(($(wc -l < "$out.csv") - 1))
[ "$rows" -ge 30 ] || { echo "cli_frame_times: only $rows frames logged"; exit 1; }
echo "cli_frame_times: $rows frames logged"
