#!/usr/bin/env bash
# damaged_golden.sh ARCFIRE OUT_DIR
# A golden PNG cut short, not a PNG at all or a folder is one FAIL line naming it and why, exit
# 1, and nothing on stderr: libpng's own complaints must not reach the terminal. A hash log cut
# short is one line naming it (exit 2).
set -u
arcfire="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out/golden/scene_duel"
cp tests/replays/scene_duel.replay "$out/"
cp tests/replays/golden/scene_duel/hashes.txt "$out/golden/scene_duel/"
for damage in cut garbage folder; do
  png="$out/golden/scene_duel/tick060.png"
  rm -rf "$png"
  case "$damage" in
    cut) head -c 3000 tests/replays/golden/scene_duel/tick060.png >"$png" ;;
    garbage) echo garbage >"$png" ;;
    folder) mkdir "$png" ;;
  esac
  "$arcfire" --headless --replay "$out/scene_duel.replay" --out "$out/snap" >"$out/stdout" 2>"$out/stderr"
  code=$?
  [ "$code" -eq 1 ] || { echo "damaged_golden ($damage): exit $code, expected 1"; cat "$out/stderr"; exit 1; }
  [ ! -s "$out/stderr" ] || { echo "damaged_golden ($damage): stderr is not empty:"; cat "$out/stderr"; exit 1; }
  fails=$(grep -c '^FAIL ' "$out/stdout")
  line=$(grep '^FAIL ' "$out/stdout")
  why="golden image damaged: $png: "
  [ "$damage" = folder ] && why="golden image $png is a folder, not a PNG file"
  [ "$fails" -eq 1 ] && grep -q "snapshot tick060: $why" <<<"$line" ||
    { echo "damaged_golden ($damage): expected one FAIL line naming $png:"; cat "$out/stdout"; exit 1; }
  echo "ok ($damage): $line"
done
rm -rf "$out/golden/scene_duel/tick060.png"
cp tests/replays/golden/scene_duel/tick060.png "$out/golden/scene_duel/"
head -c -20 tests/replays/golden/scene_duel/hashes.txt >"$out/golden/scene_duel/hashes.txt"
"$(dirname "$0")/expect.sh" 2 "hashes.txt:[0-9]+:[0-9]+: .*(cut short|16 hex digits)" -- \
  "$arcfire" --headless --no-render --replay "$out/scene_duel.replay" || exit 1
