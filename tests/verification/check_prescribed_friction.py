#!/usr/bin/env python3
"""Friction at slave nodes whose tangential motion the Dirichlet conditions fix (a symmetry axis
through a frictional contact zone in 2D; symmetry planes x = 0 and y = 0 in 3D, with a corner
fixed in both tangential directions and edges in one). Before, AL and Lagrange stopped with
"MUMPS numerically singular" whatever the algorithm. Each formulation with multipliers under each
preset must converge, say once which nodes had a friction direction dropped, and every route
must give the same contact forces (1e-6); on 1 and 2 ranks.

usage: check_prescribed_friction.py CONTACTLAB SCENE WORKDIR RANKS"""
import json, os, shutil, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import contactlab_run  # noqa: E402

exe, scene, work, ranks = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
failures, forces = [], {}
for formulation in ["augmented-lagrangian", "lagrange"]:
    for method in ["partial-newton", "generalized-newton", "fixed-point"]:
        out = os.path.join(work, f"{formulation}-{method}")
        shutil.rmtree(out, ignore_errors=True)
        _, run = contactlab_run(
            exe, scene, out, ranks=ranks, timeout=300,
            sets=[f"Contact/floor/Formulation/Type={formulation}",
                  "Contact/floor/Formulation/lagrange/Normal Complementarity Constant=1000",
                  "Contact/floor/Formulation/lagrange/Tangential Complementarity Constant=10",
                  f"Algorithm/Method={method}"])
        summary = json.load(open(os.path.join(out, "summary.json")))
        said = [l for l in run.stderr.splitlines() if "friction multiplier is dropped" in l]
        label = f"{formulation} {method}: {summary['failure'] or 'converged'}"
        ok = summary["converged"] and len(said) == 1
        print(("ok   " if ok else "FAIL ") + label + (f"; {said[0]}" if said else "; nothing said"))
        if not ok:
            failures.append(label)
            continue
        c = summary["contact"]
        forces[label] = (c["normal_force"], c["tangential_force_vector"])
        if c["stick_points"] + c["slip_points"] == 0:
            failures.append(label + ": no frictional point closed")
reference = next(iter(forces.values()), None)
for label, (n, t) in forces.items():
    n0, t0 = reference
    same = abs(n - n0) <= 1e-6 * abs(n0) and all(abs(a - b) <= 1e-6 * abs(n0) for a, b in zip(t, t0))
    print(("ok   " if same else "FAIL ") + f"{label}: N = {n:.9g}, T = {[round(v, 12) for v in t]}")
    if not same:
        failures.append(label + " differs")
sys.exit(1 if failures else 0)
