#!/usr/bin/env python3
"""A body that nothing holds in some direction before contact (issue 15) makes the first Newton
tangent singular: the run must stop with the named failure `singular-tangent`, and its message in
summary.json (and on the console) must say what it means and the remedies. Before, the same runs
ended in `linear-solver-failed` (an exact zero pivot, "matrix is numerically singular"),
`max-iterations` or `diverged` (a round-off pivot), none of which named the cause.

usage: check_singular_tangent.py CONTACTLAB SCENE OUTDIR [--set key=value ...]"""
import json, os, shutil, subprocess, sys

exe, scene, out, sets = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
shutil.rmtree(out, ignore_errors=True)
cmd = [exe, "run", scene, "--out", out] + sets
run = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
errors = []
if run.returncode == 0:
    errors.append("the run succeeded (exit 0)")
summary = json.load(open(os.path.join(out, "summary.json")))
if summary.get("failure") != "singular-tangent":
    errors.append("failure %r, expected 'singular-tangent'" % summary.get("failure"))
message = summary.get("message", "")
for part in ("the tangent is singular at iteration", "at step 1",
             "a body is not held in some direction", "Algorithm/Regularization: slow-dynamics",
             "Initial Contact: all", "a support or Springs"):
    if part not in message:
        errors.append("the message lacks %r" % part)
if "FAILED (singular-tangent)" not in run.stdout + run.stderr:
    errors.append("the console output does not name the failure")
print(" ".join(cmd))
print("failure:", summary.get("failure"), "|", message)
for e in errors:
    print("ERROR:", e)
sys.exit(1 if errors else 0)
