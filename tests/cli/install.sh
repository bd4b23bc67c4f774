#!/usr/bin/env bash
# install.sh BUILD WORK REPLAYS: `cmake --install BUILD --prefix WORK/prefix`, then the installed
# game run from a folder that holds nothing of the game: --version names the prefix's data, the
# image codec comes from the prefix, a headless frame renders, replays of the game's own levels
# (copied out of REPLAYS with their goldens) pass, and a window opens and quits (under xvfb-run,
# when it and xdotool are there).
set -u
build="$(cd "$1" && pwd)"; work="$2"; replays="$(cd "$3" && pwd)"
fail() { echo "cli_install_prefix: $*"; exit 1; }
rm -rf "$work"; mkdir -p "$work/elsewhere" "$work/replays"
work="$(cd "$work" && pwd -P)"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install failed"; }

for f in bin/arcfire lib/arcfire/libarcfire_image_codec.so share/applications/arcfire.desktop \
         share/icons/hicolor/256x256/apps/arcfire.png share/doc/arcfire/README.md \
         share/arcfire/levels/duel.json share/arcfire/assets/settings/quality.json share/arcfire/shaders/mesh.frag; do
  [ -s "$prefix/$f" ] || fail "missing $prefix/$f"
done
# Only what the game reads: no tests, tools or format notes in the data.
extra="$(cd "$prefix" && find . -type f | grep -Ev '^\./(bin/arcfire|lib/arcfire/libarcfire_image_codec\.so|share/applications/arcfire\.desktop|share/icons/hicolor/256x256/apps/arcfire\.png|share/doc/arcfire/README\.md|share/arcfire/(assets|levels|shaders)/.*\.(json|glb|png|wav|vert|frag))$')"
[ -z "$extra" ] || fail "installed files the game does not read: $extra"
grep -q '^Exec=arcfire$' "$prefix/share/applications/arcfire.desktop" || fail "the desktop entry does not start arcfire"
grep -q '^Icon=arcfire$' "$prefix/share/applications/arcfire.desktop" || fail "the desktop entry names no arcfire icon"

cd "$work/elsewhere"
unset ARCFIRE_DATA
game="$prefix/bin/arcfire"
version="$("$game" --version)" || fail "--version exited $?"
echo "$version"
grep -qx "data: $prefix/share/arcfire (beside the executable)" <<<"$version" || fail "--version does not name $prefix/share/arcfire"

# A headless frame, the image codec loaded from the prefix (LD_DEBUG names each file loaded).
LD_DEBUG=files "$game" --headless --ticks 30 --every 30 --size 320x180 --out frames >frames.log 2>&1
code=$?
[ "$code" -eq 0 ] || { grep -v '^ *[0-9]*:' frames.log | tail -5; fail "headless frame: exit $code"; }
grep -q "file=$prefix/lib/arcfire/libarcfire_image_codec.so .*dynamically loaded" frames.log ||
  fail "the image codec was not loaded from $prefix/lib/arcfire"
size=$(stat -c %s frames/frame_000030.png 2>/dev/null || echo 0)
[ "$size" -gt 4000 ] || fail "frames/frame_000030.png is $size bytes: missing or blank"
echo "ok: a headless frame of $size bytes, codec from the prefix"

# Replays of the game's own levels: the data is the prefix's, the scripts and goldens are copies.
for name in arena duel_pause_resume skirmish_wingman scene_duel; do
  cp "$replays/$name.replay" "$work/replays/"
  [ -d "$replays/golden/$name" ] && mkdir -p "$work/replays/golden" && cp -r "$replays/golden/$name" "$work/replays/golden/"
  "$game" --headless --replay "$work/replays/$name.replay" --out "out/$name" >"$name.log" 2>&1
  code=$?
  [ "$code" -eq 0 ] || { tail -5 "$name.log"; fail "replay $name: exit $code"; }
  last="$(tail -n 1 "$name.log")"
  grep -Eq '^final hash [0-9a-f]{16} at tick [0-9]+$' <<<"$last" || fail "replay $name ended with '$last'"
  echo "ok: replay $name: $last"
done

if command -v xvfb-run >/dev/null && command -v xdotool >/dev/null; then
  xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
    game="$1"
    "$game" --level levels/duel.json --size 640x360 --frame-times ft.csv >window.log 2>&1 &
    pid=$!
    win=$(timeout 30 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
    if [ -z "$win" ]; then echo "no Arcfire window appeared"; kill $pid; cat window.log; exit 1; fi
    xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
    sleep 3
    # Each key held for a while, so a slow frame cannot miss it: Esc, down to Quit, Enter.
    press() { xdotool keydown "$1"; sleep 0.3; xdotool keyup "$1"; sleep 0.5; }
    press Escape
    for i in 1 2 3 4 5; do press Down; done
    press Return
    for i in $(seq 1 300); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
    if kill -0 $pid 2>/dev/null; then echo "Quit did not end the game"; kill $pid; exit 1; fi
    wait $pid
  ' _ "$game" || { cat window.log 2>/dev/null; fail "the installed game in a window failed"; }
  rows=$(($(wc -l < ft.csv) - 1))
  [ "$rows" -ge 10 ] || fail "the window drew only $rows frames"
  echo "ok: a window of the installed game, $rows frames"
else
  echo "window part skipped: xvfb-run or xdotool is not installed"
fi
echo "cli_install_prefix: the installed game runs from $work/elsewhere"
