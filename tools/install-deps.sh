#!/usr/bin/env bash
# Installs the Debian 12 packages Arcfire needs to build, play and test, if any are missing.
# Uses sudo when not root. Safe to run repeatedly: it does nothing when all are present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglfw3-dev libglm-dev libtinygltf-dev libstb-dev libopenimageio-dev libegl-dev libepoxy-dev
  nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libimgui-dev
  libegl-mesa0 libgl1-mesa-dri libgbm1
  libopenal-dev libenet-dev libtbb-dev
  xvfb xauth xdotool time
  python3-matplotlib
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "arcfire: installing missing packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "arcfire: need root or sudo to install: ${missing[*]}" >&2; exit 2; }
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
