#!/usr/bin/env python3
"""Writes the packing that `BPMKIT_BENCH_EXPORT=DIR bpmkit_bench_contacts` exported as a LAMMPS data
file, in the same (shuffled) row order: DIR/lammps.data, and DIR/lammps.vars with the `-var`
arguments of in.compression (time step, skin, platens, materials from DIR/setup.txt).

Usage: export_lammps.py DIR

- atom_style hybrid sphere bond: "id type x y z diameter density molecule"; LAMMPS ids are the
  bpmkit ids + 1, one atom type.
- Bonds: LAMMPS has no TBBM bond (and Debian's build no BPM package), so each bond is a harmonic
  spring with the TBBM bond's axial stiffness k_n = E_b pi r_b^2 / L (r_b = min(R_i, R_j), L the
  initial length): bond_style harmonic's energy K (r - r0)^2 gives K = k_n / 2 and r0 = L. Every
  bond gets its own bond type (its own K and r0), numbered in LAMMPS's sort order (see below).
- Platens: fix wall/gran takes one material and uses E_eff = E / (2 (1 - nu)) for it, so the
  platen's E is chosen to give bpmkit's grain-steel E* (1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2) with
  the grain's nu. Restitution and friction are the means of the two materials, as bpmkit's pair rule.
"""
import math
import sys
from pathlib import Path


def read_setup(path):
    setup = {}
    for line in path.read_text().splitlines():
        if line.strip():
            key, value = line.split()
            setup[key] = float(value)
    return setup


def main():
    out = Path(sys.argv[1])
    s = read_setup(out / "setup.txt")
    rows = [line.split(",") for line in (out / "particles.csv").read_text().splitlines()[1:]]
    pid = [int(r[0]) for r in rows]
    x = [(float(r[1]), float(r[2]), float(r[3])) for r in rows]
    rad = [float(r[4]) for r in rows]
    row_of = {p: k for k, p in enumerate(pid)}
    bonds = [tuple(int(v) for v in line.split(",")[:2]) for line in (out / "bonds.csv").read_text().splitlines()[1:]]

    lo = [min(p[a] for p in x) - 3 * max(rad) for a in range(3)]
    hi = [max(p[a] for p in x) + 3 * max(rad) for a in range(3)]
    lines = ["LAMMPS data file: bpmkit's shuffled benchmark packing (bench/lammps/export_lammps.py)", "",
             f"{len(rows)} atoms", "1 atom types", f"{len(bonds)} bonds", f"{len(bonds)} bond types", "",
             f"{lo[0]!r} {hi[0]!r} xlo xhi", f"{lo[1]!r} {hi[1]!r} ylo yhi", f"{lo[2]!r} {hi[2]!r} zlo zhi", "",
             "Atoms # hybrid sphere bond", ""]
    density = s["density"]
    for k in range(len(rows)):
        lines.append(f"{pid[k] + 1} 1 {x[k][0]!r} {x[k][1]!r} {x[k][2]!r} {2 * rad[k]!r} {density!r} 1")
    # The bond types are numbered in the order of LAMMPS's own atom sort (bins of half the pair
    # cutoff, x fastest, then y, then z), by the bond's first atom (which stores the bond), so the
    # per-type K and r0 are read in memory order as in a code that keeps bond parameters with the
    # bond. The Bonds section keeps the shuffled row order.
    b = 0.5 * (2 * max(rad) + s["skin"])
    key = {p: (math.floor((x[k][2] - lo[2]) / b), math.floor((x[k][1] - lo[1]) / b), math.floor((x[k][0] - lo[0]) / b))
           for k, p in enumerate(pid)}
    type_of = {n: t for t, n in enumerate(sorted(range(len(bonds)), key=lambda n: (key[bonds[n][0]], n)), start=1)}
    coeffs, topology = [""] * len(bonds), []
    e_b, mult = s["bond_youngs_modulus"], s["bond_radius_multiplier"]
    longest = 0.0
    for n, (i, j) in enumerate(bonds):
        a, c = row_of[i], row_of[j]
        length = math.dist(x[a], x[c])
        longest = max(longest, length)
        r_b = mult * min(rad[a], rad[c])
        k_n = e_b * math.pi * r_b * r_b / length
        t = type_of[n]
        coeffs[t - 1] = f"{t} {0.5 * k_n!r} {length!r}"
        topology.append(f"{n + 1} {t} {i + 1} {j + 1}")
    lines += ["", "Bond Coeffs # harmonic", ""] + coeffs + ["", "Bonds", ""] + topology
    (out / "lammps.data").write_text("\n".join(lines) + "\n")

    nu = s["grain_poisson_ratio"]
    inv_e_star = (1 - nu**2) / s["grain_youngs_modulus"] + (1 - s["platen_poisson_ratio"] ** 2) / s["platen_youngs_modulus"]
    wall_e = 2 * (1 - nu) / inv_e_star
    variables = {
        "dt": s["dt"], "skin": s["skin"], "bottom": s["bottom"], "top": s["top"], "top_velocity": s["top_velocity"],
        "grain_E": s["grain_youngs_modulus"], "grain_nu": nu, "grain_e": s["grain_restitution"],
        "grain_mu": s["grain_friction"], "wall_E": wall_e,
        "wall_e": 0.5 * (s["grain_restitution"] + s["platen_restitution"]),
        "wall_mu": 0.5 * (s["grain_friction"] + s["platen_friction"]),
        # Ghost atoms must reach every bond partner (LAMMPS warns below 1.5 x the longest bond).
        "comm_cutoff": 2.0 * longest,
    }
    (out / "lammps.vars").write_text(" ".join(f"-var {k} {v!r}" for k, v in variables.items()) + "\n")
    print(f"wrote {out / 'lammps.data'} ({len(rows)} atoms, {len(bonds)} bonds) and {out / 'lammps.vars'}")


if __name__ == "__main__":
    main()
