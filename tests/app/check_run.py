#!/usr/bin/env python3
"""Runs a scene with the contactlab command and checks the results contract (doc/scenes.md "The output folder"):
result.pvd and its pieces readable by VTK (a rest frame at t = 0, then one per converged step),
steps.csv, summary.json with probes, contact.csv's points named by the VTK field node_id.

usage: check_run.py CONTACTLAB SCENE OUTDIR RANKS [--set key/path=value ...]
                    [--without-scene-expectations] [key=expected ...]
A scene file states its own expectations in lines "# expect: key=value@tol ..."; a variant
whose --set changes the physics drops them (--without-scene-expectations) and states its own.
An expectation `probes.tip.value.1=-0.0123@1e-3` compares a summary.json value (dotted path,
list indices allowed) with a relative tolerance; `@a1e-9` makes it absolute. A key `A/B` compares
the ratio of two values (e.g. a friction force over the normal force), `A+B` their sum (e.g. a
contact force and a spring force whose sum the load fixes)."""
import csv, json, os, shutil, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import contactlab_run, read_grid, result_frames  # noqa: E402

exe, scene, out, ranks = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
sets, expectations, scene_expectations = [], [], True
args = iter(sys.argv[5:])
for arg in args:
    if arg == "--set":
        sets.append(next(args))
    elif arg == "--without-scene-expectations":
        scene_expectations = False
    else:
        expectations.append(arg)
shutil.rmtree(out, ignore_errors=True)
cmd, run = contactlab_run(exe, scene if scene != "-" else None, out, sets, ranks, timeout=600)
print(run.stdout, run.stderr)
assert run.returncode == 0, f"exit code {run.returncode}"
assert "summary.json" in run.stdout and "result.pvd" in run.stdout

summary = json.load(open(os.path.join(out, "summary.json")))
assert summary["converged"] is True and summary["failure"] is None
assert summary["ranks"] == ranks
assert summary["dofs"] > 0 and summary["linear_solves"] >= 1

rows = list(csv.DictReader(open(os.path.join(out, "steps.csv"))))
# One row per converged step: a step cut in two (Load Steps/Max Cuts) adds rows.
steps = summary["load_steps"]
assert len(rows) == steps["converged"] >= steps["requested"], (steps, len(rows))
assert steps["cuts"] > 0 or len(rows) == steps["requested"], steps
assert float(rows[-1]["time"]) > 0



def values(array):
    return [array.GetComponent(i, c) for i in range(array.GetNumberOfTuples())
            for c in range(array.GetNumberOfComponents())]


# The series: the rest frame at t = 0, then one frame per converged step at its time.
frames = result_frames(out)
times = [t for t, _ in frames]
want = [0.0] + [float(row["time"]) for row in rows]
assert len(times) == len(want) and times[0] == 0.0 and all(
    abs(a - b) <= 1e-12 * max(1.0, abs(b)) for a, b in zip(times, want)), (times, want)
grid = read_grid(frames[-1][1])
rest = read_grid(frames[0][1])
assert grid.GetNumberOfCells() == summary["elements"], (grid.GetNumberOfCells(), summary["elements"])
for name in ["displacement", "node_id"]:
    assert grid.GetPointData().GetArray(name) is not None, name
# The rest frame has the fields of a step's, at rest: no displacement, no contact (all free).
point_fields = {grid.GetPointData().GetArrayName(i) for i in range(grid.GetPointData().GetNumberOfArrays())}
assert point_fields == {rest.GetPointData().GetArrayName(i)
                        for i in range(rest.GetPointData().GetNumberOfArrays())}, point_fields
assert rest.GetNumberOfCells() == grid.GetNumberOfCells()
for name in point_fields - {"node_id"}:
    assert not any(values(rest.GetPointData().GetArray(name))), f"rest frame: {name} is not zero"
assert values(rest.GetPointData().GetArray("node_id")) == values(grid.GetPointData().GetArray("node_id"))
for name in ["stress", "von_mises", "material", "rank"]:
    assert grid.GetCellData().GetArray(name) is not None, name
if summary.get("contact"):  # contact scenes: point data and contact.csv (doc/scenes.md "The output folder")
    for name in ["contact_pressure", "tangential_traction", "gap", "slip", "contact_status",
                 "cycling"]:
        assert grid.GetPointData().GetArray(name) is not None, name
    points = list(csv.DictReader(open(os.path.join(out, "contact.csv"))))
    assert len(points) == summary["contact_points"], (len(points), summary["contact_points"])
    status = grid.GetPointData().GetArray("contact_status")
    closed_vtk = sum(1 for i in range(status.GetNumberOfTuples()) if status.GetValue(i) > 0)
    assert closed_vtk >= summary["contact"]["contact_points_closed"] > 0, closed_vtk
    # contact_status has one meaning in contact.csv and summary.json: 1 stick, 2 slip, 3 closed
    # without friction.
    tally = {s: sum(1 for p in points if int(p["status"]) == s) for s in (1, 2, 3)}
    counts = {1: "stick_points", 2: "slip_points", 3: "closed_frictionless_points"}
    for s, key in counts.items():
        assert tally[s] == summary["contact"][key], (key, tally[s], summary["contact"][key])
    # Each point's node is a VTK point's node_id (the mesh's node id), its reference
    # coordinates that point's, and its current ones those plus the node's displacement.
    displacement = grid.GetPointData().GetArray("displacement")
    node_id = grid.GetPointData().GetArray("node_id")
    nodes = {}  # node id -> (position, displacement): one per piece holding the node
    for i in range(grid.GetNumberOfPoints()):
        u = list(displacement.GetTuple(i)) + [0.0] * (3 - displacement.GetNumberOfComponents())
        nodes.setdefault(int(node_id.GetValue(i)), []).append((grid.GetPoint(i), u))
    for p in points:
        reference = [float(p[f"reference_{c}"]) for c in "xyz"]
        assert int(p["node"]) in nodes, f"contact.csv node {p['node']} is no VTK point's node_id"
        scale = 1 + max(abs(c) for c in reference)
        for x, u in nodes[int(p["node"])]:
            assert all(abs(reference[k] - x[k]) <= 1e-12 * scale for k in range(3)), (p, x)
            assert all(abs(float(p[c]) - reference[k] - u[k]) <= 1e-9 * scale
                       for k, c in enumerate("xyz")), (p, u)
    # The formulation's unknowns: each unknown_<name> column is the VTK point field of that
    # name, point by point (0 in the field where the column is empty).
    for column in [c for c in points[0] if c.startswith("unknown_")] if points else []:
        field = grid.GetPointData().GetArray(column)
        assert field is not None, f"contact.csv has {column}, the VTK output no such field"
        at = {int(node_id.GetValue(i)): field.GetValue(i) for i in range(grid.GetNumberOfPoints())}
        for p in points:
            if int(p["node"]) in at and p[column] != "":
                assert at[int(p["node"])] == float(p[column]), (column, p["node"])
rank_array = grid.GetCellData().GetArray("rank")
ranks_seen = {int(rank_array.GetValue(i)) for i in range(rank_array.GetNumberOfTuples())}
assert ranks_seen == set(range(ranks)), ranks_seen

def lookup(obj, path):
    for part in path.split("."):
        obj = obj[int(part)] if isinstance(obj, list) else obj[part]
    return obj

# Expectations: command-line arguments, plus "# expect: key=value@tol" lines in the scene file.
specs = expectations
if scene != "-" and scene_expectations:
    for line in open(scene):
        if line.startswith("# expect:"):
            specs += line.split(":", 1)[1].split()
assert scene == "-" or specs, "a shipped scene must state at least one expectation"
for spec in specs:
    key, rest = spec.split("=", 1)
    value, tol = (rest.split("@") + ["1e-9"])[:2]
    parts = key.split("/")
    terms = parts[0].split("+")
    got = sum(float(lookup(summary, term)) for term in terms)
    if len(parts) == 2:
        got /= float(lookup(summary, parts[1]))
    want = float(value)
    bound = float(tol[1:]) if tol.startswith("a") else float(tol) * abs(want)
    assert abs(got - want) <= bound, f"{key}: got {got}, want {want} +- {bound}"
    print(f"{key} = {got:.6g} (expected {want:.6g} +- {tol})")
print("ok")
