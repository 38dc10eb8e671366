#!/usr/bin/env python3
"""Non-uniqueness above the critical friction coefficient, on a continuum (doc/verification.md V6,
issue 6): the inclined strut of scenes/strut-2d.yaml.

usage: check_uniqueness.py CONTACTLAB SCENE WORKDIR

1. `contactlab critical-mu` at mu = 1.0 and 1.5 gives the critical mu of the foot's contact set,
   the same at both (it is a property of the contact set's stiffness, not of mu).
2. Below it (0.8 mu_crit) every route -- three starting points (Contact/floor/Initial Contact:
   interpenetrated, all, none) times three algorithms (generalized Newton, partial Newton, fixed
   point) -- converges to one and the same state.
3. Above it (the scene's mu = 1.0) the routes converge to at least two measurably different
   states, and each of them satisfies the equations, checked here from the written results:
   force balance (contact resultant + support reactions = 0), Signorini (p >= 0, no
   penetration, p = 0 where the gap is open) and Coulomb (|t| <= mu p) at every contact point.
With friction switched off, or with the second solution gone, step 3 fails."""
import csv, json, os, shutil, subprocess, sys

exe, scene, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402

checklist = Checklist()
check, failures = checklist.check, checklist.failures
TOP = 0.05  # the largest prescribed displacement of the strut's top


def run(name, *sets, command="run"):
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    cmd = [exe, command, scene, "--out", out]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    summary = json.load(open(os.path.join(out, "summary.json")))
    rows = []
    if os.path.exists(os.path.join(out, "contact.csv")):
        rows = list(csv.DictReader(open(os.path.join(out, "contact.csv"))))
    return summary, rows, r.stdout


def satisfies_equations(label, mu, s, rows):
    """The converged state checked from its output, independently of the solver's own test."""
    c = s["contact"]
    force = [c["normal_force_vector"][i] + c["tangential_force_vector"][i] for i in range(2)]
    for reaction in s["reactions"].values():
        force = [force[i] + reaction[i] for i in range(2)]
    scale = max(1e-12, max(abs(v) for r in s["reactions"].values() for v in r))
    check(f"{label}: force balance |sum| = {max(map(abs, force)):.2e} (forces ~{scale:.2e})",
          max(map(abs, force)) <= 1e-8 * scale + 1e-14)
    pmax = max([float(r["pressure"]) for r in rows] + [0.0])
    bad = []
    for r in rows:
        if not r["gap"]:  # not paired (beyond the search distance): open
            continue
        p, gap = float(r["pressure"]), float(r["gap"])
        t = (float(r["traction_x"]) ** 2 + float(r["traction_y"]) ** 2) ** 0.5
        if p < 0 or gap < -1e-9 * TOP or (gap > 1e-9 * TOP and p > 1e-9 * pmax) or \
                t > mu * p * (1 + 1e-8) + 1e-12 * max(pmax, 1e-12):
            bad.append(r["node"])
    check(f"{label}: Signorini and Coulomb at every contact point", not bad)


# 1. The critical mu of the contact set, at two values of mu.
crit = {}
for mu in (1.0, 1.5):
    s, _, _ = run(f"critical-mu-{mu}", f"Contact/floor/Friction={mu}", command="critical-mu")
    cm = s["critical_mu"]
    crit[mu] = cm["zones"]["floor"] if cm["computed"] else None
    print(f"mu = {mu}: critical mu {crit[mu]} (adjacent patterns factor {cm['adjacent_factor']}, "
          f"contact set slipping {cm['slipping_factor']}), verdict {cm['verdict']}")
mu_crit = crit[1.0]
check(f"critical mu computed: {mu_crit}", mu_crit is not None and 0.3 < mu_crit < 1.0)
if mu_crit is None:
    sys.exit(1)
check(f"the same critical mu at mu = 1.5: {crit[1.5]}",
      crit[1.5] is not None and abs(crit[1.5] - mu_crit) <= 1e-6 * mu_crit)

routes = [(initial, method) for initial in ("interpenetrated", "all", "none")
          for method in ("generalized-newton", "partial-newton", "fixed-point")]


def run_routes(mu, tag):
    states = []
    for initial, method in routes:
        label = f"mu = {mu:.4g}, {initial}, {method}"
        s, rows, _ = run(f"{tag}-{initial}-{method}", f"Contact/floor/Friction={mu}",
                         f"Contact/floor/Initial Contact={initial}", f"Algorithm/Method={method}")
        if not s["converged"]:
            print(f"     {label}: {s['failure']}")
            continue
        foot = s["probes"]["foot"]["value"]
        states.append((label, s["contact"]["normal_force"], foot, s, rows))
        print(f"     {label}: normal force {s['contact']['normal_force']:.6e}, "
              f"foot at ({foot[0]:.6e}, {foot[1]:.6e})")
    return states


def distance(a, b):
    return max(abs(a[2][0] - b[2][0]), abs(a[2][1] - b[2][1]))


# 2. Below: one answer, whatever the route.
# Closer to mu_crit the slipping pattern's Jacobian nears singularity and the plain Newton
# cycles (stick-slip) from the default start: at 0.9 mu_crit it needs a cycling treatment.
below = run_routes(0.8 * mu_crit, "below")
check(f"below mu_crit: every route converges ({len(below)} of {len(routes)})",
      len(below) == len(routes))
if below:
    spread = max(distance(below[0], b) for b in below)
    nspread = max(abs(b[1] - below[0][1]) for b in below)
    check(f"below mu_crit: one state (foot positions within {spread:.1e}, normal forces within "
          f"{nspread:.1e})", spread <= 1e-8 * TOP and nspread <= 1e-10)

# 3. Above: at least two different answers, each a solution.
mu_above = 1.0
above = run_routes(mu_above, "above")
distinct = []
for state in above:
    if all(distance(state, d) > 1e-3 * TOP for d in distinct):
        distinct.append(state)
check(f"above mu_crit (mu = {mu_above}): {len(distinct)} measurably different converged states "
      "(foot positions apart by more than 1e-3 of the load)", len(distinct) >= 2)
forces = sorted(d[1] for d in distinct)
if len(distinct) >= 2:
    check(f"above mu_crit: their normal forces differ ({forces[0]:.3e} .. {forces[-1]:.3e})",
          forces[-1] - forces[0] > 0.1 * forces[-1])
for label, _, _, s, rows in distinct:
    satisfies_equations(label, mu_above, s, rows)
sys.exit(1 if failures else 0)
