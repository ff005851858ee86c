#!/usr/bin/env bash
# Installs what is missing, builds animator, and runs its main job on the demo animation.
# Until the editor lands (issue "The editor"), the main job is `animator info`: it prints the
# demo's settings, models and keyframes. Extra arguments replace the default command, e.g.
#   tools/run.sh plugins
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j "$(nproc)"   # the program and every plugin (and the tests)
if [ $# -eq 0 ]; then
  set -- info assets/animations/drop.ani
fi
exec ./build/bin/animator "$@"
