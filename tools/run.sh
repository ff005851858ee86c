#!/usr/bin/env bash
# Installs what is missing, builds animator, and opens the editor on the demo scene (it needs a
# display; on a machine without one, run it under `xvfb-run -a`). Extra arguments are passed to
# `animator`, e.g.
#   tools/run.sh assets/animations/drop.ani      # the editor on another file
#   tools/run.sh plugins                         # a subcommand
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j "$(nproc)"   # the program and every plugin (and the tests)
exec ./build/bin/animator "$@"
