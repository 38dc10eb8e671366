#!/usr/bin/env python3
"""Slow-dynamics regularization on a nearly free body (scenes/nearly-free-2d.yaml).

usage: check_slow_dynamics.py CONTACTLAB SCENE WORKDIR

The seed's table (static ~1e6, slow dynamics with a negligible mass ~1e6, with a small mass
~1e1): MUMPS' condition estimate of the static run is compared with
  - a negligible mass (Time Scale 1e6, alpha M / dt^2 ~ 1e-12): the same estimate (1 %) and the
    same solution;
  - a small mass, 'tangent-only' (the seed's prediction-correction with the static residual),
    consistent and lumped: estimate lowered more than 100 times, normal force within 1e-8;
  - the same mass, 'residual-and-tangent' (a slow dynamics): estimate lowered more than 100
    times, normal force within 1e-2 (the inertia force is the price).
A scene with density 0 is refused before solving, with a sentence."""
import os, sys

exe, scene, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402
from contactlab_run import fresh_run  # noqa: E402

checklist = Checklist()
check, failures = checklist.check, checklist.failures


def run(name, *sets):
    return fresh_run(exe, scene, os.path.join(work, name), sets)


slow = ["Algorithm/Regularization=slow-dynamics"]
static, _ = run("static")
check("static run converges", static["converged"])
kappa0, n0 = static["condition_estimate"], static["contact"]["normal_force"]
print(f"     static: condition estimate {kappa0:.3e}, normal force {n0:.10g}")
check("static condition estimate above 1e4 (the nearly free mode)", kappa0 > 1e4)

cases = [
    ("negligible mass", ["Algorithm/slow-dynamics/Time Scale=1e6"], 0.99, 1e-10),
    ("small mass, tangent-only, consistent",
     ["Algorithm/slow-dynamics/Time Scale=3e-3", "Algorithm/slow-dynamics/Inertia=tangent-only"],
     1e-2, 1e-8),
    ("small mass, tangent-only, lumped",
     ["Algorithm/slow-dynamics/Time Scale=3e-3", "Algorithm/slow-dynamics/Inertia=tangent-only",
      "Algorithm/slow-dynamics/Mass=lumped"], 1e-2, 1e-8),
    ("small mass, residual-and-tangent", ["Algorithm/slow-dynamics/Time Scale=3e-3"], 1e-2, 1e-2),
]
for name, sets, ratio, tol in cases:
    s, _ = run(name.replace(" ", "-").replace(",", ""), *(slow + sets))
    kappa, n = s["condition_estimate"], s["contact"]["normal_force"]
    print(f"     {name}: condition estimate {kappa:.3e} ({kappa0 / kappa:.3g}x lower), "
          f"normal force {n:.10g}, {s['iterations']['newton']} Newton iterations")
    check(f"{name}: converged", s["converged"])
    if ratio > 0.5:
        check(f"{name}: condition estimate unchanged (1 %)", abs(kappa / kappa0 - 1) < 0.01)
    else:
        check(f"{name}: condition estimate lowered {1 / ratio:.0f} times", kappa < ratio * kappa0)
    check(f"{name}: normal force within {tol:g} of the static one", abs(n / n0 - 1) < tol)

s, r = run("no-density", *slow, "Materials/upper/linear-elastic/density=0")
check("density 0 refused before solving: " + r.stderr.strip().splitlines()[-1][:120],
      r.returncode != 0 and "density 0" in r.stderr and s is None)

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
