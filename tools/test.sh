#!/usr/bin/env bash
# Builds animator and runs every test: first a normal build, then the whole suite again under
# AddressSanitizer + UndefinedBehaviorSanitizer, then a short run of each file reader's fuzzer
# (a clang build of the readers alone, docs/fuzzing.md). Installs missing Debian packages first.
# Usage: tools/test.sh            (all three)
#        ANIMATOR_SKIP_SANITIZE=1 tools/test.sh   (no sanitizer build, for a quicker check)
#        ANIMATOR_SKIP_FUZZ=1 tools/test.sh       (no fuzz build)
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/install-deps.sh

jobs=$(nproc)
run_suite() {
  local dir=$1; shift
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
  # The editor tests start their own Xvfb (xvfb-run -a); the renderer draws through EGL without one.
  ctest --test-dir "$dir" --output-on-failure -j "$jobs"
}

run_suite build
if [ "${ANIMATOR_SKIP_SANITIZE:-0}" != "1" ]; then
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    run_suite build-asan -DANIMATOR_SANITIZE=ON
fi
if [ "${ANIMATOR_SKIP_FUZZ:-0}" != "1" ]; then
  # libFuzzer and its sanitizers come with clang, whose objects do not mix with GCC's: a build
  # folder of its own holding only the readers and their harnesses, a few minutes in all.
  CC=clang CXX=clang++ run_suite build-fuzz -DANIMATOR_FUZZ=ON
fi
