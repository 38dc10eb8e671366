"""contactlab from Python: build a scene, run or step it, read the results as NumPy arrays.

    import contactlab
    sim = contactlab.Simulation("scenes/hertz-2d.yaml", set={"Load Steps/Steps": 2},
                                out="results/hertz", quiet=True)
    while sim.step():
        print(sim.time, sim.history["normal_force"][-1])
    sim.finish()                     # summary.json, as `contactlab run` writes it
    points = sim.contact_points()    # dict of arrays: x, gap, pressure, traction, status, ...

A Simulation writes the same output folder as `contactlab run` (result.pvd, steps.csv,
contact.csv, summary.json) and keeps each converged step's results in memory. A scene is a
file, YAML text (``text=``) or a dict (``scene=``); ``set`` overrides keys as ``--set`` does
(``{"Contact/c/Friction": 0.3}``). Bad input raises ``contactlab.InputError`` (a ValueError)
with the sentence the command line prints. Under ``mpirun -np N python3 script.py`` every rank
runs the script; displacement() is whole on rank 0 (empty elsewhere).
"""
import csv
import json
import os
import shutil
import subprocess

import yaml

from ._contactlab import InputError, rank, ranks
from ._contactlab import Simulation as _Simulation

__all__ = ["Simulation", "InputError", "run", "validate", "study", "rank", "ranks"]


def _value_text(value):
    """A --set value: YAML's spelling of booleans and lists, Python's of numbers."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value_text(v) for v in value) + "]"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _overrides(set):
    if set is None:
        return []
    if isinstance(set, dict):
        return [f"{key}={_value_text(value)}" for key, value in set.items()]
    return list(set)  # already "key=value" strings


class Simulation:
    """A run of a scene (apps/Simulation.hpp): the model, contact, solver, state and outputs.

    path: a scene file; or text: a scene's YAML; or scene: a dict (dumped to YAML); none of
    them: the embedded default scene. set: overrides (a dict, or "key=value" strings).
    out: the output folder (default: the scene's Output/Directory). restart: continue the run
    whose outputs are in that folder. validate: build and check only (cannot step).
    critical_mu: finish() also computes the critical friction coefficient of the last converged
    state's status pattern (`contactlab critical-mu`; summary["critical_mu"]).
    """

    def __init__(self, path=None, *, text=None, scene=None, set=None, out=None, quiet=False,
                 restart=None, validate=False, critical_mu=False):
        given = [p for p in (path, text, scene) if p is not None]
        if len(given) > 1:
            raise ValueError("give one of path, text and scene")
        if scene is not None:
            text = yaml.safe_dump(scene, sort_keys=False, allow_unicode=True)
        self._s = _Simulation(str(path) if path is not None else "", text or "",
                              _overrides(set), str(out) if out is not None else "", bool(quiet),
                              str(restart) if restart is not None else "", bool(validate),
                              bool(critical_mu))
        self._summary = None
        self._history = None  # the history's arrays, built once per converged step

    def on_iteration(self, observer):
        """observer(progress) after each Newton iterate (step, time, iteration, residual, target,
        status_changes, attempt); None removes it. An exception it raises leaves step() or run()
        with it, the simulation at its last converged step (the next call goes on from there)."""
        self._s.on_iteration(observer)

    def step(self):
        """One converged load step; False once the run has ended (report says how)."""
        self._history = None
        return self._s.step()

    def run(self):
        """The steps left, to End Time or the first failure; returns report."""
        self._history = None
        return self._s.run()

    def finish(self):
        """Writes summary.json (also after a failure); returns `contactlab run`'s exit code.
        Finished before End Time (after step() calls), the run is recorded as failure "stopped"
        (exit code 1). Once per simulation."""
        code = self._s.finish()
        text = self._s.summary_json()
        self._summary = json.loads(text) if text and text != "null" else None
        return code

    @property
    def report(self):
        """converged, failure, message, steps, iterations, ... of the run so far."""
        return self._s.report()

    @property
    def ended(self):
        return self._s.ended()

    @property
    def time(self):
        """The load time of the last converged step."""
        return self._s.time()

    @property
    def history(self):
        """Per converged step, as steps.csv's columns of the same names: step, time,
        newton_iterations, cuts, residual, normal_force (sum w p), contact_force (n x 3, the
        sum of w (p n + t) on the slave surfaces), contact_points, stick_points, slip_points.
        Built once per converged step (reading it after every step costs one step's worth); the
        arrays are read-only, shared by the reads until the next step."""
        if self._history is None:
            self._history = self._s.history()
            for column in self._history.values():
                column.setflags(write=False)
        return dict(self._history)

    def contact_points(self):
        """The last converged step's contact points: zone, node (ids), x and reference (n x 3),
        gap (NaN where unpaired), pressure, weight, traction, slip, normal (n x 3), status
        (0 free, 1 stick, 2 slip, 3 closed without friction)."""
        return self._s.contact_points()

    def displacement(self):
        """Nodal displacements, numNodes x dim in the mesh's node order (rank 0)."""
        return self._s.displacement()

    def nodal_fields(self):
        """The last converged step's fields at the nodes (rank 0; empty arrays on the others):
        the element averages result.vtu holds as cell fields, averaged over the elements around
        each node. stress (numNodes x 6, Cauchy, xx yy zz xy yz xz), von_mises (numNodes, of
        that averaged stress), and with plastic blocks equivalent_plastic_strain (numNodes). NaN
        at a node on no element; the mesh's node order. Collective under mpirun."""
        return self._s.nodal_fields()

    def coordinates(self):
        """Reference coordinates, numNodes x 3."""
        return self._s.coordinates()

    def node_ids(self):
        """The nodes' ids (gmsh tags), in the mesh's node order."""
        return self._s.node_ids()

    @property
    def summary(self):
        """summary.json as a dict, after finish() (None before)."""
        return self._summary

    @property
    def output_directory(self):
        return self._s.output_directory()

    @property
    def name(self):
        return self._s.scene_name()

    @property
    def dofs(self):
        return self._s.dofs()


def run(path=None, **kwargs):
    """Builds, runs and finishes a Simulation; returns it (its summary, history, fields)."""
    sim = Simulation(path, **kwargs)
    sim.run()
    sim.finish()
    return sim


def validate(path=None, **kwargs):
    """Reads, validates and builds a scene without running it (InputError when it is wrong)."""
    return Simulation(path, validate=True, **kwargs)


def _executable():
    """The `contactlab` command beside this module (build tree or install), else on the PATH."""
    from . import _paths
    if os.access(_paths.EXECUTABLE, os.X_OK):
        return _paths.EXECUTABLE
    found = shutil.which("contactlab")
    if found is None:
        raise RuntimeError(f"contactlab: the command is neither at {_paths.EXECUTABLE} nor on "
                           "the PATH")
    return found


def _cell(text):
    """A study.csv cell: a number as float, an empty cell as None, other text as it is."""
    if text == "":
        return None
    try:
        return float(text)
    except ValueError:
        return text


def study(path, out, *, retry_failed=False, plots=False, quiet=True):
    """Runs a study file (doc/studies.md) through `contactlab study` and returns its table: one
    dict per run with study.csv's columns (case, each axis, status, newton, wall_s,
    pressure_error_l2, ...; numbers as floats, empty cells None). The runs, study.md and (with
    plots) the figures are in `out`. A study that resumes reuses the runs its folder holds.
    Bad input (the study file, a scene) raises InputError with the command's sentence."""
    command = [_executable(), "study", str(path), "--out", str(out)]
    if retry_failed:
        command.append("--retry-failed")
    if not plots:
        command.append("--no-plots")
    done = subprocess.run(command, capture_output=quiet, text=True)
    if done.returncode == 2:
        lines = (done.stderr or "").strip().splitlines()
        raise InputError(lines[-1].replace("contactlab: error: ", "") if lines else str(path))
    if done.returncode != 0:
        raise RuntimeError(f"contactlab study {path} ended with exit code {done.returncode}: "
                           + (done.stderr or "").strip()[-2000:])
    with open(os.path.join(str(out), "study.csv"), newline="") as f:
        return [{key: _cell(value) for key, value in row.items()} for row in csv.DictReader(f)]
