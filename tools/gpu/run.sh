#!/usr/bin/env bash
# tools/gpu/run.sh ARGS... — runs the packed arcfire-bench (tools/gpu/pack.sh) on a machine
# with a GPU driver, from the repository root (the bench reads levels/, assets/, shaders/).
# The machine's own libstdc++ and GL dispatch are used where it has them, and the NVIDIA
# driver's EGL vendor file where the driver is mounted apart (/usr/local/nvidia).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
pack="$root/.gpu"
[ -x "$pack/bin/arcfire-bench" ] || { echo "tools/gpu/run.sh: $pack/bin/arcfire-bench: missing; run tools/gpu/pack.sh first" >&2; exit 2; }
paths="$pack/lib"
have() { ldconfig -p | grep -q "^[[:space:]]*$1 .*x86-64"; }
have libstdc++.so.6 || paths="$paths:$pack/runtime"
have libEGL.so.1 && have libOpenGL.so.0 || paths="$paths:$pack/glvnd"
export LD_LIBRARY_PATH="$paths${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# The NVIDIA driver's EGL vendor file and libraries, where the image keeps them apart.
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -f /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json ]; then
  export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
fi
for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do
  [ -d "$d" ] && LD_LIBRARY_PATH="$LD_LIBRARY_PATH:$d"
done
cd "$root"
# The packed bench has no build folder beside it: the data is this checkout's (core/data_root.h).
export ARCFIRE_DATA="${ARCFIRE_DATA:-$root}"
exec "$pack/bin/arcfire-bench" "$@"
