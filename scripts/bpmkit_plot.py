#!/usr/bin/env python3
"""Pictures of what a bpmkit command wrote into its output folder (`bpmkit plot DIR`).

Usage: /usr/bin/python3 scripts/bpmkit_plot.py DIR [--out OUTDIR]

Draws, as NAME.png and NAME.svg into DIR (or OUTDIR), every figure the folder's files allow:

- compression (`bpmkit run` with a `compression:` section): force_displacement.csv, the fit
  window shaded and the fitted line with the slope K of summary.json. The least-squares slope over
  the window is recomputed from the CSV and printed next to the reported K ("slope check"); a
  relative difference above 1e-6 is reported on stderr.
- cantilever (`bpmkit verify cantilever`): case 1 deflection along the beam against Timoshenko and
  Euler-Bernoulli (Chen 2022 Fig. 8), the tip deflection and its error against the beam length,
  resolution and particle size (cases 2-4, Chen Figs. 10, 12, 14), the error against the middle
  particle's radius (case 5, Chen Fig. 16).
- stiffness methods (`bpmkit compare`): each method's K, its error against the reference and its
  speed-up (Jarolin 2020 Fig. 4); `bpmkit calibrate`: each stage's bond modulus and K error.
- time series (`bpmkit run`): probes.csv and walls.csv.

Exit status: 0 with at least one figure, 2 for a folder with nothing to draw or without
matplotlib (Debian: python3-matplotlib; run with /usr/bin/python3).
"""
import argparse
import csv
import json
import math
import os
import sys

SLOPE_TOLERANCE = 1e-6  # relative: reported K against the slope recomputed from the CSV
FORMATS = ("png", "svg")


class PlotError(Exception):
    """A folder that cannot be drawn: the message names it and what was expected."""


# ---------------------------------------------------------------------------------------------
# Reading


def read_csv(path):
    """The columns of a CSV file with a header: {name: [float or str]}; numbers where they parse."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise PlotError(f"{path} is empty (expected a header line and rows)")
    header = rows[0]
    columns = {name: [] for name in header}
    for row in rows[1:]:
        if len(row) != len(header):
            continue  # a partial last line of a run that was killed while writing
        for name, value in zip(header, row):
            try:
                columns[name].append(float(value))
            except ValueError:
                columns[name].append(value)
    return columns


def read_json(path):
    with open(path) as f:
        return json.load(f)


def least_squares(x, y):
    """Slope and intercept of the least-squares line through (x, y)."""
    n = len(x)
    mx, my = math.fsum(x) / n, math.fsum(y) / n
    vxx = math.fsum((a - mx) ** 2 for a in x)
    vxy = math.fsum((a - mx) * (b - my) for a, b in zip(x, y))
    slope = vxy / vxx
    return slope, my - slope * mx


# ---------------------------------------------------------------------------------------------
# Output


def setup_matplotlib():
    """pyplot with the Agg backend and reproducible SVG output; PlotError if matplotlib is missing."""
    try:
        import matplotlib
    except ImportError as e:
        raise PlotError(
            f"matplotlib is not available to {sys.executable} ({e}): install python3-matplotlib (Debian) "
            "and run the script with /usr/bin/python3") from None
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "bpmkit"  # the same SVG for the same data
    import matplotlib.pyplot as plt
    return plt


def save(plt, fig, out_dir, name):
    """NAME.png and NAME.svg into out_dir; returns their paths."""
    paths = []
    for ext in FORMATS:
        path = os.path.join(out_dir, f"{name}.{ext}")
        metadata = {"Date": None} if ext == "svg" else {"Software": None}
        fig.savefig(path, dpi=120, metadata=metadata)
        paths.append(path)
    plt.close(fig)
    return paths


# ---------------------------------------------------------------------------------------------
# 1. Compression: force-displacement curve, fit window and fitted line


def compression_window(folder, block, x, y):
    """Indices of the fit window's points, and a description of where the window came from."""
    if "fit_window_m" in block:  # summary.json of bpmkit since 2026-12-03: the window itself
        lo, hi = (float(v) for v in block["fit_window_m"])
        chosen = [i for i, v in enumerate(x) if lo <= v <= hi * (1.0 + 1e-9)]
        return chosen, f"fit window [{lo:.6g}, {hi:.6g}] m of platen travel (summary.json)"
    # An older summary.json without the window: the test stopped at the first point past the
    # target strain and fitted the fit_points points before it (or up to the last one): a
    # consistency check only.
    n = int(block.get("fit_points", 0))
    if n < 2 or n > len(x):
        raise PlotError(f"{folder}: summary.json has neither fit_window_m nor usable fit_points: cannot place "
                        "the fit window")
    print(f"warning: {folder}: summary.json has no fit_window_m (written before 2026-12-03); the fit window is "
          "inferred from fit_points", file=sys.stderr)
    options = [list(range(len(x) - n, len(x)))]
    if n < len(x):
        options.append(list(range(len(x) - n - 1, len(x) - 1)))
    reported = float(block["stiffness_N_per_m"])
    best = min(options, key=lambda w: abs(least_squares([x[i] for i in w], [y[i] for i in w])[0] - reported))
    return best, f"the {n} points ending {len(x) - 1 - best[-1]} before the last (inferred: a consistency check only)"


def plot_compression(plt, folder, out_dir):
    """force_displacement.png/svg. Returns the paths."""
    curve = read_csv(os.path.join(folder, "force_displacement.csv"))
    for column in ("displacement_m", "force_N"):
        if column not in curve:
            raise PlotError(f"{folder}/force_displacement.csv has no column {column}")
    summary_path = os.path.join(folder, "summary.json")
    summary = read_json(summary_path) if os.path.isfile(summary_path) else {}
    block = summary.get("compression")
    if block is None or "stiffness_N_per_m" not in block:
        raise PlotError(f"{folder}: force_displacement.csv without a K to compare (expected summary.json with a "
                        "'compression' block, as `bpmkit run` writes it)")
    x = [float(v) for v in curve["displacement_m"]]
    y = [float(v) for v in curve["force_N"]]
    reported = float(block["stiffness_N_per_m"])
    window, where = compression_window(folder, block, x, y)
    if len(window) < 2:
        raise PlotError(f"{folder}: fewer than two points of force_displacement.csv in the fit window ({where})")
    wx, wy = [x[i] for i in window], [y[i] for i in window]
    slope, intercept = least_squares(wx, wy)
    difference = abs(slope - reported) / abs(reported) if reported else abs(slope)
    print(f"slope check: reported K = {reported:.12g} N/m, least-squares slope over the window = {slope:.12g} N/m, "
          f"relative difference {difference:.3g} ({len(window)} points; {where})")
    if difference > SLOPE_TOLERANCE:
        print(f"warning: {folder}: the slope of force_displacement.csv over the fit window ({slope:.10g} N/m) "
              f"differs from the reported K ({reported:.10g} N/m) by {difference:.3g} (relative), more than "
              f"{SLOPE_TOLERANCE:g}", file=sys.stderr)
    # The reported line: slope K through the window's centroid (the least-squares intercept for slope K).
    line_intercept = math.fsum(wy) / len(wy) - reported * math.fsum(wx) / len(wx)

    fig, ax = plt.subplots(figsize=(7, 4.8), layout="constrained")
    mm = [1e3 * v for v in x]
    ax.plot(mm, y, ".-", color="0.25", markersize=3, linewidth=0.8, label="DEM: mean platen force")
    if "force_top_N" in curve and "force_bottom_N" in curve:
        ax.plot(mm, curve["force_top_N"], color="tab:orange", linewidth=0.6, alpha=0.7, label="top platen")
        ax.plot(mm, curve["force_bottom_N"], color="tab:green", linewidth=0.6, alpha=0.7, label="bottom platen")
    ax.axvspan(1e3 * wx[0], 1e3 * wx[-1], color="tab:blue", alpha=0.12, label="fit window")
    fx = [wx[0], wx[-1]]
    ax.plot([1e3 * v for v in fx], [line_intercept + reported * v for v in fx], "-", color="tab:red", linewidth=1.6,
            label=f"fit: K = {reported:.6g} N/m")
    e_text = f", E = {float(block['youngs_modulus_Pa']):.4g} Pa" if "youngs_modulus_Pa" in block else ""
    r2_text = f", r² = {float(block['fit_r2']):.6f}" if "fit_r2" in block else ""
    ax.set_title(f"{summary.get('description') or os.path.basename(os.path.abspath(folder))}\n"
                 f"K = {reported:.6g} N/m{e_text}{r2_text}; recomputed slope {slope:.6g} N/m", fontsize=10)
    ax.set_xlabel("platen displacement [mm]")
    ax.set_ylabel("force [N]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    if "strain" in curve and block.get("sample_length_m"):
        length_mm = 1e3 * float(block["sample_length_m"])
        top = ax.secondary_xaxis("top", functions=(lambda d: 100 * d / length_mm, lambda s: s * length_mm / 100))
        top.set_xlabel("strain [%]")
    return save(plt, fig, out_dir, "force_displacement")


# ---------------------------------------------------------------------------------------------
# 2. Cantilever verification (Chen 2022 Figs. 8, 10, 12, 14, 16)

MODELS = ("pbm", "ebbm", "tbbm")
MODEL_STYLE = {"pbm": ("tab:blue", "o"), "ebbm": ("tab:orange", "s"), "tbbm": ("tab:green", "^")}


def plot_cantilever_deflection(plt, folder, out_dir):
    """Chen Fig. 8: case 1 deflection along the beam (a) and the error against Timoshenko (b)."""
    p = read_csv(os.path.join(folder, "case1_deflection.csv"))
    x = p["x_m"]
    tb = [1e3 * abs(v) for v in p["timoshenko_m"]]
    eb = [1e3 * abs(v) for v in p["euler_bernoulli_m"]]
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.4), layout="constrained")
    a.plot(x, tb, "-", color="k", label="Timoshenko")
    a.plot(x, eb, "--", color="0.5", label="Euler-Bernoulli")
    for m in MODELS:
        column = f"dem_{m}_m"
        if column not in p:
            continue
        color, marker = MODEL_STYLE[m]
        dem = [1e3 * abs(v) for v in p[column]]
        a.plot(x, dem, marker, color=color, fillstyle="none", label=f"DEM {m.upper()}")
        b.plot(x, [d - t for d, t in zip(dem, tb)], marker + "-", color=color, label=m.upper())
    b.plot(x, [e - t for e, t in zip(eb, tb)], "--", color="0.5", label="Euler-Bernoulli theory")
    a.set(xlabel="distance from the clamped end x [m]", ylabel="deflection [mm]",
          title="(a) case 1: deflection along the beam (Chen Fig. 8a)")
    b.set(xlabel="distance from the clamped end x [m]", ylabel="deflection - Timoshenko [mm]",
          title="(b) error against Timoshenko (Chen Fig. 8b)")
    for ax in (a, b):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    return save(plt, fig, out_dir, "cantilever_case1_deflection")


def tips_by_case(tips):
    """{case: [row dict, ...]} from cantilever_tips.csv's columns."""
    rows = [dict(zip(tips, values)) for values in zip(*tips.values())]
    cases = {}
    for r in rows:
        cases.setdefault(r["case"], []).append(r)
    return cases


RESOLUTION_CASES = {
    "case2": ("beam_length_m", "beam length L0 [m] (touching particles, R = 0.2 m)",
              "case 2: shortening the beam (Chen Fig. 10)"),
    "case3": ("bonds", "bonds over L0 = 4 m", "case 3: refining the beam (Chen Fig. 12)"),
    "case4": ("bonds", "bonds over L0 = 4 m (touching particles, R = 2/n)",
              "case 4: smaller particles (Chen Fig. 14)"),
}


def plot_cantilever_resolution(plt, folder, out_dir, cases):
    """Chen Figs. 10, 12, 14: tip deflection and its error against Timoshenko, one column per case."""
    present = [c for c in RESOLUTION_CASES if c in cases]
    fig, axes = plt.subplots(2, len(present), figsize=(5.2 * len(present), 7.2), layout="constrained", squeeze=False)
    for col, name in enumerate(present):
        key, xlabel, title = RESOLUTION_CASES[name]
        rows = cases[name]
        top, bottom = axes[0][col], axes[1][col]
        theory = sorted({(float(r[key]), float(r["tip_timoshenko_m"]), float(r["tip_euler_bernoulli_m"])) for r in rows})
        top.plot([t[0] for t in theory], [1e3 * t[1] for t in theory], "-", color="k", label="Timoshenko")
        top.plot([t[0] for t in theory], [1e3 * t[2] for t in theory], "--", color="0.5", label="Euler-Bernoulli")
        for m in MODELS:
            mine = sorted((float(r[key]), r) for r in rows if r["model"] == m)
            if not mine:
                continue
            color, marker = MODEL_STYLE[m]
            xs = [v for v, _ in mine]
            top.plot(xs, [1e3 * abs(float(r["tip_dem_m"])) for _, r in mine], marker, color=color, fillstyle="none",
                     label=f"DEM {m.upper()}")
            bottom.plot(xs, [100 * float(r["error_vs_timoshenko"]) for _, r in mine], marker + "-", color=color,
                        label=m.upper())
        top.set(title=title, ylabel="tip deflection [mm]", xlabel=xlabel)
        if name == "case2":
            top.set_yscale("log")
        bottom.set(xlabel=xlabel, ylabel="error against Timoshenko [%]")
        bottom.axhline(0, color="k", linewidth=0.6)
        for ax in (top, bottom):
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=8)
    return save(plt, fig, out_dir, "cantilever_resolution")


def plot_cantilever_polydispersity(plt, folder, out_dir, rows):
    """Chen Fig. 16: case 5, the error against Timoshenko per model and middle particle radius."""
    variants = sorted({r["variant"] for r in rows}, key=lambda v: float(v.split("=")[-1]) if "=" in v else 0.0)
    fig, ax = plt.subplots(figsize=(7, 4.4), layout="constrained")
    width = 0.8 / len(MODELS)
    for k, m in enumerate(MODELS):
        values = []
        for v in variants:
            match = [r for r in rows if r["model"] == m and r["variant"] == v]
            values.append(100 * float(match[0]["error_vs_timoshenko"]) if match else float("nan"))
        bars = ax.bar([i + (k - 1) * width for i in range(len(variants))], values, width, color=MODEL_STYLE[m][0],
                      label=m.upper())
        ax.bar_label(bars, fmt="%.3g", fontsize=7)
    ax.set_xticks(range(len(variants)), [v.replace("middle_radius=", "R_mid = ") + " m" for v in variants])
    theory = 1e3 * float(rows[0]["tip_timoshenko_m"])
    ax.set(ylabel="tip deflection error against Timoshenko [%]",
           title=f"case 5: polydisperse particles (Chen Fig. 16; Timoshenko {theory:.4g} mm)\n"
                 "PBM with the Euler-Bernoulli shear stiffness (Chen Eq. 26)")
    ax.axhline(0, color="k", linewidth=0.6)
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(fontsize=8)
    return save(plt, fig, out_dir, "cantilever_polydispersity")


def plot_cantilever(plt, folder, out_dir):
    paths = []
    if os.path.isfile(os.path.join(folder, "case1_deflection.csv")):
        paths += plot_cantilever_deflection(plt, folder, out_dir)
    tips_path = os.path.join(folder, "cantilever_tips.csv")
    if os.path.isfile(tips_path):
        cases = tips_by_case(read_csv(tips_path))
        if any(c in cases for c in RESOLUTION_CASES):
            paths += plot_cantilever_resolution(plt, folder, out_dir, cases)
        if "case5" in cases:
            paths += plot_cantilever_polydispersity(plt, folder, out_dir, cases["case5"])
    return paths


# ---------------------------------------------------------------------------------------------
# 3. Stiffness methods (Jarolin 2020 Fig. 4) and calibration stages


def plot_compare(plt, folder, out_dir):
    """compare.csv: K per method (a); |error| against the reference and speed-up (b, Jarolin Fig. 4)."""
    c = read_csv(os.path.join(folder, "compare.csv"))
    methods = [str(m) for m in c["method"]]
    k = c["stiffness_N_per_m"]
    errors = [100 * float(e) for e in c["error_vs_reference"]]
    speed = [float(s) for s in c["speed_up"]]
    reference = methods[0]  # compare writes the reference first
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.4), layout="constrained")
    colors = ["0.35"] + [f"C{i}" for i in range(len(methods) - 1)]
    bars = a.bar(methods, k, color=colors)
    a.bar_label(bars, labels=[f"{e:+.2f} %" if i else "reference" for i, e in enumerate(errors)], fontsize=8)
    a.axhline(k[0], color="k", linewidth=0.8, linestyle="--")
    a.set(ylabel="sample stiffness K [N/m]", title=f"(a) K by each method; {reference.upper()} = reference")
    a.set_ylim(0, 1.15 * max(k))
    others = list(range(1, len(methods)))
    names = [methods[i] for i in others]
    bars = b.bar(names, [speed[i] for i in others], color=colors[1:], alpha=0.6)
    b.bar_label(bars, fmt="%.3g x", fontsize=8)
    b.set_yscale("log")
    b.set_ylim(bottom=min([0.5] + [0.5 * speed[i] for i in others if speed[i] > 0]))
    b.set_ylabel(f"speed-up against {reference.upper()} (bars, log)")
    e_ax = b.twinx()
    e_ax.plot(names, [abs(errors[i]) for i in others], "D", color="k", label=f"|error| against {reference.upper()}")
    e_ax.set_ylabel(f"|K error| against {reference.upper()} [%] (diamonds)")
    e_ax.set_ylim(0, 1.25 * max([abs(errors[i]) for i in others] + [1e-3]))
    e_ax.legend(fontsize=8, loc="upper left")
    b.set_title("(b) error and speed-up (as Jarolin Fig. 4)")
    for ax in (a, b):
        ax.grid(True, axis="y", alpha=0.3)
    particles = int(float(c["particles"][0])) if "particles" in c else None
    bonds = int(float(c["bonds"][0])) if "bonds" in c else None
    if particles is not None:
        fig.suptitle(f"{particles} particles, {bonds} bonds", fontsize=10)
    return save(plt, fig, out_dir, "stiffness_methods")


def plot_calibration(plt, folder, out_dir):
    """calibration.json: each stage's bond Young's modulus (a) and its error against the target (b):
    the body's E (strain gauges) or the platen stiffness K, and nu where it was a target."""
    cal = read_json(os.path.join(folder, "calibration.json"))
    stages = cal.get("stages") or []
    if not stages:
        raise PlotError(f"{folder}/calibration.json has no stages")
    labels = [f"{i + 1}. {s['method']}" for i, s in enumerate(stages)]
    materials = list(stages[-1].get("bond_youngs_modulus_Pa", {}))
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.4), layout="constrained")
    width = 0.8 / max(1, len(materials))
    for k, name in enumerate(materials):
        values = [float(s.get("bond_youngs_modulus_Pa", {}).get(name, float("nan"))) for s in stages]
        offset = (k - (len(materials) - 1) / 2) * width
        bars = a.bar([i + offset for i in range(len(stages))], values, width, label=name)
        a.bar_label(bars, fmt="%.5g", fontsize=7)
    a.set_xticks(range(len(stages)), labels)
    a.set(ylabel="bond Young's modulus E_b [Pa]", title="(a) E_b found by each stage")
    a.legend(fontsize=8)
    errors = [100 * float(s["relative_error"]) for s in stages]
    b.bar(labels, errors, color=[f"C{i}" for i in range(len(stages))], alpha=0.7)
    labelled = set()
    for i, s in enumerate(stages):
        v = s.get("validated_error_vs_dem")
        if v:
            for kind, shift, color in (("bond_dominated", -0.15, "k"), ("contact_dominated", 0.15, "0.55")):
                if kind in v:
                    bound = 100 * float(v[kind]["max_abs"])
                    b.errorbar([i + shift], [0.0], yerr=[bound], fmt="none", ecolor=color, capsize=6,
                               label=None if kind in labelled else
                               f"the method's max |K error| vs DEM, {kind.replace('_', '-')} samples")
                    labelled.add(kind)
    b.axhline(0, color="k", linewidth=0.6)
    if "target_stiffness_N_per_m" in cal:
        quantity, target = "K", f"K = {float(cal['target_stiffness_N_per_m']):.6g} N/m"
    else:
        quantity, target = "E", f"body E = {float(cal['target_youngs_modulus_Pa']):.6g} Pa"
    if "target_poissons_ratio" in cal:
        target += f", nu = {float(cal['target_poissons_ratio']):.4g}"
        for i, s in enumerate(stages):
            b.annotate(f"nu {float(s.get('poissons_ratio_error', 0.0)):+.4f}", (i, 0.0), textcoords="offset points",
                       xytext=(0, 6), ha="center", fontsize=7)
    b.set(ylabel=f"{quantity} error against the target [%] (each stage's own {quantity})", title=f"(b) target {target}")
    if any(s.get("validated_error_vs_dem") for s in stages):
        b.legend(fontsize=7)
    for ax in (a, b):
        ax.grid(True, axis="y", alpha=0.3)
    return save(plt, fig, out_dir, "calibration")


# ---------------------------------------------------------------------------------------------
# 4. Time series: probes.csv and walls.csv


def plot_series(plt, folder, out_dir, name, groups):
    """One panel per quantity group (suffixes, label); a line per probe or wall and component that is
    not zero throughout."""
    t = read_csv(os.path.join(folder, f"{name}.csv"))
    if "time" not in t or len(t["time"]) == 0:
        raise PlotError(f"{folder}/{name}.csv has no column 'time' or no rows")
    time = t["time"]
    fig, axes = plt.subplots(len(groups), 1, figsize=(8, 2.6 * len(groups) + 0.6), sharex=True,
                             layout="constrained", squeeze=False)
    for ax, (suffixes, label) in zip((row[0] for row in axes), groups):
        drawn = 0
        for column, values in t.items():
            if column == "time" or not any(column.endswith("_" + s) for s in suffixes):
                continue
            if all(v == 0 for v in values):
                continue
            ax.plot(time, values, linewidth=1.0, label=column)
            drawn += 1
        if drawn == 0:
            ax.text(0.5, 0.5, "zero throughout", transform=ax.transAxes, ha="center", va="center", color="0.5")
        else:
            ax.legend(fontsize=7, ncol=3)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[-1][0].set_xlabel("time [s]")
    fig.suptitle(f"{name}.csv ({os.path.basename(os.path.abspath(folder))}; components zero throughout omitted)",
                 fontsize=10)
    return save(plt, fig, out_dir, name)


def plot_probes(plt, folder, out_dir):
    return plot_series(plt, folder, out_dir, "probes", [(("ux", "uy", "uz"), "mean displacement [m]"),
                                                         (("vx", "vy", "vz"), "mean velocity [m/s]"),
                                                         (("fx", "fy", "fz"), "summed force [N]")])


def plot_strength(plt, folder, out_dir):
    """strength.png/svg: the test's stress against strain with its peak (UCS, BTS or the tensile
    strength, as summary.json defines it), and the bonds broken in tension and in shear."""
    curve = read_csv(os.path.join(folder, "force_displacement.csv"))
    summary = read_json(os.path.join(folder, "summary.json"))
    strength = (summary.get("compression") or {}).get("strength")
    if not strength:
        raise PlotError(f"{folder}: summary.json has no compression.strength block (a run of a finished test writes it)")
    strain = [100 * float(v) for v in curve["strain"]]
    stress = [1e-6 * float(v) for v in curve["stress_Pa"]]
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.4), layout="constrained")
    a.plot(strain, stress, ".-", color="0.25", markersize=3, linewidth=0.8, label="F / A")
    peak = 100 * float(strength["peak_strain"])
    a.axvline(peak, color="tab:red", linewidth=0.8, linestyle="--",
              label=f"peak: {strength['definition']} = {1e-6 * float(strength['strength_Pa']):.4g} MPa")
    a.set(xlabel="strain [%]", ylabel="stress F / A [MPa]",
          title=f"(a) {strength['test']} test, post-peak to {float(strength['post_peak_to_fraction_of_peak']):g} of the peak")
    a.legend(fontsize=8)
    tension = [float(v) for v in curve["bonds_broken_tension"]]
    shear = [float(v) for v in curve["bonds_broken_shear"]]
    b.plot(strain, tension, color="tab:blue", label="broken in tension")
    b.plot(strain, shear, color="tab:orange", label="broken in shear")
    b.axvline(peak, color="tab:red", linewidth=0.8, linestyle="--", label="peak")
    b.set(xlabel="strain [%]", ylabel="bonds broken", title="(b) breakage by mode")
    b.legend(fontsize=8)
    for ax in (a, b):
        ax.grid(True, alpha=0.3)
    return save(plt, fig, out_dir, "strength")


def plot_walls(plt, folder, out_dir):
    return plot_series(plt, folder, out_dir, "walls", [(("ux", "uy", "uz"), "wall displacement [m]"),
                                                       (("fx", "fy", "fz"), "force of the particles [N]")])


# ---------------------------------------------------------------------------------------------


def figure_kinds(folder):
    """The figures the folder's files allow: [(label, function)]."""
    has = lambda name: os.path.isfile(os.path.join(folder, name))  # noqa: E731
    kinds = []
    if has("force_displacement.csv"):
        kinds.append(("compression", plot_compression))
        if "bonds_broken_tension" in open(os.path.join(folder, "force_displacement.csv")).readline():
            kinds.append(("strength", plot_strength))
    if has("case1_deflection.csv") or has("cantilever_tips.csv"):
        kinds.append(("cantilever", plot_cantilever))
    if has("compare.csv"):
        kinds.append(("stiffness methods", plot_compare))
    if has("calibration.json"):
        kinds.append(("calibration", plot_calibration))
    if has("probes.csv"):
        kinds.append(("probes", plot_probes))
    if has("walls.csv"):
        kinds.append(("walls", plot_walls))
    return kinds


def nothing_to_plot(folder):
    """The message for a folder without any file this script draws."""
    expected = ("force_displacement.csv (bpmkit run with compression), cantilever_tips.csv or case1_deflection.csv "
                "(bpmkit verify cantilever), compare.csv (bpmkit compare), calibration.json (bpmkit calibrate), "
                "probes.csv or walls.csv (bpmkit run)")
    hint = ""
    if os.path.isfile(os.path.join(folder, "stiffness.json")):
        try:
            method = read_json(os.path.join(folder, "stiffness.json")).get("method", "?")
        except (OSError, ValueError):
            method = "?"
        hint = (f"; its stiffness.json (bpmkit stiffness --method {method}) holds one K and no curve: "
                "`bpmkit run SCENARIO` writes force_displacement.csv, `bpmkit compare SCENARIO` the methods side by side")
    return f"{folder}: nothing to plot: expected one of {expected}{hint}"


def main(argv=None):
    parser = argparse.ArgumentParser(prog="bpmkit plot", description="PNG and SVG figures of a bpmkit output folder")
    parser.add_argument("dir", help="output folder of a bpmkit command")
    parser.add_argument("--out", help="write the figures here instead of into DIR (created if missing)")
    args = parser.parse_args(argv)
    folder = args.dir
    try:
        if not os.path.isdir(folder):
            raise PlotError(f"{folder}: no such folder (expected the --out folder of a bpmkit command)")
        kinds = figure_kinds(folder)
        if not kinds:
            raise PlotError(nothing_to_plot(folder))
        plt = setup_matplotlib()
        out_dir = args.out or folder
        os.makedirs(out_dir, exist_ok=True)
        summary_path = os.path.join(folder, "summary.json")
        if os.path.isfile(summary_path):
            status = read_json(summary_path).get("status")
            if status not in (None, "finished"):
                print(f"warning: {folder}: summary.json says status '{status}': the figures show what was written",
                      file=sys.stderr)
        written, failed = [], []
        for label, plot in kinds:
            try:
                paths = plot(plt, folder, out_dir)
            except PlotError as e:
                failed.append(f"{label}: {e}")
                continue
            except (KeyError, ValueError, IndexError, ZeroDivisionError) as e:
                failed.append(f"{label}: unexpected content ({type(e).__name__}: {e})")
                continue
            written += paths
            print(f"{label}: wrote " + ", ".join(paths))
        for message in failed:
            print(f"error: {message}", file=sys.stderr)
        if not written:
            return 2
        return 1 if failed else 0
    except PlotError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
