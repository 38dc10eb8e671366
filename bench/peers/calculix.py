"""CalculiX's side of bench/peers/peers.py: the peers' mesh as a CalculiX .inp (C3D10), its run
by `ccx` and the reading of its .dat and .sta files.

usage: import calculix; calculix.write_inp(mesh, inp, delta=..., penalty=...); ...
       python3 calculix.py WORK   (the tet10 node-order check alone)

The model (CalculiX 2.20, Debian calculix-ccx; keywords from the CalculiX CrunchiX user's manual,
http://www.dhondt.de/ccx_2.20.pdf: *CONTACT PAIR, *SURFACE BEHAVIOR, *NODE PRINT, *CONTACT
PRINT):
- the body's tet10s as C3D10, linear elastic, small strains (no NLGEOM);
- the rigid plane as a block of C3D8 elements under the sphere, every node of it fixed: its top
  face (z = 0) is the master surface;
- frictionless surface-to-surface contact, the curved surface slave, with the penalty law
  *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR (slope K: the penetration is p / K);
- symmetry and the pressing by *BOUNDARY on the nodes of sym-x, sym-y and flat;
- the default SPOOLES solver, one increment of the whole load (*STATIC 1., 1.)."""
import os, re, subprocess, sys

# gmsh's tet10 numbers the edge nodes 4: 0-1, 5: 1-2, 6: 2-0, 7: 3-0, 8: 3-2, 9: 3-1 (0-based);
# Abaqus/CalculiX C3D10 has 8: 1-3 (0-based vertices 1, 3) and 9: 2-3: the last two swap.
GMSH_TO_C3D10 = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]
# C3D10 faces by their corner nodes (0-based), numbered as in the CalculiX manual's C3D4/C3D10.
C3D10_FACES = {1: (0, 1, 2), 2: (0, 3, 1), 3: (1, 3, 2), 4: (2, 3, 0)}


def c3d10(conn):
    return [conn[i] for i in GMSH_TO_C3D10]


def num(v):
    """A float in 19 characters at most (CalculiX reads fields of up to 20)."""
    return f"{v:.12e}"


def _lines(values, per_line=8):
    """Abaqus data lines hold at most 16 entries; keep them short."""
    return "\n".join(", ".join(str(v) for v in values[i:i + per_line])
                     for i in range(0, len(values), per_line))


def write_inp(mesh, inp, delta, penalty, E=1.0, nu=0.3, block=(-0.05, 0.5, 0.25, 5)):
    """The Hertz model of the module docstring; block = (x0, x1, thickness, divisions) of the
    rigid block's square top [x0, x1]^2 at z = 0 (it only needs to cover the contact zone)."""
    out = ["*HEADING", "Quarter hemisphere pressed on a rigid plane (bench/peers)", "*NODE"]
    out += [f"{n}, {num(x)}, {num(y)}, {num(z)}" for n, (x, y, z) in sorted(mesh.nodes.items())]
    # The rigid block's nodes and C3D8s, numbered after the mesh's.
    x0, x1, thickness, k = block
    base, ids = max(mesh.nodes) + 1, {}
    for i in range(k + 1):
        for j in range(k + 1):
            for layer, z in enumerate((-thickness, 0.0)):
                ids[i, j, layer] = base + len(ids)
                x, y = x0 + (x1 - x0) * i / k, x0 + (x1 - x0) * j / k
                out.append(f"{ids[i, j, layer]}, {num(x)}, {num(y)}, {num(z)}")
    out.append("*ELEMENT, TYPE=C3D10, ELSET=EBODY")
    out += [f"{e}, " + ", ".join(str(n) for n in c3d10(conn)) for e, conn in mesh.tets]
    out.append("*ELEMENT, TYPE=C3D8, ELSET=EBLOCK")
    first, blocks = max(e for e, _ in mesh.tets) + 1, []
    for i in range(k):
        for j in range(k):
            corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            conn = [ids[c + (0,)] for c in corners] + [ids[c + (1,)] for c in corners]
            blocks.append(first + len(blocks))
            out.append(f"{blocks[-1]}, " + ", ".join(str(n) for n in conn))
    for name in ("flat", "sym-x", "sym-y"):
        out.append(f"*NSET, NSET=N{name.upper().replace('-', '')}")
        out.append(_lines(mesh.group_nodes(name)))
    out.append("*NSET, NSET=NBLOCK")
    out.append(_lines(sorted(ids.values())))
    # The slave surface: each curved tri6 as the face of the tet it bounds.
    faces = {}
    for e, conn in mesh.tets:
        cc = c3d10(conn)
        for number, corners in C3D10_FACES.items():
            faces[frozenset(cc[c] for c in corners)] = (e, number)
    out.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
    out += ["{}, S{}".format(*faces[frozenset(f[:3])]) for f in mesh.facets["curved"]]
    out.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    out += [f"{e}, S2" for e in blocks]  # C3D8 face 2: nodes 5-8-7-6, the top (z = 0)
    out += ["*MATERIAL, NAME=ELASTIC", "*ELASTIC", f"{num(E)}, {num(nu)}",
            "*SOLID SECTION, ELSET=EBODY, MATERIAL=ELASTIC",
            "*SOLID SECTION, ELSET=EBLOCK, MATERIAL=ELASTIC",
            "*SURFACE INTERACTION, NAME=FLOOR",
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", num(penalty),
            "*CONTACT PAIR, INTERACTION=FLOOR, TYPE=SURFACE TO SURFACE", "SLAVE, MASTER",
            "*STEP", "*STATIC", "1., 1.",
            "*BOUNDARY", "NBLOCK, 1, 3, 0.", "NSYMX, 1, 1, 0.", "NSYMY, 2, 2, 0.",
            f"NFLAT, 3, 3, {num(-delta)}",
            "*NODE PRINT, NSET=NFLAT, TOTALS=ONLY", "RF",
            # CSTR in the .frd: CPRESS per slave node (the .dat's CSTR of surface-to-surface
            # contact is per slave-face integration point, without coordinates).
            "*CONTACT FILE", "CSTR",
            "*END STEP", ""]
    open(inp, "w").write("\n".join(out))


def run(inp, threads=2, timeout=3600):
    """ccx on JOB.inp in its folder, with /usr/bin/time -v; returns the finished process."""
    folder, job = os.path.split(os.path.abspath(inp))
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), CCX_NPROC_STIFFNESS=str(threads))
    return subprocess.run(["/usr/bin/time", "-v", "ccx", "-i", job[:-4]], cwd=folder, env=env,
                          capture_output=True, text=True, timeout=timeout)


def _blocks(dat):
    """The .dat file's result blocks: [(title, [rows of floats])]."""
    blocks, title, rows = [], None, []
    for line in open(dat):
        if not line.strip():
            continue
        try:
            rows.append([float(v) for v in line.split()])
        except ValueError:
            if title is not None:
                blocks.append((title, rows))
            title, rows = line.strip(), []
    if title is not None:
        blocks.append((title, rows))
    return blocks


def contact_pressures(frd):
    """CPRESS of the last CONTACT block of an ASCII .frd file: {node: pressure}. Its records are
    " -1", the node in 10 columns, then 12-column values (COPEN, CSLIP1, CSLIP2, CPRESS, ...)."""
    pressures, inside = {}, False
    for line in open(frd):
        if line.startswith(" -4"):
            inside = line.split()[1] == "CONTACT"
            if inside:
                pressures = {}
        elif inside and line.startswith(" -1"):
            pressures[int(line[3:13])] = float(line[13 + 3 * 12:13 + 4 * 12])
        elif line.startswith(" -3"):
            inside = False
    return pressures


def results(inp):
    """The last time's total reaction on the flat face (minus its z: the contact force), the
    contact pressures at the slave nodes {node: p} and the Newton iterations of the step (the
    .sta file's ITRS summed over the increments, or None when it has none)."""
    base = inp[:-4]
    force = None
    for title, rows in _blocks(base + ".dat"):
        if title.startswith("total force") and "NFLAT" in title:
            force = -rows[-1][2]
    pressures = contact_pressures(base + ".frd")
    newton = None
    if os.path.exists(base + ".sta"):
        itrs = [int(m.group(1)) for m in
                re.finditer(r"^\s*\d+\s+\d+\s+\d+U?\s+(\d+)\s", open(base + ".sta").read(), re.M)]
        newton = sum(itrs) if itrs else None
    return force, pressures, newton


def check_tet10_order(work):
    """One curved-free reference tet10 in gmsh's node order, converted as write_inp converts:
    its volume must be 1/6 (a swapped edge node gives another volume, or a non-positive
    Jacobian) and a uniform strain prescribed at its nodes must give the exact uniform stress
    at every integration point. Raises AssertionError otherwise."""
    os.makedirs(work, exist_ok=True)
    vertices = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    edges = [(0, 1), (1, 2), (2, 0), (3, 0), (3, 2), (3, 1)]  # gmsh's tet10 edge nodes 4-9
    points = vertices + [tuple((a + b) / 2 for a, b in zip(vertices[i], vertices[j]))
                         for i, j in edges]
    E, nu, strain = 1.0, 0.3, (1e-3, -2e-4, 5e-4, 3e-4, -1e-4, 2e-4)  # xx yy zz xy xz yz
    exx, eyy, ezz, gxy, gxz, gyz = strain  # engineering shears

    def u(p):
        x, y, z = p
        return (exx * x + gxy / 2 * y + gxz / 2 * z, gxy / 2 * x + eyy * y + gyz / 2 * z,
                gxz / 2 * x + gyz / 2 * y + ezz * z)

    conn = c3d10(list(range(1, 11)))
    lines = ["*NODE"] + [f"{i + 1}, {x}, {y}, {z}" for i, (x, y, z) in enumerate(points)]
    lines += ["*ELEMENT, TYPE=C3D10, ELSET=E", "1, " + ", ".join(map(str, conn)),
              "*MATERIAL, NAME=M", "*ELASTIC", f"{E}, {nu}", "*SOLID SECTION, ELSET=E, MATERIAL=M",
              "*STEP", "*STATIC", "*BOUNDARY"]
    lines += [f"{i + 1}, {c + 1}, {c + 1}, {num(u(p)[c])}" for i, p in enumerate(points)
              for c in range(3)]
    lines += ["*EL PRINT, ELSET=E", "S", "*EL PRINT, ELSET=E, TOTALS=ONLY", "EVOL",
              "*END STEP", ""]
    inp = os.path.join(work, "tet10.inp")
    open(inp, "w").write("\n".join(lines))
    done = run(inp, threads=1, timeout=60)
    assert done.returncode == 0, f"ccx failed on {inp}:\n{done.stdout[-2000:]}"
    blocks = _blocks(inp[:-4] + ".dat")
    volume = [rows[-1][0] for title, rows in blocks if title.startswith("total volume")][0]
    # The .dat prints 7 digits.
    assert abs(volume - 1 / 6) < 1e-6, f"tet10 volume {volume}, not 1/6: node order wrong"
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    tr = exx + eyy + ezz
    exact = [lam * tr + 2 * mu * exx, lam * tr + 2 * mu * eyy, lam * tr + 2 * mu * ezz,
             mu * gxy, mu * gxz, mu * gyz]
    stresses = [rows for title, rows in blocks if title.startswith("stresses")][0]
    worst = max(abs(s - x) for r in stresses for s, x in zip(r[2:], exact))
    assert worst < 1e-5 * max(map(abs, exact)), f"tet10 patch test: stress off by {worst}"
    return volume, worst


if __name__ == "__main__":
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    import runs  # bench/: the scripts' shared usage check (a folder named --help was run in)

    (work,) = runs.positional(__doc__, 1)
    print("tet10 volume %.15g, patch-test stress error %.3g" % check_tet10_order(work))
