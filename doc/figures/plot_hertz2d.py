#!/usr/bin/env python3
"""Figure of doc/verification.md (V1): contact pressure of the hertz-2d scene against Hertz's
profile for the computed load, for each formulation. Runs the scene itself.

usage: doc/figures/plot_hertz2d.py [CONTACTLAB]   (default build/apps/contactlab)"""
import csv, json, math, os, subprocess, sys, tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

exe = sys.argv[1] if len(sys.argv) > 1 else "build/apps/contactlab"
here = os.path.dirname(os.path.abspath(__file__))
scene = os.path.join(here, "..", "..", "scenes", "hertz-2d.yaml")
sets = {"augmented-lagrangian": [], "lagrange":
        ["Contact/floor/Formulation/lagrange/Normal Complementarity Constant=100"],
        "penalty": ["Contact/floor/Formulation/penalty/Normal Penalty=1e4"]}
fig, ax = plt.subplots(figsize=(6.4, 4.0))
work = tempfile.mkdtemp()
for i, (f, extra) in enumerate(sets.items()):
    out = os.path.join(work, f)
    cmd = [exe, "run", scene, "--out", out, "--set", f"Contact/floor/Formulation/Type={f}"]
    for s in extra:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, capture_output=True)
    P = json.load(open(os.path.join(out, "summary.json")))["contact"]["normal_force"]
    rows = sorted(csv.DictReader(open(os.path.join(out, "contact.csv"))),
                  key=lambda r: float(r["x"]))
    a = math.sqrt(4 * P / (math.pi / (1 - 0.3 ** 2)))
    p0 = 2 * P / (math.pi * a)
    xs = [float(r["x"]) / a for r in rows if abs(float(r["x"])) < 1.5 * a]
    ps = [float(r["pressure"]) / p0 for r in rows if abs(float(r["x"])) < 1.5 * a]
    ax.plot(xs, ps, ["o", "s", "^"][i], ms=4, mfc="none", label=f"{f}")
xh = [-1.5 + 3 * k / 600 for k in range(601)]
ax.plot(xh, [math.sqrt(max(0.0, 1 - x * x)) for x in xh], "k-", lw=1, label="Hertz")
ax.set_xlabel("x / a")
ax.set_ylabel("p / p0")
ax.set_title("V1 Hertz 2D, half disc on a rigid plane (a/R = 0.08, a/h = 16)")
ax.legend()
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(here, "hertz2d-pressure.png"), dpi=110)
print("wrote", os.path.join(here, "hertz2d-pressure.png"))
