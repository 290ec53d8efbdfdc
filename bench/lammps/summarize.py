#!/usr/bin/env python3
"""Summarises a bench/lammps/compare.sh run: WORK/logs/lammps_np{1,2}_round*.log and
WORK/logs/bpmkit_round*.json. Usage: summarize.py WORK

Per run, ns per particle-step from the wall time: LAMMPS's "Loop time of X on N procs for M steps
with P atoms" gives X / (M P); bpmkit's ns_per_particle counter. On a shared machine a process gets
only part of a core, so the single-thread figures are also given from CPU time: LAMMPS's loop time
times its "% CPU use", bpmkit's CPU time per step (Google Benchmark's cpu_time, the main thread: only
meaningful at 1 thread).
"""
import json
import re
import statistics
import sys
from pathlib import Path


def main():
    logs = Path(sys.argv[1]) / "logs"
    runs = {}  # (code, threads, order) -> [(round, wall ns, cpu ns or None)]
    for log in sorted(logs.glob("lammps_np*_round*.log")):
        ranks, rnd = map(int, re.match(r"lammps_np(\d+)_round(\d+)", log.stem).groups())
        text = log.read_text()
        m = re.search(r"Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms", text)
        cpu = re.search(r"([\d.]+)% CPU use", text)
        wall = float(m[1]) / (int(m[2]) * int(m[3])) * 1e9
        runs.setdefault(("LAMMPS", ranks, ""), []).append((rnd, wall, wall * float(cpu[1]) / 100 if cpu else None))
    for path in sorted(logs.glob("bpmkit_round*.json")):
        rnd = int(re.match(r"bpmkit_round(\d+)", path.stem)[1])
        for b in json.loads(path.read_text())["benchmarks"]:
            assert b["time_unit"] == "ms"
            cpu = b["cpu_time"] * 1e6 / b["particles"]
            runs.setdefault(("bpmkit", int(b["threads"]), b["label"]), []).append((rnd, b["ns_per_particle"], cpu))

    print("ns per particle-step, each run (wall; CPU at 1 thread):")
    for key in sorted(runs):
        cells = ", ".join(f"{w:.0f}" + (f" ({c:.0f})" if key[1] == 1 and c else "") for _, w, c in sorted(runs[key]))
        print(f"  {key[0]:6s} {key[1]} {'thread(s)/rank(s)':17s} {key[2]:9s} {cells}")
    print("\nmedians and the ratio LAMMPS / bpmkit (> 1: bpmkit faster):")
    def medians(rows):  # (wall, CPU) medians of (round, wall, cpu) rows; CPU None if a row lacks it
        cpus = [c for _, _, c in rows]
        return statistics.median(w for _, w, _ in rows), None if None in cpus else statistics.median(cpus)

    for threads in (1, 2):
        ref_wall, ref_cpu = medians(runs[("LAMMPS", threads, "")])
        print(f"  {threads} thread(s)/rank(s): LAMMPS {ref_wall:.0f}" + (f" (CPU {ref_cpu:.0f})" if threads == 1 else ""))
        for order in ("shuffled", "morton"):
            ours = runs.get(("bpmkit", threads, order))
            if not ours:
                continue
            wall, cpu = medians(ours)
            line = f"    bpmkit {order:9s} {wall:6.0f}  ratio {ref_wall / wall:.2f}"
            if threads == 1:
                line += f"   CPU {cpu:6.0f}  ratio {ref_cpu / cpu:.2f}"
            print(line)


if __name__ == "__main__":
    main()
