#!/usr/bin/env bash
# hostile_paths.sh ARCFIRE WORK_DIR [render]
# A property test over the file system: every entry point through which arcfire reads a file,
# crossed with every hostile thing a path can name, each driven through the real command line.
# Each case must exit 2 within seconds (a hang is killed at 20 s), stay under 500 MB of address
# space (no-render cases), print exactly one line on stderr naming the file and what it is, and
# never abort ("terminate called"). Run from the source tree (the data root).
#
# Hostile kinds: loop (a symbolic link to itself), long (a name longer than the system allows),
# folder, fifo, zero (/dev/zero), socket, linkfifo (a symbolic link to a FIFO). A case that
# cannot exist is skipped: a fixed name (sprite_glow.png, hashes.txt) cannot be too long, and a
# folder is the normal thing where a folder is read. An unreadable file cannot be made for root,
# who reads everything; that case runs only for other users.
#
# With "render" as third argument the entry points that only a rendered frame reaches run
# (models, their external buffers and images, sprites); without it, the rest.
set -u
arcfire="$(realpath "$1")"; work="$2"; mode="${3:-}"
src="$(pwd)"
rm -rf "$work"; mkdir -p "$work"; work="$(realpath "$work")"
kinds="loop long folder fifo zero socket linkfifo unreadable"
failures=0; cases=0
long_name=$(printf 'n%.0s' $(seq 300))

have_socket=1
python3 -c 'import socket' 2>/dev/null || have_socket=0

# plant KIND DIR NAME: makes DIR/NAME (NAME+long suffix for "long") the hostile thing; prints
# the path made, or nothing when KIND cannot be made there.
plant() {
  local kind="$1" dir="$2" name="$3" p
  p="$dir/$name"
  case "$kind" in
    loop) ln -s "$name" "$p" ;;
    long) p="$dir/${long_name}${name}"; : ;;
    folder) mkdir -p "$p" ;;
    fifo) mkfifo "$p" ;;
    zero) ln -s /dev/zero "$p" ;;
    socket)
      [ "$have_socket" = 1 ] || return 0
      (cd "$dir" && python3 -c 'import socket,sys; socket.socket(socket.AF_UNIX).bind(sys.argv[1])' "$name") || return 0 ;;
    linkfifo) mkfifo "$dir/.fifo_$name.target"; ln -s ".fifo_$name.target" "$p" ;;
    unreadable)
      [ "$(id -u)" != 0 ] || return 0
      echo '{}' >"$p"; chmod 000 "$p" ;;
  esac
  printf '%s' "$p"
}

# What the one stderr line must say for KIND.
said() {
  case "$1" in
    loop) echo "a symbolic link loop" ;;
    long) echo "a name longer than the system allows" ;;
    folder) echo "a folder" ;;
    fifo | linkfifo) echo "a FIFO (named pipe)" ;;
    zero) echo "a character device" ;;
    socket) echo "a socket" ;;
    unreadable) echo "permission denied" ;;
  esac
}

# expect ENTRY KIND NAMED [ENV=VALUE...] -- ARGS...: runs arcfire, checks the rules above. NAMED
# is the part of the hostile path the line must name (its last component, cut for long names).
expect() {
  local entry="$1" kind="$2" named="$3"; shift 3
  local envs=()
  while [ "$1" != "--" ]; do envs+=("$1"); shift; done
  shift
  cases=$((cases + 1))
  local out="$work/out.$cases" t0 t1 code
  t0=$(date +%s.%N)
  (
    [ "$mode" = render ] || ulimit -v 512000
    exec env "${envs[@]}" timeout -s KILL 20 "$arcfire" "$@" >"$out.stdout" 2>"$out.stderr"
  )
  code=$?
  t1=$(date +%s.%N)
  local secs lines want
  secs=$(awk "BEGIN { printf \"%.2f\", $t1 - $t0 }")
  lines=$(wc -l <"$out.stderr")
  want="${want_text:-$(said "$kind")}"
  local why=""
  [ "$code" -eq 2 ] || why="exit $code, expected 2"
  [ -z "$why" ] && [ "$lines" -ne 1 ] && why="$lines lines on stderr, expected 1"
  [ -z "$why" ] && grep -q "terminate called" "$out.stderr" && why="aborted"
  [ -z "$why" ] && ! grep -qF -- "$want" "$out.stderr" && why="does not say '$want'"
  [ -z "$why" ] && ! grep -qF -- "${named:0:60}" "$out.stderr" && why="does not name '${named:0:60}'"
  if [ -n "$why" ]; then
    failures=$((failures + 1))
    echo "FAIL $entry x $kind (${secs}s): $why"
    sed 's/^/  stderr: /' "$out.stderr" | cut -c1-400 | head -5
  else
    echo "ok   $entry x $kind (${secs}s): $(cut -c1-160 "$out.stderr")"
  fi
}

# expect_menu KIND SETTINGS_FILE: the player's settings.json or progress.json is hostile. A bad
# player file is not bad input: the menu starts from defaults and says why on screen (stdout
# here), exit 0, at once and without an abort.
expect_menu() {
  local kind="$1" file="$2"
  cases=$((cases + 1))
  local out="$work/out.$cases" code why=""
  : >"$work/empty.ui"
  (
    ulimit -v 512000
    exec env XDG_CONFIG_HOME="$work/$kind/config" timeout -s KILL 20 "$arcfire" --headless --no-render \
      --menu-script "$work/empty.ui" >"$out.stdout" 2>"$out.stderr"
  )
  code=$?
  [ "$code" -eq 0 ] || why="exit $code, expected 0"
  [ -z "$why" ] && grep -q "terminate called" "$out.stderr" && why="aborted"
  [ -z "$why" ] && ! grep -qF "message: $file: $(said "$kind")" "$out.stdout" && why="no message '$file: $(said "$kind")'"
  if [ -n "$why" ]; then
    failures=$((failures + 1))
    echo "FAIL player file x $kind: $why"
    cat "$out.stderr" "$out.stdout" | sed 's/^/  out: /' | cut -c1-300 | head -8
  else
    echo "ok   player file x $kind: $(grep -F "message: $file" "$out.stdout" | cut -c1-160)"
  fi
}

# A data root of links to the real one, with the folders named replaced by real folders of links
# (so a file can be planted among the real ones): tree DIR assets/ships assets/effects ...
tree() {
  local d="$1"; shift
  mkdir -p "$d/assets"
  for top in levels shaders; do ln -s "$src/$top" "$d/$top"; done
  for sub in "$src"/assets/*; do ln -s "$sub" "$d/assets/$(basename "$sub")"; done
  for rel in "$@"; do
    rm "$d/$rel"; mkdir -p "$d/$rel"
    for f in "$src/$rel"/*; do ln -s "$f" "$d/$rel/$(basename "$f")"; done
  done
}

# A level of two Vipers (or ships of CLASS) and an effect named EFFECT, when given.
level() {
  local cls="${1:-viper}" effect="${2:-}"
  local fx=""
  [ -n "$effect" ] && fx=", \"effects\": [{ \"effect\": \"$effect\", \"position\": [0, 0, -50] }]"
  cat <<EOF
{ "name": "Hostile", "seed": 1, "objective": "Survive.", "win": { "type": "destroy_all_hostiles" }, "lose": { "type": "player_destroyed" },
  "ships": [ { "name": "P", "class": "$cls", "team": "blue", "player": true, "position": [0, 0, 0] },
             { "name": "R", "class": "viper", "team": "red", "position": [0, 0, -300] } ]$fx }
EOF
}

headless=(--headless --no-render --ticks 2)
frame=(--headless --ticks 1 --every 1 --size 64x48)

for kind in $kinds; do
  k="$work/$kind"; mkdir -p "$k"
  if [ "$mode" != render ]; then
    # --level, --bindings, --sounds, --replay, --menu-script: the path as given.
    for entry in level bindings sounds replay menu-script; do
      p=$(plant "$kind" "$k" "$entry.arg") && [ -n "$p" ] || continue
      case $entry in
        replay) expect "--$entry" "$kind" "$(basename "$p")" -- --headless --no-render "--$entry" "$p" ;;
        menu-script) expect "--$entry" "$kind" "$(basename "$p")" -- --headless "--$entry" "$p" ;;
        *) expect "--$entry" "$kind" "$(basename "$p")" -- "${headless[@]}" "--$entry" "$p" ;;
      esac
    done
    # A replay's level line.
    p=$(plant "$kind" "$k" "script_level.json")
    if [ -n "$p" ]; then
      printf 'arcfire-replay 1\nlevel %s\n0 end\n' "$p" >"$k/level_line.replay"
      expect "replay level line" "$kind" "$(basename "$p")" -- --headless --no-render --replay "$k/level_line.replay"
    fi
    # A replay's hash log (golden/NAME/hashes.txt), a fixed name: never too long.
    if [ "$kind" != long ]; then
      mkdir -p "$k/r/golden/hashed"
      printf 'arcfire-replay 1\nlevel %s/tests/replays/levels/range.json\n1 hash ?\n1 end\n' "$src" >"$k/r/hashed.replay"
      p=$(plant "$kind" "$k/r/golden/hashed" "hashes.txt")
      [ -n "$p" ] && expect "hash log" "$kind" "hashes.txt" -- --headless --no-render --replay "$k/r/hashed.replay"
    fi
    # The player's settings.json (a fixed name: never too long).
    if [ "$kind" != long ]; then
      mkdir -p "$k/config/arcfire"
      p=$(plant "$kind" "$k/config/arcfire" "settings.json")
      [ -n "$p" ] && expect_menu "$kind" "$p"
    fi
    # A ship class named by a level: assets/ships/NAME.json of the data root.
    tree "$k/ships_root" assets/ships
    p=$(plant "$kind" "$k/ships_root/assets/ships" "hostile.json")
    if [ -n "$p" ]; then
      cls=$(basename "$p" .json)
      level "$cls" >"$k/class_level.json"
      expect "ship class" "$kind" "${cls:0:60}" -- "${headless[@]}" --data "$k/ships_root" --level "$k/class_level.json"
    fi
    # One effect file of the effects folder, and the folder itself (not for "folder" or "long").
    tree "$k/fx_root" assets/effects
    p=$(plant "$kind" "$k/fx_root/assets/effects" "hostile.json")
    if [ -n "$p" ] && [ "$kind" != long ]; then
      expect "effect file" "$kind" "$(basename "$p")" -- "${headless[@]}" --data "$k/fx_root" --level "$src/levels/duel.json"
    fi
    if [ "$kind" != folder ] && [ "$kind" != long ]; then
      tree "$k/fxdir_root"
      rm "$k/fxdir_root/assets/effects"
      p=$(plant "$kind" "$k/fxdir_root/assets" "effects")
      [ -n "$p" ] && expect "effects folder" "$kind" "effects" -- "${headless[@]}" --data "$k/fxdir_root" --level "$src/levels/duel.json"
      # --data and --mod themselves.
      p=$(plant "$kind" "$k" "data.arg") && [ -n "$p" ] && expect "--data" "$kind" "data.arg" -- "${headless[@]}" --data "$p"
      p=$(plant "$kind" "$k" "mod_arg") && [ -n "$p" ] && expect "--mod" "$kind" "mod_arg" -- "${headless[@]}" --mod "$p"
    fi
  else
    # A model named by a ship class.
    tree "$k/model_root" assets/ships
    p=$(plant "$kind" "$k" "model.glb")
    if [ -n "$p" ]; then
      sed "s|\"assets/models/viper.glb\"|\"$p\"|" "$src/assets/ships/viper.json" >"$k/model_root/assets/ships/modelled.json"
      level modelled >"$k/model_level.json"
      expect "model" "$kind" "$(basename "$p")" -- "${frame[@]}" --data "$k/model_root" --level "$k/model_level.json" --out "$k/frames_model"
    fi
    # A glTF's external buffer and image, named by its "uri".
    for part in buffer image; do
      p=$(plant "$kind" "$k" "ext_$part.bin") || continue
      [ -n "$p" ] || continue
      if [ "$part" = buffer ]; then
        printf '{"asset":{"version":"2.0"},"buffers":[{"uri":"%s","byteLength":4}]}\n' "$(basename "$p")" >"$k/ext_$part.gltf"
      else
        printf '{"asset":{"version":"2.0"},"images":[{"uri":"%s"}]}\n' "$(basename "$p")" >"$k/ext_$part.gltf"
      fi
      sed "s|\"assets/models/viper.glb\"|\"$k/ext_$part.gltf\"|" "$src/assets/ships/viper.json" >"$k/model_root/assets/ships/ext_$part.json"
      level "ext_$part" >"$k/ext_$part.json"
      expect "glTF external $part" "$kind" "$(basename "$p")" -- "${frame[@]}" --data "$k/model_root" --level "$k/ext_$part.json" --out "$k/frames_$part"
    done
    # A sprite of the particle renderer (a fixed name: never too long).
    if [ "$kind" != long ]; then
      tree "$k/sprite_root" assets/textures
      rm "$k/sprite_root/assets/textures/sprite_glow.png"
      p=$(plant "$kind" "$k/sprite_root/assets/textures" "sprite_glow.png")
      [ -n "$p" ] && expect "sprite" "$kind" "sprite_glow.png" -- "${frame[@]}" --data "$k/sprite_root" --level "$src/levels/duel.json" --out "$k/frames_sprite"
    fi
  fi
done

# Relative ticks (+N) that add up past the last tick a script may name: refused at the line that
# gets there, never simulated for ever.
if [ "$mode" != render ]; then
  {
    printf 'arcfire-replay 1\nlevel %s/tests/replays/levels/range.json\n' "$src"
    for i in $(seq 11); do echo "+100000000 axis pitch 0.5"; done
    echo "+1 end"
  } >"$work/far.replay"
  want_text="far.replay:13:1: relative tick +100000000 after tick 1000000000 reaches tick 1100000000" \
    expect "replay relative ticks" "-" "far.replay" -- --headless --no-render --replay "$work/far.replay"
fi

echo "$cases cases, $failures failed"
[ "$failures" -eq 0 ]
