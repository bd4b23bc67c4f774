#!/usr/bin/env bash
# check_threads.sh ARCFIRE SCRIPT
# Replays SCRIPT with sim.threads = 1, 2, 4, 8 and 16. A replay compares its cheap state hash
# with the golden log (golden/NAME/hashes.txt) on every tick and the full hash every 60 ticks,
# so each passing run has the same hash of every tick as the log.
set -u
arcfire="$1"; script="$2"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
for t in 1 2 4 8 16; do
  if ! "$arcfire" --headless --no-render --replay "$script" --set sim.threads=$t >"$log" 2>&1; then
    echo "check_threads: $script fails with sim.threads=$t:"; tail -5 "$log"; exit 1
  fi
  echo "sim.threads=$t: $(tail -n 1 "$log")"
done
