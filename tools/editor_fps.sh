#!/usr/bin/env bash
# The editor's frame rate with 100 models (docs/performance.md): writes a scene of a floor and
# 99 balls in a 9 x 11 grid, dropped with Dynamics and Gravity so they bounce (some textured,
# some reflective), opens it in the editor under Xvfb (software OpenGL: Mesa's llvmpipe), plays
# its 5 s twice (the second time all baked) and prints the rate the editor drew at the second
# time ("animator: played N frames in T s (F fps)"), once per run.
# Usage: tools/editor_fps.sh [build/bin/animator] [runs] [models]
# models (default 100): a floor and models - 1 balls. The View settings (shadows, anti-aliasing)
# are the editor's own, from $XDG_STATE_HOME/animator/view: point XDG_STATE_HOME at a folder with
# a `view` file of "msaa N", "shadows 0|1", "reflections 0|1" and "resolution 100|75|50" lines to
# measure each (docs/performance.md). The frame budget that lowers them when frames are slow is
# off (ANIMATOR_FRAME_BUDGET=off) unless ANIMATOR_FRAME_BUDGET=on is given, and then the budget's
# lines are printed too; PLAYS=N plays N times instead of twice (the budget takes a playback or
# two to lower the quality: PLAYS=4), the rate of the last printed.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "${1:-build/bin/animator}")
runs=${2:-3}
budget=${ANIMATOR_FRAME_BUDGET:-off}
plays=${PLAYS:-2}
models=${3:-100}
work=$(mktemp -d)
xvfb=""
editor=""
cleanup() {
  [ -n "$editor" ] && kill "$editor" 2>/dev/null
  [ -n "$xvfb" ] && kill "$xvfb" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
python3 - "$work/hundred.ani" "$models" <<'PY'
import sys
balls = int(sys.argv[2]) - 1
out = ['animator-ani 1', '# 100 models: a floor and 99 bouncing balls (tools/editor_fps.sh)', '',
       'settings', '  max_time_ms 5000', '  gravity 9.81', '  down y', '  cel_shading false',
       '  skybox "day"', '  physics_backend "physics.custom"', 'end', '',
       'model "floor"', '  mesh "plane"', '  kd 0.6 0.6 0.6', 'end', '']
states = ['  camera position 0 12 30 rotation 0.9914449 -0.1305262 0 0 fov 50',
          '  state "floor" center 0 0 0 angles 0 0 0 scale 20 1 20 turn 0 0 0']
for i in range(balls):
    name = 'ball%02d' % i
    x, z = (i % 11) * 3.0 - 15.0, (i // 11) * 3.0 - 12.0
    out += ['model "%s"' % name, '  mesh "sphere"', '  kd %.2f %.2f %.2f' % (0.2 + 0.008 * i, 0.9 - 0.007 * i, 0.5),
            '  ks 0.5 0.5 0.5', '  shininess 40', '  dynamics true', '  gravity true']
    if i % 3 == 0:
        out += ['  texture "wood"', '  tint 0.3']
    if i % 5 == 0:
        out += ['  reflectivity 0.4']
    out += ['end', '']
    states.append('  state "%s" center %.1f %.1f %.1f angles 0 0 0 scale 1 1 1 turn 0 0 0' % (name, x, 2.0 + (i % 7), z))
out += ['keyframe 0'] + states + ['end', '']
open(sys.argv[1], 'w').write('\n'.join(out))
PY
. tools/lib/xvfb.sh
start_xvfb
for run in $(seq "$runs"); do
  : > "$work/log"
  (cd "$work" && ANIMATOR_EDITOR_SIGNALS=1 ANIMATOR_FRAME_BUDGET="$budget" exec "$bin" hundred.ani) >"$work/log" 2>&1 &
  editor=$!
  win=""
  for _ in $(seq 100); do
    win=$(xdotool search --pid "$editor" --name '^animator' 2>/dev/null | head -1 || true)
    [ -n "$win" ] && break
    sleep 0.2
  done
  [ -n "$win" ] || { echo "the editor did not open a window:" >&2; cat "$work/log" >&2; exit 1; }
  for _ in $(seq 1200); do grep -q '^animator: idle' "$work/log" && break; sleep 0.1; done   # baked and drawn
  xdotool windowfocus --sync "$win"
  # Played twice: the first time playback may wait for the bake; the second plays what is baked.
  for play in $(seq "$plays"); do
    xdotool key space
    for _ in $(seq 600); do [ "$(grep -c '^animator: played [0-9]' "$work/log")" -ge "$play" ] && break; sleep 0.1; done
  done
  if [ "$budget" != off ]; then grep 'over the [0-9.]* ms budget' "$work/log" || true; fi
  grep '^animator: played [0-9]' "$work/log" | tail -1 || { echo "no frame rate said:" >&2; cat "$work/log" >&2; exit 1; }
  kill "$editor"; wait "$editor" 2>/dev/null || true
  editor=""
done
