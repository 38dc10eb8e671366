#!/usr/bin/env python3
"""Mindlin-Deresiewicz: a partial-slip contact under a tangential load cycled +Q*, -Q*, +Q*
(scenes/cattaneo-mindlin-2d-cycle.yaml: two similar elastic discs, mu = 0.3, the shift ramped to
Q*/(mu P) = 0.64 at t = 1, back to -Q* at t = 2, to +Q* again at t = 3).

usage: check_mindlin_cycle.py CONTACTLAB SCENE WORKDIR

Reference (Johnson, Contact Mechanics, 1985, section 7.4, the line contact's form of Mindlin and
Deresiewicz's solution): loading to Q* gives Cattaneo-Mindlin's state q*(x), stick zone
c = a sqrt(1 - Q*/(mu P)). Unloading from Q* to Q, the contact sticks again and slips back from
its edges: the traction is q*(x) - 2 mu p0 [sqrt(1 - x^2/a^2) - (c'/a) sqrt(1 - x^2/c'^2)]
(the last term for |x| < c'), with the reverse-stick zone c' = a sqrt(1 - (Q* - Q)/(2 mu P));
the reverse-slip annulus c' < |x| < a carries -mu p. At Q = -Q*, c' = c and the state is -q*;
reloading to +Q* returns exactly to q* (the loop closes: the contact remembers only the last
turning point). Checked on the run to t = 1.5 (Q ~ 0), 2 and 3 against the run to t = 1, under
partial Newton; the fixed point and generalized Newton must close the loop too."""
import csv, math, os, sys

exe, scene, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402
from contact_references import hertz, node_spacing, partial_slip_traction  # noqa: E402
from contactlab_run import outcome, required_summary  # noqa: E402

checklist = Checklist()
check = checklist.check
MU, ESTAR, RADIUS = 0.3, 0.5 / (1 - 0.3 ** 2), 0.5   # two discs R = 1, E = 1, nu = 0.3
STEPS_PER_TIME = 8
STICK_TOL = 2.0       # node spacings, as the monotonic case (verification.cattaneo-mindlin)
TRACTION_TOL = 0.1    # mu p0, in the stick zone (|x| <= 0.9 c); the monotonic case at Q*/(mu P) = 0.4: 0.05


def run(end_time, method):
    name = f"{method}-t{end_time:g}"
    summary = required_summary(exe, scene, os.path.join(work, name),
                               ["Output/VTK=false", f"Algorithm/Method={method}",
                                f"Load Steps/End Time={end_time:g}",
                                f"Load Steps/Steps={round(end_time * STEPS_PER_TIME)}"], name)
    if not check(outcome(name, summary), summary["converged"]):
        return None
    rows = list(csv.DictReader(open(os.path.join(work, name, "contact.csv"))))
    c = summary["contact"]
    return dict(P=c["normal_force"], Q=c["tangential_force_vector"][0],
                rows={r["node"]: r for r in rows if int(r["status"]) != 0})


def stick_half_width(state, status=1):
    xs = [float(r["x"]) for r in state["rows"].values() if int(r["status"]) == status]
    return (max(xs) - min(xs)) / 2 if xs else 0.0


def profile_error(state, reference, width, along):
    """max |t - reference(x)| / (mu p0) over |x| <= width, t the traction along `along`."""
    return max(abs(float(r["traction_x"]) * along / (MU * p0) - reference(float(r["x"])))
               for r in state["rows"].values() if abs(float(r["x"])) <= width)


def sqrt_profile(x, b):
    return math.sqrt(1 - (x / b) ** 2) if abs(x) < b else 0.0


def same_state(name, state, ref, tol):
    common = state["rows"].keys() & ref["rows"].keys()
    dt = max(abs(float(state["rows"][k]["traction_x"]) - float(ref["rows"][k]["traction_x"]))
             for k in common) / (MU * p0)
    dp = max(abs(float(state["rows"][k]["pressure"]) - float(ref["rows"][k]["pressure"]))
             for k in common) / p0
    check(f"{name}: back at +Q*, the state of t = 1: tractions within {dt:.1e} mu p0, "
          f"pressures within {dp:.1e} p0, the same {len(common)} closed points",
          common == ref["rows"].keys() == state["rows"].keys() and dt <= tol and dp <= tol)


loaded = run(1.0, "partial-newton")
if loaded is None:
    sys.exit(1)
P, q_star = loaded["P"], loaded["Q"]
along = math.copysign(1.0, q_star)   # tractions and loads are compared along +Q*
a, p0 = hertz(P, ESTAR, RADIUS, 2)
h = node_spacing(list(loaded["rows"].values()))
ratio = abs(q_star) / (MU * P)
c = a * math.sqrt(1 - ratio)
check(f"t = 1: Q*/(mu P) = {ratio:.4f}, a partial-slip state", 0.5 < ratio < 0.8)
c_fe = stick_half_width(loaded)
check(f"t = 1: stick zone c/a = {c_fe / a:.4f} against {c / a:.4f} ({(c_fe - c) / h:+.2f} h)",
      abs(c_fe - c) <= STICK_TOL * h)
err = profile_error(loaded, lambda x: partial_slip_traction(x, a, c), 0.9 * c, along)
check(f"t = 1: stick-zone traction within {err:.3f} mu p0 of Cattaneo-Mindlin's", err <= TRACTION_TOL)

for end_time in (1.5, 2.0):
    state = run(end_time, "partial-newton")
    if state is None:
        continue
    q = state["Q"] * along
    c_rev = a * math.sqrt(1 - (abs(q_star) - q) / (2 * MU * state["P"]))
    c_fe = stick_half_width(state)
    name = f"t = {end_time:g}, Q/Q* = {q / abs(q_star):+.3f}"
    check(f"{name}: reverse-stick zone c'/a = {c_fe / a:.4f} against {c_rev / a:.4f} "
          f"({(c_fe - c_rev) / h:+.2f} h)", abs(c_fe - c_rev) <= STICK_TOL * h)
    unloaded = lambda x: (partial_slip_traction(x, a, c)  # noqa: E731
                          - 2 * (sqrt_profile(x, a) - c_rev / a * sqrt_profile(x, c_rev)))
    err = profile_error(state, unloaded, 0.9 * c_rev, along)
    check(f"{name}: reverse-stick traction within {err:.3f} mu p0 of Mindlin-Deresiewicz's",
          err <= TRACTION_TOL)
    slipping = [r for r in state["rows"].values() if int(r["status"]) == 2]
    back = max(abs(float(r["traction_x"]) * along + MU * float(r["pressure"])) for r in slipping)
    check(f"{name}: the {len(slipping)} slipping points slip back, t = -mu p within "
          f"{back / (MU * p0):.1e} mu p0", slipping and back <= 1e-4 * MU * p0)

# Partial Newton against its own t = 1 (to 1.4e-6 here); the others against it, within their
# own stopping tests (4e-5 here: the fixed point's thresholds stop at 1e-3 relative).
for method, tol in (("partial-newton", 1e-4), ("fixed-point", 1e-3), ("generalized-newton", 1e-3)):
    state = run(3.0, method)
    if state is not None:
        same_state(f"{method}, t = 3", state, loaded, tol)
sys.exit(1 if checklist.failures else 0)
