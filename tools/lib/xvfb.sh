# Sourced by the tools that drive the editor under Xvfb (editor_fps.sh, manual_screenshots.sh):
# start_xvfb starts a 1280x720 Xvfb of their own, sets DISPLAY and xvfb (its pid), and returns once
# it takes clients. A display number at random over a wide range, tried until one answers (as
# tests/editor/editor_e2e.py does): the lowest free number was seen refusing clients right after
# another server on it shut down (its exit removed the new one's socket).
start_xvfb() {
  local n _
  for _ in $(seq 20); do
    n=$((1000 + RANDOM % 29000))
    [ -e "/tmp/.X$n-lock" ] && continue
    Xvfb ":$n" -screen 0 1280x720x24 -nolisten tcp >/dev/null 2>&1 &
    xvfb=$!
    export DISPLAY=":$n"
    for _ in $(seq 100); do
      kill -0 "$xvfb" 2>/dev/null || break
      xdotool getdisplaygeometry >/dev/null 2>&1 && return 0
      sleep 0.1
    done
    kill "$xvfb" 2>/dev/null || true
    wait "$xvfb" 2>/dev/null || true
    xvfb=""
  done
  echo "Xvfb did not start" >&2
  return 1
}
