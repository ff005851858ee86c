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
  libtinygltf-dev  # `animator export` writes glTF with tinygltf
  libmeshoptimizer-dev  # the renderer's levels of detail (host/render/mesh_lod.hpp)
  libpng-dev  # rendered frames written as PNG, three times faster than stb's encoder
  blender python3-numpy  # the export tests: Blender imports every export (its importer needs numpy)
  nodejs  # the export tests: the Khronos glTF Validator runs on Node (tools/gltf-validator)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# npm comes with some builds of nodejs (NodeSource's) and is a package of its own in Debian's.
if ! command -v npm >/dev/null 2>&1; then
  missing+=(npm)
fi

# The Khronos glTF Validator, from the npm registry, at the version package-lock.json pins.
validator_dir="$(cd "$(dirname "$0")" && pwd)/gltf-validator"
validator() {
  if [ ! -d "$validator_dir/node_modules/gltf-validator" ]; then
    echo "animator: installing the glTF Validator (npm ci in tools/gltf-validator)" >&2
    (cd "$validator_dir" && npm ci --no-audit --no-fund --loglevel=error)
  fi
}

if [ ${#missing[@]} -eq 0 ]; then
  validator
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
validator
