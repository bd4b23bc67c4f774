#!/usr/bin/env bash
# net_window.sh ARCFIRE OUT_DIR [SHOTS_DIR]
# Two windows on one display (xvfb-run -a, keys from xdotool): one hosts levels/duel.json from
# the command line, the other joins it; the match launches when both are in, each pilot flies
# by keys for a few seconds (the normal input path), F3 and the held scoreboard key are pressed,
# and at tick 900 both print their final line: the same tick and hash. Both match records must
# replay headless to their hashes. With SHOTS_DIR, F12 screenshots of the match (the pilot's name
# over its ship, F3) and the scoreboard are copied there. Waits for conditions (log lines, windows), not for
# fixed times. Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing.
set -u
arcfire="$(realpath "$1")"; out="$(realpath -m "$2")"; shots="${3:-}"
for tool in xvfb-run xdotool; do
  command -v "$tool" >/dev/null || { echo "net_window: $tool is not installed; skipping"; exit 77; }
done
rm -rf "$out"; mkdir -p "$out/config_a" "$out/config_b"
port=$(( 30000 + ($$ % 20000) ))
xvfb-run -a -s "-screen 0 1700x900x24" bash -c '
  arcfire="$1"; out="$2"; port="$3"; shots="$4"
  # wait_for FILE REGEX SECONDS: until a line of FILE matches (false on timeout).
  wait_for() { for _ in $(seq 1 $(( $3 * 10 ))); do grep -qE "$2" "$1" 2>/dev/null && return 0; sleep 0.1; done; return 1; }
  window_of() { for _ in $(seq 1 600); do w=$(xdotool search --onlyvisible --pid "$1" 2>/dev/null | head -n 1); [ -n "$w" ] && { echo "$w"; return 0; }; sleep 0.1; done; return 1; }
  keys() { local w="$1"; shift; xdotool windowfocus --sync "$w"; xdotool mousemove --window "$w" 2 2; xdotool "$@"; }
  shot() {  # shot WINDOW NAME: F12, then the new file under out/screenshots is copied as NAME
    [ -n "$shots" ] || return 0
    local before; before=$(ls out/screenshots 2>/dev/null | wc -l)
    keys "$1" key F12
    for _ in $(seq 1 50); do [ "$(ls out/screenshots 2>/dev/null | wc -l)" -gt "$before" ] && break; sleep 0.1; done
    sleep 0.3; cp "out/screenshots/$(ls -t out/screenshots | head -n 1)" "$shots/$2.png"
  }
  XDG_CONFIG_HOME="$out/config_a" "$arcfire" --size 640x360 --host --port "$port" --level levels/duel.json --players 2 \
    --ticks 900 --name Host --match-record "$out/match_0.replay" >"$out/host.log" 2>&1 &
  host=$!
  win_a=$(window_of $host) || { echo "net_window: no host window"; cat "$out/host.log"; kill $host; exit 1; }
  XDG_CONFIG_HOME="$out/config_b" "$arcfire" --size 640x360 --join "127.0.0.1:$port" --ticks 900 --name Ann \
    --match-record "$out/match_1.replay" >"$out/join.log" 2>&1 &
  join=$!
  win_b=$(window_of $join) || { echo "net_window: no pilot window"; cat "$out/join.log"; kill $host $join; exit 1; }
  xdotool windowmove --sync "$win_a" 0 0; xdotool windowmove --sync "$win_b" 820 0  # apart: each takes its own keys
  for f in host join; do
    wait_for "$out/$f.log" "^net: slot [0-9] of" 60 || { echo "net_window: the $f did not start the match"; cat "$out/host.log" "$out/join.log"; kill $host $join; exit 1; }
  done
  shot "$win_a" netui_names_host  # the other ship ahead, its pilot named over it
  # Each pilot flies: throttle up, turns, fire; F3 on for the figures, the scoreboard held.
  keys "$win_a" keydown w keydown Left; keys "$win_b" keydown w keydown Right
  keys "$win_b" key F3; keys "$win_a" key F3
  keys "$win_b" mousedown 1; sleep 1; keys "$win_b" mouseup 1
  shot "$win_b" netui_f3_pilot
  keys "$win_b" keydown h; sleep 0.3; shot "$win_b" netui_scoreboard; keys "$win_b" keyup h
  keys "$win_a" keyup Left keyup w; keys "$win_b" keyup Right keyup w
  fail=0
  for p in $host $join; do
    for _ in $(seq 1 900); do kill -0 $p 2>/dev/null || break; sleep 0.1; done
    kill -0 $p 2>/dev/null && { echo "net_window: process $p did not end"; kill -TERM $p; fail=1; }
    wait $p || { echo "net_window: process $p exited $?"; fail=1; }
  done
  exit $fail
' _ "$arcfire" "$out" "$port" "$shots" || { cat "$out/host.log" "$out/join.log"; exit 1; }
a=$(grep "final tick" "$out/host.log" | sed -n "s/.*final tick \([0-9]*\) hash \([0-9a-f]*\).*/\1 \2/p")
b=$(grep "final tick" "$out/join.log" | sed -n "s/.*final tick \([0-9]*\) hash \([0-9a-f]*\).*/\1 \2/p")
echo "host: $a   pilot: $b"
[ -n "$a" ] && [ "$a" = "$b" ] && [ "${a%% *}" = 900 ] || { echo "net_window: final lines differ"; cat "$out/host.log" "$out/join.log"; exit 1; }
for i in 0 1; do
  "$arcfire" --headless --replay "$out/match_$i.replay" >/dev/null || { echo "net_window: match record $i does not replay"; exit 1; }
done
echo "net_window: host and pilot ended at tick 900 with hash ${a#* }; both records replay"
