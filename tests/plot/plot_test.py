#!/usr/bin/env python3
"""CTest driver for `bpmkit plot` (label plot): usage: plot_test.py BPMKIT_EXE

Runs real commands into a temporary folder: `bpmkit run` of a 3 x 3 x 6 bonded lattice under
uniaxial compression with two probes, `bpmkit compare` and `bpmkit calibrate --no-dem` of the same
scenario, `bpmkit verify cantilever --cases 1 3 5`; then `bpmkit plot` on each folder, and checks:
- every expected figure exists as PNG (signature and IHDR chunk) and SVG (parses as XML, root <svg>);
- the compression figure's slope check: the least-squares slope recomputed from
  force_displacement.csv over the fit window equals the K of summary.json to 1e-6 (relative), and
  the script printed no warning;
- an empty folder is refused with exit status 2 and a message naming it.
Fails with a clear message when matplotlib is missing (install python3-matplotlib, Debian).
"""
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

SCENARIO = """description: 3 x 3 x 6 bonded lattice, uniaxial compression (bpmkit plot test)
particle_materials:
  grain:
    density: 2500
    contact: {youngs_modulus: 1e9, poisson_ratio: 0.25, restitution: 0.5, friction: 0.3}
  steel:
    density: 7850
    contact: {youngs_modulus: 200e9, poisson_ratio: 0.3, restitution: 0.5, friction: 0.0}
bond_materials:
  cement: {model: tbbm, youngs_modulus: 1e9, poisson_ratio: 0.25, radius: 5e-4}
particles: {material: grain, file: lattice.csv}
bonds: {material: cement, auto: {max_gap: 1e-4}}
contacts: {particle_particle: true, bonded: superimpose}
damping: {particle: 0.7}
compression:
  platen_material: steel
  strain_rate: 2
  target_strain: 0.002
  fit_window: [0.3, 1.0]    # the slope check must use this window, not [0, 1]
  curve_points: 50
output:
  vtk: false
  probes:
    - {name: top, region: {box: {min: [-1, -1, 0.0095], max: [1, 1, 1]}}}
    - {name: bottom, particles: [0, 6, 12]}
"""

failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print(f"FAIL: {message}", file=sys.stderr)
    return ok


def run(cmd, cwd, expect=0):
    """Runs cmd in cwd; returns (stdout, stderr); a wrong exit status is a failure."""
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=120)
    print(f"$ {' '.join(cmd)}  -> {p.returncode}")
    if p.returncode != expect:
        check(False, f"{' '.join(cmd)} exited with {p.returncode}, expected {expect}\n"
                     f"stdout:\n{p.stdout}\nstderr:\n{p.stderr}")
    return p.stdout, p.stderr


def check_png(path):
    if not check(os.path.isfile(path), f"{path} was not written"):
        return
    with open(path, "rb") as f:
        head = f.read(33)
    check(head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR" and os.path.getsize(path) > 1000,
          f"{path} is not a PNG file")


def check_svg(path):
    if not check(os.path.isfile(path), f"{path} was not written"):
        return
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        check(False, f"{path} does not parse as XML: {e}")
        return
    check(root.tag in ("svg", "{http://www.w3.org/2000/svg}svg"), f"{path}: root element {root.tag}, not svg")


def check_figures(folder, names):
    for name in names:
        check_png(os.path.join(folder, name + ".png"))
        check_svg(os.path.join(folder, name + ".svg"))


def check_slope(stdout, stderr):
    """The script's slope check line: reported K and recomputed slope agree to 1e-6."""
    m = re.search(r"slope check: reported K = (\S+) N/m, least-squares slope over the window = (\S+) N/m", stdout)
    if not check(m is not None, f"bpmkit plot printed no slope check line:\n{stdout}"):
        return
    reported, recomputed = float(m.group(1)), float(m.group(2))
    difference = abs(recomputed - reported) / abs(reported)
    print(f"slope check: K = {reported:.12g}, recomputed {recomputed:.12g}, relative difference {difference:.3g}")
    check(difference <= 1e-6, f"recomputed slope {recomputed} and reported K {reported} differ by {difference:.3g}")
    window = re.search(r"fit window \[(\S+), (\S+)\] m of platen travel \(summary.json\)", stdout)
    check(window is not None and abs(float(window.group(1)) / float(window.group(2)) - 0.3) < 1e-6,
          f"the slope check did not use the scenario's fit window [0.3, 1]:\n{stdout}")
    check("warning" not in stderr, f"bpmkit plot warned:\n{stderr}")


def main(argv):
    if len(argv) != 2:
        print("usage: plot_test.py BPMKIT_EXE", file=sys.stderr)
        return 2
    exe = os.path.abspath(argv[1])
    if importlib.util.find_spec("matplotlib") is None:  # bpmkit plot runs /usr/bin/python3, as this test does
        print(f"FAIL: matplotlib is not available to {sys.executable}: `bpmkit plot` needs it; "
              "install python3-matplotlib (Debian; scripts/install-deps.sh does)", file=sys.stderr)
        return 1
    tmp = tempfile.mkdtemp(prefix="bpmkit_plot_test_")
    try:
        rows = ["id,x,y,z,radius"]
        for i in range(54):
            a, b, c = i // 18, (i // 6) % 3, i % 6
            rows.append(f"{i},{2e-3 * a:g},{2e-3 * b:g},{2e-3 * c:g},0.001")
        with open(os.path.join(tmp, "lattice.csv"), "w") as f:
            f.write("\n".join(rows) + "\n")
        with open(os.path.join(tmp, "compression.yaml"), "w") as f:
            f.write(SCENARIO)
        quiet = [exe, "--threads", "1", "--quiet"]
        run(quiet + ["run", "compression.yaml", "--out", "run"], tmp)
        run(quiet + ["compare", "compression.yaml", "--out", "compare"], tmp)
        run(quiet + ["calibrate", "--target-K", "3.5e5", "--no-dem", "compression.yaml", "--out", "calibrate"], tmp)
        run(quiet + ["verify", "cantilever", "--cases", "1", "3", "5", "--out", "cantilever"], tmp)

        out, err = run([exe, "plot", "run"], tmp)
        check_slope(out, err)
        check_figures(os.path.join(tmp, "run"), ["force_displacement", "probes", "walls"])
        run([exe, "plot", "compare"], tmp)
        check_figures(os.path.join(tmp, "compare"), ["stiffness_methods"])
        run([exe, "plot", "calibrate"], tmp)
        check_figures(os.path.join(tmp, "calibrate"), ["calibration"])
        run([exe, "plot", "cantilever", "--out", "cantilever_figures"], tmp)  # --out: another folder
        check_figures(os.path.join(tmp, "cantilever_figures"),
                      ["cantilever_case1_deflection", "cantilever_resolution", "cantilever_polydispersity"])
        check(not os.path.exists(os.path.join(tmp, "cantilever", "cantilever_resolution.png")),
              "--out: the figures went into DIR")

        os.mkdir(os.path.join(tmp, "empty"))
        _, err = run([exe, "plot", "empty"], tmp, expect=2)
        check("empty: nothing to plot" in err, f"an empty folder: unexpected message {err!r}")
    finally:
        if failures:
            print(f"kept {tmp} for inspection", file=sys.stderr)
        else:
            shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print(f"{len(failures)} check(s) failed", file=sys.stderr)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
