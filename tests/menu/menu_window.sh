#!/usr/bin/env bash
# menu_window.sh ARCFIRE OUT_DIR
# The main menu in a window (under xvfb-run -a, keys and mouse fed by xdotool), as a new player
# would use it: Settings by a mouse click, Controls, mouse sensitivity up twice, Remap keys,
# Fire beam remapped to V, back and Quit. Then a second start with the same config folder: the
# saved settings.json must hold both changes, and nothing may have been kept as a .bak.
# Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; it installs nothing.
set -u
arcfire="$(realpath "$1")"; out="$(realpath -m "$2")"
for tool in xvfb-run xdotool; do
  command -v "$tool" >/dev/null || { echo "menu_window: $tool is not installed; skipping"; exit 77; }
done
rm -rf "$out"; mkdir -p "$out"
export XDG_CONFIG_HOME="$out/config"

# run_menu LOG KEYS: starts the game without --level, waits for its window, runs KEYS (bash
# with $win set), then waits for the game to quit (KEYS end on the menu's Quit).
run_menu() {
  xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
    arcfire="$1"; log="$2"; keys="$3"
    "$arcfire" --size 1280x720 >"$log" 2>&1 &
    pid=$!
    win=$(timeout 60 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
    if [ -z "$win" ]; then echo "menu_window: no Arcfire window appeared"; kill $pid; cat "$log"; exit 1; fi
    xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
    # The menu loads the models of every listed mission before it takes keys; a loaded machine needs longer.
    sleep 4
    key() { xdotool key --window "$win" "$@"; sleep 0.5; }
    eval "$keys"
    for i in $(seq 1 20); do kill -0 $pid 2>/dev/null || exit 0; sleep 0.5; done
    echo "menu_window: the game did not quit from the menu"; kill -TERM $pid; cat "$log"; exit 1
  ' _ "$arcfire" "$@"
}

# Settings is the third item of the main menu; at 1280x720 its row is at y 228.
run_menu "$out/first.log" '
  xdotool mousemove --window "$win" 640 228; sleep 0.5; xdotool click --window "$win" 1; sleep 0.5
  key Down Down; key Return; key Right; key Right
  key Down Down Down; key Return
  key Return; key v
  key Escape; key Escape; key Escape; key Up; key Return' || exit 1
settings="$XDG_CONFIG_HOME/arcfire/settings.json"
[ -s "$settings" ] || { echo "menu_window: no $settings"; cat "$out/first.log"; exit 1; }
grep -q '"mouse_sensitivity": 0.14' "$settings" || { echo "menu_window: sensitivity not kept"; cat "$settings"; exit 1; }
grep -q '"fire_primary": "V"' "$settings" || { echo "menu_window: remap not kept"; cat "$settings"; exit 1; }
# The second start reads them back without complaint and quits from the menu.
run_menu "$out/second.log" 'key Up; key Return' || exit 1
if ls "$XDG_CONFIG_HOME/arcfire/"*.bak >/dev/null 2>&1; then
  echo "menu_window: a file was replaced on the second start"; cat "$out/second.log"; exit 1
fi
grep -q '"fire_primary": "V"' "$settings" || { echo "menu_window: remap lost on restart"; cat "$settings"; exit 1; }
echo "menu_window: sensitivity and the remapped key were kept across a restart"
