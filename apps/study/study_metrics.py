"""Metrics of one run of a study (doc/studies.md): cost from its summary.json, accuracy from
its contact.csv against a reference -- an analytic field registered here by name, or another
run's contact pressure."""
import csv
import json
import math
import os

# Contact pressure references: name -> function(point, parameters, normal_force) -> pressure.
# `point` is (x, y, z) of a contact node; normal_force the run's own resultant (the analytic
# fields are scaled to the load the run actually carried, as in the verification scripts).


def _hertz_2d(point, prm, force):
    """Plane-strain cylinder (per unit thickness): a = sqrt(4 P R / (pi E*)),
    p = 2 P / (pi a) sqrt(1 - (x / a)^2)."""
    e_star = prm["E"] / (1 - prm["nu"] ** 2)
    a = math.sqrt(4 * force * prm["Radius"] / (math.pi * e_star))
    x = point[0] - prm.get("Centre", [0.0])[0]
    return 2 * force / (math.pi * a) * math.sqrt(max(0.0, 1 - (x / a) ** 2))


def _hertz_3d(point, prm, force):
    """Sphere on a rigid plane: a = (3 P R / (4 E*))^(1/3), p = 3 P / (2 pi a^2) sqrt(1 - r^2/a^2)."""
    e_star = prm["E"] / (1 - prm["nu"] ** 2)
    a = (3 * force * prm["Radius"] / (4 * e_star)) ** (1 / 3)
    c = prm.get("Centre", [0.0, 0.0])
    r2 = (point[0] - c[0]) ** 2 + (point[1] - c[1]) ** 2
    return 3 * force / (2 * math.pi * a * a) * math.sqrt(max(0.0, 1 - r2 / (a * a)))


ANALYTIC = {
    "hertz-2d": (_hertz_2d, ["Radius", "E", "nu"], "plane-strain Hertz pressure"),
    "hertz-3d": (_hertz_3d, ["Radius", "E", "nu"], "3D Hertz pressure (sphere on a plane)"),
}


def read_contact(run_dir, zone=None):
    """Contact points of the run's last state with a finite gap: [(x, y, z, pressure, gap)]."""
    path = os.path.join(run_dir, "contact.csv")
    if not os.path.exists(path):
        return []
    points = []
    for row in csv.DictReader(open(path)):
        if zone and row["zone"] != zone:
            continue
        gap, p = float(row["gap"]), float(row["pressure"])
        if math.isfinite(gap) and math.isfinite(p):
            points.append((float(row["x"]), float(row["y"]), float(row["z"]), p, gap))
    return points


def _nearest(points, x):
    return min(points, key=lambda q: (q[0] - x[0]) ** 2 + (q[1] - x[1]) ** 2 + (q[2] - x[2]) ** 2)


def pressure_errors(points, reference):
    """Relative L2 (nodal) and max errors of the contact pressure against `reference`, a
    function of a point. None when no point carries pressure in the reference."""
    ref = [reference(q[:3]) for q in points]
    scale_l2 = math.sqrt(sum(r * r for r in ref))
    scale_max = max(ref, default=0.0)
    if not points or scale_max <= 0:
        return None, None
    l2 = math.sqrt(sum((q[3] - r) ** 2 for q, r in zip(points, ref))) / scale_l2
    mx = max(abs(q[3] - r) for q, r in zip(points, ref)) / scale_max
    return l2, mx


def reference_function(spec, run_dir, summary, reference_points):
    """The pressure reference for one run: analytic (scaled to the run's normal force) or the
    reference run's pressure at the nearest of its contact points."""
    if spec["Type"] == "analytic":
        fn = ANALYTIC[spec["Name"]][0]
        force = abs((summary.get("contact") or {}).get("normal_force") or 0.0)
        return lambda x: fn(x, spec, force)
    if spec["Type"] == "run" and reference_points:
        return lambda x: _nearest(reference_points, x)[3]
    return None


def force_balance(summary):
    """|contact resultant + support reactions| relative to the largest reaction."""
    c = summary.get("contact")
    reactions = list((summary.get("reactions") or {}).values())
    if not c or not reactions:
        return None
    total = [c["normal_force_vector"][i] + c["tangential_force_vector"][i]
             for i in range(len(c["normal_force_vector"]))]
    for r in reactions:
        total = [total[i] + r[i] for i in range(len(total))]
    scale = max(abs(v) for r in reactions for v in r)
    return max(abs(v) for v in total) / scale if scale > 0 else None


def probe_error(summary, reference_summary):
    """Largest difference of the probes' values against the reference run, relative to the
    largest reference value (the displacement error where the scene's probes are)."""
    if not reference_summary:
        return None
    mine, ref = summary.get("probes") or {}, reference_summary.get("probes") or {}
    diffs, scale = [], 0.0
    for name, p in ref.items():
        if name not in mine:
            continue
        a, b = mine[name]["value"], p["value"]
        a, b = (a if isinstance(a, list) else [a]), (b if isinstance(b, list) else [b])
        diffs += [abs(u - v) for u, v in zip(a, b)]
        scale = max([scale] + [abs(v) for v in b])
    if not diffs or scale <= 0:
        return None
    return max(diffs) / scale


def cost_metrics(summary):
    it = summary.get("iterations") or {}
    sec = summary.get("seconds") or {}
    unknowns = summary.get("unknowns") or {}
    return {
        "newton": it.get("newton"), "status_its": it.get("status"),
        "threshold_its": it.get("threshold"), "geometry_its": it.get("geometry"),
        "linear_solves": summary.get("linear_solves"),
        "cycling_events": sum((summary.get("cycling") or {}).values()),
        "steps": (summary.get("load_steps") or {}).get("converged"),
        "cuts": (summary.get("load_steps") or {}).get("cuts"),
        "assembly_s": sec.get("assembly"), "contact_s": sec.get("contact"),
        "linear_solve_s": sec.get("linear_solve"), "solver_total_s": sec.get("total"),
        "peak_memory_mb": summary.get("peak_memory_mb"),
        "unknowns_displacement": unknowns.get("displacement"),
        "unknowns_contact": unknowns.get("contact_multipliers"),
        "unknowns_friction": unknowns.get("friction_multipliers"),
    }


def load_summary(run_dir):
    try:
        return json.load(open(os.path.join(run_dir, "summary.json")))
    except (OSError, ValueError):
        return None
