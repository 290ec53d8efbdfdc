#!/usr/bin/env bash
# The compression step of bpmkit against Debian's LAMMPS on the same shuffled packing, in one run
# (issue 12, item 3; BENCHMARKS.md, "bpmkit against LAMMPS"). Usage:
#
#   bench/lammps/compare.sh [BUILD_DIR [WORK_DIR [ROUNDS [LAMMPS_STEPS [BPMKIT_MIN_TIME_S]]]]]
#
# defaults: build /tmp/bpmkit_lammps 2 200 5. Needs `apt-get install lammps` (lmp, and mpirun from
# Open MPI) and python3, and BUILD_DIR configured with -DBPMKIT_ENABLE_BENCH=ON.
#
# 1. bpmkit_bench_contacts exports the benchmark's 1e5-particle bonded cylinder with its rows shuffled
#    (BPMKIT_BENCH_EXPORT) and export_lammps.py writes it as a LAMMPS data file in the same order.
# 2. Each round runs LAMMPS (1 rank, 2 MPI ranks) and bpmkit's BM_CompressionStep (1 and 2 threads;
#    order 1 = the shuffled rows as stored, order 2 = the canonical Morton order that loading the
#    shuffled file through a scenario gives), alternating which goes first.
# 3. ns per particle-step: LAMMPS's "Loop time of X on N procs for M steps with P atoms" (setup and
#    the first neighbour build excluded) X / (M P); bpmkit's ns_per_particle counter; at 1 thread
#    also from CPU time (summarize.py). Logs in WORK/logs, the table in WORK/summary.txt.
set -euo pipefail
build=${1:-build}
work=${2:-/tmp/bpmkit_lammps}
rounds=${3:-2}
steps=${4:-200}
min_time=${5:-5}
here=$(cd "$(dirname "$0")" && pwd)
bench=$(cd "$build" && pwd)/bench/bpmkit_bench_contacts
mkdir -p "$work/logs"
export OMP_NUM_THREADS=1  # LAMMPS; the benchmark sets its own thread counts
# Threads wait passively, as `bpmkit` sets it for itself (BENCHMARKS.md, "the OpenMP wait policy"):
# on shared cores spinning threads make 2 threads slower than 1.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}

BPMKIT_BENCH_EXPORT="$work" "$bench"
python3 "$here/export_lammps.py" "$work"
read -r -a vars <"$work/lammps.vars"

lammps() {  # ranks round
  local log="$work/logs/lammps_np$1_round$2.log"
  local cmd=(lmp -in "$here/in.compression" "${vars[@]}" -var data "$work/lammps.data" -var steps "$steps"
    -log none)
  if [ "$1" -gt 1 ]; then cmd=(mpirun --allow-run-as-root --oversubscribe -np "$1" "${cmd[@]}"); fi
  (cd "$work" && "${cmd[@]}") >"$log" 2>&1
  awk -v r="$2" -v np="$1" '/^Loop time of/ {printf "round %s  LAMMPS  %s rank(s)            %8.1f ns per particle-step\n", r, np, $4 / ($9 * $12) * 1e9}' "$log" | tee -a "$work/results.txt"
}

bpmkit() {  # round
  local json="$work/logs/bpmkit_round$1.json"
  "$bench" --benchmark_filter='BM_CompressionStep/kparticles:100/threads:[12]/order:[12]/' \
    --benchmark_min_time="$min_time" --benchmark_out="$json" --benchmark_out_format=json >"$work/logs/bpmkit_round$1.log" 2>&1
  python3 - "$json" "$1" <<'PY' | tee -a "$work/results.txt"
import json, sys
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    print(f"round {sys.argv[2]}  bpmkit  {int(b['threads']):d} thread(s), {b['label']:9s} {b['ns_per_particle']:8.1f} ns per particle-step"
          f" ({int(b['iterations'])} steps)")
PY
}

: >"$work/results.txt"
lscpu | grep 'Model name' | tee -a "$work/results.txt"
for ((r = 1; r <= rounds; ++r)); do
  if ((r % 2)); then
    lammps 1 "$r"; lammps 2 "$r"; bpmkit "$r"
  else
    bpmkit "$r"; lammps 1 "$r"; lammps 2 "$r"
  fi
done

python3 "$here/summarize.py" "$work" | tee "$work/summary.txt"
