#!/usr/bin/python3
"""contactlab, GetFEM and CalculiX side by side (issue 19): the same gmsh tet10 mesh of a quarter
of the Hertz hemisphere (R = 1, E = 1, nu = 0.3, symmetry planes x = 0 and y = 0, frictionless,
its flat top at z = R lowered by --delta onto the rigid plane z = 0), run by each program in turn,
one at a time, each under /usr/bin/time -v. Prints, per program: displacement dofs (+ contact and
constraint multipliers), Newton iterations, wall and CPU seconds, peak resident memory, the full
sphere's contact force F (4 x the quarter's), Hertz's radius a for that F and the pressure error
against Hertz, and the wall-time ratio peer / contactlab.

The pressure metric is the same for all three, tests/contact_references.py's (the one
tests/verification/check_contact.py applies to contactlab): Hertz from each program's own F,
E* = E / (1 - nu^2), a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2),
p(r) = p0 sqrt(1 - r^2 / a^2); the error is the RMS and the max of |p_node - p(r)| / p0 over the
contact nodes with r <= 0.9 a (r from the reference coordinates). The nodes are each program's
own: contactlab's contact points (every node of the curved surface), GetFEM's P1 multiplier
nodes (the vertices), CalculiX's slave nodes (CPRESS in the .frd).

The peers are bench-only: installed with apt-get (python3-getfem, calculix-ccx) when missing,
never project dependencies. GetFEM runs under /usr/bin/python3 (Debian's module).

usage: peers.py CONTACTLAB WORK [--size H] [--delta D] [--penalty K] [--threads N]
                [--programs contactlab getfem calculix] [--mesh-only] [--doc DOC]
  --size: the mesh's Size Contact (default 0.00713: 125 730 dofs with gmsh 4.8.4, the issue's
          size, minutes per program; 0.02: 14 505 dofs, the small validation size, seconds each)
  --penalty: CalculiX's pressure-overclosure slope K in units of E / R (default 1000: the
          penetration p / K is ~0.7 % of delta at Hertz's p0, and F ~0.5 % below the exact
          multipliers'; 5000 and above take CalculiX 18-28 iterations at the small size)
  --mesh-only: generate the mesh, print its nodes and dofs, stop (to pick --size)
  --doc: write the table between the `peers` markers of DOC (bench/docblock.py)"""
import argparse, csv, json, os, re, shutil, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))  # bench/: runs, docblock
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests"))  # contact_references
import calculix  # noqa: E402
import docblock  # noqa: E402
import peers_mesh  # noqa: E402
import runs  # noqa: E402
from contact_references import hertz, hertz_pressure_errors  # noqa: E402

E, NU, RADIUS = 1.0, 0.3, 1.0

SCENE = """# Written by bench/peers/peers.py: the peers' quarter hemisphere, contactlab's defaults.
contactlab:
  Name: peers-hertz
  Description: Quarter hemisphere on a rigid plane, the mesh GetFEM and CalculiX run
  Mesh:
    Type: file
    file: {{Path: {mesh}}}
  Materials:
    body:
      Type: linear-elastic
      linear-elastic: {{E: {E}, nu: {nu}}}
  Symmetry:
    cut-x: {{Group: sym-x}}
    cut-y: {{Group: sym-y}}
  # Only z on the flat face: the symmetry planes fix the x and y translations and the rotation
  # about z; the other rotations are held by the flat face's z values.
  Dirichlet:
    press: {{Group: flat, Components: z, Value: {value}}}
  # The default formulation (augmented Lagrangian) with its automatic r_n = E / h.
  Contact:
    floor:
      Slave: curved
      Obstacle: {{Type: plane, Point: [0.0, 0.0, 0.0], Normal: [0.0, 0.0, 1.0]}}
  Load Steps: {{Steps: 1}}
"""


def ensure_peers():
    """Installs GetFEM's python module and CalculiX with apt-get when either is missing."""
    getfem = subprocess.run(["/usr/bin/python3", "-c", "import getfem"],
                            capture_output=True).returncode == 0
    if getfem and shutil.which("ccx"):
        return
    print("installing the peers: apt-get install -y python3-getfem calculix-ccx", flush=True)
    subprocess.run(["apt-get", "install", "-y", "python3-getfem", "calculix-ccx"], check=True,
                   stdout=subprocess.DEVNULL)


def gnu_time(stderr):
    """Wall s, CPU s (user + system) and max resident MiB from /usr/bin/time -v's report."""
    def field(name):
        return re.search(re.escape(name) + r": (.*)", stderr).group(1).strip()
    clock = [float(v) for v in field("Elapsed (wall clock) time (h:mm:ss or m:ss)").split(":")]
    wall = sum(v * 60 ** i for i, v in enumerate(reversed(clock)))
    cpu = float(field("User time (seconds)")) + float(field("System time (seconds)"))
    return wall, cpu, float(field("Maximum resident set size (kbytes)")) / 1024


def pressure_metric(force, points, vertices):
    """Hertz's a for the full sphere's force and the pressure errors of the points (dicts with
    reference x, y and pressure), with tests/contact_references.py's definitions; `at_vertices`
    the same errors over the points on the curved surface's vertices only (a point without a
    node is GetFEM's P1 multiplier, on a vertex by construction), so that every program is
    measured on the same nodes: contactlab and CalculiX also give mid-edge nodes, GetFEM not."""
    a, p0 = hertz(force, E / (1 - NU ** 2), RADIUS, 3)
    on_vertices = [p for p in points if p.get("node") is None or p["node"] in vertices]
    return dict(a=a, p0=p0, at_vertices=hertz_pressure_errors(on_vertices, a, p0, 3),
                **hertz_pressure_errors(points, a, p0, 3))


def run_contactlab(exe, work, msh, delta):
    folder = os.path.join(work, "contactlab")
    os.makedirs(folder, exist_ok=True)
    scene = os.path.join(folder, "peers-hertz.yaml")
    open(scene, "w").write(SCENE.format(mesh=os.path.relpath(msh, folder), E=E, nu=NU,
                                        value=-delta))
    out = os.path.join(folder, "out")
    summary, _, done = runs.run(exe, "run", scene, out, quiet=True,
                                prefix=["/usr/bin/time", "-v"])
    if done.returncode != 0 or summary is None or not summary["converged"]:
        sys.exit(f"contactlab failed on {scene}:\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
    wall, cpu, mib = gnu_time(done.stderr)
    # Every contact point (open ones at p = 0), at its reference position like the peers'.
    points = [dict(x=r["reference_x"], y=r["reference_y"], pressure=r["pressure"],
                   node=int(r["node"]))
              for r in csv.DictReader(open(os.path.join(out, "contact.csv")))]
    u = summary["unknowns"]
    mode = summary["linear_solver"]["parameters"]["Mode"]
    rn = next((z.get("automatic_normal_augmentation") for z in
               (summary.get("formulation") or {}).values()), None)
    return dict(program="contactlab",
                settings=f"defaults: augmented Lagrangian (automatic r_n = "
                         f"{f'{rn:g}' if rn else '?'}), {summary['discretization']['floor']}, "
                         f"{summary['algorithm']['method']}, MUMPS {mode}",
                dofs=f"{u['displacement']} + {u['contact_multipliers']}",
                newton=summary["iterations"]["newton"], wall=wall, cpu=cpu, mib=mib,
                force=4 * summary["contact"]["normal_force"], points=points)


def run_getfem(work, msh, delta, r):
    folder = os.path.join(work, "getfem")
    os.makedirs(folder, exist_ok=True)
    out = os.path.join(folder, "result.json")
    if os.path.exists(out):
        os.remove(out)
    cmd = ["/usr/bin/time", "-v", "/usr/bin/python3", os.path.join(HERE, "getfem_run.py"), msh,
           out, "--delta", repr(delta), "--r", repr(r), "--E", repr(E), "--nu", repr(NU)]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=3600)
    open(os.path.join(folder, "getfem.log"), "w").write(done.stdout + done.stderr)
    if done.returncode != 0 or not os.path.exists(out):
        sys.exit(f"GetFEM failed:\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
    result = json.load(open(out))
    if not result["converged"]:
        sys.exit(f"GetFEM's Newton did not converge (see {folder}/getfem.log)")
    wall, cpu, mib = gnu_time(done.stderr)
    return dict(program="GetFEM 5.4",
                settings=f"integral augmented Lagrangian, Alart-Curnier non-symmetric "
                         f"(r = {r:g}), P1 multiplier, MUMPS "
                         f"({result['setup_seconds']:.1f} s before Model.solve)",
                dofs=f"{result['dofs']} + {result['multipliers']}", newton=result["newton"],
                wall=wall, cpu=cpu, mib=mib, force=4 * result["force"], points=result["points"])


def run_calculix(work, mesh, delta, penalty, threads):
    folder = os.path.join(work, "calculix")
    shutil.rmtree(folder, ignore_errors=True)
    calculix.check_tet10_order(os.path.join(folder, "tet10-check"))
    inp = os.path.join(folder, "hertz.inp")
    calculix.write_inp(mesh, inp, delta=delta, penalty=penalty, E=E, nu=NU)
    done = calculix.run(inp, threads=threads)
    open(os.path.join(folder, "ccx.log"), "w").write(done.stdout + done.stderr)
    if done.returncode != 0 or "Job finished" not in done.stdout:
        sys.exit(f"CalculiX failed on {inp}:\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
    force, pressures, newton = calculix.results(inp)
    wall, cpu, mib = gnu_time(done.stderr)
    slave = {n for f in mesh.facets["curved"] for n in f}
    points = [dict(x=mesh.nodes[n][0], y=mesh.nodes[n][1], pressure=p, node=n)
              for n, p in pressures.items() if n in slave]
    return dict(program="CalculiX 2.20",
                settings=f"surface-to-surface penalty (K = {penalty:g}), SPOOLES, "
                         f"{threads} threads",
                dofs=f"{3 * len(mesh.nodes)}", newton=newton, wall=wall, cpu=cpu, mib=mib,
                force=4 * force, points=points)


def table(rows, size, nodes):
    base = rows[0]["wall"] if rows[0]["program"] == "contactlab" else None
    text = (f"Mesh: Size Contact {size}, {nodes} nodes ({3 * nodes} displacement dofs); "
            f"pressure error over the contact nodes with r <= 0.9 a, in % of p0: over each "
            f"program's own nodes, and over the surface's vertices only (the nodes all three "
            f"have).\n\n"
            "| program | settings | dofs (+ multipliers) | Newton | wall s | CPU s | peak MiB | "
            "F | a | pressure error RMS | max | RMS at vertices | max at vertices | "
            "wall / contactlab |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        m = r["metric"]
        newton = "not read" if r["newton"] is None else r["newton"]
        # No pressure inside 0.9 a (e.g. a .frd without its CONTACT block) is no error of 0.
        def errors(e):
            return ((f"{100 * e['rms']:.2f} %", f"{100 * e['max']:.2f} %") if e["inside"]
                    else ("no pressures read", ""))
        rms, worst = errors(m)
        vrms, vworst = errors(m["at_vertices"])
        ratio = f"{r['wall'] / base:.2f}" if base else ""
        text += (f"| {r['program']} | {r['settings']} | {r['dofs']} | {newton} | "
                 f"{r['wall']:.1f} | {r['cpu']:.1f} | {r['mib']:.0f} | {r['force']:.5e} | "
                 f"{m['a']:.4f} | {rms} | {worst} | {vrms} | {vworst} | {ratio} |\n")
    return text


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("work")
    ap.add_argument("--size", type=float, default=0.00713)
    ap.add_argument("--delta", type=float, default=0.0095)
    ap.add_argument("--penalty", type=float, default=1000.0)
    ap.add_argument("--threads", type=int, default=2, help="CalculiX's OMP_NUM_THREADS")
    ap.add_argument("--programs", nargs="+", default=["contactlab", "getfem", "calculix"],
                    choices=["contactlab", "getfem", "calculix"])
    ap.add_argument("--mesh-only", action="store_true")
    ap.add_argument("--doc")
    args = ap.parse_args()
    exe, work = os.path.abspath(args.exe), os.path.abspath(args.work)
    msh = peers_mesh.generate(os.path.join(work, "mesh"), args.size, RADIUS)
    mesh = peers_mesh.read(msh)
    print(f"mesh {msh}: Size Contact {args.size}, {len(mesh.nodes)} nodes, {len(mesh.tets)} "
          f"tet10, {3 * len(mesh.nodes)} displacement dofs", flush=True)
    if args.mesh_only:
        return
    ensure_peers()
    rn = E / args.size  # GetFEM's r: E / h at the contact point (contactlab's is automatic)
    penalty = args.penalty * E / RADIUS
    vertices = {n for facet in mesh.facets["curved"] for n in facet[:3]}  # tri6 corners first
    rows = []
    for program in ("contactlab", "getfem", "calculix"):  # one at a time, contactlab first
        if program not in args.programs:
            continue
        print(f"running {program} ...", flush=True)
        if program == "contactlab":
            row = run_contactlab(exe, work, msh, args.delta)
        elif program == "getfem":
            row = run_getfem(work, msh, args.delta, rn)
        else:
            row = run_calculix(work, mesh, args.delta, penalty, args.threads)
        row["metric"] = pressure_metric(row["force"], row["points"], vertices)
        print(f"  {row['program']}: F = {row['force']:.6e}, Newton {row['newton']}, "
              f"wall {row['wall']:.1f} s, {row['metric']['inside']} nodes inside a", flush=True)
        rows.append(row)
    text = table(rows, args.size, len(mesh.nodes))
    forces = [r["force"] for r in rows]
    spread = (max(forces) - min(forces)) / min(forces)
    text += f"\nContact forces within {100 * spread:.2f} % of each other.\n"
    print(text)
    if args.doc:
        docblock.write(args.doc, "peers", "bench/peers/peers.py", text)


if __name__ == "__main__":
    main()
