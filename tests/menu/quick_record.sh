#!/bin/bash
# quick_record.sh ARCFIRE OUT: a quick battle launched from the menu in a window under xvfb-run
# with --record (Up Up Enter: the page; Up Up Enter: Launch), flown a moment, ended with SIGTERM.
# The script must name the level copied beside it (OUT.level.json) and replay headless with
# every hash matching. Exits 77 (ctest: skipped) without xvfb-run or xdotool.
set -u
arcfire="$1"; out="$2"
source "$(dirname "$0")/../replays/live_window.sh"
require_tools quick_battle_record
mkdir -p "$(dirname "$out")"
rm -f "$out.replay" "$out.level.json" "$out.log"
export XDG_CONFIG_HOME="$out.config"; rm -rf "$XDG_CONFIG_HOME"
xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
  arcfire="$1"; out="$2"
  "$arcfire" --size 1280x720 --record "$out.replay" >"$out.log" 2>&1 &
  pid=$!
  win=$(timeout 60 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
  if [ -z "$win" ]; then echo "quick_record: no Arcfire window appeared"; kill $pid; cat "$out.log"; exit 1; fi
  xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
  sleep 3
  for k in Up Up Return Up Up Return; do xdotool key --window "$win" $k; sleep 0.5; done
  sleep 3
  xdotool key --window "$win" w; sleep 2
  kill -TERM $pid; wait $pid
  exit 0
' _ "$arcfire" "$out" || { cat "$out.log" 2>/dev/null; exit 1; }
grep -q "^level .*$(basename "$out").level.json$" "$out.replay" || { echo "quick_record: the script does not name the level beside it"; head -3 "$out.replay"; cat "$out.log"; exit 1; }
grep -q '"name": "Quick battle"' "$out.level.json" || { echo "quick_record: $out.level.json is not a quick battle"; exit 1; }
"$arcfire" --headless --no-render --replay "$out.replay"
