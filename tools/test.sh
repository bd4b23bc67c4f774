#!/usr/bin/env bash
# README's test command: installs what is missing, builds everything, runs the whole ctest suite.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure -j"$(nproc)" "$@"
