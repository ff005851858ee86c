#!/usr/bin/env bash
# Draws the pictures of docs/physics.md: stairs_tumble.ani baked by each backend, a row of frames
# each (0.5, 1, 1.5 s and 3.5 s, at rest), the rows one above the other, written to
# docs/physics/stairs_tumble.png. Renders headless (animator render needs no display); tiles
# with ffmpeg (tools/install-deps.sh installs it).
# Usage: tools/physics_pictures.sh [build/bin/animator]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "${1:-build/bin/animator}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p docs/physics
rows=()
for backend in physics.custom physics.bullet; do
  "$bin" render assets/animations/stairs_tumble.ani --backend "$backend" --from 0 --to 3.5 \
    --fps 2 --size 480x270 --out "$work/$backend" >/dev/null
  # Frames 1, 2, 3 and 7: 0.5, 1, 1.5 and 3.5 s.
  ffmpeg -loglevel error -y -i "$work/$backend/frame_00001.png" -i "$work/$backend/frame_00002.png" \
    -i "$work/$backend/frame_00003.png" -i "$work/$backend/frame_00007.png" \
    -filter_complex hstack=inputs=4 "$work/$backend.png"
  rows+=(-i "$work/$backend.png")
done
ffmpeg -loglevel error -y "${rows[@]}" -filter_complex vstack=inputs=2 docs/physics/stairs_tumble.png
echo "wrote docs/physics/stairs_tumble.png"
