#!/usr/bin/env python3
"""The tables and Jarolin's Fig. 4 of scripts/validation_fig4.sh's run (docs/validation.md).

    python3 scripts/validation_fig4.py OUT SAMPLE...

Prints the per-sample table and the per-case summary (mean, standard deviation and largest |K
error| against the DEM, mean speed-up over the DEM), writes OUT/samples.csv and, where matplotlib
is installed (Debian's python3-matplotlib), OUT/fig4.png and OUT/fig4.svg.
"""
import csv
import json
import math
import os
import re
import sys

# (folder, label): the methods' K against the DEM's.
METHODS = [("dsm-current", "dsm"), ("dsm-initial", "dsm (initial axes)"),
           ("dsm-nonlinear-current", "dsm-nonlinear"), ("dsm-nonlinear-initial", "dsm-nonlinear (initial axes)"),
           ("paper-3", "paper's DSM: 3 DOF, no slip, initial axes"), ("paper-6", "the same with 6 DOF"),
           ("ste", "ste"), ("dsm-kinematic", "dsm-kinematic")]
# The body's E and nu (strain gauges on the middle third) against the DEM's.
BODY = [("dsm-current", "dsm"), ("dsm-nonlinear-current", "dsm-nonlinear"), ("ste", "ste")]
FIGURE = [("dsm-current", "linear DSM"), ("dsm-nonlinear-current", "nonlinear DSM"),
          ("paper-3", "paper's DSM (3 DOF)"), ("ste", "STE")]


def read(path):
    with open(path) as f:
        return json.load(f)


def case_of(sample):
    return "case 1" if sample == "small_cylinder" or sample.startswith("case1") else sample.split("_")[0].replace("case", "case ")


def true_bond_modulus(scenario):
    text = open(scenario).read()
    m = re.search(r"bond_materials:\s*\n\s*\w+:\s*\{[^}]*youngs_modulus:\s*([0-9.eE+-]+)", text)
    return float(m.group(1))


def measure(out, sample):
    d = os.path.join(out, sample)
    dem = read(os.path.join(d, "dem", "stiffness.json"))
    row = {"sample": sample, "case": case_of(sample), "K_DEM": dem["stiffness_N_per_m"],
           "platen_imbalance": dem["details"]["max_platen_force_imbalance"],
           "kinetic_to_elastic": dem["details"]["max_kinetic_to_elastic_energy"], "dem_s": dem["wall_s"]}
    for folder, _ in METHODS:
        j = read(os.path.join(d, folder, "stiffness.json"))
        row[f"{folder}_K"] = j["stiffness_N_per_m"]
        row[f"{folder}_error"] = j["stiffness_N_per_m"] / row["K_DEM"] - 1.0
        row[f"{folder}_s"] = j["wall_s"]
    for folder in ["dem"] + [f for f, _ in BODY]:
        body = read(os.path.join(d, folder, "stiffness.json")).get("body") or {}
        row[f"{folder}_body_E"] = body.get("youngs_modulus_Pa")
        row[f"{folder}_body_nu"] = body.get("poissons_ratio")
    row["dem_platen_E"] = dem["youngs_modulus_Pa"]
    answer = read(os.path.join(d, "calibrate", "calibration.json"))["stages"][-1]["bond_youngs_modulus_Pa"]
    row["calibrate_Eb_error"] = next(iter(answer.values())) / true_bond_modulus(os.path.join(d, "compression.yaml")) - 1.0
    return row


def stats(values):
    mean = sum(abs(v) for v in values) / len(values)
    std = math.sqrt(sum((abs(v) - mean) ** 2 for v in values) / len(values))
    return mean, std, max(abs(v) for v in values)


def main():
    out, samples = sys.argv[1], sys.argv[2:]
    rows = [measure(out, s) for s in samples]
    pct = lambda v: f"{100 * v:+.2f} %"
    print("| sample | K_DEM [N/m] | platen imbalance | kinetic/elastic | "
          + " | ".join(label for _, label in METHODS) + " | calibrate --no-dem: E_b error |")
    print("|---|---:|---:|---:|" + "---:|" * len(METHODS) + "---:|")
    for r in rows:
        print(f"| {r['sample']} | {r['K_DEM']:,.1f} | {100 * r['platen_imbalance']:.2f} % | {r['kinetic_to_elastic']:.1e} | "
              + " | ".join(pct(r[f'{f}_error']) for f, _ in METHODS) + f" | {pct(r['calibrate_Eb_error'])} |")
    with open(os.path.join(out, "samples.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    if all(r["dem_body_E"] for r in rows):
        print("\n| sample | DEM: body E [Pa] | DEM: nu | DEM: K l / A over body E | "
              + " | ".join(f"{label}: E error | {label}: nu - nu_DEM" for _, label in BODY) + " |")
        print("|---|---:|---:|---:|" + "---:|---:|" * len(BODY))
        for r in rows:
            cells = []
            for folder, _ in BODY:
                e, nu = r[f"{folder}_body_E"], r[f"{folder}_body_nu"]
                cells.append(f"{pct(e / r['dem_body_E'] - 1)} | {nu - r['dem_body_nu']:+.3f}" if e else "- | -")
            print(f"| {r['sample']} | {r['dem_body_E']:.4g} | {r['dem_body_nu']:.3f} | "
                  f"{r['dem_platen_E'] / r['dem_body_E']:.2f} | " + " | ".join(cells) + " |")

    cases = sorted({r["case"] for r in rows})
    print("\n| case | samples | method | mean \\|error\\| | std | max | mean speed-up over the DEM |")
    print("|---|---:|---|---:|---:|---:|---:|")
    summary = {}
    for case in cases:
        mine = [r for r in rows if r["case"] == case]
        for folder, label in FIGURE:
            mean, std, largest = stats([r[f"{folder}_error"] for r in mine])
            speed = sum(r["dem_s"] / r[f"{folder}_s"] for r in mine) / len(mine)
            summary[(case, folder)] = (mean, std, speed)
            print(f"| {case} | {len(mine)} | {label} | {100 * mean:.2f} % | {100 * std:.2f} % | "
                  f"{100 * largest:.2f} % | {speed:,.0f}x |")
        mean, std, largest = stats([r["calibrate_Eb_error"] for r in mine])
        print(f"| {case} | {len(mine)} | calibrate --no-dem (E_b error) | {100 * mean:.2f} % | {100 * std:.2f} % | "
              f"{100 * largest:.2f} % | - |")
    print("\n| method | bond-dominated (cases 1, 3): mean \\|error\\|, max | contact-dominated (case 2) |")
    print("|---|---:|---:|")
    for folder, label in METHODS:
        part = lambda contact: stats([r[f"{folder}_error"] for r in rows if (r["case"] == "case 2") == contact])
        b, c = part(False), part(True)
        print(f"| {label} | {100 * b[0]:.2f} %, {100 * b[2]:.2f} % | {100 * c[0]:.2f} %, {100 * c[2]:.2f} % |")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(no matplotlib: fig4 not drawn; Debian's python3-matplotlib draws it)")
        return
    fig, speed_axis = plt.subplots(figsize=(8, 4.2))
    error_axis = speed_axis.twinx()
    width = 0.8 / len(FIGURE)
    for m, (folder, label) in enumerate(FIGURE):
        xs = [c + (m - (len(FIGURE) - 1) / 2) * width for c in range(len(cases))]
        speed_axis.bar(xs, [summary[(case, folder)][2] for case in cases], width, color=f"C{m}", alpha=0.45,
                       label=f"{label}: speed-up")
        error_axis.errorbar(xs, [100 * summary[(case, folder)][0] for case in cases],
                            yerr=[100 * summary[(case, folder)][1] for case in cases], fmt="o", color=f"C{m}",
                            capsize=3)
    speed_axis.set_yscale("log")
    speed_axis.set_ylabel("speed-up over the DEM (bars)")
    error_axis.set_yscale("log")
    error_axis.set_ylabel("mean |K error| against the DEM [%] (points, std)")
    speed_axis.set_xticks(range(len(cases)))
    count = lambda c: sum(r["case"] == c for r in rows)
    speed_axis.set_xticklabels([f"{c} ({count(c)} sample{'s' if count(c) > 1 else ''})" for c in cases])
    speed_axis.legend(loc="upper left", fontsize=7)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out, f"fig4.{ext}"), dpi=120)


if __name__ == "__main__":
    main()
