#!/usr/bin/env bash
# output_never_input.sh ARCFIRE OUT_DIR
# An output never replaces an input: each run below names one of its inputs (the level, a ship
# class of a mod, a frame name in --out, a replay's script or golden image) as an output, by the
# same path, another spelling, a symbolic link or a hard link. Each must exit 2 with one line
# naming both, before anything is written: every input stays byte-identical.
set -u
arcfire="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out/mod/assets/ships" "$out/frames" "$out/golden/scene_duel"
fail() { echo "output_never_input: $*"; exit 1; }
cp levels/duel.json "$out/d.json"
ln -s d.json "$out/link.json"
ln "$out/d.json" "$out/hard.json"
cp assets/ships/viper.json "$out/mod/assets/ships/viper.json"
cp levels/duel.json "$out/frames/frame_000030.png"
cp tests/replays/scene_duel.replay "$out/scene_duel.replay"
cp tests/replays/golden/scene_duel/* "$out/golden/scene_duel/"
sums() { find "$out" -type f ! -name '*.err' -exec md5sum {} + | sort; }
before=$(sums)

refused() {  # refused WHAT -- ARGS...: exit 2, one line saying an output is an input
  local what="$1"; shift 2
  "$arcfire" "$@" >/dev/null 2>"$out/run.err"; local code=$?
  [ "$code" -eq 2 ] || fail "$what: exit $code, expected 2: $(cat "$out/run.err")"
  [ "$(grep -c '' "$out/run.err")" -eq 1 ] || fail "$what: expected one line: $(cat "$out/run.err")"
  grep -Eq "is the same file as .*; an output may not replace an input" "$out/run.err" ||
    fail "$what: the line does not name both: $(cat "$out/run.err")"
  echo "ok ($what): $(cat "$out/run.err")"
}
run=(--headless --no-render --ticks 1)
refused "summary is the level" -- "${run[@]}" --level "$out/d.json" --summary "$out/d.json"
refused "summary by another spelling" -- "${run[@]}" --level "$out/d.json" --summary "$out/frames/../d.json"
refused "summary is a link to the level" -- "${run[@]}" --level "$out/d.json" --summary "$out/link.json"
refused "summary is a hard link to the level" -- "${run[@]}" --level "$out/link.json" --summary "$out/hard.json"
refused "sound is the level" -- "${run[@]}" --level "$out/d.json" --audio-out "$out/hard.json"
refused "summary is a ship class" -- "${run[@]}" --mod "$out/mod" --summary "$out/mod/assets/ships/viper.json"
refused "a frame is the level" -- --headless --ticks 30 --every 30 --size 32x32 --level "$out/frames/frame_000030.png" --out "$out/frames"
refused "sound is the replay" -- --replay "$out/scene_duel.replay" --no-render --audio-out "$out/scene_duel.replay"
refused "snapshots over their goldens" -- --headless --replay "$out/scene_duel.replay" --out "$out/golden/scene_duel"
[ "$(sums)" = "$before" ] || fail "an input changed"
[ -L "$out/link.json" ] || fail "the link is gone"
echo "ok: every input byte-identical"
