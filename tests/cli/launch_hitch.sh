#!/bin/bash
# launch_hitch.sh ARCFIRE OUT [BOUND_MS] [HITCH_MS]: the main menu in a window under xvfb-run
# with --frame-times; a mission launched as a player would (Enter on Play, on the first
# mission, on Launch), flown for two seconds, then the game ended with SIGTERM. Prints the
# frame that launched the mission and the first frame of the mission, in ms, and what each took
# beyond the median of the ten menu frames before the launch (the hitch a player feels, on a
# machine whose other load slows every frame alike). Fails when either frame took longer than
# BOUND_MS (default 150) or stood more than HITCH_MS (default 50) above that median. Exits 77
# (ctest: skipped) without xvfb-run or xdotool.
set -u
arcfire="$1"; out="$2"; bound="${3:-150}"; hitch="${4:-50}"
source "$(dirname "$0")/../replays/live_window.sh"
require_tools cli_launch_hitch
mkdir -p "$(dirname "$out")"
rm -f "$out.csv" "$out.log"
export XDG_CONFIG_HOME="$out.config"; rm -rf "$XDG_CONFIG_HOME"
xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
  arcfire="$1"; out="$2"
  "$arcfire" --size 1280x720 --frame-times "$out.csv" >"$out.log" 2>&1 &
  pid=$!
  win=$(timeout 60 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
  if [ -z "$win" ]; then echo "cli_launch_hitch: no Arcfire window appeared"; kill $pid; cat "$out.log"; exit 1; fi
  xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
  sleep 3
  xdotool key --window "$win" Return; sleep 1
  xdotool key --window "$win" Return; sleep 2  # the briefing, read for two seconds
  xdotool key --window "$win" Return; sleep 2
  kill -TERM $pid; wait $pid
  exit 0
' _ "$arcfire" "$out" || { cat "$out.log" 2>/dev/null; exit 1; }
[ -s "$out.csv" ] || { echo "cli_launch_hitch: no frame-time log"; cat "$out.log"; exit 1; }
# The launch is the first frame whose tick falls back (the mission starts at tick 0); the
# frame after it is the mission's first. The ten frames before the launch are the menu's.
awk -F, -v bound="$bound" -v hitch="$hitch" 'NR > 1 {
    if (seen == 1) { first = $2; seen = 2 }
    if (!seen && NR > 2 && $3 + 0 < prev) { launch = $2; seen = 1 }
    if (!seen) { recent[n % 10] = $2 + 0; n++ }
    prev = $3 + 0
  }
  END {
    if (seen < 2) { print "cli_launch_hitch: no launch found in the frame-time log"; exit 1 }
    m = n < 10 ? n : 10
    for (i = 0; i < m; i++) sorted[i] = recent[i]
    for (i = 1; i < m; i++) for (j = i; j > 0 && sorted[j - 1] > sorted[j]; j--) { t = sorted[j]; sorted[j] = sorted[j - 1]; sorted[j - 1] = t }
    median = m ? (m % 2 ? sorted[int(m / 2)] : (sorted[m / 2 - 1] + sorted[m / 2]) / 2) : 0
    printf "cli_launch_hitch: launch frame %.1f ms (+%.1f), first mission frame %.1f ms (+%.1f) over the menu median %.1f ms (bounds %d ms, +%d ms)\n", launch, launch - median, first, first - median, median, bound, hitch
    exit (launch > bound || first > bound || launch - median > hitch || first - median > hitch) ? 1 : 0
  }' "$out.csv"
