#!/usr/bin/env bash
# deb_package.sh BUILD WORK: CPack builds the .deb into WORK; dpkg-deb shows that it holds the
# game, its codec module, its data, the desktop entry and the icon, and that its Depends are
# exactly the packages that provide the libraries the program and the module link (their
# NEEDED entries, found by ldd, owned per dpkg -S) and libEGL, which libepoxy opens by name.
# Skipped (77) without the Debian tools.
set -u
build="$1"; work="$2"
fail() { echo "cli_deb_package: $*"; exit 1; }
for tool in cpack dpkg-deb dpkg-shlibdeps dpkg readelf ldd; do
  command -v "$tool" >/dev/null || { echo "cli_deb_package: $tool is not installed; skipping"; exit 77; }
done
rm -rf "$work"; mkdir -p "$work"
build="$(cd "$build" && pwd)"; work="$(cd "$work" && pwd)"
(cd "$build" && cpack -G DEB -B "$work") >"$work/cpack.log" 2>&1 || { tail -20 "$work/cpack.log"; fail "cpack failed"; }
debs=("$work"/arcfire_*.deb)
[ -f "${debs[0]}" ] || { tail -20 "$work/cpack.log"; fail "no arcfire_*.deb in $work"; }
deb="${debs[0]}"
echo "package: $(basename "$deb")"
[ "$(dpkg-deb -f "$deb" Package)" = arcfire ] || fail "the package is not named arcfire"

contents="$(dpkg-deb -c "$deb" | awk '{print $NF}')"
for f in ./usr/bin/arcfire ./usr/lib/arcfire/libarcfire_image_codec.so ./usr/share/arcfire/levels/duel.json \
         ./usr/share/arcfire/assets/models/viper.glb ./usr/share/arcfire/assets/settings/quality.json \
         ./usr/share/arcfire/shaders/mesh.frag ./usr/share/applications/arcfire.desktop \
         ./usr/share/icons/hicolor/256x256/apps/arcfire.png; do
  grep -qxF "$f" <<<"$contents" || fail "$f is not in the package"
done
! grep -Eq '^\./usr/share/arcfire/tests/|\.md$' <<<"$(grep -v '^./usr/share/doc/' <<<"$contents")" ||
  fail "the package holds tests or notes the game does not read"

# The unpacked package runs from an unrelated folder: its data, its codec module, a frame.
dpkg-deb -x "$deb" "$work/root"
mkdir -p "$work/elsewhere"
(
  cd "$work/elsewhere" && unset ARCFIRE_DATA
  "$work/root/usr/bin/arcfire" --version | grep -qx "data: $work/root/usr/share/arcfire (beside the executable)" ||
    fail "the unpacked game does not use its own data: $("$work/root/usr/bin/arcfire" --version 2>&1 | tr '\n' ' ')"
  "$work/root/usr/bin/arcfire" --headless --ticks 30 --every 30 --size 160x90 --out frames >run.log 2>&1 ||
    { cat run.log; fail "the unpacked game failed a headless frame"; }
  [ -s frames/frame_000030.png ] || fail "the unpacked game wrote no frame"
) || exit 1
echo "ok: the unpacked package renders a frame from $work/elsewhere"

# The package owning a library file; ldd may name /lib/... where dpkg knows /usr/lib/... (usrmerge).
owner() {
  local path="$1" p pkg
  for p in "$path" "$(readlink -f "$path")" "/usr$path" "${path#/usr}"; do
    pkg="$(dpkg -S "$p" 2>/dev/null | head -n 1 | cut -d: -f1)"
    [ -n "$pkg" ] && { echo "$pkg"; return 0; }
  done
  return 1
}
expected=""
for elf in "$build/arcfire" "$build/libarcfire_image_codec.so"; do
  libs="$(ldd "$elf")"
  for needed in $(readelf -d "$elf" | sed -n 's/.*(NEEDED).*\[\(.*\)\].*/\1/p'); do
    path="$(awk -v lib="$needed" '$1 == lib && $2 == "=>" {print $3}' <<<"$libs")"
    [ -n "$path" ] || fail "ldd does not resolve $needed of $elf"
    pkg="$(owner "$path")" || fail "no package owns $path ($needed of $elf)"
    expected+="$pkg"$'\n'
  done
done
# libepoxy opens libEGL.so.1 by name for headless rendering: no NEEDED entry, found by ldconfig.
egl="$(ldconfig -p | awk '$1 == "libEGL.so.1" && $0 ~ /x86-64/ {print $NF; exit}')"
[ -n "$egl" ] || fail "libEGL.so.1 is not installed here"
pkg="$(owner "$egl")" || fail "no package owns $egl"
expected+="$pkg"$'\n'
expected="$(sort -u <<<"$expected" | sed '/^$/d')"
depends="$(dpkg-deb -f "$deb" Depends)"
echo "Depends: $depends"
# Each Depends entry is one package or alternatives (a | b); the installed one must be among them.
declared="$(tr ',' '\n' <<<"$depends" | sed 's/([^)]*)//g; s/ //g' | sed '/^$/d')"
n_declared=$(grep -c '' <<<"$declared"); n_expected=$(grep -c '' <<<"$expected")
[ "$n_declared" -eq "$n_expected" ] ||
  fail "Depends has $n_declared entries, the linked libraries come from $n_expected packages: $(tr '\n' ' ' <<<"$expected")"
while read -r pkg; do
  tr '|' '\n' <<<"$declared" | grep -qxF "$pkg" || fail "$pkg (providing a linked library) is not in Depends"
done <<<"$expected"
echo "ok: Depends names the $n_expected packages of the linked libraries: $(tr '\n' ' ' <<<"$expected")"
