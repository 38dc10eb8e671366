#!/usr/bin/env python3
"""NAFEMS contact patch test CGS-4 (scenes/nafems-cgs4-2d.yaml, nafems-cgs4-3d.yaml): a block
pressed by G and pushed up a frictional incline (slope tan(alpha) = 0.1, mu = 0.3) on a
non-matching mesh, under each algorithm preset, both discretizations, every formulation, in 2D
and 3D.

usage: check_nafems_cgs4.py CONTACTLAB SCENES_DIR WORKDIR

Reference: once the block slides, its equilibrium (the push F along x, the load G, the
incline's normal force N and the friction mu N down the slope) gives
F / G = (tan(alpha) + mu) / (1 - mu tan(alpha)) = 0.412371, and pushed down the slope
(mu - tan(alpha)) / (1 + mu tan(alpha)) = 0.194175. The formula is for a rigid incline; the test's
base (E = 1100) flattens under the block by p (dh/dx) / E = 10 x 0.1 / 1100 = 9.1e-4 of slope
(the base is thicker where the incline is higher), so contactlab's F / G ends 0.25 % (node to
segment) and 0.42 % (mortar) below it, a deviation that grows with the load from 0 (at every
step, at most 0.5 % of the load's fraction t), and that vanishes with a stiff base
(E = 1.1e7: 0.412371 to 1e-5). FrontISTR's models of the test end 0.05 % below. With the
longer incline as slave, the closed points must lie under the block: its nodes beyond the
block's ends face no master.
Every run also balances (the base's reaction against the push and G), every contact point
slips with |T| = mu N, and F / G is the formula's value at the slope of the contact's own
resultant (the friction acts along the interface the normal force says). And the uniqueness
diagnostic against the same equilibrium: a rigid block wedges at mu = 1 / tan(alpha) = 10, where
F / G grows without bound; contactlab critical-mu on a stiff block (mortar) finds 10.0009."""
import csv, json, os, sys

exe, scenes, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402
from contactlab_run import contactlab_run, outcome, required_summary  # noqa: E402

checklist = Checklist()
check = checklist.check
MU, TAN, G = 0.3, 0.1, 40.0
UP = (TAN + MU) / (1 - MU * TAN)
DOWN = (MU - TAN) / (1 + MU * TAN)
MORTAR = "Contact/incline/Discretization=mortar"
STIFF_BASE = "Materials/base/linear-elastic/E=1.1e7"
FORMULATION = "Contact/incline/Formulation/Type="
PENALTY = [FORMULATION + "penalty", "Contact/incline/Formulation/penalty/Normal Penalty=1e5",
           "Contact/incline/Formulation/penalty/Tangential Penalty=1e5"]

# (name, scene, sets, reference ratio, bound on the relative deviation below it)
runs = [(f"{method}{'-mortar' if m else ''}", "2d", [f"Algorithm/Method={method}"] + m, UP, 5e-3)
        for method in ("fixed-point", "partial-newton", "generalized-newton")
        for m in ([], [MORTAR])]
runs += [(name, "2d", sets, UP, 5e-3) for name, sets in (
    ("lagrange", [FORMULATION + "lagrange"]), ("penalty", PENALTY),
    ("normal-field", [FORMULATION + "normal-field-augmented-lagrangian"]))]
runs += [("3d", "3d", [], UP, 5e-3), ("3d-mortar", "3d", [MORTAR], UP, 5e-3),
         ("stiff-base", "2d", [STIFF_BASE], UP, 1e-5),
         ("stiff-base-mortar", "2d", [STIFF_BASE, MORTAR], UP, 1e-5),
         ("stiff-base-down", "2d", [STIFF_BASE, "Dirichlet/push/Value=-0.2"], -DOWN, 1e-5)]
# The longer incline as slave: its nodes beyond the block's ends face no master (they were closed
# against the block bottom's extension, and Newton took 274 / 420 / 679 iterations).
INCLINE_SLAVE = ["Contact/incline/Slave=incline", "Contact/incline/Master=block-bottom"]
runs += [(f"incline-slave-{method}", "2d", INCLINE_SLAVE + [f"Algorithm/Method={method}"], UP, 5e-3)
         for method in ("fixed-point", "partial-newton", "generalized-newton")]

for name, dim, sets, ratio, bound in runs:
    out = os.path.join(work, name)
    summary = required_summary(exe, os.path.join(scenes, f"nafems-cgs4-{dim}.yaml"), out,
                               ["Output/VTK=false", *sets], name)
    if not check(outcome(name, summary), summary["converged"]):
        continue
    c, reactions = summary["contact"], summary["reactions"]
    f, base = reactions["push"][0], reactions["base"]
    # y is balanced to round-off (the load is G); x to the Newton tolerance (the push's
    # reaction is the residual at the pushed nodes, 4e-8 of G here).
    check(f"{name}: the base carries the push and G ({base[0]:.9f}, {base[1]:.9f})",
          abs(base[0] + f) <= 1e-6 and abs(base[1] - G) <= 1e-9 * G)
    closed = c["contact_points_closed"]
    if name.startswith("incline-slave"):
        # The block's bottom spans x in [1.2, ~5.2] after the push (its left side moved 0.2).
        rows = list(csv.DictReader(open(os.path.join(out, "contact.csv"))))
        xs = [float(p["x"]) for p in rows if p["status"] != "0"]
        check(f"{name}: the {len(xs)} closed incline nodes lie under the block "
              f"(x in [{min(xs):.4f}, {max(xs):.4f}])", 1.2 - 1e-9 <= min(xs) and max(xs) <= 5.25)
    check(f"{name}: all {closed} closed points slip ({c['stick_points']} stick)",
          closed > 0 and c["slip_points"] == closed)
    t = sum(x * x for x in c["tangential_force_vector"]) ** 0.5
    check(f"{name}: |T| = mu N ({t / c['normal_force']:.7f})", abs(t / c["normal_force"] - MU) <= 2e-5)
    # The formula at the resultant's own slope s (the incline as deformed), signed as F.
    n = c["normal_force_vector"]
    s = -n[0] / n[1]
    at_slope = (s + MU) / (1 - MU * s) if ratio > 0 else -(MU - s) / (1 + MU * s)
    check(f"{name}: F / G = {f / G:.7f} = the formula at the contact's slope {s:.6f} "
          f"({at_slope:.7f})", abs(f / G - at_slope) <= 2e-5 * abs(at_slope))
    deviation = (f / G) / ratio - 1
    check(f"{name}: F / G = {f / G:.7f} against {ratio:.7f} ({deviation:+.2e}, within "
          f"-{bound:g}, never above)", -bound <= deviation <= 1e-6)
    if bound > 1e-5:
        # Along the ramp the deviation grows with the load from zero: at most 0.5 % of t.
        steps = list(csv.DictReader(open(os.path.join(out, "steps.csv"))))
        worst = max(abs(-float(s["contact_force_x"]) / float(s["contact_force_y"]) / ratio - 1)
                    / float(s["time"]) for s in steps)
        check(f"{name}: at each of {len(steps)} steps F / G within {worst:.2e} t of the "
              f"rigid incline's", worst <= bound)
# The uniqueness diagnostic (contactlab critical-mu) against the same equilibrium: a rigid block
# sliding up the incline needs F = G (tan a + mu) / (1 - mu tan a), which grows without bound as
# mu -> 1 / tan a = 10, where the slipping contact set's tangent turns singular (the block wedges).
# A stiff block (E = 1.1e7) by mortar (its normals the block's own): mu_crit = 10.0009.
out = os.path.join(work, "critical-mu-stiff-block")
_, r = contactlab_run(exe, os.path.join(scenes, "nafems-cgs4-2d.yaml"), out,
                      ["Output/VTK=false", "Materials/block/linear-elastic/E=1.1e7", MORTAR],
                      options=["--quiet"], command="critical-mu")
summary = json.load(open(os.path.join(out, "summary.json"))) if r.returncode == 0 else {}
mu_crit = summary.get("critical_mu", {}).get("zones", {}).get("incline", float("nan"))
check(f"critical-mu, stiff block: mu_crit = {mu_crit:.5g} against 1 / tan(alpha) = "
      f"{1 / TAN:g} (within 1 %)", abs(mu_crit * TAN - 1) <= 0.01)
sys.exit(1 if checklist.failures else 0)
