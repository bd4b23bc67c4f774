#!/usr/bin/env bash
# full_disk.sh ARCFIRE DIR MODE
# Writes onto a full disk: headless frames, replay snapshots, --update-golden and --summary.
# Each must exit 1 with one stderr line naming the file and "No space left on device", print
# no "wrote N frames", leave every old file byte for byte as it was and no partial or temporary
# file behind (a file written before the disk filled is complete).
# MODE tmpfs:  DIR becomes a 64 KiB tmpfs (needs root; exits 77, ctest's skip, when mount is
#              not permitted). Filler files take the space each case needs taken.
# MODE inject: ARCFIRE_WRITE_LIMIT=N makes arcfire's writes fail after N bytes as a full disk
#              would (core/file_writer.h), so the test runs anywhere.
set -u
arcfire="$(realpath "$1")"; dir="$2"; mode="$3"
fail() { echo "full_disk ($mode): $*"; exit 1; }

mkdir -p "$dir"
if [ "$mode" = tmpfs ]; then
  mountpoint -q "$dir" && umount "$dir"
  mount -t tmpfs -o size=64k tmpfs "$dir" 2>/dev/null ||
    { echo "full_disk: cannot mount a tmpfs on $dir (not root?); skipping"; exit 77; }
  trap 'umount "$dir"' EXIT
fi
side="$dir.side"  # outputs that must not fail live off the full disk
rm -rf "$side"; mkdir -p "$side"

# fresh FILLER_KB: an empty DIR; on the tmpfs, FILLER_KB of it taken.
fresh() {
  rm -rf "${dir:?}"/* "$side"/*
  if [ "$mode" = tmpfs ] && [ "$1" -gt 0 ]; then head -c $(($1 * 1024)) /dev/zero >"$dir/filler"; fi
}

# run_full NAME LIMIT CMD...: runs CMD with the write limit (inject mode) and checks exit 1,
# one stderr line about a full disk, no "wrote" on stdout.
run_full() {
  local name="$1" limit="$2"; shift 2
  local env=()
  [ "$mode" = inject ] && env=(env "ARCFIRE_WRITE_LIMIT=$limit")
  "${env[@]}" "$@" >"$side/$name.out" 2>"$side/$name.err"
  local code=$?
  [ "$code" -eq 1 ] || fail "$name: exit $code, expected 1; stderr: $(cat "$side/$name.err")"
  [ "$(grep -c '' "$side/$name.err")" -eq 1 ] || fail "$name: expected one stderr line, got: $(cat "$side/$name.err")"
  grep -q "^arcfire: $dir/.*: cannot write: No space left on device$" "$side/$name.err" ||
    fail "$name: the line does not name the file and the reason: $(cat "$side/$name.err")"
  ! grep -q "wrote" "$side/$name.out" || fail "$name: reported success: $(grep wrote "$side/$name.out")"
  echo "ok: $name: $(cat "$side/$name.err")"
}

# Nothing but the expected files: no temporary or partial one.
only_files() {
  local where="$1"; shift
  local found; found="$(cd "$where" && find . -type f ! -name filler | sort | tr '\n' ' ')"
  [ "$found" = "$* " ] || fail "files in $where: '$found', expected '$* '"
}

complete_png() { tail -c 8 "$1" | grep -q IEND; }

# Frames: four old frames; those not yet written stay old, the ones written are whole PNGs.
fresh 8
mkdir -p "$dir/frames"
for t in 000030 000060 000090 000120; do echo "old frame $t" >"$dir/frames/frame_$t.png"; done
run_full frames 30000 "$arcfire" --headless --level levels/duel.json --ticks 120 --every 30 --size 320x180 --out "$dir/frames"
old=0
for t in 000030 000060 000090 000120; do
  f="$dir/frames/frame_$t.png"
  if echo "old frame $t" | cmp -s - "$f"; then old=$((old + 1)); else complete_png "$f" || fail "$f is cut short"; fi
done
[ "$old" -ge 1 ] || fail "every frame was replaced: the disk never filled"
only_files "$dir/frames" ./frame_000030.png ./frame_000060.png ./frame_000090.png ./frame_000120.png

# Replay snapshots: the old snapshot stays.
fresh 32
mkdir -p "$dir/snap"
echo "old snapshot" >"$dir/snap/tick060.png"
run_full snapshot 20000 "$arcfire" --headless --replay tests/replays/scene_duel.replay --out "$dir/snap"
[ "$(cat "$dir/snap/tick060.png")" = "old snapshot" ] || fail "the old snapshot was replaced"
only_files "$dir/snap" ./tick060.png

# --update-golden: the snapshot goes to --out off the full disk; the goldens (PNG, hash log and
# the script's hash lines) are all kept as they were.
fresh 0
mkdir -p "$dir/g/golden"
cp tests/replays/scene_duel.replay "$dir/g/"
cp -r tests/replays/golden/scene_duel "$dir/g/golden/"
sed -i 's/^60 full_hash .*/60 full_hash ?/' "$dir/g/scene_duel.replay"
(cd "$dir/g" && md5sum scene_duel.replay golden/scene_duel/*) >"$side/golden.md5"
# Room for the snapshot in --out and little more, so the first golden write finds the disk full.
golden_room=$(($(wc -c <tests/replays/golden/scene_duel/tick060.png) + 100))
run_full golden "$golden_room" "$arcfire" --headless --replay "$dir/g/scene_duel.replay" --update-golden --out "$side/snap"
(cd "$dir/g" && md5sum --quiet -c "$side/golden.md5") || fail "a golden file changed"
only_files "$dir/g" ./golden/scene_duel/hashes.txt ./golden/scene_duel/tick060.png ./scene_duel.replay

# --summary: the old summary stays.
fresh 60
echo "old summary" >"$dir/summary.json"
run_full summary 100 "$arcfire" --headless --no-render --level levels/duel.json --ticks 60 --summary "$dir/summary.json"
[ "$(cat "$dir/summary.json")" = "old summary" ] || fail "the old summary was replaced"
only_files "$dir" ./summary.json
echo "ok: frames, snapshots, goldens and the summary survive a full disk ($mode)"
