#!/usr/bin/env bash
# legal_extremes.sh ARCFIRE WORK_DIR
# The largest honest inputs the limits are set from (engine/core/input_limits.h) load and run:
# a generated level of 10 000 ships, and a ship class of 100 000 exhaust points pretty-printed
# (about 8 MB) flown by the player. Each runs a tick without rendering and must exit 0; the time
# each takes is printed, not asserted. Each must fit in 500 MB of address space: a ship carries
# at most 8 exhaust plumes whatever its count of points. Run from the source tree (the data root).
set -u
arcfire="$(realpath "$1")"; work="$2"
src="$(pwd)"
rm -rf "$work"; mkdir -p "$work"; work="$(realpath "$work")"
failures=0

run() {
  local what="$1"; shift
  local t0 t1 code
  t0=$(date +%s.%N)
  ( ulimit -v 500000; exec timeout -s KILL 300 "$arcfire" "$@" >"$work/stdout" 2>"$work/stderr" )
  code=$?
  t1=$(date +%s.%N)
  local secs
  secs=$(awk "BEGIN { printf \"%.2f\", $t1 - $t0 }")
  if [ "$code" -ne 0 ]; then
    failures=$((failures + 1))
    echo "FAIL $what: exit $code in ${secs}s"
    head -c 600 "$work/stderr"
  else
    echo "ok   $what: loaded and ran a tick in ${secs}s"
  fi
}

# A level of 10 000 ships: two fleets of 5 000 in 50 m grids, 2 km apart.
awk 'BEGIN {
  print "{ \"name\": \"Fleets\", \"seed\": 7, \"objective\": \"Win.\",";
  print "  \"win\": { \"type\": \"destroy_all_hostiles\" }, \"lose\": { \"type\": \"player_destroyed\" },";
  print "  \"ships\": [";
  for (i = 0; i < 10000; i++) {
    team = i < 5000 ? "blue" : "red"; j = i % 5000;
    z = i < 5000 ? 1000 : -1000;
    printf "    { \"name\": \"S%d\", \"class\": \"viper\", \"team\": \"%s\"%s, \"position\": [%d, %d, %d] }%s\n",
      i, team, i == 0 ? ", \"player\": true" : "", (j % 100) * 50, int(j / 100) * 50, z, i < 9999 ? "," : "";
  }
  print "  ] }";
}' >"$work/fleets.json"
echo "fleets.json: $(wc -c <"$work/fleets.json") bytes"
run "a level of 10 000 ships" --headless --no-render --ticks 1 --level "$work/fleets.json"

# A ship class of 100 000 exhausts, one number a line as a JSON writer with indentation puts it.
mkdir -p "$work/root/assets/ships"
for top in levels shaders; do ln -s "$src/$top" "$work/root/$top"; done
for sub in "$src"/assets/*; do [ "$(basename "$sub")" = ships ] || ln -s "$sub" "$work/root/assets/$(basename "$sub")"; done
for f in "$src"/assets/ships/*.json; do ln -s "$f" "$work/root/assets/ships/$(basename "$f")"; done
{
  grep -v '"exhausts"' "$src/assets/ships/viper.json" | sed '$d' | sed '$s/,*$/,/'
  echo '  "exhausts": ['
  awk 'BEGIN {
    for (i = 0; i < 100000; i++)
      printf "    [\n      %.4f,\n      %.4f,\n      %.4f\n    ]%s\n", -8 + (i % 400) * 0.04, -2 + int(i / 400) * 0.016, 6.125, i < 99999 ? "," : "";
  }'
  echo '  ]'
  echo '}'
} >"$work/root/assets/ships/vents.json"
echo "vents.json: $(wc -c <"$work/root/assets/ships/vents.json") bytes"
sed '0,/"class": "viper"/s//"class": "vents"/' "$src/levels/duel.json" >"$work/vents_level.json"
run "a ship of 100 000 exhaust points" --headless --no-render --ticks 1 --data "$work/root" --level "$work/vents_level.json"

[ "$failures" -eq 0 ]
