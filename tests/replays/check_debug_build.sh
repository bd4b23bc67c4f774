#!/usr/bin/env bash
# check_debug_build.sh [RELEASE_BUILD_DIR] [DEBUG_BUILD_DIR]
# Determinism across build types: builds arcfire as Release (default build/) and as Debug
# (default build-debug/) from the same sources, replays every script with --no-render in
# both, and requires the same `final hash` line from each (and, when the goldens are current,
# both pass). A second configuration does not fit CI's time budget, so this runs by hand after
# touching simulation code or compiler flags; CI's Release build checks the recorded hashes.
set -eu
root="$(cd "$(dirname "$0")/../.." && pwd)"
release="${1:-$root/build}"
debug="${2:-$root/build-debug}"
cmake -S "$root" -B "$release" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake -S "$root" -B "$debug" -DCMAKE_BUILD_TYPE=Debug -DARCFIRE_BUILD_BENCH=OFF >/dev/null
make -C "$release" -j2 arcfire >/dev/null
make -C "$debug" -j2 arcfire >/dev/null
cd "$root"
failed=0
for s in tests/replays/*.replay; do
  name="$(basename "$s" .replay)"
  "$release/arcfire" --headless --no-render --replay "$s" >"$release/debugcheck-$name.log" 2>&1 || true
  "$debug/arcfire" --headless --no-render --replay "$s" >"$debug/debugcheck-$name.log" 2>&1 || true
  r="$(tail -n 1 "$release/debugcheck-$name.log")"; d="$(tail -n 1 "$debug/debugcheck-$name.log")"
  if [ "$r" = "$d" ] && [[ "$r" == final\ hash* ]]; then
    echo "same $name: $r"
  else
    echo "DIFF $name: Release '$r', Debug '$d' (logs: $release/debugcheck-$name.log, $debug/debugcheck-$name.log)"
    failed=1
  fi
done
exit $failed
