#!/usr/bin/env python3
"""contact.csv names each point by the mesh's own node id (issue 20): on a gmsh mesh whose node
tags are not 1..N nor in the order of the nodes, its node column holds the tags of the slave
group's nodes and reference_x..z those nodes' coordinates in the .msh file, the same on 1 and 2
ranks; the VTK field node_id holds the tags too. The result series starts with a rest frame at
t = 0, and a run that converges no step leaves that frame alone in a valid result.pvd.

The .msh (format 4.1, written here): two stacked blocks, lower [0, 1] x [0, 1] (2 x 2 quad4) and
upper [0, 1] x [1, 1.5] (3 x 1 quad4), pressed together by lowering the top 0.01: the
contact patch test, whose contact force is E * 0.01 / 1.5 per unit width (node-to-segment on these
non-matching meshes misses it by 0.3%).

usage: check_node_ids.py CONTACTLAB WORKDIR"""
import csv, json, os, random, shutil, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from contactlab_run import contactlab_run, read_grid, result_frames  # noqa: E402

exe, work = sys.argv[1:3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)


def grid(x0, y0, width, height, nx, ny):
    """Nodes (row by row) and counter-clockwise quads of a structured block, by local index."""
    nodes = [(x0 + width * i / nx, y0 + height * j / ny) for j in range(ny + 1) for i in range(nx + 1)]
    quads = [(j * (nx + 1) + i, j * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i)
             for j in range(ny) for i in range(nx)]
    return nodes, quads


lower_nodes, lower_quads = grid(0.0, 0.0, 1.0, 1.0, 2, 2)
upper_nodes, upper_quads = grid(0.0, 1.0, 1.0, 0.5, 3, 1)
# Tags: distinct, with gaps, shuffled against the geometry (the mesh's own numbering is by
# increasing tag, so index + 1 is none of them).
tags = random.Random(20).sample(range(5, 900), len(lower_nodes) + len(upper_nodes))
lower_tags, upper_tags = tags[:len(lower_nodes)], tags[len(lower_nodes):]
assert sorted(tags) != list(range(1, len(tags) + 1))
coords = {t: (x, y, 0.0) for t, (x, y) in zip(tags, lower_nodes + upper_nodes)}


def edge(block_tags, nx, row):
    """Line elements along grid row `row` of a block with nx cells a row."""
    return [(block_tags[row * (nx + 1) + i], block_tags[row * (nx + 1) + i + 1]) for i in range(nx)]


curves = {  # curve entity tag: (physical tag, name, lines)
    1: (11, "lower-bottom", edge(lower_tags, 2, 0)),
    2: (12, "lower-top", edge(lower_tags, 2, 2)),
    3: (13, "upper-bottom", edge(upper_tags, 3, 0)),
    4: (14, "upper-top", edge(upper_tags, 3, 1)),
}
surfaces = {1: (1, "lower", [tuple(lower_tags[k] for k in q) for q in lower_quads]),
            2: (2, "upper", [tuple(upper_tags[k] for k in q) for q in upper_quads])}
slave_tags = sorted({t for line in curves[3][2] for t in line})

msh = ["$MeshFormat", "4.1 0 8", "$EndMeshFormat", "$PhysicalNames",
       str(len(curves) + len(surfaces))]
msh += [f'1 {p} "{name}"' for p, name, _ in curves.values()]
msh += [f'2 {p} "{name}"' for p, name, _ in surfaces.values()]
msh += ["$EndPhysicalNames", "$Entities", f"0 {len(curves)} {len(surfaces)} 0"]
msh += [f"{c} 0 0 0 1 1.5 0 1 {p} 0" for c, (p, _, _) in curves.items()]
msh += [f"{s} 0 0 0 1 1.5 0 1 {p} 0" for s, (p, _, _) in surfaces.items()]
msh += ["$EndEntities", "$Nodes", f"2 {len(tags)} {min(tags)} {max(tags)}"]
for s, block in ((1, lower_tags), (2, upper_tags)):
    msh += [f"2 {s} 0 {len(block)}"] + [str(t) for t in block]
    msh += ["%.17g %.17g %.17g" % coords[t] for t in block]
elements = [(1, c, 1, lines) for c, (_, _, lines) in curves.items()] + \
           [(2, s, 3, quads) for s, (_, _, quads) in surfaces.items()]
count = sum(len(cells) for *_, cells in elements)
msh += ["$EndNodes", "$Elements", f"{len(elements)} {count} 1 {count}"]
tag = 0
for dim, entity, gmsh_type, cells in elements:
    msh.append(f"{dim} {entity} {gmsh_type} {len(cells)}")
    for cell in cells:
        tag += 1
        msh.append(" ".join(map(str, (tag,) + cell)))
msh.append("$EndElements")
open(os.path.join(work, "tags.msh"), "w").write("\n".join(msh) + "\n")

E = 2.0e6
scene = os.path.join(work, "node-ids.yaml")
open(scene, "w").write(f"""# expect: contact.normal_force={E * 0.01 / 1.5}@1e-2
contactlab:
  Name: node-ids
  Description: Contact patch test on a gmsh mesh with non-contiguous node tags
  Mesh:
    Type: file
    file: {{Path: tags.msh}}
  Materials:
    lower: {{Type: linear-elastic, linear-elastic: {{E: {E}, nu: 0.0}}}}
    upper: {{Type: linear-elastic, linear-elastic: {{E: {E}, nu: 0.0}}}}
  Dirichlet:
    base: {{Group: lower-bottom, Components: xy, Value: 0.0}}
    press: {{Group: upper-top, Components: y, Value: -0.01}}
    guide: {{Group: upper-top, Components: x, Value: 0.0}}
  Contact:
    interface:
      Slave: upper-bottom
      Master: lower-top
      Formulation:
        Type: augmented-lagrangian
        augmented-lagrangian: {{Normal Augmentation: 2.0e7}}
  Load Steps: {{Steps: 2}}
""")

failures = 0


def check(what, ok, detail=""):
    global failures
    print(f"{'ok  ' if ok else 'FAIL'} {what}" + (f": {detail}" if detail and not ok else ""))
    failures += not ok


rows = {}
for ranks in (1, 2):
    out = os.path.join(work, f"np{ranks}")
    # The results contract of every scene: the rest frame, contact.csv's nodes as VTK node_ids.
    run = subprocess.run([sys.executable, os.path.join(HERE, "check_run.py"), exe, scene, out,
                          str(ranks)], capture_output=True, text=True)
    check(f"{ranks} rank(s): check_run.py (results contract, contact force)", run.returncode == 0,
          run.stdout[-3000:] + run.stderr[-3000:])
    if not os.path.exists(os.path.join(out, "contact.csv")):
        continue
    points = list(csv.DictReader(open(os.path.join(out, "contact.csv"))))
    rows[ranks] = {int(p["node"]): p for p in points}
    check(f"{ranks} rank(s): contact.csv's node column holds the slave nodes' gmsh tags",
          sorted(rows[ranks]) == slave_tags and len(points) == len(slave_tags),
          f"{[p['node'] for p in points]} against {slave_tags}")
    wrong = [n for n, p in rows[ranks].items() if n not in coords or
             [float(p[f"reference_{c}"]) for c in "xyz"] != list(coords[n])]
    check(f"{ranks} rank(s): reference_x..z are those tags' coordinates in the .msh", not wrong,
          f"nodes {wrong}")
    g = read_grid(result_frames(out)[-1][1])
    ids = g.GetPointData().GetArray("node_id")
    by_id = {int(ids.GetValue(i)): g.GetPoint(i) for i in range(g.GetNumberOfPoints())} if ids else {}
    check(f"{ranks} rank(s): VTK node_id holds every gmsh tag at its .msh position",
          sorted(by_id) == sorted(tags) and all(list(by_id[t]) == list(coords[t]) for t in tags),
          f"{sorted(by_id)}")

if len(rows) == 2:
    same = sorted(rows[1]) == sorted(rows[2]) and all(
        rows[1][n][k] == rows[2][n][k] for n in rows[1] for k in
        ("zone", "reference_x", "reference_y", "reference_z", "status")) and all(
        abs(float(rows[1][n][k]) - float(rows[2][n][k])) <= 1e-9 * (1 + abs(float(rows[1][n][k])))
        for n in rows[1] for k in ("x", "y", "z", "pressure"))
    check("1 and 2 ranks write the same contact.csv rows", same)

# A run that converges no step (a tolerance out of reach: max-iterations at step 1) keeps the
# rest frame alone in a valid series, and summary.json names it.
out = os.path.join(work, "failed")
_, run = contactlab_run(exe, scene, out, ["Newton/Max Iterations=2", "Newton/Relative Tolerance=1e-30",
                                          "Newton/Absolute Tolerance=0"], 1)
summary = json.load(open(os.path.join(out, "summary.json")))
pvd = os.path.join(out, "result.pvd")
frames = result_frames(out) if os.path.exists(pvd) else []
check("a run that converges no step: exit 1, the rest frame alone in result.pvd",
      run.returncode == 1 and summary["load_steps"]["converged"] == 0
      and [t for t, _ in frames] == [0.0] and os.path.exists(frames[0][1])
      and read_grid(frames[0][1]).GetNumberOfCells() == summary["elements"]
      and summary["result_pvd"] and os.path.samefile(summary["result_pvd"], pvd),
      f"exit {run.returncode}, {summary['load_steps']}, frames {frames}, {summary['result_pvd']}")

print(f"{'FAILED' if failures else 'passed'}: {failures} failure(s)")
sys.exit(1 if failures else 0)
