#!/usr/bin/env bash
# Configures and builds Arcfire into build/ (Release by default; BUILD_TYPE=Debug to change).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/tools/install-deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" >/dev/null
cmake --build "$root/build" -j"$(nproc)" "$@"
