#!/bin/sh
# A short, reproducible fuzz run for ctest:
#   short_run.sh FUZZER WORK_DIR ARTIFACT_DIR [libFuzzer flags...] SEED_DIR...
# WORK_DIR is emptied and given first, so each run starts from the seeds alone (libFuzzer
# writes the new inputs it finds into its first corpus folder, and only there). A crashing
# input is kept in ARTIFACT_DIR, which is not emptied. libFuzzer's exit status is the result:
# non-zero for a crash, a sanitizer report, a leak, a timeout, an allocation over
# -malloc_limit_mb or memory over -rss_limit_mb.
set -eu
fuzzer=$1
work=$2
artifacts=$3
shift 3
rm -rf "$work"
mkdir -p "$work" "$artifacts"
exec "$fuzzer" -artifact_prefix="$artifacts/" "$work" "$@"
