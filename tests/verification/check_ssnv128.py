#!/usr/bin/env python3
"""code_aster SSNV128 (scenes/ssnv128-2d.yaml) under contactlab's algorithms and formulations.

usage: check_ssnv128.py CONTACTLAB SCENE WORKDIR [SET ...]   (each SET a --set for every run)

Every run below that converges must converge to the same state, and that state must be a
solution: the tangential displacements of the contact face at A-E within 5 % of code_aster's
reference (the average of other codes, V6.04.128), Coulomb's law at every closed point
(|t| <= mu p), and the stick points where they started (the load is proportional from rest, so a
stick point never slipped). The runs: the defaults (augmented Lagrangian with its automatic r_n
and r_t, partial Newton); generalized Newton; the fixed point (statuses-not-converged before
'combined' forced its contact cycles); Lagrange with its defaults (c_n automatic, E/h);
Lagrange with c_n = 1 (its old default, fourteen decades below this model's E/h: it may stop with
a named failure, not with a wrong state); Lagrange with c_n = E/h, c_t = 2e6 in one step. The last
two converged before to states that are not solutions, which the residual did not see: the
contact rows are lengths and numbers beside forces (ContactLaw.hpp, LawOutput::normalRowForce).
c_n = 1 gave stick points that had slipped up to 3 um (u_x 1.1-5.1 % above the reference at
A-E), c_t = 2e6 a point slipping at 2.4 mu p (its forced cycling status was accepted)."""
import csv, os, sys

exe, scene, work, common = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402
from contactlab_run import outcome, required_summary  # noqa: E402

checklist = Checklist()
check, failures = checklist.check, checklist.failures
REFERENCE = {0.0: 2.86e-5, 0.00125: 2.72e-5, 0.005: 2.28e-5, 0.0075: 1.98e-5, 0.01125: 1.5e-5}
MU = 1.0
LAGRANGE = "Contact/base/Formulation/lagrange/"

# (name, --sets, whether it must converge: Lagrange with c_n = 1 may fail, by name, but must not
# report a state that is not a solution).
runs = [
    ("defaults", [], True),
    ("generalized-newton", ["Algorithm/Method=generalized-newton"], True),
    ("fixed-point", ["Algorithm/Method=fixed-point"], True),
    ("lagrange", ["Contact/base/Formulation/Type=lagrange"], True),
    ("lagrange-cn1", ["Contact/base/Formulation/Type=lagrange",
                      LAGRANGE + "Normal Complementarity Constant=1"], False),
    ("lagrange-ct2e6-one-step", ["Contact/base/Formulation/Type=lagrange",
                                 LAGRANGE + "Normal Complementarity Constant=1.04e14",
                                 LAGRANGE + "Tangential Complementarity Constant=2e6",
                                 "Load Steps/Steps=1"], True),
]
states = {}
for name, sets, must_converge in runs:
    summary = required_summary(exe, scene, os.path.join(work, name),
                               ["Output/VTK=false", *common, *sets], name)
    if not summary["converged"]:
        allowed = " (a named failure is allowed here)" if not must_converge else ""
        check(outcome(name, summary) + allowed, not must_converge and bool(summary["failure"]))
        continue
    check(outcome(name, summary), True)
    rows = list(csv.DictReader(open(os.path.join(work, name, "contact.csv"))))
    ux = {}  # at the reference points (the mesh's nodes there, to round-off)
    for p in rows:
        for x in REFERENCE:
            if abs(float(p["reference_x"]) - x) <= 1e-9:
                ux[x] = float(p["x"]) - float(p["reference_x"])
    for x, ref in REFERENCE.items():
        check(f"{name}: u_x at x = {x * 1000:g} mm {ux[x]:.4e} within 5 % of {ref:g}",
              abs(ux[x] - ref) <= 0.05 * ref)
    scale = max(abs(float(p["slip_x"])) for p in rows)
    worst_coulomb, worst_stick = 0.0, 0.0
    for p in rows:
        pressure, traction = float(p["pressure"]), abs(float(p["traction_x"]))
        if p["status"] in ("1", "2"):
            worst_coulomb = max(worst_coulomb, traction / (MU * pressure) - 1)
        if p["status"] == "1":
            worst_stick = max(worst_stick, abs(float(p["slip_x"])) / scale)
    check(f"{name}: Coulomb |t| <= mu p at every closed point (worst excess {worst_coulomb:.1e})",
          worst_coulomb <= 1e-6)
    check(f"{name}: the stick points never slipped (worst {worst_stick:.1e} of the largest slip)",
          worst_stick <= 1e-6)
    states[name] = ux
# One state, to 1e-6 of u_x: the fixed point stops on its threshold loop's tolerance (1e-12 m
# here), the Newton routes agree to round-off; the wrong states were 1e-7 m and more apart.
names = list(states)
bound = 1e-6 * max(abs(u) for u in states[names[0]].values())
for name in names[1:]:
    gap = max(abs(states[name][x] - states[names[0]][x]) for x in states[names[0]])
    check(f"{name}: the same state as {names[0]} (u_x within {gap:.1e} m, bound {bound:.1e})",
          gap <= bound)
sys.exit(1 if failures else 0)
