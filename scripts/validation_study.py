#!/usr/bin/env python3
"""Jarolin & Dosta (2020) section 4 reproduced with bpmkit's own DEM as the reference.

For every sample (each generated independently, from its own seed) the script runs
`bpmkit stiffness` with the DEM (real platens), the linear DSM (platen walls), the nonlinear DSM,
the STE (plain and layered) and the kinematic DSM, and `bpmkit calibrate --target-K K_DEM` with its
default stages; it writes each method's error against the DEM, its wall time and speed-up, and the
calibrated bond modulus against the true one.

docs/validation.md runs its Fig. 5 with it (its tables and Fig. 4 come from
scripts/validation_fig4.sh, on fixed samples). Cases:
- case 1: bonded cylinders (height = diameter), TBBM bonds superimposed on Hertz-Mindlin contacts,
  steel platens (friction 0; the grain-steel pair takes the mean, 0.15), 2 % strain (the paper's aerogel samples);
- case 2: bi-component agglomerates (spheres), two bond materials in stiffness ratios 1:2, 2:1 and
  1:4, mixing ratios from 10 to 100 %, bonds superimposed on Hertz-Mindlin, 2 % strain;
- case 3: an inverse-opal-like porous box: a dense packing with a regular array of spherical pores
  removed (the bonds replace the contacts), 2 % strain;
- fig5: wall time against particle count, independently generated cylinders.

Outputs (under --out, default out/validation_study): samples.csv (one row per sample and method),
summary.csv and summary.md (mean, standard deviation and maximum of |error| per case and method,
mean speed-up, as in Jarolin Fig. 4), fig4.png/svg and fig5.png/svg (with matplotlib, Debian's
python3-matplotlib: run with /usr/bin/python3).

Usage: /usr/bin/python3 scripts/validation_study.py [--case1 N] [--case1-particles P] ...
(--help lists them). Methods already measured on a sample (its result.json under --out) are not
run again, so an interrupted study resumes where it stopped; --rerun dsm calibrate measures those
again (after a change to them) and keeps the DEM.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
METHODS = ["dem", "dsm", "dsm-nonlinear", "ste", "ste-layered", "dsm-kinematic"]
PARTICLE_RADIUS = 1.0e-4  # m, case 1 and fig. 5 (mean)
AGGLOMERATE_RADIUS = 4.0e-5  # m, case 2 (mean)
BOND_E = 2.0e8  # Pa, case 1 bond Young's modulus (the small cylinder's)


def cylinder_radius(particles, porosity=0.42, r=PARTICLE_RADIUS):
    # N (4/3 pi r^3) = (1 - porosity) pi R^2 (2 R)
    return (particles * (4.0 / 3.0) * r**3 / (2.0 * (1.0 - porosity))) ** (1.0 / 3.0)


def sphere_radius(particles, porosity=0.45, r=AGGLOMERATE_RADIUS):
    return (particles * r**3 / (1.0 - porosity)) ** (1.0 / 3.0)


MASS_SCALING = {"factor": 1.0}  # --mass-scaling: the DEM's compression.mass_scaling


def scenario_yaml(description, density, bond_materials, strain, bonded="superimpose"):
    """A compression scenario on structure/particles.csv and bonds.csv: Hertz-Mindlin grains
    (E = 1e8 Pa), bonds `bonded` on the contacts, steel platens (friction 0, the pair with
    the grains 0.15: the mean), local damping; the DEM's masses scaled by --mass-scaling."""
    scaling = MASS_SCALING["factor"]
    scaling_line = f"\n  mass_scaling: {scaling:g}" if scaling != 1.0 else ""
    return f"""description: {description}
particle_materials:
  grain:
    density: {density}
    contact: {{youngs_modulus: 1e8, poisson_ratio: 0.25, restitution: 0.5, friction: 0.3}}
  steel:
    density: 7850
    contact: {{youngs_modulus: 200e9, poisson_ratio: 0.3, restitution: 0.5, friction: 0.0}}

bond_materials:
{bond_materials}
particles:
  material: grain
  file: structure/particles.csv
bonds:
  file: structure/bonds.csv
contacts:
  particle_particle: true
  bonded: {bonded}
damping:
  particle: 0.7
compression:
  platen_material: steel
  strain_rate: 2
  target_strain: {strain}
  fit_window: [0.2, 1.0]{scaling_line}
output:
  vtk: false
"""


def spec_yaml(description, seed, container, radii, packing, bonds):
    """A `bpmkit generate` spec: each argument is the YAML of its key's value (indented lines)."""
    return f"""description: {description}
seed: {seed}
container:
  {container}
radii:
  {radii}
packing:
{packing}
bonds:
{bonds}
output:
  vtk: false
  scenario: false
"""


def case1_files(seed, particles):
    radius = cylinder_radius(particles)
    spec = spec_yaml(f"validation case 1 cylinder, seed {seed}", seed,
                     f"cylinder: {{radius: {radius:.6e}, height: {2 * radius:.6e}, base: [0, 0, 0]}}",
                     f"normal: {{mean: {PARTICLE_RADIUS:.3e}, std: {0.1 * PARTICLE_RADIUS:.3e}}}",
                     "  porosity: 0.42\n  overlap_tolerance: 0.01", "  contact_radius_multiplier: 1.15")
    bonds = f"  bond: {{model: tbbm, youngs_modulus: {BOND_E:g}, poisson_ratio: 0.25, radius_multiplier: 0.8}}"
    scenario = scenario_yaml(f"validation case 1, seed {seed}", 1500, bonds, 0.02)
    return spec, scenario, {"bond": BOND_E}


def case2_files(seed, particles, ratio, mixing, strain):
    """ratio = (a, b): E_A : E_B; mixing = fraction of bonds of material A."""
    e_a, e_b = 1e8 * ratio[0], 1e8 * ratio[1]
    shares = {"a": mixing} if mixing >= 1.0 else {"a": mixing, "b": round(1.0 - mixing, 6)}
    share_text = "\n".join(f"    {k}: {v}" for k, v in shares.items())
    spec = spec_yaml(f"validation case 2 agglomerate, seed {seed}", seed,
                     f"sphere: {{radius: {sphere_radius(particles):.6e}, centre: [0, 0, 0]}}",
                     f"lognormal: {{mean: {AGGLOMERATE_RADIUS:.3e}, std: {0.1 * AGGLOMERATE_RADIUS:.3e}}}",
                     f"  count: {particles}\n  overlap_tolerance: 0.01",
                     f"  contact_radius_multiplier: 1.25\n  materials:\n{share_text}")
    bonds = (f"  a: {{model: tbbm, youngs_modulus: {e_a:g}, poisson_ratio: 0.25, radius_multiplier: 0.7}}\n"
             f"  b: {{model: tbbm, youngs_modulus: {e_b:g}, poisson_ratio: 0.25, radius_multiplier: 0.7}}")
    scenario = scenario_yaml(f"validation case 2, seed {seed}, E_A:E_B = {ratio[0]}:{ratio[1]}, {100 * mixing:.0f} % A",
                             2000, bonds, strain)
    return spec, scenario, {"a": e_a, "b": e_b}


def case3_files(seed, cells, pore_fraction=0.8):
    """A dense box of cells^3 cells of edge a = 10 particle diameters; the spheres whose centres lie
    in a pore of radius pore_fraction a / 2 at each cell's centre are removed with their bonds
    (carve), leaving an inverse-opal-like skeleton whose bonds replace the contacts."""
    edge = 10 * 2 * PARTICLE_RADIUS
    size = cells * edge
    spec = spec_yaml(f"validation case 3 inverse-opal-like box, seed {seed}", seed,
                     f"box: {{min: [0, 0, 0], max: [{size:.6e}, {size:.6e}, {size:.6e}]}}",
                     f"normal: {{mean: {PARTICLE_RADIUS:.3e}, std: {0.05 * PARTICLE_RADIUS:.3e}}}",
                     "  porosity: 0.4\n  overlap_tolerance: 0.01", "  contact_radius_multiplier: 1.15")
    pores = [((i + 0.5) * edge, (j + 0.5) * edge, (k + 0.5) * edge)
             for i in range(cells) for j in range(cells) for k in range(cells)]
    bonds = f"  bond: {{model: tbbm, youngs_modulus: {BOND_E:g}, poisson_ratio: 0.25, radius_multiplier: 0.8}}"
    scenario = scenario_yaml(f"validation case 3, seed {seed}", 1500, bonds, 0.02, bonded="replace")
    return spec, scenario, {"bond": BOND_E}, (pores, 0.5 * pore_fraction * edge)


def carve(structure, pores, radius):
    """Removes the particles whose centres lie in a pore, and their bonds (ids are kept)."""
    with open(os.path.join(structure, "particles.csv")) as f:
        lines = f.read().splitlines()
    kept, removed = [lines[0]], set()
    for line in lines[1:]:
        fields = line.split(",")
        x = [float(v) for v in fields[1:4]]
        if any(sum((x[k] - c[k]) ** 2 for k in range(3)) < radius**2 for c in pores):
            removed.add(fields[0])
        else:
            kept.append(line)
    with open(os.path.join(structure, "bonds.csv")) as f:
        bonds = f.read().splitlines()
    bonds = [bonds[0]] + [b for b in bonds[1:] if b.split(",")[0] not in removed and b.split(",")[1] not in removed]
    for name, rows in (("particles.csv", kept), ("bonds.csv", bonds)):
        with open(os.path.join(structure, name), "w") as f:
            f.write("\n".join(rows) + "\n")


THREADS = {}  # environment for the bpmkit runs (OMP_NUM_THREADS when samples run side by side)


def run(cmd, log):
    start = time.monotonic()
    with open(log, "a") as out:
        out.write("$ " + " ".join(cmd) + "\n")
        out.flush()
        done = subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT, cwd=ROOT, env={**os.environ, **THREADS})
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed (exit {done.returncode}); see {log}")
    return time.monotonic() - start


def measure(bpmkit, sample_dir, true_moduli, methods, calibrate, rerun=()):
    """Runs every method on one sample; returns {method: {K, seconds, ...}}. Results are kept in
    result.json: only the methods missing there, or named in `rerun`, are run."""
    result_path = os.path.join(sample_dir, "result.json")
    results = {}
    if os.path.exists(result_path):
        with open(result_path) as f:
            results = {k: v for k, v in json.load(f).items() if k not in rerun}
    log = os.path.join(sample_dir, "log.txt")
    scenario = os.path.join(sample_dir, "compression.yaml")

    def save():  # after every method: an interrupted study keeps what it measured
        with open(result_path + ".tmp", "w") as f:
            json.dump(results, f, indent=1)
        os.replace(result_path + ".tmp", result_path)

    for method in methods:
        if method in results:
            continue
        out = os.path.join(sample_dir, method)
        args = ["--method", method.replace("-layered", "")] + (["--layered"] if method == "ste-layered" else [])
        try:
            run([bpmkit, "stiffness", scenario, "--out", out, "--overwrite"] + args, log)
        except RuntimeError as e:  # a method that fails on a sample is a result too
            results[method] = {"failed": str(e)}
            save()
            continue
        with open(os.path.join(out, "stiffness.json")) as f:
            j = json.load(f)
        results[method] = {"K": j["stiffness_N_per_m"], "seconds": j["wall_s"], "details": j["details"]}
        save()
    if calibrate and "K" in results.get("dem", {}) and "calibrate" not in results:
        out = os.path.join(sample_dir, "calibrate")
        k_dem = results["dem"]["K"]
        run([bpmkit, "calibrate", scenario, "--target-K", repr(k_dem), "--out", out, "--overwrite"], log)
        with open(os.path.join(out, "calibration.json")) as f:
            j = json.load(f)
        final = j["stages"][-1]["bond_youngs_modulus_Pa"]
        errors = {m: final[m] / true_moduli[m] - 1.0 for m in final}
        results["calibrate"] = {"moduli": final, "modulus_error": errors,
                                "seconds": sum(s["wall_s"] for s in j["stages"])}
    save()
    return results


def seed_results(csv_path, jobs):
    """Fills each sample's result.json with the methods measured in csv_path (a samples.csv of an
    earlier run, e.g. docs/validation/fig5_samples.csv), and its calibrations' E_b errors,
    keeping what result.json holds:
    a rerun then measures only what is missing, e.g. the calibration after a change to it. The
    structures regenerate identically from their seeds."""
    by_label = {(case, label): d for case, label, d, *_ in jobs}
    seeded = {}
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            d = by_label.get((row["case"], row["sample"]))
            if d is not None and row["method"] == "calibrate (default)" and row["calibrated_modulus_error"]:
                seeded.setdefault(d, {})["calibrate"] = {
                    "moduli": {}, "modulus_error": {"seeded": float(row["calibrated_modulus_error"])},
                    "seconds": float(row["wall_s"])}
                continue
            if d is None or row["method"] not in METHODS or row["K_N_per_m"] in ("", "failed"):
                continue
            entry = {"K": float(row["K_N_per_m"]), "seconds": float(row["wall_s"]), "details": {}}
            if row["method"] == "dem":
                entry["details"] = {"max_kinetic_to_elastic_energy": float(row["dem_kinetic_to_elastic"]),
                                    "max_platen_force_imbalance": float(row["dem_platen_imbalance"])}
            seeded.setdefault(d, {})[row["method"]] = entry
    for d, methods in seeded.items():
        os.makedirs(d, exist_ok=True)
        path = os.path.join(d, "result.json")
        results = {}
        if os.path.exists(path):
            with open(path) as f:
                results = json.load(f)
        results = {**methods, **results}
        with open(path + ".tmp", "w") as f:
            json.dump(results, f, indent=1)
        os.replace(path + ".tmp", path)
    print(f"seeded {len(seeded)} samples from {csv_path}")


def prepare(bpmkit, sample_dir, spec, scenario, pores=None):
    os.makedirs(sample_dir, exist_ok=True)
    structure = os.path.join(sample_dir, "structure")
    if not os.path.exists(os.path.join(structure, "bonds.csv")):
        spec_path = os.path.join(sample_dir, "structure.yml")
        with open(spec_path, "w") as f:
            f.write(spec)
        run([bpmkit, "generate", spec_path, "--out", structure, "--overwrite"], os.path.join(sample_dir, "log.txt"))
        if pores:
            carve(structure, *pores)
    with open(os.path.join(sample_dir, "compression.yaml"), "w") as f:
        f.write(scenario)
    with open(os.path.join(structure, "particles.csv")) as f:
        return sum(1 for line in f if line[:1].isdigit())


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--bpmkit", default=os.path.join(ROOT, "build", "src", "bpmkit"))
    p.add_argument("--out", default=os.path.join(ROOT, "out", "validation_study"))
    p.add_argument("--case1", type=int, default=12, help="case 1 samples (paper: 18 at 1e5 particles)")
    p.add_argument("--case1-particles", type=int, default=10000, help="paper: 1e5")
    p.add_argument("--case2-particles", type=int, default=6000, help="paper: 6000")
    p.add_argument("--case2-mixing", type=float, nargs="*", default=[0.1, 0.4, 0.7, 1.0, 0.25, 0.55, 0.85, 0.5],
                   help="mixing ratios of material A; every ratio 1:2, 2:1, 1:4 with each (paper: 10 to 100 %%)")
    p.add_argument("--case3-cells", type=int, nargs="*", default=[], help="pore cells per edge of case 3 boxes")
    p.add_argument("--fig5", type=int, nargs="*", default=[], help="particle counts of the scaling samples")
    p.add_argument("--fig5-fast-only", type=int, nargs="*", default=[], help="counts run with the DSM and STE only")
    p.add_argument("--jobs", type=int, default=1, help="samples run at once (each uses OMP_NUM_THREADS threads)")
    p.add_argument("--no-calibrate", action="store_true")
    p.add_argument("--rerun", nargs="*", default=[], help="methods (or calibrate) to run again on samples measured before")
    p.add_argument("--case2-strain", type=float, default=0.02, help="case 2 target strain (paper: 2 %%)")
    p.add_argument("--mass-scaling", type=float, default=1.0,
                   help="the DEM's mass scaling factor (compression.mass_scaling; 25: about 5x fewer steps, but "
                        "the scaled runs are not quasi-static: platen forces 9-27 %% apart on larger samples)")
    p.add_argument("--seed-from", help="a samples.csv of an earlier run: its measured methods are kept, so only "
                                       "what it lacks runs (e.g. --seed-from docs/validation/fig5_samples.csv after a "
                                       "change to calibrate)")
    a = p.parse_args()
    MASS_SCALING["factor"] = a.mass_scaling
    if a.jobs > 1:
        THREADS["OMP_NUM_THREADS"] = "1"  # side by side: one thread each, no oversubscription
    if not os.access(a.bpmkit, os.X_OK):
        sys.exit(f"{a.bpmkit} is not an executable: build bpmkit first (bash scripts/setup.sh)")
    os.makedirs(a.out, exist_ok=True)

    jobs = []  # (case, label, dir, spec, scenario, moduli, methods, calibrate, pores)
    for s in range(a.case1):
        spec, scen, moduli = case1_files(1000 + s, a.case1_particles)
        jobs.append(("case1", f"seed {1000 + s}", os.path.join(a.out, f"case1_{s:02d}"), spec, scen, moduli,
                     METHODS, not a.no_calibrate, None))
    seed = 2000
    for ratio in [(1, 2), (2, 1), (1, 4)]:
        for mixing in a.case2_mixing:
            spec, scen, moduli = case2_files(seed, a.case2_particles, ratio, mixing, a.case2_strain)
            jobs.append(("case2", f"{ratio[0]}:{ratio[1]}, {100 * mixing:.0f} % A",
                         os.path.join(a.out, f"case2_{seed}"), spec, scen, moduli, METHODS, not a.no_calibrate, None))
            seed += 1
    for cells in a.case3_cells:
        spec, scen, moduli, pores = case3_files(3000 + cells, cells)
        jobs.append(("case3", f"{cells}^3 pores", os.path.join(a.out, f"case3_{cells}"), spec, scen, moduli,
                     METHODS, False, pores))
    for n in a.fig5 + a.fig5_fast_only:
        spec, scen, moduli = case1_files(5000 + n, n)
        methods = METHODS if n in a.fig5 else ["dsm", "ste"]
        jobs.append(("fig5", f"{n} particles", os.path.join(a.out, f"fig5_{n}"), spec, scen, moduli, methods, False,
                     None))

    if a.seed_from:
        seed_results(a.seed_from, jobs)

    def work(job):
        case, label, d, spec, scen, moduli, methods, calibrate, pores = job
        particles = prepare(a.bpmkit, d, spec, scen, pores)
        r = measure(a.bpmkit, d, moduli, methods, calibrate, a.rerun)
        print(f"{case} {label}: {particles} particles, " +
              ", ".join(f"{m} {r[m]['K']:.5g}" if "K" in r[m] else f"{m} failed" for m in methods if m in r),
              flush=True)
        return case, label, d, particles, r

    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        done = list(pool.map(work, jobs))
    write_tables(a.out, done)
    plot(a.out, done)


def write_tables(out, done):
    rows = []
    for case, label, d, particles, r in done:
        k_dem = r["dem"].get("K") if "dem" in r else None
        for m in METHODS:
            if m not in r:
                continue
            if "K" not in r[m]:
                rows.append({"case": case, "sample": label, "particles": particles, "method": m, "K_N_per_m": "failed"})
                continue
            row = {"case": case, "sample": label, "particles": particles, "method": m,
                   "K_N_per_m": r[m]["K"], "wall_s": r[m]["seconds"],
                   "error_vs_dem": (r[m]["K"] / k_dem - 1.0) if k_dem else "",
                   "speed_up_vs_dem": (r["dem"]["seconds"] / r[m]["seconds"]) if k_dem else ""}
            if m == "dem":
                row["dem_kinetic_to_elastic"] = r[m]["details"].get("max_kinetic_to_elastic_energy", "")
                row["dem_platen_imbalance"] = r[m]["details"].get("max_platen_force_imbalance", "")
            rows.append(row)
        if "calibrate" in r:
            c = r["calibrate"]
            worst = max(c["modulus_error"].values(), key=abs)
            rows.append({"case": case, "sample": label, "particles": particles, "method": "calibrate (default)",
                         "K_N_per_m": "", "wall_s": c["seconds"], "error_vs_dem": "",
                         "speed_up_vs_dem": "", "calibrated_modulus_error": worst})
    fields = ["case", "sample", "particles", "method", "K_N_per_m", "wall_s", "error_vs_dem", "speed_up_vs_dem",
              "calibrated_modulus_error", "dem_kinetic_to_elastic", "dem_platen_imbalance"]
    with open(os.path.join(out, "samples.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)

    summary = []
    for case in ["case1", "case2", "case3", "fig5"]:
        for m in METHODS[1:] + ["calibrate (default)"]:
            sel = [x for x in rows if x["case"] == case and x["method"] == m]
            key = "calibrated_modulus_error" if m.startswith("calibrate") else "error_vs_dem"
            errs = [abs(x[key]) for x in sel if x.get(key, "") != ""]
            failed = sum(1 for x in sel if x.get("K_N_per_m") == "failed")
            if not errs:
                continue
            speed = [x["speed_up_vs_dem"] for x in sel if x.get("speed_up_vs_dem", "") != ""]
            summary.append({"case": case, "method": m, "samples": len(errs), "failed": failed,
                            "mean_abs_error_pct": 100 * statistics.mean(errs),
                            "std_abs_error_pct": 100 * (statistics.stdev(errs) if len(errs) > 1 else 0.0),
                            "max_abs_error_pct": 100 * max(errs),
                            "mean_speed_up": statistics.mean(speed) if speed else "",
                            "mean_wall_s": statistics.mean(x["wall_s"] for x in sel if "wall_s" in x)})
    with open(os.path.join(out, "summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(summary[0].keys()) if summary else ["case"])
        w.writeheader()
        w.writerows(summary)
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("| case | method | samples (failed) | mean abs error | std | max | mean speed-up vs DEM | mean wall time |\n")
        f.write("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n")
        for s in summary:
            what = "E_b error" if s["method"].startswith("calibrate") else "K error"
            speed = f"{s['mean_speed_up']:.0f}x" if s["mean_speed_up"] != "" else "-"
            f.write(f"| {s['case']} | {s['method']} ({what}) | {s['samples']} ({s['failed']}) | {s['mean_abs_error_pct']:.2f} % | "
                    f"{s['std_abs_error_pct']:.2f} % | {s['max_abs_error_pct']:.2f} % | {speed} | "
                    f"{s['mean_wall_s']:.2f} s |\n")
    print(open(os.path.join(out, "summary.md")).read())


def plot(out, done):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not found (Debian: python3-matplotlib; run with /usr/bin/python3): no figures")
        return
    fast = ["dsm", "dsm-nonlinear", "ste", "ste-layered"]
    cases = [c for c in ["case1", "case2", "case3"] if any(x[0] == c for x in done)]
    if cases:
        fig, ax1 = plt.subplots(figsize=(8, 4.5))
        ax2 = ax1.twinx()
        width = 0.8 / len(fast)
        for k, m in enumerate(fast):
            speed, err, err_sd = [], [], []
            for c in cases:
                sel = [r for case, _, _, _, r in done if case == c and "K" in r.get(m, {}) and "K" in r.get("dem", {})]
                s = [r["dem"]["seconds"] / r[m]["seconds"] for r in sel]
                e = [100 * abs(r[m]["K"] / r["dem"]["K"] - 1) for r in sel]
                speed.append(math.log10(statistics.mean(s)) if s else 0)
                err.append(statistics.mean(e) if e else float("nan"))
                err_sd.append(statistics.stdev(e) if len(e) > 1 else 0)
            xs = [i + (k - 1.5) * width for i in range(len(cases))]
            ax1.bar(xs, speed, width, label=f"{m} speed-up", alpha=0.6)
            ax2.errorbar(xs, err, yerr=err_sd, fmt="o", capsize=3, label=f"{m} |error|")
        ax1.set_xticks(range(len(cases)))
        ax1.set_xticklabels(cases)
        ax1.set_ylabel("log10 speed-up against the DEM (bars)")
        ax2.set_ylabel("|K error| against the DEM, % (points)")
        ax2.set_yscale("log")
        ax2.set_ylim(0.1, 1000.0)
        ax1.set_ylim(0.0, 5.0)
        ax1.legend(loc="upper left", fontsize=7)
        ax2.legend(loc="upper center", fontsize=7)
        ax1.set_title("Jarolin Fig. 4 with bpmkit's DEM (real platens) as the reference")
        fig.tight_layout()
        for ext in ("png", "svg"):
            fig.savefig(os.path.join(out, f"fig4.{ext}"), dpi=120)
    scaling = [x for x in done if x[0] == "fig5"]
    if scaling:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for k, m in enumerate(["dem", "dsm", "dsm-nonlinear", "ste"]):
            pts = sorted((n, r[m]["seconds"]) for _, _, _, n, r in scaling if "K" in r.get(m, {}))
            if pts:
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", color=f"C{k}", label=m)
        ax.set_xlabel("particles")
        ax.set_ylabel("wall time, s")
        ax.set_title("Jarolin Fig. 5: independently generated cylinders")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_ylim(bottom=1e-3)  # room for the legend below the STE
        ax.legend(fontsize=7, loc="lower right")
        fig.tight_layout()
        for ext in ("png", "svg"):
            fig.savefig(os.path.join(out, f"fig5.{ext}"), dpi=120)


if __name__ == "__main__":
    main()
