#!/usr/bin/env python3
"""Runs scenes/prandtl-punch-2d.yaml (a stiff flat punch of width B pressed into a plane-strain
elastic-perfectly-plastic von Mises block, the half x >= 0 modelled) and compares the mean
pressure under the punch, p = 2 F_n / B (F_n the contact's normal force of the half model), with
Prandtl's limit (Prandtl 1920; Hill 1950 for the smooth punch, the same load):

  p_L = (2 + pi) k,   k = sigma_y / sqrt(3)  (von Mises in plane strain)

de Souza Neto, Peric & Owen, Computational Methods for Plasticity (2008), section 7.5, compute
the same strip footing (there by prescribed displacements, without contact).

usage: check_prandtl_punch.py CONTACTLAB SCENE OUTDIR CASE TOL [--size-factor F ...]
                              [--set key=value ...]
CASE:
  limit   on each mesh (Mesh/file/Size Factor, in the order given: coarse to fine) the run
          converges and the peak's error shrinks from each mesh to the next (mesh convergence);
          on the last, the peak of p is within TOL of p_L and p stays within TOL of p_L from
          the step it first comes within TOL to the end (a plateau: the limit reached and held).
  locks   the run converges and p rises on: its last value exceeds (1 + TOL) p_L and it still
          grew over the last quarter of the travel (full integration's volumetric locking: a
          perfectly plastic block that never reaches a limit).
Prints "RESULT ..." lines for doc/verification.md."""
import argparse
import math
import os
import sys

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import converged_steps  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("app"); ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("case", choices=["limit", "locks"])
ap.add_argument("tol", type=float)
ap.add_argument("--width", type=float, default=1.0, help="the punch's width B (the .geo's)")
ap.add_argument("--size-factor", type=float, action="append", default=[])
ap.add_argument("--set", action="append", default=[])
args = ap.parse_args()

scene = yaml.safe_load(open(args.scene))["contactlab"]
sigma_y = float(scene["Materials"]["soil"]["j2-small-strain"]["Yield Stress"])
p_limit = (2.0 + math.pi) * sigma_y / math.sqrt(3.0)


def pressures(out, sets, name):
    """The run's (time, mean pressure / p_L) per converged step."""
    rows = converged_steps(args.app, args.scene, out, sets, name)
    return [(float(r["time"]), 2.0 * float(r["normal_force"]) / args.width / p_limit)
            for r in rows]


failures = []
factors = args.size_factor or [None]
peak_errors = []
for factor in factors:
    sets = list(args.set)
    name = os.path.basename(args.out)
    out = args.out
    if factor is not None:
        sets.append(f"Mesh/file/Size Factor={factor!r}")
        name += f" (size factor {factor:g})"
        out = f"{args.out}-h{factor:g}"
    curve = pressures(out, sets, name)
    ratio = [p for _, p in curve]
    print("  p / p_L:", " ".join(f"{t:.3g}:{p:.4f}" for t, p in curve))
    if args.case == "locks":
        last, quarter = ratio[-1], ratio[len(ratio) * 3 // 4]
        print(f"RESULT {name}: p / p_L = {last:.4f} at the end, {quarter:.4f} at 3/4 of the travel")
        if last <= 1.0 + args.tol:
            failures.append(f"{name}: p / p_L = {last:.4f} at the end, not above {1 + args.tol:g}")
        if last <= quarter:
            failures.append(f"{name}: p no longer rises ({quarter:.4f} -> {last:.4f})")
        continue
    peak = max(ratio)
    peak_errors.append(peak - 1.0)
    first = next((i for i, p in enumerate(ratio) if abs(p - 1.0) <= args.tol), None)
    held = first is not None and all(abs(p - 1.0) <= args.tol for p in ratio[first:])
    reached = f"t = {curve[first][0]:.3g}" if first is not None else "never"
    print(f"RESULT {name}: peak p / p_L = {peak:.4f} (error {100 * (peak - 1):+.2f} %), "
          f"end {ratio[-1]:.4f}, within {args.tol:g} from {reached}")
    if factor != factors[-1]:
        continue  # a coarser mesh: only its error's place in the sequence is checked
    if abs(peak - 1.0) > args.tol:
        failures.append(f"{name}: peak p / p_L = {peak:.4f}, not within {args.tol:g}")
    if not held:
        failures.append(f"{name}: p does not stay within {args.tol:g} of p_L to the end")
for coarse, fine in zip(peak_errors, peak_errors[1:]):
    if abs(fine) >= abs(coarse):
        failures.append(f"the peak's error does not shrink under refinement: {peak_errors}")
        break

if failures:
    sys.exit("FAIL: " + "; ".join(failures))
print("PASS")
