#!/usr/bin/env python3
"""progress.log (apps/RunProgress.hpp): whatever the console shows, a run writes its iterate and
step lines to DIR/progress.log, ending with its closing line. A --quiet run of hertz-2d (2
steps) prints no iterate on stderr and logs every iterate, both steps and "converged in 2
step(s)"; the sliding block above its Coulomb threshold (no equilibrium) logs its FAILED line
with the failure's name; a rerun into the same folder starts a new log.

usage: check_progress_log.py CONTACTLAB SCENES_DIR WORKDIR"""
import json, os, shutil, subprocess, sys

exe, scenes, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
failures = []


def check(what, ok):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def quiet_run(scene, out, *sets):
    cmd = [exe, "run", os.path.join(scenes, scene), "--out", out, "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300)


out = os.path.join(work, "hertz")
for attempt in (1, 2):  # the second run into the same folder replaces the log
    r = quiet_run("hertz-2d.yaml", out)
    lines = open(os.path.join(out, "progress.log")).read().splitlines()
    iterations = json.load(open(os.path.join(out, "summary.json")))["iterations"]["newton"]
    logged = [l for l in lines if " iteration " in l]
    steps = [l for l in lines if "(2 planned)" in l]
    check(f"run {attempt}: stderr quiet ({r.stderr.count(' iteration ')} iterate lines)",
          r.returncode == 0 and " iteration " not in r.stderr)
    check(f"run {attempt}: progress.log has {len(logged)} iterate lines (at least the "
          f"{iterations} Newton iterations) and {len(steps)} step lines (2)",
          len(logged) >= iterations > 0 and len(steps) == 2)
    check(f"run {attempt}: it ends with the closing line ({lines[-1] if lines else ''!r})",
          bool(lines) and "converged in 2 step(s)" in lines[-1])

out = os.path.join(work, "sliding")
r = quiet_run("sliding-block-2d.yaml", out, "Contact/floor/Friction=0.29703")
summary = json.load(open(os.path.join(out, "summary.json")))
lines = open(os.path.join(out, "progress.log")).read().splitlines()
check(f"a failed run logs its failure ({lines[-1] if lines else ''!r})",
      r.returncode == 1 and bool(lines) and "FAILED" in lines[-1]
      and summary["failure"] in lines[-1])
sys.exit(1 if failures else 0)
