#!/usr/bin/env bash
# Fails when a Catch test's name cannot reach ctest whole, so that the test would never run:
# catch_discover_tests keeps the names in a CMake list, which cuts a name at ';', and a lone '[' or
# ']' (CMake's bracket nesting) stops every later ';' of the list from splitting it, so that the
# tests after it became one test named by all their names; ctest then runs a filter that matches
# no test, and Catch 2 passes it. And ctest takes a name starting with '-' as an option.
# Usage: check_test_names.sh CATCH_BINARY...
set -euo pipefail
status=0
for binary in "$@"; do
  # (Catch 2 exits with the number of tests it listed.)
  names=$("$binary" --list-test-names-only || true)
  count=$(printf '%s\n' "$names" | grep -c . || true)
  if [ "$count" -eq 0 ]; then
    echo "FAIL $(basename "$binary"): listed no test"
    status=1
    continue
  fi
  bad=$(printf '%s\n' "$names" | grep -e ';' -e '^-' -e '\[' -e '\]' || true)
  if [ -n "$bad" ]; then
    echo "FAIL $(basename "$binary"): names ctest cannot run (no ';', '[' or ']', none starting with '-'):"
    printf '%s\n' "$bad" | sed 's/^/  /'
    status=1
  else
    echo "ok   $(basename "$binary"): $count names"
  fi
done
exit $status
