#!/usr/bin/env bash
# net_loopback.sh ARCFIRE OUT_DIR PILOTS TICKS LEVEL [--set key=value ...]
# A network match on the loopback: a headless host and PILOTS-1 headless pilots, each flying the
# scripted test pilot, TICKS ticks of LEVEL. Every process must end with 0 and print the same hash
# at the same final tick. Every peer's match record is a replay script: each must hold the same
# hashes, and `--replay` must play it to them and to the peer's final hash; the host's record
# also plays with --audio-out and with a snapshot line added.
set -u
arcfire="$1"; out="$2"; pilots="$3"; ticks="$4"; level="$5"; shift 5
mkdir -p "$out"
port=$(( 30000 + ($$ % 20000) ))
pids=()
"$arcfire" --headless --host --port "$port" --players "$pilots" --level "$level" --ticks "$ticks" --net-pilot scripted \
  --name Host --match-record "$out/match_0.replay" "$@" >"$out/peer_0.log" 2>&1 &
pids+=($!)
sleep 1
for ((i = 1; i < pilots; i++)); do
  "$arcfire" --headless --join "127.0.0.1:$port" --ticks "$ticks" --net-pilot scripted --name "Pilot$i" \
    --match-record "$out/match_$i.replay" "$@" >"$out/peer_$i.log" 2>&1 &
  pids+=($!)
done
fail=0
for ((i = 0; i < pilots; i++)); do
  wait "${pids[$i]}" || { echo "net_loopback: peer $i exited $?:"; cat "$out/peer_$i.log"; fail=1; }
done
[ $fail -eq 0 ] || exit 1
first=""
for ((i = 0; i < pilots; i++)); do
  line=$(grep "final tick" "$out/peer_$i.log")
  echo "peer $i: $line"
  h=$(echo "$line" | sed -n 's/.*final tick \([0-9]*\) hash \([0-9a-f]*\).*/\1 \2/p')
  [ "${h%% *}" = "$ticks" ] || { echo "net_loopback: peer $i ended at tick ${h%% *}, not $ticks"; exit 1; }
  [ -z "$first" ] && first="$h"
  [ "$h" = "$first" ] || { echo "net_loopback: peer $i's hash differs: $h vs $first"; exit 1; }
  rec="$out/match_$i.replay"
  "$arcfire" --headless --no-render --replay "$rec" >"$out/replay_$i.log" 2>&1 ||
    { echo "net_loopback: match record $i does not replay:"; tail -5 "$out/replay_$i.log"; exit 1; }
  replayed=$(sed -n 's/^final hash \([0-9a-f]*\) at tick \([0-9]*\).*/\2 \1/p' "$out/replay_$i.log")
  [ "$replayed" = "$h" ] || { echo "net_loopback: record $i replays to '$replayed', the peer ended at '$h'"; exit 1; }
  grep -E '^[0-9]+ hash ' "$rec" >"$out/hashes_$i.txt"
  [ -s "$out/hashes_$i.txt" ] || { echo "net_loopback: record $i holds no hashes"; exit 1; }
  cmp -s "$out/hashes_0.txt" "$out/hashes_$i.txt" || { echo "net_loopback: records 0 and $i hold different hashes"; exit 1; }
  echo "peer $i: record replays, $(wc -l <"$out/hashes_$i.txt") hashes as peer 0's"
done
# Like any replay: its sound, and a frame from a snapshot line added at its end.
"$arcfire" --headless --no-render --replay "$out/match_0.replay" --audio-out "$out/match_0.wav" >/dev/null 2>&1 &&
  [ -s "$out/match_0.wav" ] || { echo "net_loopback: --audio-out of the record failed"; exit 1; }
sed "s/^\($ticks\) end\$/\1 snapshot last\n\1 end/" "$out/match_0.replay" >"$out/match_shot.replay"
rm -rf "$out/golden"
"$arcfire" --headless --replay "$out/match_shot.replay" --update-golden --out "$out/shot" >"$out/shot.log" 2>&1 &&
  [ -s "$out/golden/match_shot/last.png" ] || { echo "net_loopback: a snapshot of the record failed:"; tail -5 "$out/shot.log"; exit 1; }
echo "ok: $pilots pilots, tick $ticks, hash ${first#* }"
