#!/usr/bin/env python3
"""Runs scenes/sphere-indentation-axisymmetric.yaml (an elastic-perfectly-plastic sphere pressed
by a rigid flat, axisymmetric, frictionless) on several meshes and compares the contact force at
each step with the finite-element fit of Kogut & Etsion, "Elastic-plastic contact analysis of a
sphere and a rigid flat", J. Appl. Mech. 69 (2002) 657-662:

  omega_c = (pi K H / (2 E'))^2 R,  K = 0.454 + 0.41 nu,  H = 2.8 sigma_y,  E' = E / (1 - nu^2)
  P_c = (2/3) pi K H R omega_c
  P / P_c = 1.03 (omega/omega_c)^1.425  (1 <= omega/omega_c <= 6),
            1.40 (omega/omega_c)^1.263  (6 <= omega/omega_c <= 110).

At omega/omega_c = 6, where the two fits differ by 2 %, the nearer one is taken. The force is the
contact's normal force per full ring (steps.csv), the interference the flat's prescribed
displacement at the step's time (a ramp to the scene's travel at its last load time).

usage: check_sphere_indentation.py CONTACTLAB SCENE OUTDIR TOL [--size-factor F ...]
                                   [--set key=value ...]
On every mesh (Mesh/file/Size Factor, coarse to fine) the run converges; on the last, the force at
each step is within TOL of the fit; and the force converges under refinement: the largest change
between the last two meshes (over the steps) is below the largest change between the two before
and below TOL / 4. Prints "RESULT ..." lines for doc/verification.md."""
import argparse
import math
import os
import sys

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import converged_steps  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("app"); ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("tol", type=float)
ap.add_argument("--size-factor", type=float, action="append", default=[])
ap.add_argument("--set", action="append", default=[])
args = ap.parse_args()

scene = yaml.safe_load(open(args.scene))["contactlab"]
material = scene["Materials"]["sphere"]["j2-small-strain"]
E, nu, sigma_y = (float(material[k]) for k in ("E", "nu", "Yield Stress"))
R = 1.0  # the .geo's radius
travel = -float(scene["Dirichlet"]["press"]["Value"])
end_time = float(scene["Load Steps"]["Times"][-1])  # the press reaches `travel` there
K, H, E_eff = 0.454 + 0.41 * nu, 2.8 * sigma_y, E / (1 - nu ** 2)
omega_c = (math.pi * K * H / (2 * E_eff)) ** 2 * R
P_c = 2.0 / 3.0 * math.pi * K * H * R * omega_c


def fit_error(ratio, force):
    """The relative error of `force` against the fit at omega / omega_c = ratio."""
    fits = []
    if ratio <= 6.001:
        fits.append(1.03 * ratio ** 1.425 * P_c)
    if ratio >= 5.999:
        fits.append(1.40 * ratio ** 1.263 * P_c)
    return min((force / f - 1 for f in fits), key=abs)


def forces(out, sets, name):
    """The run's (omega / omega_c, normal force) per converged step."""
    rows = converged_steps(args.app, args.scene, out, sets, name)
    return [(float(r["time"]) / end_time * travel / omega_c, float(r["normal_force"]))
            for r in rows]


failures = []
factors = args.size_factor or [None]
curves = []
for factor in factors:
    sets, name, out = list(args.set), os.path.basename(args.out), args.out
    if factor is not None:
        sets.append(f"Mesh/file/Size Factor={factor!r}")
        name += f" (size factor {factor:g})"
        out = f"{args.out}-h{factor:g}"
    curve = forces(out, sets, name)
    errors = [fit_error(ratio, force) for ratio, force in curve]
    print(f"RESULT {name}: P / fit - 1 at omega/omega_c = " +
          ", ".join(f"{ratio:.3g}: {100 * e:+.1f} %" for (ratio, _), e in zip(curve, errors)))
    curves.append(curve)
    if factor == factors[-1]:
        worst = max(errors, key=abs)
        if abs(worst) > args.tol:
            failures.append(f"{name}: the force is {100 * worst:+.1f} % off the fit "
                            f"(tolerance {100 * args.tol:g} %)")

changes = []
for coarse, fine in zip(curves, curves[1:]):
    if len(coarse) != len(fine):
        sys.exit("FAIL: the meshes' runs have different steps")
    changes.append(max(abs(f / c - 1) for (_, c), (_, f) in zip(coarse, fine)))
if changes:
    print("RESULT the force's largest change from one mesh to the next: " +
          ", ".join(f"{100 * c:.2f} %" for c in changes))
    if changes[-1] > args.tol / 4:
        failures.append(f"the force still changes by {100 * changes[-1]:.2f} % on the finest mesh")
    if len(changes) > 1 and changes[-1] >= changes[-2]:
        failures.append(f"the force's change does not shrink under refinement: {changes}")

if failures:
    sys.exit("FAIL: " + "; ".join(failures))
print("PASS")
