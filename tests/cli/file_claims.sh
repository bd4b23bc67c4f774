#!/usr/bin/env bash
# file_claims.sh ARCFIRE OUT_DIR PART
# Files that are not what they claim, through the real program: each bad file is laid over the
# data as a mod (or named by its option) and the run must end with exit 2 and one line naming the
# file, the place and what is allowed. PART:
#   gltf        a ship class naming a model of glTF 1.0, one needing Draco, one with an accessor
#               of zero positions, one whose nested node scales overflow (loaded to render)
#   duplicates  a key written twice in a ship class, an effect, the quality presets, the HUD (in
#               a window under xvfb-run) and AI settings, the sounds and the bindings; in
#               settings.json and progress.json the menu shows the line and keeps the file as .bak
#   paths       whole key paths: a ship class's beam.mounts[1][0], a level's ships[1].position[1]
#   limits      a position beyond ±2^30; curve key times equal in float; an integer setting
#               written 50000.0 is accepted, 50000.5 refused
set -u
arcfire="$1"; out="$2"; part="$3"
rm -rf "$out"; mkdir -p "$out"
fail() { echo "file_claims $part: $*"; exit 1; }

# expect_line CODE REGEX -- COMMAND...: exit CODE and, for a non-zero code, one stderr line matching.
expect_line() {
  local want="$1" regex="$2"; shift 3
  local err; err="$("$@" 2>&1 >/dev/null)"; local got=$?
  [ "$got" -eq "$want" ] || fail "exit $got, expected $want: $* -> $err"
  [ "$want" -eq 0 ] && return 0
  [ "$(printf '%s\n' "$err" | grep -c '')" -eq 1 ] || fail "expected one line from $*, got: $err"
  printf '%s\n' "$err" | grep -Eq -- "$regex" || fail "'$err' does not match '$regex'"
  echo "ok: $err"
}

# new_mod NAME: an empty mod folder; prints its path.
new_mod() { mkdir -p "$out/$1/assets/ships" "$out/$1/assets/models" "$out/$1/assets/effects" "$out/$1/assets/settings" "$out/$1/levels"; echo "$out/$1"; }

run_level() {  # run_level MOD [ARGS...]: a headless frame of the duel with the mod laid over the data
  local mod="$1"; shift
  "$arcfire" --mod "$mod" --headless --level levels/duel.json --ticks 1 --size 64x36 --out "$out/frames" "$@"
}
run_sim() {  # the same without GL
  local mod="$1"; shift
  "$arcfire" --mod "$mod" --headless --no-render --level levels/duel.json --ticks 1 "$@"
}

# A one-triangle .gltf with an embedded buffer; ASSET, NODES, COUNT and EXTRA replaced.
gltf() {
  local asset="$1" nodes="$2" count="$3" extra="$4"
  cat <<GLTF
{
  "asset": $asset,
  "scenes": [{"nodes": [0]}],
  "nodes": $nodes,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
  "buffers": [{"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA", "byteLength": 42}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": $count, "type": "VEC3"},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}
  ]$extra
}
GLTF
}

case "$part" in
gltf)
  mod=$(new_mod gltf_mod)
  ok='{"version": "2.0"}'; one='[{"mesh": 0}]'
  gltf "$ok" "$one" 3 "" > "$mod/assets/models/good.gltf"
  gltf '{"version": "1.0"}' "$one" 3 "" > "$mod/assets/models/old.gltf"
  gltf "$ok" "$one" 3 ', "extensionsRequired": ["KHR_draco_mesh_compression"]' > "$mod/assets/models/draco.gltf"
  gltf "$ok" "$one" 0 "" > "$mod/assets/models/empty.gltf"
  gltf "$ok" '[{"name": "hull", "scale": [1e30, 1e30, 1e30], "children": [1]}, {"name": "wing", "scale": [1e30, 1e30, 1e30], "mesh": 0}]' 3 "" \
    > "$mod/assets/models/huge.gltf"
  ship() { sed "s|\"model\": \"assets/models/viper.glb\"|\"model\": \"assets/models/$1\"|" assets/ships/viper.json > "$mod/assets/ships/viper.json"; }
  ship good.gltf
  run_level "$mod" > "$out/good.txt" 2>&1 || { cat "$out/good.txt"; fail "the good model did not load"; }
  ship old.gltf
  expect_line 2 "old\.gltf: asset\.version '1\.0' is not glTF 2\.x; allowed: \"2\.0\" or another 2\.x" -- run_level "$mod"
  ship draco.gltf
  expect_line 2 "draco\.gltf: extensionsRequired lists 'KHR_draco_mesh_compression', which this loader does not implement; allowed: " -- run_level "$mod"
  ship empty.gltf
  expect_line 2 "empty\.gltf: mesh 0 primitive 0: POSITION accessor 0: count is 0; allowed: at least 1" -- run_level "$mod"
  ship huge.gltf
  expect_line 2 "huge\.gltf: node 1 'wing': scale overflows the transform composed from the root \(an entry reaches 1e\+60\); allowed: " -- run_level "$mod"
  ;;
duplicates)
  twice="appears twice in this object \(first at [0-9]+:[0-9]+\); allowed: each key once"
  dup() {  # dup REL_FILE SED_EXPR: the base file with one key written twice, in a mod of its own
    local m; m=$(new_mod "dup_$(basename "$1" .json)")
    sed "$2" "$1" > "$m/$1"
    cmp -s "$1" "$m/$1" && fail "the edit '$2' changed nothing in $1"
    echo "$m"
  }
  m=$(dup assets/ships/viper.json 's/"mass": 12000,/"mass": 12000, "mass": 9000,/')
  expect_line 2 "viper\.json:4:[0-9]+: key 'mass' $twice" -- run_sim "$m"
  m=$(dup assets/effects/shield_hit.json 's/"lifetime": 0.35,/"lifetime": 0.35, "lifetime": 0.5,/')
  expect_line 2 "shield_hit\.json:[0-9]+:[0-9]+: key 'lifetime' $twice" -- run_sim "$m"
  m=$(dup assets/settings/quality.json '0,/"render.scale": 0.5,/s//"render.scale": 0.5, "render.scale": 0.6,/')
  expect_line 2 "quality\.json:[0-9]+:[0-9]+: key 'render\.scale' $twice" -- run_sim "$m" --quality low
  m=$(dup assets/settings/hud.json 's/"hit_marker_seconds": 0.25,/"hit_marker_seconds": 0.25, "hit_marker_seconds": 1,/')
  # The HUD settings are read by the window only: under xvfb-run when it is there.
  if command -v xvfb-run > /dev/null; then
    expect_line 2 "hud\.json:[0-9]+:[0-9]+: key 'hit_marker_seconds' $twice" -- \
      timeout 60 xvfb-run -a "$arcfire" --mod "$m" --level levels/duel.json --size 320x180
  else
    echo "skipped: hud.json (no xvfb-run)"
  fi
  m=$(dup assets/settings/ai.json '0,/"jink": 0,/s//"jink": 0, "jink": 1,/')
  expect_line 2 "ai\.json:[0-9]+:[0-9]+: key 'jink' $twice" -- run_sim "$m"
  sed 's/"doppler_factor": 1,/"doppler_factor": 1, "doppler_factor": 2,/' assets/sounds/sounds.json > "$out/sounds.json"
  expect_line 2 "sounds\.json:[0-9]+:[0-9]+: key 'doppler_factor' $twice" -- \
    "$arcfire" --headless --no-render --ticks 1 --sounds "$out/sounds.json"
  sed 's/"throttle_zero": "X",/"throttle_zero": "X", "throttle_zero": "Z",/' assets/settings/bindings.json > "$out/bindings.json"
  expect_line 2 "bindings\.json:[0-9]+:[0-9]+: key 'throttle_zero' $twice" -- \
    "$arcfire" --headless --no-render --ticks 1 --bindings "$out/bindings.json"
  # The player's own files: the menu says what is wrong and keeps the file as .bak.
  for f in settings progress; do
    cfg="$out/config_$f"; mkdir -p "$cfg/arcfire"
    if [ $f = settings ]; then body='"fov": 70, "fov": 80'; key=fov; else body='"best": {}, "best": {}'; key=best; fi
    printf '{ "format": 1, %s }\n' "$body" > "$cfg/arcfire/$f.json"
    printf 'back\n' > "$out/menu.ui"
    XDG_CONFIG_HOME="$cfg" "$arcfire" --headless --no-render --menu-script "$out/menu.ui" > "$out/menu_$f.txt" 2>&1 ||
      { cat "$out/menu_$f.txt"; fail "the menu did not run with a bad $f.json"; }
    grep -Eq "$f\.json:1:[0-9]+: key '$key' $twice" "$out/menu_$f.txt" ||
      { cat "$out/menu_$f.txt"; fail "the menu does not show the duplicate key of $f.json"; }
    [ -f "$cfg/arcfire/$f.json.bak" ] || fail "$f.json was not kept as $f.json.bak"
    echo "ok: $f.json"
  done
  ;;
paths)
  m=$(new_mod paths_mod)
  sed 's/"mounts": \[\[-2.5, -0.4, -6.5\], \[2.5, -0.4, -6.5\]\]/"mounts": [[-2.5, -0.4, -6.5], [250, -0.4, -6.5]]/' assets/ships/viper.json > "$m/assets/ships/viper.json"
  cmp -s assets/ships/viper.json "$m/assets/ships/viper.json" && fail "the mount edit changed nothing"
  expect_line 2 "viper\.json:[0-9]+:[0-9]+: 'beam\.mounts\[1\]\[0\]' must be in \[-100, 100\], got 250$" -- run_sim "$m"
  sed 's/"position": \[60, 20, -1200\]/"position": [60, "up", -1200]/' tests/cli/bad/duplicate_key.json | sed '/"seed": 7,/d' > "$out/level.json"
  expect_line 2 "level\.json:[0-9]+:[0-9]+: 'ships\[1\]\.position\[1\]' must be a number in \[-1073741824, 1073741824\], got a string$" -- \
    "$arcfire" --headless --no-render --ticks 1 --level "$out/level.json"
  ;;
limits)
  sed 's/"position": \[60, 20, -1200\]/"position": [60, 20, -2e9]/' tests/cli/bad/duplicate_key.json | sed '/"seed": 7,/d' > "$out/far.json"
  expect_line 2 "far\.json:[0-9]+:[0-9]+: 'ships\[1\]\.position\[2\]' must be in \[-1073741824, 1073741824\], got -2e\+09$" -- \
    "$arcfire" --headless --no-render --ticks 1 --level "$out/far.json"
  m=$(new_mod limits_mod)
  sed 's/"alpha": \[\[0, 1\], \[1, 0\]\]/"alpha": [[0, 1], [0.1000000001, 1], [0.1000000002, 0.5], [1, 0]]/' assets/effects/shield_hit.json > "$m/assets/effects/shield_hit.json"
  cmp -s assets/effects/shield_hit.json "$m/assets/effects/shield_hit.json" && fail "the curve edit changed nothing"
  expect_line 2 "shield_hit\.json:[0-9]+:[0-9]+: 'clusters\[0\]\.curves\.alpha\[2\]\[0\]': key times 0\.1000000001 and 0\.1000000002 are the same in single precision; allowed: " -- run_sim "$m"
  expect_line 0 "" -- "$arcfire" --headless --no-render --ticks 1 --set particles.budget=50000.0
  expect_line 2 "--set particles\.budget=50000\.5: setting 'particles\.budget' must be an integer in \[1000, 4e\+06\], got '50000\.5'$" -- \
    "$arcfire" --headless --no-render --ticks 1 --set particles.budget=50000.5
  m=$(new_mod limits_quality)
  sed '0,/"particles.budget": 50000,/s//"particles.budget": 50000.0,/' assets/settings/quality.json > "$m/assets/settings/quality.json"
  cmp -s assets/settings/quality.json "$m/assets/settings/quality.json" && fail "the budget edit changed nothing"
  expect_line 0 "" -- run_sim "$m" --quality low
  ;;
*) fail "unknown part '$part'" ;;
esac
echo "file_claims $part: ok"
