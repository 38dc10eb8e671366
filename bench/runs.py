#!/usr/bin/env python3
"""One timed `contactlab` run of a benchmark and its summary, shared by the bench scripts (each
wrote the same clear-run-time-read sequence).

usage: import runs; summary, wall, done = runs.run(exe, "run", scene_yaml, out, sets)"""
import json, os, shutil, subprocess, sys, time


def positional(doc, count):
    """The first `count` command-line arguments; the script's doc (its usage) and exit status 0
    on -h/--help, status 2 when fewer are given (instead of a traceback)."""
    if "-h" in sys.argv[1:] or "--help" in sys.argv[1:]:
        print(doc)
        sys.exit(0)
    if len(sys.argv) <= count:
        print(doc, file=sys.stderr)
        sys.exit(2)
    return sys.argv[1:count + 1]


def run(exe, command, scene, out, sets=(), quiet=False, timeout=3600, ranks=1, prefix=()):
    """`exe command scene --out out` into a cleared folder, without VTK output, with a `--set`
    for each of sets, on `ranks` MPI processes (mpirun beyond one), the whole command after
    prefix (e.g. ["/usr/bin/time", "-v"], whose report ends the stderr). Returns the
    summary.json (None when the run wrote none or an unreadable one), the wall seconds and the
    finished process."""
    shutil.rmtree(out, ignore_errors=True)
    launcher = ["mpirun", "--oversubscribe", "-np", str(ranks)] if ranks > 1 else []
    cmd = [*prefix, *launcher, exe, command, scene, "--out", out] + (["--quiet"] if quiet else [])
    for s in ["Output/VTK=false", *sets]:
        cmd += ["--set", s]
    start = time.time()
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    wall = time.time() - start
    try:
        summary = json.load(open(os.path.join(out, "summary.json")))
    except (OSError, ValueError):
        summary = None
    return summary, wall, done
