#!/usr/bin/env python3
"""Sample stiffness K of the small cylinder (examples/04_compression/small_cylinder) against the
bond Young's modulus E_b: three DEM compression tests from Python, then the calibration of E_b for
a target K. Run from the repository root after the build:

    PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_bond_modulus.py
"""
import os
import bpmkit

path = "examples/04_compression/small_cylinder/compression.yaml"
spec = bpmkit.read_scenario(path)                    # the YAML file as a dict
for E_b in (1e8, 2e8, 4e8):
    spec["bond_materials"]["bond"]["youngs_modulus"] = E_b
    result = bpmkit.run(spec, f"out/sweep/E_b={E_b:g}", base_dir=os.path.dirname(path))
    print(f"E_b = {E_b:.3g} Pa: K = {result['compression']['stiffness_N_per_m']:.6g} N/m")

calibration = bpmkit.calibrate(path, target_K=80000, no_dem=True)   # the DSM stages only
print("E_b for K = 80000 N/m:", calibration["bond_youngs_modulus_Pa"]["bond"], "Pa")
