#!/usr/bin/env python3
"""MUMPS' Mode 'automatic' (the default) resolves per model: LDL^T (symmetric-indefinite) on a
symmetric tangent, LU (general) otherwise; summary.json reports the mode used.

usage: check_solver_mode.py CONTACTLAB SCENES_DIR WORKDIR"""
import json, os, subprocess, sys

exe, scenes, work = sys.argv[1:4]
cases = [  # scene, overrides, expected mode
    ("hertz-2d", [], "symmetric-indefinite"),  # frictionless augmented Lagrangian
    ("hertz-2d", ["Contact/floor/Formulation/Type=lagrange",
                  "Contact/floor/Formulation/lagrange/Normal Complementarity Constant=1e3"],
     "general"),  # Lagrange: not symmetric at an open point
    ("sliding-block-2d", [], "general"),  # friction
    ("pressurized-cube-finite-strain", [], "general"),  # follower pressure
    ("cantilever-2d", [], "symmetric-indefinite"),  # no contact
    ("hertz-2d", ["Linear Solver/mumps/Mode=general"], "general"),  # the user's choice stays
]
failures = 0
for i, (scene, sets, expected) in enumerate(cases):
    out = os.path.join(work, f"mode-{i}")
    cmd = [exe, "run", os.path.join(scenes, scene + ".yaml"), "--out", out, "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    mode = json.load(open(os.path.join(out, "summary.json")))["linear_solver"]["parameters"]["Mode"]
    ok = run.returncode == 0 and mode == expected
    failures += not ok
    print(f"{'ok  ' if ok else 'FAIL'} {scene} {sets}: Mode {mode} (expected {expected}), "
          f"exit {run.returncode}")
sys.exit(1 if failures else 0)
