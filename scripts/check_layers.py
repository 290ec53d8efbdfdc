#!/usr/bin/env python3
"""The layer check, run by every build (CMake target bpmkit_layers) and by the test command: a file of
src/ may include headers of its own folder and of the layers below it, never above, so the folders
form no cycle (docs/architecture.md has the picture). The layers, bottom up, are the LAYERS list.

scripts/layer-exceptions.txt lists the upward includes written before the check ("FILE -> HEADER"),
not yet moved. The list only shrinks: a new upward include fails, and so does a listed one that is
gone (remove its line).
"""
import pathlib
import re
import sys

# Bottom up, one folder a layer.
LAYERS = [
    ["core"],                      # vectors, quaternions, errors, the thread loops
    ["solvers"],                   # sparse SPD solvers, AMG, MPI: the solver room, no particles
    ["bonds"],                     # the unified bond law, bond models and materials (Chen)
    ["model"],                     # particle and bond stores, their canonical order
    ["spatial"],                   # the one cell grid and neighbour search
    ["contacts"],                  # the contact law, the Verlet list, the contact forces
    ["walls"],                     # walls and their contacts
    ["linear"],                    # the bond element (the linearised law)
    ["dem"],                       # the model, the explicit DEM, time steps
    ["statics"],                   # the static core: contacts, assembly, K u + h(u) = f, Newton
    ["compress"],                  # uniaxial compression: platens, loading, DEM protocol
    ["io"],                        # formats: YAML fields, CSV, binary tables, VTK, JSON; output folders
    ["scenario"],                  # scenario -> model and run, the run's outputs, checkpoints
    ["structure"],                 # bpmkit generate: packing, relaxation, bonding
    ["verify"],                    # the cantilever verification (Chen cases 1-5)
    ["dsm"],                       # the direct stiffness method (Jarolin 3.1) on the static core
    ["ste"],                       # the stiffness tensor estimation (Jarolin 3.2)
    ["calibrate"],                 # K by any method, the E_b search, validation data
    ["cli"],                       # the commands
    ["python"],                    # the Python module
]
RANK = {folder: rank for rank, folders in enumerate(LAYERS) for folder in folders}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_0-9]+)/([^"]+)"')

root = pathlib.Path(__file__).resolve().parent.parent
exceptions_file = root / "scripts" / "layer-exceptions.txt"
listed = {line.strip() for line in exceptions_file.read_text().splitlines() if line.strip() and not line.startswith("#")}

files = sorted(str(p.relative_to(root)) for p in (root / "src").rglob("*") if p.suffix in (".cpp", ".hpp"))
upward, unknown = set(), []
for name in files:
    folder = pathlib.PurePosixPath(name).parts[1]
    if folder not in RANK:
        unknown.append(name)
        continue
    for line in (root / name).read_text().splitlines():
        match = INCLUDE.match(line)
        if not match or match.group(1) not in RANK:
            continue
        if RANK[match.group(1)] > RANK[folder]:
            upward.add(f"{name} -> {match.group(1)}/{match.group(2)}")

new, gone = sorted(upward - listed), sorted(listed - upward)
if unknown:
    print("folders without a layer (add them to LAYERS in scripts/check_layers.py):")
    print("\n".join(f"  {n}" for n in unknown))
if new:
    print("upward includes (move the header down, or the code up; docs/architecture.md):")
    print("\n".join(f"  {n}" for n in new))
if gone:
    print(f"gone, remove them from {exceptions_file.relative_to(root)}:")
    print("\n".join(f"  {n}" for n in gone))
if unknown or new or gone:
    sys.exit(1)
print(f"layers: {len(files)} files, {len(LAYERS)} layers, {len(listed)} upward includes listed to move")
