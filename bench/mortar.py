#!/usr/bin/env python3
"""Mortar against node-to-segment on the two-body 3D Hertz scene (scenes/hertz-3d-two-body.yaml):
cost per Newton iteration (pairing = search + mortar integration, contact terms, linear solve),
total time, and the pressure error against Hertz, over a mesh sequence; then total time at
equal accuracy. Writes its tables into doc/performance.md between the bench:mortar markers.

usage: mortar.py CONTACTLAB SCENES OUTDIR [--doc doc/performance.md] [--sizes 0.02,0.012,0.0075]
"""
import argparse, csv, datetime, json, math, os, re, subprocess, sys, time

ap = argparse.ArgumentParser()
ap.add_argument("exe"); ap.add_argument("scenes"); ap.add_argument("out")
ap.add_argument("--doc", default="")
ap.add_argument("--sizes", default="0.02,0.012,0.0075",
                help="Size Contact of the mesh sequence (0.0075: about 100 000 dofs)")
args = ap.parse_args()
scene = os.path.join(args.scenes, "hertz-3d-two-body.yaml")
E, nu, R = 1.0, 0.3, 1.0
Estar = E / (2 * (1 - nu * nu))  # two bodies of the same material

cases = [("node-to-segment", None), ("mortar", "dual"), ("mortar", "standard")]
rows = []
for size in [float(s) for s in args.sizes.split(",")]:
    for disc, basis in cases:
        if basis == "standard" and size < 0.01:
            continue  # the standard basis' error is known by then: not worth 10 minutes
        name = disc if basis is None else f"{disc} ({basis})"
        out = os.path.join(args.out, f"{disc}-{basis or 'nts'}-{size}")
        cmd = [args.exe, "run", scene, "--out", out, "--set", f"Mesh/half-sphere/Size Contact={size}",
               "--set", f"Contact/floor/Discretization={disc}"]
        if basis:
            cmd += ["--set", f"Contact/floor/Multiplier Basis={basis}"]
        start = time.time()
        run = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.time() - start
        s = json.load(open(os.path.join(out, "summary.json")))
        points = list(csv.DictReader(open(os.path.join(out, "contact.csv"))))
        P = s["contact"]["normal_force"]
        a = (3 * P * R / (4 * Estar)) ** (1 / 3)
        p0 = 3 * P / (2 * math.pi * a * a)
        errors = []
        for p in points:
            r = math.hypot(float(p["x"]), float(p["y"]))
            if r <= 0.9 * a:
                errors.append(abs(float(p["pressure"]) - p0 * math.sqrt(1 - r * r / (a * a))) / p0)
        its = max(s["iterations"]["newton"], 1)
        sec = s["seconds"]
        row = dict(name=name, size=size, dofs=s["dofs"], points=s["contact_points"],
                   status="converged" if s["converged"] else s["failure"], its=its,
                   pairing=sec["pairing"] / its, contact=sec["contact"] / its,
                   solve=sec["linear_solve"] / its, total=sec["total"], wall=wall,
                   inside=len(errors), emax=100 * max(errors),
                   erms=100 * math.sqrt(sum(e * e for e in errors) / len(errors)),
                   pen=s["contact"]["max_penetration"])
        rows.append(row)
        print(f"{name:24s} h={size} dofs={row['dofs']} its={its} pairing={row['pairing']:.3f} "
              f"contact={row['contact']:.3f} solve={row['solve']:.2f} total={row['total']:.1f} s "
              f"error max {row['emax']:.1f} % rms {row['erms']:.2f} %", flush=True)

header = ("| discretization | Size Contact | dofs | contact points | Newton its | pairing + mortar "
          "integration s/it | contact terms s/it | linear solve s/it | total s | points r ≤ 0.9a | "
          "pressure error / p0, max (rms) | max penetration |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|\n")
table = header + "".join(
    f"| {r['name']} | {r['size']} | {r['dofs']} | {r['points']} | {r['its']}"
    f"{'' if r['status'] == 'converged' else ' (' + r['status'] + ')'} | {r['pairing']:.3f} | "
    f"{r['contact']:.3f} | {r['solve']:.2f} | {r['total']:.1f} | {r['inside']} | "
    f"{r['emax']:.1f} % ({r['erms']:.2f} %) | {r['pen']:.1e} |\n" for r in rows)

# Equal accuracy: for each mortar (dual) run, the cheapest node-to-segment run at least as
# accurate (rms), if any.
lines = []
for m in [r for r in rows if r["name"] == "mortar (dual)"]:
    better = [r for r in rows if r["name"] == "node-to-segment" and r["erms"] <= m["erms"]]
    if better:
        b = min(better, key=lambda r: r["total"])
        lines.append(f"- mortar (dual) at {m['dofs']} dofs: {m['erms']:.2f} % rms in "
                     f"{m['total']:.1f} s; node-to-segment reaches it at {b['dofs']} dofs in "
                     f"{b['total']:.1f} s.")
    else:
        lines.append(f"- mortar (dual) at {m['dofs']} dofs: {m['erms']:.2f} % rms in "
                     f"{m['total']:.1f} s; no node-to-segment run of the sequence is as accurate "
                     f"(best {min(r['erms'] for r in rows if r['name'] == 'node-to-segment'):.2f} %).")
text = table + "\n" + "\n".join(lines) + "\n"
print(text)
if args.doc:
    doc = open(args.doc).read()
    start, end = "<!-- bench:mortar:start -->", "<!-- bench:mortar:end -->"
    block = f"{start}\nMeasured {datetime.date.today()} by `bench/mortar.py`:\n\n{text}{end}"
    if start in doc:
        doc = re.sub(re.escape(start) + ".*?" + re.escape(end), lambda _: block, doc, flags=re.S)
    else:
        doc += "\n" + block + "\n"
    open(args.doc, "w").write(doc)
