#!/usr/bin/env bash
# The one command that rewrites goldens: every replay script under tests/replays/ and the
# benchmark's recorded dogfight (tests/bench/combat_view.replay) (image tests
# are scene_*.replay scripts) replayed with --update-golden, which rewrites its hash lines,
# golden/<script>/hashes.txt and its snapshot PNGs. Scripts whose snapshots compare with
# another script's frames (`snapshots_like`) run last, against the fresh frames. Look at the
# changed PNGs before committing them. Last, the effect filmstrips of tests/preview/golden
# (build/test_preview with ARCFIRE_UPDATE_GOLDEN=1).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/tools/build.sh"
cd "$root"
shopt -s nullglob
update() {
  ./build/arcfire --headless --replay "$1" --update-golden --out "build/replay-out/$(basename "$1" .replay)" || true
}
for s in tests/replays/*.replay tests/bench/*.replay; do
  grep -Eq '^[[:space:]]*snapshots_like[[:space:]]' "$s" || update "$s"
done
for s in tests/replays/*.replay; do
  if grep -Eq '^[[:space:]]*snapshots_like[[:space:]]' "$s"; then update "$s"; fi
done
# The effect filmstrips (tests/preview/golden/*.png).
ARCFIRE_UPDATE_GOLDEN=1 ./build/test_preview || true
git status --short -- tests
