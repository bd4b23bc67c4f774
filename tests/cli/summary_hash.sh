#!/usr/bin/env bash
# summary_hash.sh ARCFIRE OUT_DIR
# The summary's hash is the 16-digit hex string the replay prints ("final hash HEX at tick N")
# for the same 60 ticks of the duel without input: a JSON number above 2^53 would be rounded by
# the tools that read it (jq printed 9335964740700133000 for 9335964740700132916).
set -u
arcfire="$1"; out="$2"
mkdir -p "$out"
"$arcfire" --headless --no-render --level levels/duel.json --ticks 60 --summary "$out/summary.json" >/dev/null || exit 1
replayed=$("$arcfire" --headless --no-render --replay tests/replays/scene_duel.replay | sed -n 's/^final hash \([0-9a-f]*\) at tick 60$/\1/p')
[ ${#replayed} -eq 16 ] || { echo "summary_hash: the replay printed no final hash at tick 60"; exit 1; }
grep -q "^  \"hash\": \"$replayed\",\?$" "$out/summary.json" ||
  { echo "summary_hash: expected \"hash\": \"$replayed\" in the summary:"; grep hash "$out/summary.json"; exit 1; }
echo "ok: summary hash \"$replayed\" as the replay prints it"
