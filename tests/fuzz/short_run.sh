#!/bin/sh
# A short, reproducible fuzz run for ctest:
#   short_run.sh FUZZER WORK_DIR ARTIFACT_DIR [libFuzzer flags...] SEED_DIR...
# WORK_DIR is emptied and given first, so each run starts from the seeds alone (libFuzzer
# writes the new inputs it finds into its first corpus folder, and only there). A crashing
# input is kept in ARTIFACT_DIR, which is not emptied. libFuzzer's exit status is the result:
# non-zero for a crash, a sanitizer report, a leak, a timeout, an allocation over
# -malloc_limit_mb or memory over -rss_limit_mb.
#
# On a failure the last lines printed repeat what went wrong and the input itself, because a CI
# log may keep only the head and the tail of a long output (and the artifact stays on CI).
set -eu
fuzzer=$1
work=$2
artifacts=$3
shift 3
rm -rf "$work"
mkdir -p "$work" "$artifacts"
log="$work.log"
status=0
"$fuzzer" -artifact_prefix="$artifacts/" "$work" "$@" > "$log" 2>&1 || status=$?
cat "$log"
if [ "$status" -ne 0 ]; then
  echo "---- the short run failed (exit $status); what the harness and the sanitizers said:"
  grep -E "fuzz harness:|ERROR:|SUMMARY:|^    #[0-9] |^    #1[0-9] " "$log" | head -40 || true
  input=$(ls -t "$artifacts" | head -n 1)
  if [ -n "$input" ]; then
    echo "---- the input ($artifacts/$input, first 3000 bytes, non-printing bytes shown by cat -v):"
    head -c 3000 "$artifacts/$input" | cat -v
    echo
  fi
fi
exit "$status"
