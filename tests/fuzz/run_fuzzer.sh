#!/usr/bin/env bash
# Runs one libFuzzer target for a fixed number of inputs from a fixed seed, as CTest does in CI:
#   run_fuzzer.sh FUZZER RUNS SEED_FILE...
# The seed files (those under 64 KiB) are copied into a fresh corpus, so the run never writes
# into the source tree; new inputs go to a scratch folder that is removed afterwards. Any crash,
# hang (-timeout), sanitizer report or memory blow-up (-rss_limit_mb) fails the test, and
# libFuzzer leaves the offending input as crash-*/timeout-* in the working directory.
set -euo pipefail
fuzzer=$1 runs=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/seeds" "$work/new"
for f in "$@"; do
  [ -f "$f" ] && [ "$(stat -c %s "$f")" -lt 65536 ] && cp "$f" "$work/seeds/$(basename "$(dirname "$f")")_$(basename "$f")"
done
exec "$fuzzer" -runs="$runs" -seed=1 -timeout=30 -rss_limit_mb=4096 -max_len=65536 \
  -print_final_stats=1 "$work/new" "$work/seeds"
