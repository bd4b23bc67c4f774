#!/usr/bin/env bash
# The whole ctest suite built with AddressSanitizer and UndefinedBehaviorSanitizer in
# build-asan/ (RelWithDebInfo, no benchmarks), stopping at the first report. Too slow for CI
# (a second full build); run it by hand after touching memory handling or the renderer.
# Leak checking is off: Mesa's llvmpipe keeps allocations alive until process exit.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/build-asan}"
"$root/tools/install-deps.sh"
cmake -S "$root" -B "$out" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARCFIRE_BUILD_BENCH=OFF \
  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$out" -j"$(nproc)"
cd "$out"
ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j"$(nproc)" "$@"
