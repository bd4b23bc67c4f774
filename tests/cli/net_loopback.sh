#!/usr/bin/env bash
# net_loopback.sh ARCFIRE OUT_DIR PILOTS TICKS LEVEL [--set key=value ...]
# A network match on the loopback: a headless host and PILOTS-1 headless pilots, each flying the
# scripted test pilot, TICKS ticks of LEVEL. Every process must end with 0 and print the same hash
# at the same final tick; every match record must replay to its hashes (--replay-match).
set -u
arcfire="$1"; out="$2"; pilots="$3"; ticks="$4"; level="$5"; shift 5
mkdir -p "$out"
port=$(( 30000 + ($$ % 20000) ))
pids=()
"$arcfire" --headless --host --port "$port" --players "$pilots" --level "$level" --ticks "$ticks" --net-pilot scripted \
  --name Host --match-record "$out/match_0.txt" "$@" >"$out/peer_0.log" 2>&1 &
pids+=($!)
sleep 1
for ((i = 1; i < pilots; i++)); do
  "$arcfire" --headless --join "127.0.0.1:$port" --ticks "$ticks" --net-pilot scripted --name "Pilot$i" \
    --match-record "$out/match_$i.txt" "$@" >"$out/peer_$i.log" 2>&1 &
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
  "$arcfire" --headless --replay-match "$out/match_$i.txt" || { echo "net_loopback: match record $i does not replay"; exit 1; }
done
echo "ok: $pilots pilots, tick $ticks, hash ${first#* }"
