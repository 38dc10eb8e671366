"""`contactlab run` as the test scripts start it: on one rank, or under mpirun on several (as root
too, as the CI runs), with the output captured. Imported by scripts in tests/app and
tests/verification (they put tests/ on sys.path)."""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET


def contactlab_run(exe, scene, out, sets=(), ranks=1, options=(), timeout=900, command="run"):
    """Runs `exe COMMAND [SCENE] --out OUT [options] --set S ...` (COMMAND `run` or
    `critical-mu`; no SCENE when `scene` is None: the built-in one) on `ranks` ranks; returns the
    command and its CompletedProcess."""
    cmd = [exe, command] + ([scene] if scene is not None else []) + ["--out", out] + list(options)
    for s in sets:
        cmd += ["--set", s]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--oversubscribe"] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return cmd, subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)


def fresh_run(exe, scene, out, sets=(), timeout=300):
    """`run` into a cleared OUT, whatever its outcome; returns its summary.json (None when it wrote
    none) and its CompletedProcess."""
    shutil.rmtree(out, ignore_errors=True)
    _, run = contactlab_run(exe, scene, out, sets, timeout=timeout)
    path = os.path.join(out, "summary.json")
    return (json.load(open(path)) if os.path.exists(path) else None), run


def required_summary(exe, scene, out, sets, name):
    """fresh_run, ending the check script (FAIL, with the run's stderr) when the run wrote no
    summary.json: a crash, not a named failure."""
    summary, run = fresh_run(exe, scene, out, sets)
    if summary is None:
        sys.exit(f"FAIL: {name} wrote no summary.json\n{run.stderr}")
    return summary


def converged_steps(exe, scene, out, sets, name):
    """The steps.csv rows of a run that must converge (required_summary; FAIL with its failure
    otherwise), after printing "NAME: converged in N Newton iterations, M steps"."""
    summary = required_summary(exe, scene, out, sets, name)
    if not summary["converged"]:
        sys.exit(f"FAIL: {name}: {summary['failure']}: {summary['message']}")
    with open(os.path.join(out, "steps.csv")) as f:
        rows = list(csv.DictReader(f))
    print(f"{name}: converged in {summary['iterations']['newton']} Newton iterations, "
          f"{len(rows)} steps")
    return rows


def outcome(name, summary):
    """"NAME: converged in N Newton iterations" (or the failure's name), a check's sentence."""
    return (f"{name}: {summary['failure'] or 'converged'} in "
            f"{summary['iterations']['newton']} Newton iterations")


def scene_check_arguments():
    """The command line of a check that runs one scene and bounds an error: APP SCENE OUT TOL
    [--ranks N] [--set key=value ...]; the caller adds its own options and parses."""
    parser = argparse.ArgumentParser()
    parser.add_argument("app")
    parser.add_argument("scene")
    parser.add_argument("out")
    parser.add_argument("tol", type=float)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--set", action="append", default=[])
    return parser


def converged_run(exe, scene, out, sets=(), ranks=1):
    """A fresh `run --quiet` into OUT that must exit 0 and converge (else the script exits with
    FAIL and why); returns its summary.json."""
    shutil.rmtree(out, ignore_errors=True)
    cmd, run = contactlab_run(exe, scene, out, sets, ranks, options=["--quiet"])
    if run.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited with {run.returncode}\n{run.stdout}\n{run.stderr}")
    summary = json.load(open(os.path.join(out, "summary.json")))
    if not summary["converged"]:
        sys.exit(f"FAIL: the run did not converge: {summary['failure']}: {summary['message']}")
    return summary


def result_frames(out):
    """The frames OUT/result.pvd lists, in order: (time, path of the .vtu or .pvtu) each; the
    first is the rest frame at t = 0."""
    datasets = ET.parse(os.path.join(out, "result.pvd")).getroot().findall(".//DataSet")
    return [(float(d.get("timestep")), os.path.join(out, d.get("file"))) for d in datasets]


def read_grid(path):
    """The unstructured grid of a .vtu (1 rank) or .pvtu (several) file, by VTK's own readers
    (vtk is imported here: a script that reads no VTK file needs no VTK)."""
    import vtk
    reader = (vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu")
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()
