#!/usr/bin/env bash
# README's play command: installs what is missing, builds (Release), starts the game in a window.
# Without a display it says so and runs the headless attract demo instead, writing PNG frames
# and a contact sheet to out/demo/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/tools/build.sh" --target arcfire
cd "$root"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec ./build/arcfire "$@"
fi
echo "arcfire: no display found (DISPLAY is not set); running the headless attract demo instead."
exec ./build/arcfire --headless --demo --out out/demo "$@"
