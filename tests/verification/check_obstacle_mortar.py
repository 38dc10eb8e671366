#!/usr/bin/env python3
"""Mortar against a rigid obstacle against node-to-segment on the same scene: both converge, and
their normal and tangential contact resultants agree within TOL_NORMAL and TOL_TANGENTIAL
relative to the normal force. On a curved obstacle this checks that mortar's gap is the
integrated weighted gap, not the gap at the facets' weighted position (doc/verification.md
"Mortar against an obstacle"). The tangential resultant of a coarse mesh is the less converged
(node-to-segment's the more: 7 % above the fine meshes' on obstacle-sphere-3d).

usage: check_obstacle_mortar.py CONTACTLAB SCENE WORKDIR ZONE TOL_NORMAL TOL_TANGENTIAL"""
import os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import required_summary  # noqa: E402

exe, scene, work, zone = sys.argv[1:5]
tolerances = {"normal": float(sys.argv[5]), "tangential": float(sys.argv[6])}
forces = {}
for discretization in ("mortar", "node-to-segment"):
    summary = required_summary(exe, scene, os.path.join(work, discretization),
                               [f"Contact/{zone}/Discretization={discretization}",
                                "Output/VTK=false"], discretization)
    if not summary["converged"]:
        sys.exit(f"FAIL: {discretization} did not converge: {summary['failure']}")
    contact = summary["contact"]
    forces[discretization] = contact
    print(f"{discretization}: {summary['discretization'][zone]}, "
          f"{summary['iterations']['newton']} Newton iterations, normal force "
          f"{contact['normal_force']:.8g}, closed points {contact['contact_points_closed']}")
scale = forces["node-to-segment"]["normal_force"]
failed = []
for kind, tol in tolerances.items():
    mortar, nts = (forces[d][f"{kind}_force_vector"] for d in ("mortar", "node-to-segment"))
    difference = max(abs(a - b) for a, b in zip(mortar, nts)) / scale
    print(f"RESULT obstacle-mortar {kind} difference={difference:.3g} (bound {tol:g})")
    if not difference <= tol:
        failed.append(f"{kind} resultants differ by {difference:.3g} of the normal force "
                      f"(bound {tol:g})")
if failed:
    sys.exit("FAIL: mortar and node-to-segment: " + "; ".join(failed))
