#!/usr/bin/env python3
"""The seed's frictional pad (scenes/pad-2d.yaml) under each algorithm and cycling treatment.

usage: check_pad.py CONTACTLAB SCENE WORKDIR MU

Asserts what doc/algorithms.md reports: the generalized and partial Newton without treatment cycle
(a cycling detected: sub-cycling 1, or a contact flip-flop) and stop with 'diverged', "Newton cycles" (a residual that repeats a
two-iterate cycle; before that test, max-iterations). The fixed point cycles too (events counted)
but converges with every treatment and without, from each step's last state (Newton/Extrapolation
none, the seed's algorithm) and from the default extrapolated start: a status update that opens
back the points the last one closed lets the friction thresholds update before Newton restarts
(doc/algorithms.md "Cycling"; the seed's untreated fixed point fails here, and so did this one
with statuses-not-converged until 2026-11-29, also with 'automatic' at mu = 0.45);
'automatic' and 'forced' save the two Newton presets (at mu = 0.45 these end with degraded-contact without the tangent
predictor on the drag steps, doc/algorithms.md "Predictor": their forced state violates the contact
law at two points by far more than the tolerance, Newton from it cycles again, and the run says so
instead of reporting it converged; checked with Newton/Predictor none). Step cutting saves the
untreated generalized Newton, and 'automatic' saves Lagrange's Newton presets too (its cycling
points forced). These runs assess the treatments alone: Newton/Line Search Retry is 'never'.
With the default retry (a failed step solved again by a Backtrack line search before it is
cut), the two Newton presets converge without treatment. Every run that converges ends in the same state
(normal and tangential force within 1e-6)."""
import os, sys

exe, scene, work, mu = sys.argv[1:5]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402
from contactlab_run import required_summary  # noqa: E402

checklist = Checklist()
check, failures = checklist.check, checklist.failures


def run(name, *sets, retry="never"):
    return required_summary(exe, scene, os.path.join(work, name),
                            [f"Contact/floor/Friction={mu}", f"Newton/Line Search Retry={retry}",
                             *sets], name)


converged = {}
for method in ["generalized-newton", "partial-newton", "fixed-point"]:
    for treatment in ["none", "automatic", "forced"]:
        expect_failure = treatment == "none" and method != "fixed-point"
        # The fixed point untreated from each step's last state, the seed's algorithm (from
        # the default extrapolated start: below).
        plain = ["Newton/Extrapolation=none"] if method == "fixed-point" and treatment == "none" else []
        s = run(f"{method}-{treatment}", f"Algorithm/Method={method}",
                f"Algorithm/Cycling Treatment={treatment}", *plain)
        label = f"mu={mu} {method} {treatment}: {s['failure'] or 'converged'} {s['cycling']}"
        if expect_failure:
            check(label + " (expected diverged)", s["failure"] == "diverged")
            check(label + " says Newton cycles", "Newton cycles" in (s["message"] or ""))
            # The kind it meets first follows the path: partial Newton at mu = 0.45 met
            # sub-cycling 1 until the inexact solves between geometry updates, a contact
            # flip-flop since (doc/algorithms.md "Inexact solves between fixed-point updates").
            check(label + " detects cycling", sum(s["cycling"].values()) > 0)
        else:
            if treatment == "forced" and method != "fixed-point" and float(mu) < 1:
                d = run(f"{method}-{treatment}-no-predictor", f"Algorithm/Method={method}",
                        f"Algorithm/Cycling Treatment={treatment}", "Newton/Predictor=none")
                check(f"mu={mu} {method} forced without the predictor: "
                      f"{d['failure'] or 'converged'} (expected degraded-contact)",
                      d["failure"] == "degraded-contact")
            check(label, s["converged"])
            # Which kind the treated run meets first depends on round-off (the BLAS kernels);
            # that it met one is what made the treatment act. The untreated fixed point meets
            # them too: the statuses still flip between its updates before the thresholds move.
            if method != "fixed-point" or treatment == "none":
                check(label + " detects cycling", sum(s["cycling"].values()) > 0)
            if s["converged"]:
                converged[f"{method} {treatment}"] = s
# The fixed point untreated with its default, extrapolated step start (doc/algorithms.md
# "Extrapolated start"): it converged at mu = 1 and cycled at mu = 0.45 until the thresholds
# updated on a status reversal; it converges at both.
s = run("fixed-point-none-extrapolated", "Algorithm/Method=fixed-point",
        "Algorithm/Cycling Treatment=none")
check(f"mu={mu} fixed-point none, extrapolated start: {s['failure'] or 'converged'} "
      f"(expected converged)", s["converged"])
if s["converged"]:
    converged["fixed-point none, extrapolated start"] = s
s = run("generalized-newton-cuts", "Load Steps/Max Cuts=4", "Algorithm/Cycling Treatment=none")
check(f"mu={mu} generalized-newton none with step cutting: {s['failure'] or 'converged'}, "
      f"{s['load_steps']['cuts']} cuts", s["converged"] and s["load_steps"]["cuts"] > 0)
if s["converged"]:
    converged["generalized-newton none, cuts"] = s

# The default line-search retry rescues the untreated Newton presets (the retry solves the step
# that failed with full steps again, from its start).
for method in ["generalized-newton", "partial-newton"]:
    s = run(f"{method}-none-retry", f"Algorithm/Method={method}",
            "Algorithm/Cycling Treatment=none", retry="every-failure")
    check(f"mu={mu} {method} none with the line-search retry: {s['failure'] or 'converged'}, "
          f"{s['load_steps']['line_search_retries']} retries",
          s["converged"] and s["load_steps"]["line_search_retries"] > 0)
    if s["converged"]:
        converged[f"{method} none, line-search retry"] = s

# Lagrange, its constants the scene's augmentations (c_n = 20, c_t = 100): they only pick the
# status, so 'automatic' forces its cycling points instead of scaling them (before, both Newton
# presets cycled to max-iterations at the first drag step, |R| 9e6, where the augmented
# Lagrangian converges).
for method in ["generalized-newton", "partial-newton"]:
    s = run(f"{method}-automatic-lagrange", f"Algorithm/Method={method}",
            "Algorithm/Cycling Treatment=automatic", "Contact/floor/Formulation/Type=lagrange",
            "Contact/floor/Formulation/lagrange/Normal Complementarity Constant=20",
            "Contact/floor/Formulation/lagrange/Tangential Complementarity Constant=100")
    check(f"mu={mu} {method} automatic, lagrange: {s['failure'] or 'converged'} {s['cycling']}",
          s["converged"])
    if s["converged"]:
        converged[f"{method} automatic, lagrange"] = s

reference = converged.get("generalized-newton automatic")
if reference:
    n0 = reference["contact"]["normal_force"]
    t0 = reference["contact"]["tangential_force_vector"][0]
    for label, s in converged.items():
        n, t = s["contact"]["normal_force"], s["contact"]["tangential_force_vector"][0]
        check(f"{label}: N = {n:.9g}, T = {t:.9g} (reference {n0:.9g}, {t0:.9g})",
              abs(n - n0) <= 1e-6 * abs(n0) and abs(t - t0) <= 1e-6 * abs(n0))
sys.exit(1 if failures else 0)
