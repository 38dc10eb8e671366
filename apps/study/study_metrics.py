"""Metrics of one run of a study (doc/studies.md): cost from its summary.json, accuracy from
its contact.csv against a reference -- an analytic field registered here by name, or another
run's contact pressure."""
import csv
import json
import math
import os

# Analytic references: name -> (builder, required parameters, what it is). A builder takes the
# reference's parameters and the run's summary and returns (pressure, shear): functions of a
# contact point (a ContactPoint), or None for a field it does not give. The Hertz-type fields
# are scaled to the loads the run actually carried (P, Q), as in the verification scripts.


class ContactPoint:
    __slots__ = ("x", "pressure", "gap", "shear", "status")

    def __init__(self, x, pressure, gap, shear, status):
        self.x, self.pressure, self.gap, self.shear, self.status = x, pressure, gap, shear, status


def _e_star(prm):
    return prm["E Star"] if "E Star" in prm else prm["E"] / (1 - prm["nu"] ** 2)


def _loads(summary):
    c = summary.get("contact") or {}
    return abs(c.get("normal_force") or 0.0), abs((c.get("tangential_force_vector") or [0])[0])


def _hertz_2d_profile(prm, force):
    a = math.sqrt(4 * force * prm["Radius"] / (math.pi * _e_star(prm)))
    p0 = 2 * force / (math.pi * a) if a > 0 else 0.0
    centre = prm.get("Centre", [0.0])[0]
    return a, p0, lambda q: p0 * math.sqrt(max(0.0, 1 - ((q.x[0] - centre) / a) ** 2))


def _hertz_2d(prm, summary):
    """Plane-strain cylinder (per unit thickness): a = sqrt(4 P R / (pi E*)),
    p = 2 P / (pi a) sqrt(1 - (x / a)^2)."""
    return _hertz_2d_profile(prm, _loads(summary)[0])[2], None


def _hertz_3d(prm, summary):
    """Sphere on a rigid plane: a = (3 P R / (4 E*))^(1/3), p = 3 P / (2 pi a^2) sqrt(1 - r^2/a^2)."""
    force = _loads(summary)[0]
    a = (3 * force * prm["Radius"] / (4 * _e_star(prm))) ** (1 / 3)
    c = prm.get("Centre", [0.0, 0.0])
    p0 = 3 * force / (2 * math.pi * a * a) if a > 0 else 0.0
    return (lambda q: p0 * math.sqrt(max(0.0, 1 - ((q.x[0] - c[0]) ** 2 + (q.x[1] - c[1]) ** 2)
                                         / (a * a)))), None


def _cattaneo_mindlin_2d(prm, summary):
    """Hertz 2D pressure, and the Cattaneo-Mindlin shear traction for the run's P and Q:
    c/a = sqrt(1 - Q/(mu P)), q = mu p0 (sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)) in the
    stick zone |x| < c, mu p in the slip zone."""
    force, shear = _loads(summary)
    a, p0, pressure = _hertz_2d_profile(prm, force)
    mu = prm["mu"]
    c = a * math.sqrt(max(0.0, 1 - shear / (mu * force))) if force > 0 else 0.0
    centre = prm.get("Centre", [0.0])[0]

    def q(point):
        x = point.x[0] - centre
        value = mu * pressure(point)
        if abs(x) < c:
            value -= mu * p0 * (c / a) * math.sqrt(1 - (x / c) ** 2)
        return value

    return pressure, q


def _coulomb(prm, summary):
    """The Coulomb threshold at the run's own pressure: |t| = mu p where a point slips, and
    |t| <= mu p where it sticks (its own |t|, or mu p when it exceeds it)."""
    mu = prm["mu"]
    return None, lambda q: mu * q.pressure if q.status == 2 else min(q.shear, mu * q.pressure)


ANALYTIC = {
    "hertz-2d": (_hertz_2d, ["Radius"], "plane-strain Hertz pressure (E Star, or E and nu)"),
    "hertz-3d": (_hertz_3d, ["Radius"], "3D Hertz pressure, sphere on a plane (E Star, or E, nu)"),
    "cattaneo-mindlin-2d": (_cattaneo_mindlin_2d, ["Radius", "mu"],
                            "Hertz 2D pressure and Cattaneo-Mindlin shear traction"),
    "coulomb": (_coulomb, ["mu"], "the Coulomb threshold on the shear traction"),
}


def read_contact(run_dir, zone=None):
    """Paired contact points of the run's last state, as ContactPoint."""
    path = os.path.join(run_dir, "contact.csv")
    if not os.path.exists(path):
        return []
    points = []
    for row in csv.DictReader(open(path)):
        if (zone and row["zone"] != zone) or not row["gap"]:  # empty gap: not paired
            continue
        gap, p = float(row["gap"]), float(row["pressure"])
        t = [float(row[f"traction_{c}"]) for c in "xyz"]
        if math.isfinite(gap) and math.isfinite(p):
            points.append(ContactPoint((float(row["x"]), float(row["y"]), float(row["z"])), p,
                                       gap, math.sqrt(sum(v * v for v in t)),
                                       int(row["status"])))
    return points


def _nearest(points, x):
    return min(points, key=lambda q: sum((q.x[i] - x[i]) ** 2 for i in range(3)))


def field_errors(points, value, reference):
    """Relative L2 (nodal) and max errors of a field (`value` of a point) against `reference`
    (a function of a point). (None, None) when the reference is zero everywhere."""
    ref = [reference(q) for q in points]
    scale_l2 = math.sqrt(sum(r * r for r in ref))
    scale_max = max((abs(r) for r in ref), default=0.0)
    if not points or scale_max <= 0:
        return None, None
    l2 = math.sqrt(sum((value(q) - r) ** 2 for q, r in zip(points, ref))) / scale_l2
    mx = max(abs(value(q) - r) for q, r in zip(points, ref)) / scale_max
    return l2, mx


def references(spec, summary, reference_points):
    """(pressure, shear) reference functions for one run: analytic, or the reference run's
    values at the nearest of its contact points."""
    if spec["Type"] == "analytic":
        return ANALYTIC[spec["Name"]][0](spec, summary)
    if spec["Type"] == "run" and reference_points:
        return (lambda q: _nearest(reference_points, q.x).pressure,
                lambda q: _nearest(reference_points, q.x).shear)
    return None, None


def force_balance(summary):
    """|sum of the external forces| relative to the largest reaction: the support reactions,
    plus the contact resultant when a zone presses on a rigid obstacle (between two bodies
    the contact forces are internal and cancel)."""
    c = summary.get("contact")
    reactions = list((summary.get("reactions") or {}).values())
    if not c or not reactions:
        return None
    total = [0.0] * len(reactions[0])
    zones = (summary.get("formulation") or {}).values()
    if any(z.get("master") == "obstacle" for z in zones):
        total = [c["normal_force_vector"][i] + c["tangential_force_vector"][i]
                 for i in range(len(total))]
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
        "geometric_terms": (summary.get("algorithm") or {}).get("geometric_terms"),
    }


def non_finite_outputs(run_dir):
    """The run's CSV and JSON outputs holding a NaN or an infinity (an empty CSV cell is a
    value that is not defined, e.g. the gap of an unpaired point, not a NaN)."""
    bad = []
    for name in sorted(os.listdir(run_dir)):
        path = os.path.join(run_dir, name)
        if name.endswith(".csv"):
            for row in csv.reader(open(path)):
                if any(cell.strip().lower() in ("nan", "-nan", "inf", "-inf") for cell in row):
                    bad.append(name)
                    break
        elif name.endswith(".json") and name not in ("case.json", "record.json"):
            found = []
            try:
                json.load(open(path), parse_constant=found.append)
            except ValueError:
                found.append("unreadable")
            if found:
                bad.append(name)
    return bad


def load_summary(run_dir):
    try:
        return json.load(open(os.path.join(run_dir, "summary.json")))
    except (OSError, ValueError):
        return None
