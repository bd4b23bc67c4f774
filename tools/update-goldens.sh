#!/usr/bin/env bash
# Regenerates every golden image (unit-test goldens and replay snapshots). Review the changed
# PNGs before committing them.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/tools/build.sh"
cd "$root"
for t in build/test_gfx build/test_app; do
  [ -x "$t" ] && ARCFIRE_UPDATE_GOLDEN=1 "$t" --gtest_filter='*Golden*'
done
for s in tests/replays/*.replay; do
  [ -e "$s" ] || continue
  ./build/arcfire --headless --replay "$s" --update-golden --out "build/replay-out/$(basename "$s" .replay)" || true
done
git status --short -- tests
