"""The peers' mesh: a quarter of the Hertz hemisphere written as a gmsh .geo, meshed by the gmsh
binary (there is no gmsh python module here) in tet10, read back from its msh 2.2 file.

usage: import peers_mesh; msh = peers_mesh.generate(folder, size); mesh = peers_mesh.read(msh)"""
import os, subprocess

# Physical group tags, written into the .geo (getfem_run.py uses the same numbers as regions).
BODY, FLAT, CURVED, SYM_X, SYM_Y = 1, 2, 3, 4, 5
GROUPS = {"flat": FLAT, "curved": CURVED, "sym-x": SYM_X, "sym-y": SYM_Y}

# The grading of scenes/hertz-3d.yaml's half-sphere: Size Contact within Fine Radius of the
# lowest point, growing to Size Far over Transition Length.
SIZE_FAR, FINE_RADIUS, TRANSITION = 0.2, 0.15, 0.6

GEO = """// Quarter of the hemisphere of radius {R} centred at (0, 0, {R}):
// x >= 0, y >= 0, z <= {R}.
SetFactory("OpenCASCADE");
Sphere(1) = {{0, 0, {R}, {R}}};
Box(2) = {{0, 0, 0, {R}, {R}, {R}}};
v() = BooleanIntersection{{ Volume{{1}}; Delete; }}{{ Volume{{2}}; Delete; }};
e = 1e-6;
flat() = Surface In BoundingBox{{-e, -e, {R} - e, {R} + e, {R} + e, {R} + e}};
symx() = Surface In BoundingBox{{-e, -e, -e, e, {R} + e, {R} + e}};
symy() = Surface In BoundingBox{{-e, -e, -e, {R} + e, e, {R} + e}};
curved() = Abs(Boundary{{ Volume{{v()}}; }});
curved() -= {{flat(), symx(), symy()}};
Physical Volume("body", {BODY}) = {{v()}};
Physical Surface("flat", {FLAT}) = {{flat()}};
Physical Surface("curved", {CURVED}) = {{curved()}};
Physical Surface("sym-x", {SYM_X}) = {{symx()}};
Physical Surface("sym-y", {SYM_Y}) = {{symy()}};
// Size Contact within Fine Radius of the contact point (0, 0, 0), Size Far beyond the transition.
tip() = Point In BoundingBox{{-e, -e, -e, e, e, e}};
Field[1] = Distance;
Field[1].PointsList = {{tip()}};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = {size};
Field[2].SizeMax = {far};
Field[2].DistMin = {fine};
Field[2].DistMax = {fine} + {transition};
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
"""


def generate(folder, size, radius=1.0):
    """Writes folder/quarter-sphere.geo, meshes it (tet10, msh 2.2) and returns the .msh path."""
    os.makedirs(folder, exist_ok=True)
    geo = os.path.join(folder, "quarter-sphere.geo")
    msh = os.path.join(folder, "quarter-sphere.msh")
    open(geo, "w").write(GEO.format(R=radius, size=size, far=SIZE_FAR, fine=FINE_RADIUS,
                                    transition=TRANSITION, BODY=BODY, FLAT=FLAT, CURVED=CURVED,
                                    SYM_X=SYM_X, SYM_Y=SYM_Y))
    done = subprocess.run(["gmsh", "-3", "-order", "2", "-format", "msh22", geo, "-o", msh],
                          capture_output=True, text=True)
    if done.returncode != 0 or not os.path.exists(msh):
        raise RuntimeError(f"gmsh failed on {geo}:\n{done.stdout[-2000:]}{done.stderr}")
    return msh


class Mesh:
    """A msh 2.2 file's nodes {tag: (x, y, z)}, tet10s [(tag, [10 node tags])] of the body and
    tri6 facets {group name: [[6 node tags]]}, each in gmsh's own node order."""

    def __init__(self):
        self.nodes, self.tets, self.facets = {}, [], {name: [] for name in GROUPS}

    def group_nodes(self, name):
        return sorted({n for f in self.facets[name] for n in f})


def read(msh):
    mesh, names = Mesh(), {tag: name for name, tag in GROUPS.items()}
    lines = iter(open(msh).read().split("\n"))
    for line in lines:
        if line == "$Nodes":
            for _ in range(int(next(lines))):
                tag, x, y, z = next(lines).split()
                mesh.nodes[int(tag)] = (float(x), float(y), float(z))
        elif line == "$Elements":
            for _ in range(int(next(lines))):
                f = [int(v) for v in next(lines).split()]
                kind, ntags = f[1], f[2]
                physical, conn = f[3], f[3 + ntags:]
                if kind == 11 and physical == BODY:  # 10-node tetrahedron
                    mesh.tets.append((f[0], conn))
                elif kind == 9 and physical in names:  # 6-node triangle
                    mesh.facets[names[physical]].append(conn)
    return mesh
