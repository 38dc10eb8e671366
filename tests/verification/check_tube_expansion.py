#!/usr/bin/env python3
"""The tube expansion in 3D against its axisymmetric model (issue 18: "3D against axisymmetric
within 2 %"): scenes/tube-expansion-3d.yaml, expanded over the tube's whole length (--set, so
that both models carry the same load), a 10-degree sector whose cuts are symmetry planes (one
inclined), against scenes/tube-expansion-axisymmetric.yaml, whose forces are per full ring.
Compares after the release: the residual contact normal force (the sector's times 360 / Angle),
the residual contact pressure along the joint (mean over each model's contact points in the
middle half of the length, away from the free top end) and the tube's residual hoop stress at
mid-wall over the same half (the scenes' Output/Profiles/tube-mid-wall: 3D stress_tt in
cylindrical components, axisymmetric stress_zz). Each relative difference must be below TOL.

usage: check_tube_expansion.py CONTACTLAB SCENE_3D SCENE_AXISYMMETRIC OUTDIR TOL"""
import csv, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import converged_run  # noqa: E402

if len(sys.argv) != 6:
    sys.exit(__doc__)
exe, scene3d, scene_axi, out, tol = sys.argv[1:5] + [float(sys.argv[5])]
THICKNESS, ANGLE = 20.0, 10.0
full_length = ["Mesh/tube-in-tubesheet/Expansion Start=0",
               f"Mesh/tube-in-tubesheet/Expansion End={THICKNESS:g}",
               "Mesh/tube-in-tubesheet/Axial Divisions=[0,16,0]"]
s3 = converged_run(exe, scene3d, os.path.join(out, "3d"), full_length)
sa = converged_run(exe, scene_axi, os.path.join(out, "axisymmetric"))


def middle_pressure(folder, axial):
    """Mean contact pressure over the points whose axial coordinate is in the middle half."""
    rows = list(csv.DictReader(open(os.path.join(folder, "contact.csv"))))
    values = [float(r["pressure"]) for r in rows
              if 0.25 * THICKNESS <= float(r[axial]) <= 0.75 * THICKNESS]
    return sum(values) / len(values)


def middle_hoop(folder, column):
    """Mean hoop stress of profile_tube-mid-wall.csv over its middle half (axial s)."""
    rows = list(csv.DictReader(open(os.path.join(folder, "profile_tube-mid-wall.csv"))))
    values = [float(r[column]) for r in rows
              if 0.25 * THICKNESS <= float(r["s"]) <= 0.75 * THICKNESS]
    return sum(values) / len(values)


force3d = s3["contact"]["normal_force"] * 360.0 / ANGLE
force_axi = sa["contact"]["normal_force"]
p3d = middle_pressure(os.path.join(out, "3d"), "reference_z")
p_axi = middle_pressure(os.path.join(out, "axisymmetric"), "reference_y")
force_error = abs(force3d / force_axi - 1)
pressure_error = abs(p3d / p_axi - 1)
hoop3d = middle_hoop(os.path.join(out, "3d"), "stress_tt")
hoop_axi = middle_hoop(os.path.join(out, "axisymmetric"), "stress_zz")
hoop_error = abs(hoop3d / hoop_axi - 1)
print(f"RESULT force_3d_ring={force3d:.6g} force_axisymmetric={force_axi:.6g} "
      f"pressure_3d={p3d:.6g} pressure_axisymmetric={p_axi:.6g} "
      f"hoop_3d={hoop3d:.6g} hoop_axisymmetric={hoop_axi:.6g} "
      f"force_difference={force_error:.3e} pressure_difference={pressure_error:.3e} "
      f"hoop_difference={hoop_error:.3e} "
      f"newton_3d={s3['iterations']['newton']} newton_axisymmetric={sa['iterations']['newton']} "
      f"seconds_3d={s3['seconds']['total']:.1f} seconds_axisymmetric={sa['seconds']['total']:.2f}")
if not (force3d > 0 and p3d > 0):
    sys.exit("FAIL: no residual contact after the release")
if not (force_error <= tol and pressure_error <= tol and hoop_error <= tol):
    sys.exit(f"FAIL: 3D and axisymmetric differ by more than {tol}")
print("PASS")
