#!/usr/bin/env python3
"""Jarolin's Fig. 6: the local stiffness deviation of the STE's map (docs/validation.md).

    python3 scripts/validation_fig6.py STIFFNESS_MAP.vtp OUT_PREFIX

Reads the map `bpmkit stiffness --method ste` writes (stiffness_map.vtp; the scenario's
output.vtk on): per particle the excess (E_i - mean E_i) / mean E_i of the directional moduli of
the local tensor, averaged over a sphere of three particle diameters (Jarolin Eq. 36 with the sign
turned: positive where locally stiffer). Prints its distribution, core against shell, and, with
Debian's python3-matplotlib, draws the particles of a slab through the axis coloured by it
(OUT_PREFIX.png and .svg).
"""
import math
import re
import struct
import sys
import zlib


def read_vtp(path):
    """The appended, zlib-compressed arrays of a bpmkit VTP (UInt64 headers), by name."""
    data = open(path, "rb").read()
    start = data.index(b"<AppendedData")
    raw = data[data.index(b"_", start) + 1:]
    arrays = {}
    kinds = {"Float64": "d", "Int64": "q", "Int32": "i"}
    for m in re.finditer(rb'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" format="appended" '
                         rb'offset="(\d+)"', data[:start]):
        kind, name, components, offset = m.group(1).decode(), m.group(2).decode(), int(m.group(3)), int(m.group(4))
        blocks, _, _ = struct.unpack_from("<3Q", raw, offset)
        sizes = struct.unpack_from(f"<{blocks}Q", raw, offset + 24)
        at = offset + 24 + 8 * blocks
        payload = b""
        for size in sizes:
            payload += zlib.decompress(raw[at:at + size])
            at += size
        values = struct.unpack(f"<{len(payload) // 8 if kind != 'Int32' else len(payload) // 4}{kinds[kind]}", payload)
        arrays[name] = [values[i:i + components] for i in range(0, len(values), components)] if components > 1 \
            else list(values)
    return arrays


def percentile(sorted_values, q):
    return sorted_values[min(len(sorted_values) - 1, int(q * len(sorted_values)))]


def main():
    path, prefix = sys.argv[1], sys.argv[2]
    a = read_vtp(path)
    position, radius = a["position"], a["radius"]
    n = len(position)
    centre = [sum(p[k] for p in position) / n for k in range(3)]
    distance = [math.hypot(p[0] - centre[0], p[1] - centre[1]) for p in position]
    outer = max(distance)
    diameter = 2.0 * sum(radius) / n
    valid = [i for i in range(n) if a["E_local_z"][i] > 0.0]
    print(f"{n} particles, {len(valid)} with a local value; mean diameter {diameter:.3e} m, radius of the body "
          f"{outer:.3e} m")
    print("| direction | 1st percentile | 99th percentile | within +-15 % | core (r < R - 3 d) | "
          "shell (r > R - 3 d) |")
    print("|---|---:|---:|---:|---:|---:|")
    for axis in "xyz":
        e = [a[f"E_excess_{axis}"][i] for i in valid]
        s = sorted(e)
        within = sum(abs(v) <= 0.15 for v in e) / len(e)
        core = [a[f"E_excess_{axis}"][i] for i in valid if distance[i] < outer - 3 * diameter]
        shell = [a[f"E_excess_{axis}"][i] for i in valid if distance[i] >= outer - 3 * diameter]
        print(f"| {axis} | {100 * percentile(s, 0.01):+.1f} % | {100 * percentile(s, 0.99):+.1f} % | "
              f"{100 * within:.1f} % | {100 * sum(core) / len(core):+.1f} % | {100 * sum(shell) / len(shell):+.1f} % |")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(no matplotlib: the figure is not drawn; Debian's python3-matplotlib draws it)")
        return
    slab = [i for i in valid if abs(position[i][1] - centre[1]) < 1.5 * diameter]
    fig, axes = plt.subplots(1, 3, figsize=(10, 3.9), sharey=True, constrained_layout=True)
    for ax, axis in zip(axes, "xyz"):
        shown = ax.scatter([position[i][0] * 1e3 for i in slab], [position[i][2] * 1e3 for i in slab],
                           c=[100 * a[f"E_excess_{axis}"][i] for i in slab], s=4, cmap="coolwarm", vmin=-15, vmax=15)
        ax.set_title(f"E_{axis}")
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]")
    axes[0].set_ylabel("z [mm]")
    fig.colorbar(shown, ax=axes, label="(E_local - mean) / mean [%]", shrink=0.9)
    for ext in ("png", "svg"):
        fig.savefig(f"{prefix}.{ext}", dpi=90)


if __name__ == "__main__":
    main()
