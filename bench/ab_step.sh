#!/usr/bin/env bash
# A/B of the DEM step between two builds, alternating in rounds (BENCHMARKS.md, "Page faults and
# teams of one"): the small cylinder's whole run on one thread, Chen's cantilever suite (the
# README's main job), BM_CompressionStep on the 1e5 packing (1 and 2 threads), and the lattice's
# BM_Step and BM_GatherBondLoads (1 thread).
# Usage: bench/ab_step.sh OLD_BUILD_DIR NEW_BUILD_DIR [ROUNDS]   (builds with -DBPMKIT_ENABLE_BENCH=ON)
set -euo pipefail
old=$1 new=$2 rounds=${3:-3}
export OMP_WAIT_POLICY=passive  # as bpmkit sets it for itself
scenario="$(cd "$(dirname "$0")/.." && pwd)/examples/04_compression/small_cylinder/compression.yaml"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for round in $(seq "$rounds"); do
  for side in old new; do
    dir=$old; [ "$side" = new ] && dir=$new
    rm -rf "$out/run"
    small=$( { /usr/bin/time -f "%e" "$dir/src/bpmkit" --quiet run "$scenario" --out "$out/run" --threads 1 >/dev/null; } 2>&1 | tail -1)
    rm -rf "$out/cantilever"
    cantilever=$( { /usr/bin/time -f "%e" "$dir/src/bpmkit" --quiet verify cantilever --out "$out/cantilever" >/dev/null; } 2>&1 | tail -1)
    compression=$("$dir/bench/bpmkit_bench_contacts" --benchmark_filter='CompressionStep/kparticles:100/threads:[12]/order:2' \
      --benchmark_min_time=2 2>/dev/null | awk '/Compression/ {printf "%s ", $2}')
    lattice=$("$dir/bench/bpmkit_bench" --benchmark_filter='BM_Step/threads:1|GatherBondLoads/threads:1' \
      --benchmark_min_time=1 2>/dev/null | awk '/BM_/ {printf "%s ", $2}')
    echo "round $round $side: small cylinder $small s | cantilever suite $cantilever s | compression 1t 2t: $compression ms | lattice step, gather (1t): $lattice ms"
  done
done
