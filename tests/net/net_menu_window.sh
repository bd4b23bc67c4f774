#!/usr/bin/env bash
# net_menu_window.sh ARCFIRE OUT_DIR [SHOTS_DIR]
# A network match from the menu in two windows (xvfb-run -a, keys from xdotool): one opens
# Multiplayer, Host a match (Duel, a port of its own) and its lobby; the other Multiplayer, Join
# a match, types 127.0.0.1;PORT (';' types ':') and joins. Both lobbies list both pilots; the
# host launches; both fly by keys; the host leaves with Esc twice (no pause in a network match),
# the pilot is told the host left, and both match records replay headless to their hashes. With
# SHOTS_DIR, F12 screenshots of both lobbies are copied there. Waits for log lines, not fixed
# times. Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing.
set -u
arcfire="$(realpath "$1")"; out="$(realpath -m "$2")"; shots="${3:-}"
[ -n "$shots" ] && shots="$(realpath -m "$shots")"
root="$(pwd)"
for tool in xvfb-run xdotool; do
  command -v "$tool" >/dev/null || { echo "net_menu_window: $tool is not installed; skipping"; exit 77; }
done
rm -rf "$out"; mkdir -p "$out/a/config" "$out/b/config"
step=$(( 1 + $$ % 10 )); port=$(( 27960 + step ))
xvfb-run -a -s "-screen 0 1700x900x24" bash -c '
  arcfire="$1"; out="$2"; step="$3"; port="$4"; shots="$5"
  wait_for() { for _ in $(seq 1 $(( $3 * 10 ))); do grep -qE "$2" "$1" 2>/dev/null && return 0; sleep 0.1; done; echo "net_menu_window: no \"$2\" in $1"; return 1; }
  window_of() { for _ in $(seq 1 600); do w=$(xdotool search --onlyvisible --pid "$1" 2>/dev/null | head -n 1); [ -n "$w" ] && { echo "$w"; return 0; }; sleep 0.1; done; return 1; }
  keys() { local w="$1"; shift; xdotool windowfocus --sync "$w"; xdotool mousemove --window "$w" 2 2; for k in "$@"; do xdotool key "$k"; sleep 0.5; done; }
  shot() {
    [ -n "$shots" ] || return 0
    local dir="$out/$1/out/screenshots" before; before=$(ls "$dir" 2>/dev/null | wc -l)
    keys "$2" F12
    for _ in $(seq 1 50); do [ "$(ls "$dir" 2>/dev/null | wc -l)" -gt "$before" ] && break; sleep 0.1; done
    sleep 0.3; cp "$dir/$(ls -t "$dir" | head -n 1)" "$shots/$3.png"
  }
  fail() { echo "net_menu_window: $1"; for w in $win_a $win_b; do xdotool windowfocus --sync $w; xdotool key F12; done; sleep 2; cat "$out/a/log" "$out/b/log"; kill $a $b 2>/dev/null; exit 1; }
  win_a=""; win_b=""
  (cd "$out/a" && XDG_CONFIG_HOME="$out/a/config" exec "$arcfire" --size 800x450 --name Host >log 2>&1) &
  a=$!
  (cd "$out/b" && XDG_CONFIG_HOME="$out/b/config" exec "$arcfire" --size 800x450 --name Ann >log 2>&1) &
  b=$!
  win_a=$(window_of $a) || fail "no host window"
  win_b=$(window_of $b) || fail "no pilot window"
  xdotool windowmove --sync "$win_a" 0 0; xdotool windowmove --sync "$win_b" 820 0  # apart: each takes its own keys
  # Each window takes keys once it answers F12 with a screenshot line (its menu is up).
  ready() { for _ in $(seq 1 30); do keys "$2" F12; wait_for "$out/$1/log" "screenshot" 2 >/dev/null && return 0; done; return 1; }
  ready a "$win_a" || fail "the host window takes no keys"
  ready b "$win_b" || fail "the pilot window takes no keys"
  # Multiplayer, Host a match, the port moved on by $step, Open the lobby.
  rights=$(for _ in $(seq 1 $step); do echo -n "Right "; done)
  keys "$win_a" Down Down Down Return Return Down Down $rights Down Return
  wait_for "$out/a/log" "^net: Hosting levels/duel.json on port $port" 30 || fail "the host did not open its lobby"
  # Multiplayer, Join a match, the address typed, Join.
  keys "$win_b" Down Down Down Return Down Return Return 1 2 7 period 0 period 0 period 1 semicolon \
    $(echo "$port" | sed "s/./& /g") Return Down Return
  wait_for "$out/a/log" "^net: Ann joined" 30 || fail "the pilot did not join"
  sleep 1  # the lobby refreshes twice a second: both rows with their pings
  shot a "$win_a" netui_lobby_host; shot b "$win_b" netui_lobby_pilot
  keys "$win_a" Return  # Launch (the host lobby opens on it)
  wait_for "$out/a/log" "^net: slot 0 of 2" 30 && wait_for "$out/b/log" "^net: slot 1 of 2" 30 || fail "no launch"
  keys "$win_a"; xdotool keydown w; sleep 1; xdotool keyup w
  keys "$win_b"; xdotool keydown w keydown Left; sleep 1; xdotool keyup Left keyup w
  keys "$win_a" Escape Escape
  wait_for "$out/a/log" "^net: match record" 30 || fail "the host wrote no match record"
  wait_for "$out/b/log" "^net: The host left at tick" 30 || fail "the pilot was not told"
  wait_for "$out/b/log" "^net: match record" 30 || fail "the pilot wrote no match record"
  kill -TERM $a $b; wait $a; wait $b
  exit 0
' _ "$arcfire" "$out" "$step" "$port" "$shots" || exit 1
for p in a b; do
  rec=$(sed -n "s/^net: match record //p" "$out/$p/log")
  (cd "$out/$p" && ARCFIRE_DATA="$root" "$arcfire" --headless --replay "$rec") || { echo "net_menu_window: $p's record does not replay"; exit 1; }
done
echo "net_menu_window: hosted and joined from the menu; the host left; both records replay"
