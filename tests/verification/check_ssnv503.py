#!/usr/bin/env python3
"""code_aster SSNV503 (scenes/ssnv503-2d.yaml): a skate 2 mm above a rigid plane, pressed by
Pn = 300 MPa and pushed by Pt, held by soft springs, under each algorithm preset and the other
formulations, for the test's three loads.

usage: check_ssnv503.py CONTACTLAB SCENE WORKDIR

References (V6.04.503, the skate's deformation neglected): Pt = 0: the contact carries the whole
pressure (N = 12 000 N) and A and B move the 2 mm of the gap; Pt = 178.2 MPa (0.99 mu N): the
skate sticks, A and B do not slide (code_aster's modelling B: 0.031 mm at A within its 2.7 %
of 1 mm, 0.006 at B); Pt = 181.8 MPa (1.01 mu N): every point slips, T = mu N, and the skate
slides until the springs (4 N/mm along the plane) carry T - mu N = 36 N: 9 mm at A and B, to 1 %
(code_aster's precision). Every run also balances exactly: the contact's and the springs' forces
sum to the applied ones (to 1e-9). Each run must converge: a load-controlled body whose first
iterate is thrown through the plane (the gap is open, the springs soft) failed under the fixed
point (Newton stalled at the round-off of that iterate) and generalized Newton (its geometric
columns were 1e-4 off there) before."""
import csv, json, os, sys

exe, scene, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402
from contactlab_run import outcome, required_summary  # noqa: E402

checklist = Checklist()
check = checklist.check
MU, PN, LX, LY, GAP = 0.3, 300.0, 40.0, 20.0, 2.0
FORMULATION = "Contact/skate/Formulation/Type="
runs = [(f"{method}-{pt:g}", pt, [f"Algorithm/Method={method}"])
        for method in ("fixed-point", "partial-newton", "generalized-newton")
        for pt in (0.0, 178.2, 181.8)]
# Penalty with the test's coefficients (E_N = 1e7, E_T = 1e5 N/mm^3; penalty has no automatic one).
PENALTY = [FORMULATION + "penalty", "Contact/skate/Formulation/penalty/Normal Penalty=1e7",
           "Contact/skate/Formulation/penalty/Tangential Penalty=1e5"]
runs += [(f"{f}-{pt:g}", pt, sets) for f, sets in (("lagrange", [FORMULATION + "lagrange"]),
                                                   ("penalty", PENALTY)) for pt in (178.2, 181.8)]
for name, pt, sets in runs:
    out = os.path.join(work, name)
    summary = required_summary(exe, scene, out,
                               ["Output/VTK=false", f"Loads/tangential/Value={pt:g}", *sets], name)
    if not check(outcome(name, summary), summary["converged"]):
        continue
    c, springs = summary["contact"], summary["springs"]
    n, t = c["normal_force"], c["tangential_force_vector"][0]
    held_y = sum(f[1] for s, f in springs.items() if s.startswith("top"))
    held_x = sum(f[0] for s, f in springs.items() if s.startswith("lateral"))
    check(f"{name}: N + springs = {n + held_y:.6f} = Pn Lx", abs(n + held_y - PN * LX) <= 1e-9 * PN * LX)
    check(f"{name}: T + springs = {t + held_x:.6f} = -Pt Ly",
          abs(t + held_x + pt * LY) <= 1e-9 * PN * LX)
    rows = list(csv.DictReader(open(os.path.join(out, "contact.csv"))))
    corners = {p["reference_x"]: p for p in rows if float(p["reference_x"]) in (0.0, LX)}
    ux = [float(p["x"]) - float(p["reference_x"]) for p in corners.values()]
    uy = [float(p["y"]) - float(p["reference_y"]) for p in corners.values()]
    check(f"{name}: A and B move the gap across the plane (u_y {min(uy):.4f}, {max(uy):.4f})",
          all(abs(u + GAP) <= 0.01 * GAP for u in uy))
    statuses = [p["status"] for p in rows]
    if pt == 0.0:
        check(f"{name}: no friction force ({t:.2e})", abs(t) <= 1e-6 * n)
    elif pt < MU * PN * LX / LY:
        check(f"{name}: A and B stick (u_x {min(ux):.4f}, {max(ux):.4f} mm, within 0.04)",
              all(abs(u) <= 0.04 for u in ux))
        check(f"{name}: some points stick ({statuses.count('1')})", "1" in statuses)
    else:
        check(f"{name}: every point slips", all(s == "2" for s in statuses))
        check(f"{name}: T = -mu N ({t / n:.8f})", abs(t / n + MU) <= 1e-6)
        check(f"{name}: A and B slide 9 mm to 1 % (u_x {min(ux):.4f}, {max(ux):.4f})",
              all(abs(u - 9.0) <= 0.09 for u in ux))
sys.exit(1 if checklist.failures else 0)
