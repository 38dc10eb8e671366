#!/usr/bin/env python3
"""The normal-field augmented Lagrangian against the augmented Lagrangian (issue 17): the same
scene, the same r_n and r_t, under partial and generalized Newton. Per run: the outcome, Newton
iterations, geometry updates, cycling events, wall seconds, and the largest difference of the
final contact pressures from the augmented Lagrangian's under partial Newton (relative to its
peak). Then the sensitivity of the seed's target case (ironing-2d: a roller dragged over a soft
block, normals turning under it) to kappa_n. Tables to stdout and, with --doc, into
doc/verification.md between the bench:normal-field markers.

usage: normal_field.py CONTACTLAB SCENES_DIR WORKDIR [--doc doc/verification.md]"""
import csv, json, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import docblock, runs

exe, scenes, work = runs.positional(__doc__, 3)
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
    ("polyurethane-block-2d", "press", {"Normal Augmentation": "20"}, [],
     "the seed's case: SVK block pressed by a strongly curved master"),
]


def run(scene, sets, out):
    summary, wall, _ = runs.run(exe, "run", os.path.join(scenes, scene + ".yaml"), out, sets,
                                quiet=True)
    if summary is None:
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



# The seed's own case side by side: the polyurethane block's pressure under the roller with each
# formulation (partial Newton), against the augmented Lagrangian on a mesh 2.5 times finer.
def profile(points):
    closed = sorted((float(p["reference_x"]), float(p["pressure"])) for p in points)
    return [x for x, _ in closed], [p for _, p in closed]


def roughness(x, p):
    # The largest second difference of the closed points' pressures, relative to the peak: the
    # node-to-node scatter a smooth field does not have.
    inside = [i for i in range(1, len(p) - 1) if p[i - 1] > 0 and p[i] > 0 and p[i + 1] > 0]
    peak = max(p) or 1.0
    return max((abs(p[i] - 0.5 * (p[i - 1] + p[i + 1])) for i in inside), default=0.0) / peak


def interpolate(xr, pr, x):
    for k in range(1, len(xr)):
        if xr[k] >= x:
            a = (x - xr[k - 1]) / (xr[k] - xr[k - 1])
            return (1 - a) * pr[k - 1] + a * pr[k]
    return pr[-1]


scene, zone, coefficients, _, _ = CASES[-1]
fine_sets = formulation_sets(zone, "augmented-lagrangian", coefficients) + [
    "Mesh/roller-on-base/Size Contact=0.1"]
s_fine, fine, wall = run(scene, fine_sets, os.path.join(work, "polyurethane-fine"))
xr, pr = profile(fine)
curves = {}
compare = ("\n`polyurethane-block-2d` (the seed's case), partial Newton: the pressure under the "
           "roller against the augmented Lagrangian at Size Contact 0.1 (reference, "
           f"{s_fine['iterations']['newton'] if s_fine else '–'} Newton iterations):\n\n"
           "| formulation | Newton its | cycling events | max abs(p − p_ref) / max p_ref "
           "| roughness (max second difference / p_max) |\n|---|---|---|---|---|\n")
for formulation in ["augmented-lagrangian", NF]:
    out = os.path.join(work, f"{scene}-{formulation}-partial-newton")
    s = json.load(open(os.path.join(out, "summary.json")))
    x, p = profile(list(csv.DictReader(open(os.path.join(out, "contact.csv")))))
    curves[formulation] = (x, p)
    error = max(abs(pi - interpolate(xr, pr, xi)) for xi, pi in zip(x, p)) / max(pr)
    line = (f"| {formulation} | {s['iterations']['newton']} | {sum(s['cycling'].values())} | "
            f"{error:.3f} | {roughness(x, p):.3f} |")
    print(line, flush=True)
    compare += line + "\n"
compare += f"| reference (fine) | – | – | – | {roughness(xr, pr):.3f} |\n"
table += compare
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(xr, pr, "k-", lw=1, label="augmented Lagrangian, Size Contact 0.1 (reference)")
    for (formulation, (x, p)), style in zip(curves.items(), ["o", "x"]):
        ax.plot(x, p, style, ms=4, label=f"{formulation}, Size Contact 0.25")
    ax.set_xlabel("x on the block's top, reference position (mm)")
    ax.set_ylabel("contact pressure (MPa)")
    ax.set_xlim(-9, 9)
    ax.set_ylim(-0.45 * max(pr), 1.1 * max(pr))  # room for the legend below the profile
    ax.set_title("Polyurethane block (SVK, E 4.07 MPa, nu 0.48) pressed 3 mm by a roller, R 10 mm",
                 fontsize=9)
    ax.legend(fontsize=8, loc="lower center")
    fig.tight_layout()
    figure = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "doc", "figures",
                          "normal-field-polyurethane.png")
    fig.savefig(figure, dpi=110)
    table += "\n![pressure under the roller](figures/normal-field-polyurethane.png)\n"
except ImportError:
    print("bench: no matplotlib, no figure")

if doc:
    docblock.write(doc, "normal-field", "bench/normal_field.py", table)
    print(f"bench: {doc} updated")
