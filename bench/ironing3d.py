#!/usr/bin/env python3
"""The seed's 3D ironing at its full travel (scenes/ironing-3d.yaml with `--set`: press 14 mm,
then slide 40 mm, slab 27 x 12 x 9 hex8): each slab material of the seed under the default
algorithm, and the neo-Hookean slab under each preset. With --small: the scene as shipped
(press 14 mm, slide 10 mm, 18 x 8 x 6 slab), every material under every method. Prints a table (status, steps, cuts,
Newton and geometry iterations, seconds, the die's final forces, stick points) and plots the
die's normal and tangential force histories; with --doc, writes both into doc/verification.md
between the bench:ironing3d markers.

usage: ironing3d.py CONTACTLAB SCENES OUTDIR [--doc doc/verification.md] [--only NAME,...] [--small]
                    [--reuse]
Run it with Debian's /usr/bin/python3 (python3-matplotlib).
"""
import argparse, csv, json, os, subprocess, sys

ap = argparse.ArgumentParser()
ap.add_argument("exe"); ap.add_argument("scenes"); ap.add_argument("out")
ap.add_argument("--doc", default="")
ap.add_argument("--only", default="", help="comma-separated case names to run")
ap.add_argument("--small", action="store_true", help="the shipped scene, every material x method")
ap.add_argument("--reuse", action="store_true",
                help="take the runs already in OUTDIR (their summary.json) instead of rerunning")
args = ap.parse_args()
scene = os.path.join(args.scenes, "ironing-3d.yaml")

full = ["Mesh/die-on-slab/Slab Divisions=[27,12,9]", "Mesh/die-on-slab/Die Divisions=[1,14,36]",
        "Dirichlet/press/Stop Time=0.25", "Dirichlet/drag/Start Time=0.25",
        "Dirichlet/drag/Value=40", "Load Steps/Steps=20"]
simo = ["Materials/slab/Type=simo-miehe"]  # the scene's simo-miehe sublist
c10 = ["Materials/slab/neo-hookean/E=0", "Materials/slab/neo-hookean/C10=1.0",
       "Materials/slab/neo-hookean/D1=0.4615"]
cases = [
    ("(a) neo-Hookean E = 1 MPa, nu = 0.3", "partial-newton", []),
    ("(b) simo-miehe, yield 0.3 MPa", "partial-newton", simo),
    ("(c) neo-Hookean C10 = 1 MPa", "partial-newton", c10),
    ("(a) neo-Hookean E = 1 MPa, nu = 0.3", "generalized-newton", []),
    ("(a) neo-Hookean E = 1 MPa, nu = 0.3", "fixed-point", []),
]
if args.small:
    full = []
    cases = [(m, method, sets) for method in ("partial-newton", "generalized-newton", "fixed-point")
             for m, sets in ((cases[0][0], []), (cases[1][0], simo), (cases[2][0], c10))]
marker = "ironing3d-small" if args.small else "ironing3d"
only = set(args.only.split(",")) if args.only else None
rows = []
for material, method, sets in cases:
    name = f"{material[:3].strip('()')}-{method}"
    if only and name not in only:
        continue
    out = os.path.join(args.out, name)
    cmd = [args.exe, "run", scene, "--out", out, "--quiet"]
    for s in full + sets + [f"Algorithm/Method={method}"]:
        cmd += ["--set", s]
    if not (args.reuse and os.path.exists(os.path.join(out, "summary.json"))):
        subprocess.run(cmd, capture_output=True, text=True)
    s = json.load(open(os.path.join(out, "summary.json")))
    steps = list(csv.DictReader(open(os.path.join(out, "steps.csv"))))
    last = steps[-1] if steps else {}
    rows.append(dict(
        name=name, material=material, method=method,
        status="converged" if s["converged"] else s["failure"],
        time=float(last.get("time", 0)), steps=s["load_steps"]["converged"],
        cuts=s["load_steps"]["cuts"], newton=s["iterations"]["newton"],
        geometry=s["iterations"]["geometry"], wall=s["seconds"]["total"],
        fx=float(last.get("contact_force_x", "nan")), fz=float(last.get("contact_force_z", "nan")),
        stick=s["contact"]["stick_points"], slip=s["contact"]["slip_points"],
        plastic=(s.get("plasticity") or {}).get("max_equivalent_plastic_strain"),
        history=[(float(r["time"]), float(r["contact_force_x"]), float(r["contact_force_z"]))
                 for r in steps]))
    r = rows[-1]
    print(f"{name}: {r['status']} t={r['time']:.3f} {r['newton']} its {r['wall']:.0f} s", flush=True)

table = ["| slab | method | status (last t) | steps (cuts) | Newton | geometry updates | "
         "seconds | die F_x, F_z at the end (N) | stick / slip points | max plastic strain |",
         "|---|---|---|---|---|---|---|---|---|---|"]
for r in rows:
    plastic = f"{r['plastic']:.2f}" if r["plastic"] is not None else "–"
    table.append(f"| {r['material']} | {r['method']} | {r['status']} ({r['time']:.3f}) | "
                 f"{r['steps']} ({r['cuts']}) | {r['newton']} | {r['geometry']} | {r['wall']:.0f} | "
                 f"{r['fx']:.1f}, {r['fz']:.1f} | {r['stick']} / {r['slip']} | {plastic} |")
table = "\n".join(table)
print(table)

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
for r in rows:
    if not r["history"]:
        continue
    t, fx, fz = zip(*([(0.0, 0.0, 0.0)] + r["history"]))
    label = f"{r['material']}, {r['method']}"
    style = "-" if r["method"] == "partial-newton" else "--"
    top.plot(t, [-f for f in fz], style, marker=".", label=label)
    bottom.plot(t, fx, style, marker=".", label=label)
top.set_ylabel("normal force on the die, -F_z (N)")
bottom.set_ylabel("tangential force on the die, F_x (N)")
bottom.set_xlabel("load time (press 14 mm over [0, 0.5], then slide 10 mm)" if args.small else
                  "load time (press 14 mm over [0, 0.25], then slide 40 mm)")
for ax in (top, bottom):
    ax.axvline(0.5 if args.small else 0.25, color="grey", lw=0.8, ls=":")
    ax.grid(alpha=0.3)
top.legend(fontsize=8)
top.set_title("3D ironing (seed; Puso & Laursen 2004 in mm): die forces" +
              (", shipped scene (slide 10 mm)" if args.small else ", full travel (slide 40 mm)"))
fig.tight_layout()
folder = os.path.join(os.path.dirname(args.doc), "figures") if args.doc else args.out
plot = os.path.join(folder, f"{marker}-forces.png")
fig.savefig(plot, dpi=110)

if args.doc:
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import docblock  # noqa: E402
    how = "bench/ironing3d.py --small" if args.small else "bench/ironing3d.py"
    docblock.write(args.doc, marker, how,
                   f"{table}\n\n![die forces](figures/{marker}-forces.png)\n")
