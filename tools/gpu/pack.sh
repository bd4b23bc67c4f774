#!/usr/bin/env bash
# tools/gpu/pack.sh [BUILD_DIR] — packs build/arcfire-bench into .gpu/ for a bare GPU machine
# that has a driver but none of Debian's packages (the lent NVIDIA machines: no OpenImageIO,
# no network). docs/performance.md's GPU figures are measured with it:
#
#   tools/gpu/pack.sh                      # here, after a build
#   tools/gpu/run.sh --scene particle_scale  # there, from the repository root, with .gpu/ carried
#
# .gpu/bin      arcfire-bench, and the PNG-only codec module (assets/codec/png_codec.cpp, stb_image)
#               as libarcfire_image_codec.so beside it, so OpenImageIO's ~270 libraries stay here
# .gpu/lib      every library the two need that is not the C runtime
# .gpu/runtime  libstdc++ and libgcc_s, used only where the machine has none
# .gpu/glvnd    the GL vendor-neutral dispatch (libEGL, libOpenGL...), used only where the
#               machine has none; the driver's own EGL vendor library is always the machine's
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build}"
bench="$build/arcfire-bench"
module="$build/libarcfire_image_codec_png.so"
for f in "$bench" "$module"; do
  [ -x "$f" ] || [ -f "$f" ] || { echo "tools/gpu/pack.sh: $f: missing; build first (cmake --build build)" >&2; exit 2; }
done
for f in "$bench" "$module"; do
  missing="$(ldd "$f" | awk '/not found/ {print $1}' | tr '\n' ' ')"
  [ -z "$missing" ] || { echo "tools/gpu/pack.sh: $f: needs libraries this machine lacks: $missing(tools/install-deps.sh)" >&2; exit 2; }
done
out="$root/.gpu"
rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/runtime" "$out/glvnd"
cp "$bench" "$out/bin/arcfire-bench"
cp "$module" "$out/bin/libarcfire_image_codec.so"
# The C runtime and the loader must be the machine's own.
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so)'
for f in "$bench" "$module"; do
  ldd "$f" | awk '$3 ~ /^\// {print $1, $3}'
done | sort -u | while read -r name path; do
  [[ "$name" =~ $skip ]] && continue
  case "$name" in
    libstdc++.so*|libgcc_s.so*) cp -L "$path" "$out/runtime/$name" ;;
    *) cp -L "$path" "$out/lib/$name" ;;
  esac
done
# libepoxy opens these by name at run time (ldd does not list them).
for name in libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0 libGL.so.1 libGLX.so.0; do
  path="$(ldconfig -p | awk -v n="$name" '$1 == n && $0 ~ /x86-64/ {print $NF; exit}')"
  [ -n "$path" ] || { echo "tools/gpu/pack.sh: $name: not found here (install libegl1, libopengl0, libgl1)" >&2; exit 2; }
  cp -L "$path" "$out/glvnd/$name"
done
echo "tools/gpu/pack.sh: $(du -sh "$out" | cut -f1) in $out ($(ls "$out/lib" | wc -l) libraries)"
