#!/usr/bin/env bash
# update_golden_link.sh ARCFIRE OUT_DIR
# --update-golden on a replay reached through a symbolic link writes the script through the link
# (the link stays a link) and changes only the bytes of the hash value it updates: the rest of
# the file, here without a final newline, stays byte-identical.
set -u
arcfire="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out/scripts"
fail() { echo "update_golden_link: $*"; exit 1; }
script=tests/replays/range_beam_shield.replay
value=$(sed -n 's/^60 hash \([0-9a-f]*\).*/\1/p' "$script")
[ -n "$value" ] || fail "no '60 hash' line in $script"
head -c -1 "$script" >"$out/want.replay"  # the script as it is, less its final newline
sed "s/^60 hash $value/60 hash 0000000000000000/" "$out/want.replay" >"$out/scripts/real.replay"
[ "$(tail -c 1 "$out/scripts/real.replay" | od -An -c | tr -d ' ')" = d ] || fail "the test script ends in a newline"
ln -s scripts/real.replay "$out/link.replay"
"$arcfire" --replay "$out/link.replay" --no-render --update-golden >"$out/run.log" 2>&1 ||
  { cat "$out/run.log"; fail "the update failed"; }
[ -L "$out/link.replay" ] || fail "the link was replaced by a file"
cmp "$out/scripts/real.replay" "$out/want.replay" || fail "the script differs from the original beyond its hash value"
[ -f "$out/golden/link/hashes.txt" ] || fail "no hash log written"
echo "ok: the link stays, only the hash value changed"
