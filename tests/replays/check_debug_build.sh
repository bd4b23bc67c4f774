#!/usr/bin/env bash
# check_debug_build.sh [BUILD_DIR]
# Determinism across build types: builds arcfire as Debug (default build-debug/) and replays
# every script with --no-render. The scripts' hash lines and golden hash logs were recorded
# by a Release build, so every replay passing means Debug and Release simulate bit for bit
# alike. Too slow for CI's budget (a second full build); run it after touching simulation
# code or compiler flags.
set -eu
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build-debug}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DARCFIRE_BUILD_BENCH=OFF >/dev/null
make -C "$build" -j2 arcfire
cd "$root"
failed=0
for s in tests/replays/*.replay; do
  if "$build/arcfire" --headless --no-render --replay "$s" >"$build/replay-$(basename "$s" .replay).log" 2>&1; then
    echo "ok   $s: $(tail -n 1 "$build/replay-$(basename "$s" .replay).log")"
  else
    echo "FAIL $s (log: $build/replay-$(basename "$s" .replay).log)"; failed=1
  fi
done
exit $failed
