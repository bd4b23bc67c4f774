#!/usr/bin/env bash
# damaged_golden.sh ARCFIRE OUT_DIR
# A golden PNG cut short (or not a PNG at all) is one FAIL line naming it, exit 1, and nothing
# on stderr: libpng's own complaints must not reach the terminal.
set -u
arcfire="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out/golden/scene_duel"
cp tests/replays/scene_duel.replay "$out/"
cp tests/replays/golden/scene_duel/hashes.txt "$out/golden/scene_duel/"
for damage in cut garbage; do
  png="$out/golden/scene_duel/tick060.png"
  if [ "$damage" = cut ]; then head -c 3000 tests/replays/golden/scene_duel/tick060.png >"$png"; else echo garbage >"$png"; fi
  "$arcfire" --headless --replay "$out/scene_duel.replay" --out "$out/snap" >"$out/stdout" 2>"$out/stderr"
  code=$?
  [ "$code" -eq 1 ] || { echo "damaged_golden ($damage): exit $code, expected 1"; cat "$out/stderr"; exit 1; }
  [ ! -s "$out/stderr" ] || { echo "damaged_golden ($damage): stderr is not empty:"; cat "$out/stderr"; exit 1; }
  fails=$(grep -c '^FAIL ' "$out/stdout")
  line=$(grep '^FAIL ' "$out/stdout")
  [ "$fails" -eq 1 ] && grep -q "snapshot tick060: golden image damaged: $png: " <<<"$line" ||
    { echo "damaged_golden ($damage): expected one FAIL line naming $png:"; cat "$out/stdout"; exit 1; }
  echo "ok ($damage): $line"
done
