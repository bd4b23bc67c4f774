#!/usr/bin/env bash
# The headless command of README writes frame_000030.png .. frame_000120.png, non-blank.
set -eu
arcfire="$1"; out="$2"
rm -rf "$out"
"$arcfire" --headless --level levels/duel.json --ticks 120 --every 30 --size 320x180 --out "$out"
for t in 000030 000060 000090 000120; do
  f="$out/frame_$t.png"
  [ -s "$f" ] || { echo "missing $f"; exit 1; }
done
# Non-blank: the PNG of a black or flat frame compresses to almost nothing.
size=$(stat -c %s "$out/frame_000120.png")
[ "$size" -gt 4000 ] || { echo "frame_000120.png is only $size bytes: blank?"; exit 1; }
echo "ok: 4 frames, last is $size bytes"
