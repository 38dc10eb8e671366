#!/usr/bin/env python3
"""The normal-field augmented Lagrangian against the augmented Lagrangian (issue 17): the same
scene, the same r_n and r_t, under partial and generalized Newton. Per run: the outcome, Newton
iterations, geometry updates, cycling events, wall seconds, and the largest difference of the
final contact pressures from the augmented Lagrangian's under partial Newton (relative to its
peak). Then the sensitivity of the seed's target case (ironing-2d: a roller dragged over a soft
block, normals turning under it) to kappa_n. Tables to stdout and, with --doc, into
doc/verification.md between the bench:normal-field markers.

usage: normal_field.py CONTACTLAB SCENES_DIR WORKDIR [--doc doc/verification.md]"""
import csv, json, os, shutil, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import docblock

exe, scenes, work = sys.argv[1:4]
doc = sys.argv[sys.argv.index("--doc") + 1] if "--doc" in sys.argv else None
NF = "normal-field-augmented-lagrangian"
# scene, zone, the scene's own coefficients, extra --set arguments, what it shows
CASES = [
    ("hertz-2d-two-body", "roller", {"Normal Augmentation": "1e5"}, [],
     "2D, frictionless, curved slave on a flat master"),
    ("cattaneo-mindlin-2d", "interface",
     {"Normal Augmentation": "100", "Tangential Augmentation": "1000"}, [],
     "2D, friction, two curved bodies"),
    ("ironing-2d", "ironing", {"Normal Augmentation": "10", "Tangential Augmentation": "10"}, [],
     "2D, friction, finite strain, the die's curved master slides"),
    ("hertz-3d-two-body", "floor", {"Normal Augmentation": "50"},
     ["Contact/floor/Discretization=node-to-segment"], "3D, frictionless, tet4"),
    ("ironing-3d", "ironing", {"Normal Augmentation": "0.2", "Tangential Augmentation": "0.2"},
     [], "3D, friction, finite strain, the die's curved master slides"),
]


def run(scene, sets, out):
    shutil.rmtree(out, ignore_errors=True)
    cmd = [exe, "run", os.path.join(scenes, scene + ".yaml"), "--out", out, "--quiet",
           "--set", "Output/VTK=false"]
    for s in sets:
        cmd += ["--set", s]
    start = time.time()
    subprocess.run(cmd, capture_output=True, text=True, timeout=3600)
    wall = time.time() - start
    try:
        summary = json.load(open(os.path.join(out, "summary.json")))
    except (OSError, ValueError):
        return None, [], wall
    try:  # a run that failed before its first step has no contact.csv
        points = list(csv.DictReader(open(os.path.join(out, "contact.csv"))))
    except OSError:
        points = []
    return summary, points, wall


def formulation_sets(zone, formulation, coefficients):
    sets = [f"Contact/{zone}/Formulation/Type={formulation}"]
    sets += [f"Contact/{zone}/Formulation/{formulation}/{k}={v}" for k, v in coefficients.items()]
    return sets


def row(label, s, points, wall, reference):
    if s is None:
        return f"| {label} | no summary |" + " – |" * 5
    it = s["iterations"]
    result = "converged" if s["converged"] else f"`{s['failure']}`"
    cycling = sum(s["cycling"].values()) if isinstance(s["cycling"], dict) else s["cycling"]
    diff = "–"
    if reference and s["converged"]:
        peak = max(abs(float(p["pressure"])) for p in reference) or 1.0
        diff = "%.1e" % (max(abs(float(a["pressure"]) - float(b["pressure"]))
                             for a, b in zip(points, reference)) / peak)
    return (f"| {label} | {result} | {it['newton']} | {it['geometry']} | {cycling} | "
            f"{wall:.1f} | {diff} |")


header = ("| scene, formulation, preset | result | Newton its | geometry updates | cycling events "
          "| wall s | max Δp / p_max vs AL partial Newton |\n|---|---|---|---|---|---|---|\n")
table = header
print(header, end="")
for scene, zone, coefficients, extra, what in CASES:
    reference = None
    for method in ["partial-newton", "generalized-newton"]:
        for formulation in ["augmented-lagrangian", NF]:
            sets = formulation_sets(zone, formulation, coefficients) + extra
            sets.append(f"Algorithm/Method={method}")
            out = os.path.join(work, f"{scene}-{formulation}-{method}")
            s, points, wall = run(scene, sets, out)
            if formulation != NF and method == "partial-newton" and s and s["converged"]:
                reference = points
            short = "AL" if formulation != NF else "normal field"
            line = row(f"`{scene}` ({what}), {short}, {method}", s, points, wall, reference)
            print(line, flush=True)
            table += line + "\n"

sweep = ("\n`ironing-2d`, partial Newton, the normal field's kappa_n (automatic: r_n times the "
         "point's size):\n\n" + header.replace("scene, formulation, preset", "kappa_n"))
print(sweep, end="")
scene, zone, coefficients, extra, _ = CASES[2]
for kappa in ["0", "1e-2", "1", "1e2", "1e4"]:
    sets = formulation_sets(zone, NF, dict(coefficients, **{"Normal Field Penalty": kappa}))
    s, points, wall = run(scene, sets, os.path.join(work, f"kappa-{kappa}"))
    label = "automatic" if kappa == "0" else kappa
    line = row(label, s, points, wall, None)
    print(line, flush=True)
    sweep += line + "\n"
table += sweep

if doc:
    docblock.write(doc, "normal-field", "bench/normal_field.py", table)
    print(f"bench: {doc} updated")
