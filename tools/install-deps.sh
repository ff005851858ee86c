#!/usr/bin/env bash
# Installs the Debian packages animator needs, only those missing. Safe to run twice.
# Uses sudo only when not root.
set -euo pipefail

packages=(
  build-essential cmake pkg-config python3
  libbullet-dev libglfw3-dev libx11-dev python3-glad libimgui-dev libglm-dev libassimp-dev
  libsfml-dev liblua5.4-dev libstb-dev catch2 libcli11-dev
  nlohmann-json3-dev  # `animator info --json` (and its tests)
  lua5.4  # the tests' independent CS488 transform stack (tests/data/cs488/shim.lua)
  libboost-dev  # Boost.Math's elliptic functions: physics.custom's exact free rotation
  libgl-dev xvfb xauth xdotool imagemagick mesa-utils libgl1-mesa-dri
  libegl-dev libegl-mesa0
  clang libclang-rt-14-dev llvm-14
  ffmpeg  # `animator render --video` and the editor's Render > Video (tests: render_video)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "animator: installing missing packages: ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
