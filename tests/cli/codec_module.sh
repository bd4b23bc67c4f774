#!/usr/bin/env bash
# codec_module.sh ARCFIRE OUT_DIR
# The image codec module is looked for next to the executable first, then at its build path:
# a copy of the game alone in a folder still renders (it finds the build's module), and a
# copy beside a damaged module answers with one line naming that module, exit 2.
set -u
arcfire="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out/alone" "$out/broken"
cp "$arcfire" "$out/alone/arcfire"
cp "$arcfire" "$out/broken/arcfire"
echo "not a shared library" >"$out/broken/libarcfire_image_codec.so"
# A copy away from the build has no arcfire-data-root beside it: the data is named (core/data_root.h).
run=(--data . --headless --level levels/duel.json --ticks 30 --every 30 --size 160x90)

"$out/alone/arcfire" "${run[@]}" --out "$out/alone/frames" >/dev/null 2>"$out/alone/stderr" ||
  { echo "alone: exit $?, expected 0:"; cat "$out/alone/stderr"; exit 1; }
[ -s "$out/alone/frames/frame_000030.png" ] || { echo "alone: no frame written"; exit 1; }
echo "ok (alone): the build's module was found"

"$out/broken/arcfire" "${run[@]}" --out "$out/broken/frames" >/dev/null 2>"$out/broken/stderr"
code=$?
msg="$(cat "$out/broken/stderr")"
[ "$code" -eq 2 ] || { echo "broken: exit $code, expected 2: $msg"; exit 1; }
[ "$(grep -c '' "$out/broken/stderr")" -eq 1 ] || { echo "broken: expected one line: $msg"; exit 1; }
grep -q "^arcfire: $out/broken/libarcfire_image_codec.so: cannot load the image codec module" <<<"$msg" ||
  { echo "broken: the line does not name the module next to the executable: $msg"; exit 1; }
echo "ok (broken): $msg"
