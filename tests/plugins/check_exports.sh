#!/usr/bin/env bash
# Fails unless every library given exports exactly one defined dynamic symbol,
# animator_plugin_entry (nm -D lists what another program can bind to).
set -euo pipefail
status=0
for lib in "$@"; do
  exported=$(nm -D --defined-only "$lib" | awk '{print $NF}' | sort -u)
  if [ "$exported" != "animator_plugin_entry" ]; then
    echo "FAIL $lib exports:"; echo "$exported" | sed 's/^/  /'
    status=1
  else
    echo "ok   $lib exports only animator_plugin_entry"
  fi
done
exit $status
