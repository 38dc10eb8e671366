#!/usr/bin/env python3
"""1 rank and 2 ranks give the same contact results (doc/architecture.md): runs a scene on both and
compares contact.csv point by point (pressure, gap, tangential traction, status) and the
summary's resultants and iteration counts.

usage: check_ranks_agree.py CONTACTLAB SCENE OUTDIR [TOL]   (TOL relative to the max pressure)"""
import csv, json, os, shutil, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import contactlab_run  # noqa: E402

exe, scene, out = sys.argv[1:4]
tol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-8
results = {}
for ranks in (1, 2):
    d = os.path.join(out, f"np{ranks}")
    shutil.rmtree(d, ignore_errors=True)
    _, run = contactlab_run(exe, scene, d, ranks=ranks, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    rows = {(r["zone"], r["node"]): r for r in csv.DictReader(open(os.path.join(d, "contact.csv")))}
    results[ranks] = (rows, json.load(open(os.path.join(d, "summary.json"))))
(one, s1), (two, s2) = results[1], results[2]
assert one.keys() == two.keys(), "different contact points"
scale = max(abs(float(r["pressure"])) for r in one.values())
worst = 0.0
for key, r in one.items():
    q = two[key]
    assert r["status"] == q["status"], (key, r["status"], q["status"])
    for f in ("pressure", "traction_x", "traction_y", "traction_z"):
        worst = max(worst, abs(float(r[f]) - float(q[f])) / scale)
print(f"{len(one)} points, max difference {worst:.3g} of the max pressure; "
      f"iterations {s1['iterations']} vs {s2['iterations']}")
assert worst <= tol, f"1 and 2 ranks differ by {worst} > {tol}"
assert s1["iterations"] == s2["iterations"], "different iteration counts"
