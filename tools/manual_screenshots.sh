#!/usr/bin/env bash
# Takes the screenshots of docs/manual.md from the real editor: starts it on the demo scene under
# Xvfb, drives it with xdotool as a user would, and writes docs/manual/*.png.
# Usage: tools/manual_screenshots.sh [build/bin/animator]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "${1:-build/bin/animator}")
out=$(realpath docs/manual)
mkdir -p "$out"
work=$(mktemp -d)
# Autosave's recovery files go here, not to ~/.local/state: one of the user's own would greet
# the editor with a "Recover unsaved work" dialog in every screenshot.
export XDG_STATE_HOME="$work/state"
editor=""
xvfb=""
cleanup() {
  [ -n "$editor" ] && kill "$editor" 2>/dev/null
  [ -n "$xvfb" ] && kill "$xvfb" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
. tools/lib/xvfb.sh
start_xvfb
# The editor says "animator: idle ..." once it has drawn everything and sleeps.
# Starts the editor on FILE (a name in $work; "" for the demo scene) with any extra VAR=value
# settings, waits for its window, for it to draw and sleep, and focuses it.
start_editor() {
  local file=$1
  shift
  if [ -n "$editor" ]; then kill "$editor" 2>/dev/null || true; wait "$editor" 2>/dev/null || true; fi
  : > "$work/log"
  (cd "$work" && exec env "$@" ANIMATOR_EDITOR_SIGNALS=1 "$bin" ${file:+"$file"}) >"$work/log" 2>&1 &
  editor=$!
  win=""
  for _ in $(seq 50); do
    win=$(xdotool search --pid "$editor" --name '^animator' 2>/dev/null | head -1 || true)
    [ -n "$win" ] && break
    sleep 0.2
  done
  [ -n "$win" ] || { echo "the editor did not open a window:" >&2; cat "$work/log" >&2; exit 1; }
  for _ in $(seq 600); do grep -q '^animator: idle' "$work/log" && break; sleep 0.1; done
  xdotool windowfocus --sync "$win"
}
start_editor ""

shot() { sleep "${2:-0.6}"; import -window root "$out/$1.png"; }
# ImGui 1.86 sees one mouse position per frame: give it a moment between actions.
# The pointer moves first and rests: a click sent with the move may land where it was before.
click() { xdotool mousemove --window "$win" "$1" "$2"; sleep 0.3; xdotool click 1; sleep 0.4; }

shot 01-editor
# The 3D view is right of the Animator Interface and above the Timeline (560 px tall at 1280x720).
click 642 196                  # the red ball: selected, tinted yellow, its Model Interface opens beside the view
shot 02-selected
xdotool key space              # play: the ball falls and bounces
shot 03-playing 0.55
xdotool key space              # pause
click 27 370                   # Cel Shading
shot 04-cel-shading
click 27 370                   # back to Phong
click 576 296                  # the textured cube
click 174 63                   # Translate mode
xdotool mousemove --window "$win" 128 86 keydown ctrl click 1 keyup ctrl   # the Time slider as a text field
sleep 0.4
xdotool key ctrl+a type 4000
xdotool key Return
sleep 0.4
xdotool mousemove --window "$win" 576 296 mousedown 3
for dx in 20 40 60 80 100 120 140 160; do
  xdotool mousemove --window "$win" $((576 - dx / 5)) $((296 - dx * 2 / 5))   # up and a little left, clear of the cylinder
  sleep 0.05
done
xdotool mouseup 3
shot 05-new-keyframe
xdotool key p                  # the cube's motion path: from its place at 0 s to its new key at 4 s
shot 09-paths
xdotool key p
xdotool key f                  # the free view, framing the selected cube
sleep 0.4
xdotool mousemove --window "$win" 700 470 keydown alt mousedown 1   # Alt + left drag: orbit
for dx in 15 30 45 60 75 90; do
  xdotool mousemove --window "$win" $((700 + dx)) $((470 + dx * 2 / 3))
  sleep 0.05
done
xdotool mouseup 1 keyup alt
xdotool mousemove --window "$win" 640 500 click 5 click 5 click 5 click 5   # the wheel: zoom out
shot 06-free-view
# The Timeline: the cube's key at 4 s (rows: Camera, floor, ball, cube, ...; 20 s across the
# tracks from x 476 to 1264) dragged to 8 s; the ball's bounces tick its row and the floor's.
xdotool mousemove --window "$win" 634 656; sleep 0.3
xdotool mousedown 1; sleep 0.2
for x in 660 690 720 750 780 791; do xdotool mousemove --window "$win" $x 656; sleep 0.05; done
sleep 0.2; xdotool mouseup 1
xdotool mousemove --window "$win" 1000 450
shot 08-timeline

# Models inside each other: the demo's cube as it once was, half inside the floor.
sed 's/cube:translate(-1.5, 1, 0).*/cube:translate(-1.5, 0.5, 0)/' assets/scenes/simple.lua > "$work/sunk.lua"
grep -q 'translate(-1.5, 0.5, 0)' "$work/sunk.lua" || { echo "simple.lua changed: no cube to sink" >&2; exit 1; }
start_editor sunk.lua
click 753 303                  # the cube, sunk half into the floor (the view spans the window right of the panel, above the Timeline)
click 927 109                  # Model Interface > Physics > Gravity: the bake finds them overlapping
for _ in $(seq 600); do grep -q "overlap at t = 0 s" "$work/log" && break; sleep 0.1; done
xdotool mousemove --window "$win" 700 650
shot 07-overlap 1.5

# The Outliner and the Model Interface over several models (docs/manual.md, "The Outliner").
ctrl_click() { xdotool mousemove --window "$win" "$1" "$2"; sleep 0.3; xdotool keydown ctrl; sleep 0.1; xdotool click 1; sleep 0.1; xdotool keyup ctrl; sleep 0.4; }
# Outliner rows (1280x720) start at y 584, 17 px apart; a row's box is at x 33 + 21 per level.
cp assets/scenes/puppet.lua "$work/"
start_editor puppet.lua
click 110 652                  # the left arm's row (under left_shoulder)
ctrl_click 110 686             # and the right arm's: both selected, outlined in the view
click 54 618                   # the head's box: hidden from the view
xdotool mousemove --window "$win" 700 650
shot outliner
cp assets/scenes/simple.lua "$work/"
start_editor simple.lua
click 110 601                  # the ball's row
ctrl_click 110 618             # and the cube's: the Model Interface edits both, mixed fields say so
xdotool mousemove --window "$win" 700 650
shot multi-edit
# The transform gizmo (docs/manual.md, "Transforming the camera and models"): the cube selected,
# `w` (Translate), the pointer over its X arrow, which turns yellow.
cp assets/scenes/simple.lua "$work/"
start_editor simple.lua
click 752 280                  # the cube (the view right of the Animator Interface, above the Timeline)
xdotool key w
xdotool mousemove --window "$win" 617 280
shot 10-gizmo
# Autosave and recovery: an edit autosaved (every second here), the editor killed, started again.
cp assets/animations/drop.ani "$work/drop.ani"
touch -d '1 minute ago' "$work/drop.ani"   # the autosave is newer: offered
# A home of its own, so the dialog names the folder a user's shows: ~/.local/state/animator/recovery.
mkdir -p "$work/home"
start_editor drop.ani HOME="$work/home" XDG_STATE_HOME= ANIMATOR_AUTOSAVE_SECONDS=1
click 27 370                   # Cel Shading: an unsaved change
for _ in $(seq 600); do grep -q '^animator: autosaved' "$work/log" && break; sleep 0.1; done
grep -q '^animator: autosaved' "$work/log" || { echo "no autosave:" >&2; cat "$work/log" >&2; exit 1; }
kill -KILL "$editor"; wait "$editor" 2>/dev/null || true
start_editor drop.ani HOME="$work/home" XDG_STATE_HOME=
grep -q '^animator: Recover unsaved work' "$work/log" || { echo "no recovery offered:" >&2; cat "$work/log" >&2; exit 1; }
xdotool mousemove --window "$win" 700 650
shot recovery-dialog 1.0
# The File menu with Open Recent, and the file browser (docs/manual.md, "Files").
kill "$editor" 2>/dev/null || true; wait "$editor" 2>/dev/null || true; editor=""
rm -rf "$work/state"
mkdir -p "$work/files/animations"
cp assets/scenes/simple.lua assets/scenes/puppet.lua "$work/files/"
cp assets/animations/drop.ani "$work/files/animations/"
start_editor files/puppet.lua
start_editor files/animations/drop.ani   # Open Recent: drop.ani, then puppet.lua
click 24 19                    # File
xdotool mousemove --window "$win" 60 78   # Open Recent: its submenu opens
shot files-menu 1.0
click 800 300                  # closes the menu
xdotool key ctrl+o; sleep 0.5  # Open: the browser, in drop.ani's folder
xdotool key BackSpace; sleep 0.3   # up to the folder of scenes
xdotool key Down; sleep 0.3; xdotool key Down; sleep 0.3
shot files-browser

# Rendering from the editor (docs/manual.md, "Rendering and exporting from the editor"): CTRL+F12
# opens Render, its Render button starts, and the progress bar shows once frames are written;
# ESC cancels it.
cp assets/animations/drop.ani "$work/drop.ani"
start_editor drop.ani
xdotool keydown ctrl; sleep 0.1; xdotool keydown F12; sleep 0.1; xdotool keyup F12; sleep 0.1; xdotool keyup ctrl
sleep 0.6
click 406 455                  # Render (frames, 1280x720, 0 to 10 s at 30 fps)
for _ in $(seq 600); do [ "$(ls "$work/drop_render" 2>/dev/null | wc -l)" -ge 20 ] && break; sleep 0.1; done
shot render-progress 0.1
xdotool keydown Escape; sleep 0.1; xdotool keyup Escape   # cancel
for _ in $(seq 600); do grep -q '^animator: render cancelled' "$work/log" && break; sleep 0.1; done
# File > Export glTF (.glb)...: the Export dialog with only glTF ticked (docs/export.md).
sleep 0.5
click 24 19                    # File
click 60 192                   # Export glTF (.glb)...
shot export-gltf
xdotool key Escape; sleep 0.3

# Adding models (docs/manual.md, "Adding, duplicating and deleting models"): SHIFT+A's dialog
# over the demo scene, "c" typed to narrow the meshes listed.
start_editor simple.lua
xdotool key shift+a; sleep 0.5
xdotool type --delay 80 c
xdotool mousemove --window "$win" 700 650
shot add-model

# Lights (docs/manual.md, "Lights"): a course ray-tracer scene lit by its own two lights, the
# Lights window open from the menu bar, the first light's colour typed brighter than white, red.
cp tests/data/cs488/a4_hier.lua "$work/"
start_editor a4_hier.lua
click 86 19                    # Lights
for field in 503 593; do       # the first light's G and B: 0
  xdotool mousemove --window "$win" "$field" 179 keydown ctrl click 1 keyup ctrl; sleep 0.4
  xdotool key ctrl+a type 0; xdotool key Return; sleep 0.4
done
xdotool mousemove --window "$win" 410 179 keydown ctrl click 1 keyup ctrl; sleep 0.4   # its R: 2.5
xdotool key ctrl+a type 2.5; xdotool key Return
xdotool mousemove --window "$win" 900 480
shot lights

# Joints (docs/manual.md, "Joints"): the sheared puppet's neck (x -20..20), chosen in the
# Outliner, turned up in Rotate mode past its range: held at -20, the tooltip says so.
cp tests/data/cs488/sheared_puppet.lua "$work/"
start_editor sheared_puppet.lua
click 100 638                  # neck, in the Outliner
click 101 64                   # Rotate
xdotool mousemove --window "$win" 900 300 mousedown 3
for dy in $(seq 10 10 200); do xdotool mousemove --window "$win" 900 $((300 - dy)); sleep 0.05; done
shot joints
xdotool mouseup 3
# Shadows and anti-aliasing (docs/manual.md): simple.lua's models and their shadows (the
# camera's light), anti-aliased, the View menu open.
cp assets/scenes/simple.lua "$work/"
start_editor simple.lua
click 137 19                   # View
xdotool mousemove --window "$win" 137 19
shot view-shadows
xdotool key Escape
# Reflections of other models (docs/manual.md): orbs.ani at its start, the mirror orb showing its
# neighbour, the View menu open.
cp assets/animations/orbs.ani "$work/"
start_editor orbs.ani
click 137 19                   # View
xdotool mousemove --window "$win" 137 19
shot view-reflections
xdotool key Escape
echo "wrote the screenshots to $out"
