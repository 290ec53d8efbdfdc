"""bpmkit from Python: bonded-particle models for DEM (Chen 2022 unified bond law).

    import bpmkit
    s = bpmkit.load_scenario("examples/04_compression/small_cylinder/compression.yaml")
    result = bpmkit.run(s, "out/compression")          # what `bpmkit run` does
    print(result["compression"]["stiffness_N_per_m"])

Scenarios load from a YAML file or from a dict (the same keys, docs/scenario.md). `run` runs a
scenario as `bpmkit run` does and returns its summary.json as a dict; `Simulation` steps a scenario
yourself, with an observer. `generate`, `stiffness`, `calibrate`, `compare`, `convert` and
`export_lammps` run the bpmkit command of that name in this process and return its summary.json:
the same numbers as the command line. Bad input raises bpmkit.InputError (a ValueError) with the
command line's message. See docs/python.md.
"""
import json
import os
import tempfile

from . import _bpmkit
from ._bpmkit import CommandFailed, DivergenceError, InputError, RunSummary, Scenario, UsageError

__all__ = ["load_scenario", "read_scenario", "run", "Simulation", "generate", "stiffness", "calibrate",
           "compare", "convert", "export_lammps", "Scenario", "RunSummary", "InputError", "UsageError",
           "CommandFailed", "DivergenceError"]


def read_scenario(path):
    """The scenario file as a dict (to change and pass to load_scenario). Needs python3-yaml."""
    import yaml
    with open(path, encoding="utf-8") as f:
        return yaml.safe_load(f)


def load_scenario(source, base_dir=None):
    """A Scenario from a YAML file path or from a dict of the same keys.

    For a dict, files it names (particles.file, bonds.file) are relative to base_dir (default: the
    current directory), and messages name it '<dict>'.
    """
    if isinstance(source, dict):
        base = os.fspath(base_dir) if base_dir is not None else os.getcwd()
        return _bpmkit.load_scenario_text(json.dumps(source), os.path.join(base, "<dict>"))
    if isinstance(source, (str, os.PathLike)):
        return _bpmkit.load_scenario(os.fspath(source))
    raise TypeError(f"load_scenario takes a path or a dict, not {type(source).__name__}")


def _summary(out_dir):
    with open(os.path.join(out_dir, "summary.json"), encoding="utf-8") as f:
        return json.load(f)


def run(scenario, out, base_dir=None):
    """Runs a scenario (a Scenario, a path or a dict) as `bpmkit run` does, writing its outputs
    into `out` (refused if it holds an earlier run); returns its summary.json as a dict. A Scenario
    object advances: run it once."""
    if not isinstance(scenario, Scenario):
        scenario = load_scenario(scenario, base_dir)
    _bpmkit.run_scenario(scenario, os.fspath(out))
    return _summary(out)


class Simulation:
    """The explicit DEM of a scenario, stepped from Python.

        sim = bpmkit.Simulation(bpmkit.load_scenario("case1_pbm.yaml"))
        sim.run(observer=lambda s: print(s.time, s.particles()["displacement"][-1]), every=5000)

    The particle and bond state are copies: snapshots of the moment they are taken, which stay valid
    while the simulation steps on. A compression test (a `compression` section) runs with
    `bpmkit.run`.
    """

    def __init__(self, scenario, base_dir=None):
        if not isinstance(scenario, Scenario):
            scenario = load_scenario(scenario, base_dir)
        self._sim = _bpmkit.Simulation(scenario)

    def step(self, n=1):
        """Advances n time steps."""
        self._sim.step(n)

    def run(self, observer=None, every=1000):
        """Runs to the scenario's stop criteria, calling observer(self) every `every` steps and at
        the end; returns the run summary (reason, steps, time, wall_seconds, max_speed) as a dict."""
        callback = (lambda: observer(self)) if observer is not None else None
        return self._sim.run(callback, every).as_dict()

    time = property(lambda self: self._sim.time, doc="simulated time, s")
    steps = property(lambda self: self._sim.steps, doc="steps taken")
    dt = property(lambda self: self._sim.dt, doc="time step, s")
    max_speed = property(lambda self: self._sim.max_speed, doc="max over particles of max(|U|, R |omega|), m/s")
    scenario = property(lambda self: self._sim.scenario)

    def energies(self):
        """Kinetic, elastic (bonds) and contact energy, J."""
        return self._sim.energies()

    def particles(self):
        """id, position, displacement, velocity, angular_velocity, force, torque, radius, mass,
        material as NumPy arrays (copies)."""
        return self._sim.particles()

    def bonds(self):
        """alpha, beta (particle ids), intact, force, moment, radius, length, k_n, k_s, k_tor, k_ben,
        material as NumPy arrays (copies)."""
        return self._sim.bonds()


def _option(name):
    return "--" + name.replace("_", "-")


def _command(words, out, options):
    """Runs `bpmkit WORDS... --out OUT [--option value ...]` here; returns its summary.json. With
    out=None the outputs go into a temporary folder, removed after reading the summary."""
    args = list(words)
    for name, value in options.items():
        if value is None or value is False:
            continue
        if value is True:
            args.append(_option(name))
        elif isinstance(value, (list, tuple)):
            args += [_option(name)] + [str(v) for v in value]
        else:
            args += [_option(name), str(value)]
    if out is not None:
        _bpmkit.run_command(args + ["--out", os.fspath(out)])
        return _summary(out)
    with tempfile.TemporaryDirectory(prefix="bpmkit_") as tmp:
        folder = os.path.join(tmp, "out")
        _bpmkit.run_command(args + ["--out", folder])
        return _summary(folder)


def generate(spec, out=None, **options):
    """`bpmkit generate SPEC` (docs/generate.md); returns its summary."""
    return _command(["generate", os.fspath(spec)], out, options)


def stiffness(scenario, method="dsm", out=None, **options):
    """`bpmkit stiffness --method METHOD SCENARIO` (dsm, dsm-nonlinear, ste, dem, ...); options as
    the command's, e.g. dofs=3, solver="amg"; returns its summary."""
    return _command(["stiffness", "--method", method, os.fspath(scenario)], out, options)


def calibrate(scenario, target_K=None, target_E=None, out=None, target_nu=None, **options):
    """`bpmkit calibrate --target-E E [--target-nu NU] SCENARIO` (the body's E and nu, strain
    gauges on its middle third), or `--target-K K` (the platen stiffness); returns its summary.
    The calibrated scenario is OUT/calibrated.yaml."""
    return _command(["calibrate", os.fspath(scenario)], out,
                    dict(options, target_K=target_K, target_E=target_E, target_nu=target_nu))


def compare(scenario, out=None, **options):
    """`bpmkit compare SCENARIO`: every method against the DEM; returns its summary."""
    return _command(["compare", os.fspath(scenario)], out, options)


def convert(source, to, out=None, **options):
    """`bpmkit convert SOURCE --to FORMAT` (bpmkit, lammps, yade, musen; docs/formats.md)."""
    return _command(["convert", os.fspath(source), "--to", to], out, options)


def export_lammps(scenario, out=None):
    """`bpmkit export lammps SCENARIO`: data file and deck for bond_style bpm/rotational."""
    return _command(["export", "lammps", os.fspath(scenario)], out, {})
