#!/usr/bin/env bash
# references_checked.sh ARCFIRE OUT_DIR
# Every file a data file names is checked at load, rendering or not: a level's prop model, a ship
# class's model (through a mod) and a level's effect that do not exist are one line (exit 2)
# naming the file that makes the reference, its key (or whole key path) and the file looked for;
# so is an effect's sprite whose texture is missing from the data folder.
set -u
arcfire="$1"; out="$2"; expect="$(dirname "$0")/expect.sh"
rm -rf "$out"; mkdir -p "$out/mod/assets/ships" "$out/mod/levels"
sed 's#assets/models/asteroid.glb#assets/models/no_such_rock.glb#' levels/duel.json >"$out/prop.json"
sed 's#"model": *"[^"]*"#"model": "assets/models/no_such_hull.glb"#' assets/ships/viper.json >"$out/mod/assets/ships/ghost.json"
sed 's/"class": "viper"/"class": "ghost"/' levels/duel.json >"$out/mod/levels/ghost.json"
sed 's#"props": \[#"effects": [ { "effect": "no_such_effect" } ],\n  "props": [#' levels/duel.json >"$out/effect.json"
run=(--headless --no-render --ticks 1)
"$expect" 2 "prop.json:[0-9]+:[0-9]+: '(props\[0\]\.)?model' names model .*assets/models/no_such_rock.glb: no such file" -- \
  "$arcfire" "${run[@]}" --level "$out/prop.json" || exit 1
"$expect" 2 "ghost.json:3:[0-9]+: 'model' names model .*assets/models/no_such_hull.glb: no such file" -- \
  "$arcfire" "${run[@]}" --mod "$out/mod" --level levels/ghost.json || exit 1
"$expect" 2 "effect.json:[0-9]+:[0-9]+: '(effects\[0\]\.)?effect' names effect file .*assets/effects/no_such_effect.json: no such file" -- \
  "$arcfire" "${run[@]}" --level "$out/effect.json" || exit 1
mkdir -p "$out/data" && cp -r assets levels shaders "$out/data/" && rm "$out/data/assets/textures/sprite_spark.png"
"$expect" 2 "effects/[a-z_]+.json: cluster '[a-z_0-9]+': sprite 'spark' names texture .*assets/textures/sprite_spark.png: no such file" -- \
  "$arcfire" "${run[@]}" --data "$out/data" || exit 1
