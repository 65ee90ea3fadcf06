#!/usr/bin/env bash
# A bounded libFuzzer run: run_fuzzer.sh FUZZER SEED_DIR FINDINGS_DIR [SECONDS]
# New inputs go to a temporary corpus that is removed at the end; SEED_DIR is only read. A crash,
# sanitizer report, leak, timeout or memory blow-up is saved into FINDINGS_DIR (crash-<sha1> and
# the like) and makes the run fail: copy it into SEED_DIR once the reader is fixed.
set -euo pipefail
fuzzer=$1 seeds=$2 findings=$3 seconds=${4:-10}
work=$(mktemp -d "${TMPDIR:-/tmp}/fdh-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/corpus" "$findings"
# The target writes each input to a file in $TMPDIR: the work folder, removed with it.
TMPDIR=$work "$fuzzer" -max_total_time="$seconds" -timeout=10 -max_len=4096 -rss_limit_mb=2048 \
  -malloc_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/" \
  "$work/corpus" "$seeds"
