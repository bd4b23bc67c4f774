#!/usr/bin/env bash
# mods.sh ARCFIRE OUT_DIR
# The example mod (examples/mods/red_rally) laid over the data with --mod: --version names it and
# its content hash; its mission (a new level using a new ship class and a new effect) plays
# headless and is listed apart on the menu; a replay recorded with the mod names it and its hash,
# plays with it, and is refused in one line (exit 2) without it or with other content; a folder
# that is not a mod is refused in one line.
set -u
arcfire="$1"; out="$2"
mod=examples/mods/red_rally
rm -rf "$out"; mkdir -p "$out"
fail() { echo "mods: $*"; exit 1; }

# --version: the mod and its hash.
line=$("$arcfire" --mod "$mod" --version | grep '^mod: ') || fail "--version names no mod"
hash=$(echo "$line" | sed -n 's/^mod: red_rally \([0-9a-f]\{16\}\) (.*)$/\1/p')
[ -n "$hash" ] || fail "--version's mod line is not 'mod: red_rally HASH (DIR)': $line"

# The mod's mission: its level, ship class and effect load; the base game knows none of them.
"$arcfire" --mod "$mod" --headless --no-render --level levels/red_rally.json --ticks 300 --summary "$out/summary.json" \
  > "$out/run.txt" 2>&1 || { cat "$out/run.txt"; fail "the mod's mission did not run"; }
grep -q '"Rally 1"' "$out/summary.json" || fail "the summary does not hold the mod's ships"
err=$("$arcfire" --headless --no-render --level levels/red_rally.json --ticks 1 2>&1); code=$?
[ $code -eq 2 ] || fail "without --mod the mod's level should be bad input (2), got $code: $err"

# A replay of the mod's mission with its mod line: plays with the mod, refused without it.
cat > "$out/rally.replay" <<SCRIPT
arcfire-replay 1
level levels/red_rally.json
mod red_rally $hash
0 press fire_primary
120 expect alive Player
120 end
SCRIPT
"$arcfire" --mod "$mod" --headless --no-render --replay "$out/rally.replay" > "$out/replay.txt" 2>&1 ||
  { cat "$out/replay.txt"; fail "the replay with its mod failed"; }
err=$("$arcfire" --headless --no-render --replay "$out/rally.replay" 2>&1); code=$?
[ $code -eq 2 ] || fail "the replay without its mod should exit 2, got $code: $err"
echo "$err" | grep -q "rally.replay:3:5: recorded with mod 'red_rally'" || fail "unclear refusal without the mod: $err"
# The same mod with one byte changed: other data than recorded.
cp -r "$mod" "$out/red_rally"
sed -i 's/"hull": 260/"hull": 261/' "$out/red_rally/assets/ships/viper_mk2.json"
err=$("$arcfire" --mod "$out/red_rally" --headless --no-render --replay "$out/rally.replay" 2>&1); code=$?
[ $code -eq 2 ] || fail "the replay under changed mod data should exit 2, got $code: $err"
echo "$err" | grep -q "mod 'red_rally' (.*) holds other data than when recorded" || fail "unclear refusal under changed data: $err"
# A base-game replay under a mod: refused, the mod named.
err=$("$arcfire" --mod "$mod" --headless --no-render --replay tests/replays/range_course.replay 2>&1); code=$?
[ $code -eq 2 ] || fail "a base replay under a mod should exit 2, got $code: $err"
echo "$err" | grep -q "recorded without mod 'red_rally'" || fail "unclear refusal of a base replay: $err"

# The menu lists the mod's mission apart, after the game's own.
printf 'accept\n' > "$out/menu.ui"
XDG_CONFIG_HOME="$out/config" "$arcfire" --mod "$mod" --headless --menu-script "$out/menu.ui" --out "$out/menu" \
  > "$out/menu_run.txt" 2>&1 || { cat "$out/menu_run.txt"; fail "the menu script failed"; }
missions=$(ls "$out"/menu/*missions*.txt 2>/dev/null | head -1)
[ -n "$missions" ] || fail "no missions screen in $out/menu"
grep -q '\[red_rally\] 1\. Red Rally' "$missions" || { cat "$missions"; fail "the missions screen does not list the mod's mission apart"; }

# Not a mod: one line, exit 2.
err=$("$arcfire" --mod tests/cli --headless --no-render --ticks 1 2>&1); code=$?
[ $code -eq 2 ] || fail "a folder without data folders should be refused with 2, got $code"
[ "$(echo "$err" | wc -l)" -eq 1 ] && echo "$err" | grep -q "holds none of assets/, levels/, shaders/" ||
  fail "unclear refusal of a non-mod folder: $err"
echo "ok: the example mod adds a mission, ship and effect, replays with its hash and is refused without it"
