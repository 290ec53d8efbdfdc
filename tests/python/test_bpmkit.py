"""The Python module (python/bpmkit): scenarios from files and dicts, the Simulation and its
observer, NumPy state, runs and commands giving the command line's numbers, errors as exceptions
with the command line's messages."""
import json
import os
import subprocess

import numpy as np
import pytest

import bpmkit

EXE = os.environ["BPMKIT_EXE"]
EXAMPLES = os.environ["BPMKIT_EXAMPLES"]
CANTILEVER = os.path.join(EXAMPLES, "01_cantilever", "case1_pbm.yaml")
CYLINDER = os.path.join(EXAMPLES, "04_compression", "small_cylinder", "compression.yaml")


def cli(*args):
    """Runs the bpmkit program; its exit status and stderr."""
    done = subprocess.run([EXE, "--quiet", *args], capture_output=True, text=True)
    return done.returncode, done.stderr


def test_file_and_dict_give_the_same_model():
    from_file = bpmkit.load_scenario(CANTILEVER)
    from_dict = bpmkit.load_scenario(bpmkit.read_scenario(CANTILEVER))
    a, b = from_file.particles(), from_dict.particles()
    assert from_file.particle_count == 11 and from_file.bond_count == 10
    assert np.array_equal(a["id"], b["id"])
    assert np.array_equal(a["position"], b["position"])
    assert a["position"].shape == (11, 3)
    assert np.array_equal(from_file.bonds()["k_n"], from_dict.bonds()["k_n"])
    assert from_file.time_step == from_dict.time_step


def test_dict_csv_files_are_relative_to_base_dir():
    spec = bpmkit.read_scenario(CYLINDER)
    base = os.path.dirname(CYLINDER)
    assert bpmkit.load_scenario(spec, base_dir=base).particle_count == 847
    with pytest.raises(bpmkit.InputError, match="structure/particles.csv"):
        bpmkit.load_scenario(spec, base_dir=os.path.dirname(base))


def test_simulation_observer_and_state():
    sim = bpmkit.Simulation(bpmkit.load_scenario(CANTILEVER))
    times = []
    summary = sim.run(observer=lambda s: times.append(s.time), every=5000)
    assert summary["reason"] == "rest"
    # Every 5000 steps and once at the end.
    assert len(times) == summary["steps"] // 5000 + 1
    assert times == sorted(times) and times[-1] == pytest.approx(sim.time)
    p = sim.particles()
    tip = p["displacement"][p["id"] == 10][0]
    assert tip[1] == pytest.approx(-8.508e-3, rel=2e-3)  # Chen case 1, PBM (examples/01_cantilever)
    bonds = sim.bonds()
    assert bonds["force"].shape == (10, 3) and bonds["intact"].all()
    # Equilibrium at rest: the bond forces on the clamped end carry the 100 kN load.
    assert abs(bonds["force"][:, 1]).max() == pytest.approx(1e5, rel=1e-3)
    assert sim.energies()["elastic"] > 0


def test_step_advances_time():
    sim = bpmkit.Simulation(CANTILEVER)
    sim.step(10)
    assert sim.steps == 10 and sim.time == pytest.approx(10 * sim.dt)


def test_tip_deflection_scales_with_one_over_E_in_a_sweep():
    spec = bpmkit.read_scenario(CANTILEVER)
    deflection_times_E = []
    for E in (100e9, 200e9, 400e9):
        spec["bond_materials"]["beam"]["youngs_modulus"] = E
        sim = bpmkit.Simulation(bpmkit.load_scenario(spec))
        sim.run()
        p = sim.particles()
        deflection_times_E.append(p["displacement"][p["id"] == 10][0][1] * E)
    # Linear elasticity: the static deflection is proportional to 1/E (rest at 1e-9 m/s).
    assert np.ptp(deflection_times_E) < 1e-4 * abs(deflection_times_E[0])


def test_run_gives_the_command_lines_K(tmp_path):
    ours = bpmkit.run(CYLINDER, tmp_path / "python")
    status, _ = cli("run", CYLINDER, "--out", str(tmp_path / "cli"))
    assert status == 0
    with open(tmp_path / "cli" / "summary.json") as f:
        theirs = json.load(f)
    assert ours["status"] == "finished"
    assert ours["compression"]["stiffness_N_per_m"] == theirs["compression"]["stiffness_N_per_m"]
    assert ours["compression"]["stiffness_N_per_m"] == pytest.approx(58720, rel=1e-3)


def test_stiffness_gives_the_command_lines_number(tmp_path):
    ours = bpmkit.stiffness(CYLINDER, method="dsm")
    status, _ = cli("stiffness", "--method", "dsm", CYLINDER, "--out", str(tmp_path / "cli"))
    assert status == 0
    with open(tmp_path / "cli" / "summary.json") as f:
        theirs = json.load(f)
    assert ours["stiffness_N_per_m"] == theirs["stiffness_N_per_m"]


def test_errors_carry_the_command_lines_message(tmp_path):
    bad = tmp_path / "bad.yaml"
    text = open(CANTILEVER).read().replace("poisson_ratio: 0.3", "poisson_ratio: 0.7")
    bad.write_text(text)
    with pytest.raises(bpmkit.InputError) as caught:
        bpmkit.load_scenario(str(bad))
    status, stderr = cli("run", str(bad), "--out", str(tmp_path / "out"))
    assert status == 2
    assert stderr.strip() == "error: " + str(caught.value)
    assert "poisson_ratio" in str(caught.value)
    with pytest.raises(bpmkit.InputError, match="unknown method 'no-such-method'"):
        bpmkit.stiffness(CYLINDER, method="no-such-method")
    with pytest.raises(bpmkit.UsageError, match="no-such-option"):
        bpmkit.stiffness(CYLINDER, no_such_option=1)
    with pytest.raises(TypeError):
        bpmkit.load_scenario(42)
