"""The generated blocks of doc/verification.md and doc/studies.md (doc/generate.py writes and
checks them): the runs they need, how their numbers are printed, and one function per block.
BLOCKS says which page each block is on, which function writes it and what it runs."""
import csv
import json
import math
import os
import re
import shutil
import sys
import threading

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))
from contact_references import cattaneo_mindlin as reference_cattaneo_mindlin  # noqa: E402
from contact_references import hertz, hertz_pressure_errors, node_spacing  # noqa: E402
from contactlab_run import contactlab_run  # noqa: E402

# Below this a quantity is round-off (a gap closed exactly, 1 rank against 2) and is written as
# a bound, not a value: its digits change with the BLAS kernels.
ROUNDOFF = 1e-10


# ---------------------------------------------------------------- number formatting

def num(x, digits=4):
    """x to `digits` significant digits, always with a point or an exponent, so that the check
    compares it within NUMBER_RTOL (a bare integer is compared exactly)."""
    s = f"{x:.{digits}g}"
    if re.fullmatch(r"-?\d+", s):
        s = f"{x:.{digits - 1}e}" if abs(x) >= 10 ** digits else f"{x:.1f}"
    return s


def pct(x, digits=2):
    """A fraction as a percentage to `digits` significant digits."""
    return f"{num(100 * x, digits)} %"


def bounded(x, scale=1.0, floor=ROUNDOFF, why="round-off"):
    """x / scale, or the bound `floor` (with why) when it is below: the digits of a quantity
    that round-off or a solver's tolerance decides are not the case's."""
    return f"< {floor:.0e} ({why})" if abs(x) < floor * scale else num(x / scale, 2)


def table(header, rows):
    """A Markdown table."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------- runs

class Runs:
    """`contactlab run`s into WORK, each once: the same scene and settings give the same run
    (blocks share them)."""

    def __init__(self, exe, work, ranks=1):
        self.exe, self.work, self.ranks = exe, work, ranks
        self.done, self.lock = {}, threading.Lock()

    def __call__(self, scene, sets=(), ranks=None):
        """(summary, contact.csv rows, return code) of SCENE (a name in scenes/) with SETS, on
        RANKS ranks (default the --ranks given)."""
        ranks = ranks or self.ranks
        key = self._key(scene, sets, ranks)
        with self.lock:
            entry = self.done.setdefault(key, {"lock": threading.Lock(), "n": len(self.done)})
        with entry["lock"]:  # a second block asking for a run under way waits for it
            if "result" not in entry:
                entry["out"] = os.path.join(self.work, "runs",
                                            f"{entry['n']:03d}-{scene}-np{ranks}")
                entry["result"] = self._run(scene, sets, ranks, entry["out"])
        return entry["result"]

    def folder(self, scene, sets=(), ranks=None):
        """The output folder of that run (run first if needed): its other files."""
        self(scene, sets, ranks)
        return self.done[self._key(scene, sets, ranks)]["out"]

    def _key(self, scene, sets, ranks):
        return (scene, tuple(sets), ranks or self.ranks)

    def _run(self, scene, sets, ranks, out):
        shutil.rmtree(out, ignore_errors=True)
        path = os.path.join(ROOT, "scenes", scene + ".yaml")
        cmd, run = contactlab_run(self.exe, path, out, ["Output/VTK=false"] + list(sets), ranks,
                                  options=["--quiet"])
        summary_file = os.path.join(out, "summary.json")
        if not os.path.exists(summary_file):
            sys.exit(f"{' '.join(cmd)} wrote no summary ({run.returncode}):\n{run.stderr}")
        contact = os.path.join(out, "contact.csv")  # none when no step converged
        rows = list(csv.DictReader(open(contact))) if os.path.exists(contact) else []
        return json.load(open(summary_file)), rows, run.returncode

    def study(self, name, plots_to=None, prefix=None):
        """The rows of study.csv of scenes/studies/NAME.yaml; its plots copied into PLOTS_TO as
        PREFIX-*.png (default study-NAME) when given."""
        out = os.path.join(self.work, "study-" + name)
        shutil.rmtree(out, ignore_errors=True)
        path = os.path.join(ROOT, "scenes", "studies", name + ".yaml")
        cmd, run = contactlab_run(self.exe, path, out, command="study",
                                  options=[] if plots_to else ["--no-plots"], timeout=1800)
        if run.returncode != 0:
            sys.exit(f"{' '.join(cmd)} exited with {run.returncode}:\n{run.stdout}\n{run.stderr}")
        if plots_to:
            for png in ("accuracy_vs_time", "newton_per_step", "sensitivity"):
                if os.path.exists(os.path.join(out, png + ".png")):
                    shutil.copy(os.path.join(out, png + ".png"), os.path.join(
                        plots_to, f"{prefix or 'study-' + name}-{png.replace('_', '-')}.png"))
        return list(csv.DictReader(open(os.path.join(out, "study.csv"))))


def closed(rows):
    return [r for r in rows if int(r["status"]) != 0]


def newton(summary):
    return summary["iterations"]["newton"]


# ---------------------------------------------------------------- Hertz 2D (V1)

H2_SETS = {"augmented-lagrangian": [],
           "lagrange": ["Contact/floor/Formulation/lagrange/Normal Complementarity Constant=100"],
           "penalty": ["Contact/floor/Formulation/penalty/Normal Penalty=1e4"]}
H2_ESTAR = 1 / (1 - 0.3 ** 2)  # E = 1, nu = 0.3 on a rigid plane


def hertz_2d_errors(summary, rows, estar, radius=1.0):
    """|p - p_H| / p0 at the nodes (contact_references.hertz_pressure_errors: max and rms over
    |x| <= 0.9a, max beyond, the nodes inside the contact width), with P, a and p0."""
    P = summary["contact"]["normal_force"]
    a, p0 = hertz(P, estar, radius, 2)
    return dict(P=P, a=a, p0=p0, **hertz_pressure_errors(rows, a, p0, 2))


def h2_run(runs, formulation, extra=()):
    return runs("hertz-2d", [f"Contact/floor/Formulation/Type={formulation}"]
                + H2_SETS[formulation] + list(extra))


def block_hertz_2d(runs, figures):
    """V1: each formulation's pressure against Hertz's, and the figure."""
    out = []
    for f in H2_SETS:
        summary, rows, _ = h2_run(runs, f)
        e = hertz_2d_errors(summary, rows, H2_ESTAR)
        out.append([f, num(e["P"]), num(e["a"], 3), num(e["p0"]), e["inside"], pct(e["max"]),
                    pct(e["rms"]), pct(e["edge"]),
                    bounded(summary["contact"]["max_penetration"]), newton(summary)])
    plot_hertz_2d(runs, os.path.join(figures, "hertz2d-pressure.png"))
    return table(["formulation", "P", "a", "p0", "nodes in 2a", "max \\|p − p_H\\|/p0 "
                  "(\\|x\\| ≤ 0.9a)", "rms", "edge nodes", "max penetration", "Newton its"],
                 out) + "\n![V1 pressure profile](figures/hertz2d-pressure.png)\n"


def plot_hertz_2d(runs, path):
    """The pressure of each formulation against Hertz's profile, in units of a and p0."""
    from matplotlib.figure import Figure
    fig = Figure(figsize=(6.4, 4.0))
    ax = fig.subplots()
    for marker, f in zip("os^", H2_SETS):
        summary, rows, _ = h2_run(runs, f)
        e = hertz_2d_errors(summary, rows, H2_ESTAR)
        pts = sorted((float(r["x"]) / e["a"], float(r["pressure"]) / e["p0"]) for r in rows)
        pts = [p for p in pts if abs(p[0]) < 1.5]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker, ms=4, mfc="none", label=f)
    xh = [-1.5 + 3 * k / 600 for k in range(601)]
    ax.plot(xh, [math.sqrt(max(0.0, 1 - x * x)) for x in xh], "k-", lw=1, label="Hertz")
    ax.set_xlabel("x / a")
    ax.set_ylabel("p / p0")
    ax.set_title(f"V1 Hertz 2D, half disc on a rigid plane (a/R = {e['a']:.2f}, "
                 f"a/h = {e['inside'] / 2:.0f})")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def block_hertz_2d_refinement(runs, figures):
    """V1: the augmented Lagrangian's error as the contact mesh is refined, at two loads."""
    out = []
    for delta, sizes in (("0.01", ("0.01", "0.005", "0.0025", "0.00125")),
                         ("0.0025", ("0.005", "0.0025", "0.00125"))):
        for h in sizes:
            extra = [] if (delta, h) == ("0.01", "0.005") else [
                f"Mesh/half-disc/Size Contact={h}", f"Dirichlet/press/Value=-{delta}"]
            e = hertz_2d_errors(*h2_run(runs, "augmented-lagrangian", extra)[:2], H2_ESTAR)
            out.append([delta, num(e["a"], 2), h, f"{e['inside'] / 2:.1f}", pct(e["max"]),
                        pct(e["rms"], 3), pct(e["edge"])])
    return table(["δ", "a/R", "Size Contact", "a/h", "max", "rms", "edge node"], out)


# ---------------------------------------------------------------- patch test (V3)

PATCH_SETS = {"augmented-lagrangian": [],
              "lagrange": ["Contact/interface/Formulation/lagrange/"
                           "Normal Complementarity Constant=2e7"],
              "penalty": ["Contact/interface/Formulation/penalty/Normal Penalty=2e9"]}


def block_patch_test_nts(runs, figures):
    """V3, node-to-segment on non-matching meshes: each side as the slave, every formulation."""
    out = []
    for side, swap in (("finer (lower, 5 divisions)", []),
                       ("coarser (upper, 3 divisions)", ["Contact/interface/Slave=upper-bottom",
                                                         "Contact/interface/Master=lower-top"])):
        for f, extra in PATCH_SETS.items():
            summary, rows, _ = runs("patch-test-2d", swap + extra + [
                f"Contact/interface/Formulation/Type={f}"])
            p = [float(r["pressure"]) for r in closed(rows)]
            dev = max(abs(x - 1e5) for x in p) / 1e5
            out.append([side, f, len(p), pct(dev), num(min(p), 4), num(max(p), 4),
                        num(summary["contact"]["normal_force"] / 1e5, 5)])
    return table(["slave side", "formulation", "closed points", "max deviation from 1e5",
                  "lowest pressure", "highest", "total force / 1e5"], out)


# ---------------------------------------------------------------- Coulomb (V5)

V5_SETS = {"penalty": ["Contact/floor/Formulation/penalty/Normal Penalty=1e6",
                       "Contact/floor/Formulation/penalty/Tangential Penalty=1e6"],
           "lagrange": ["Contact/floor/Formulation/lagrange/Normal Complementarity Constant=1e4",
                        "Contact/floor/Formulation/lagrange/"
                        "Tangential Complementarity Constant=100"],
           "augmented-lagrangian": []}


def v5_cell(summary, rows, returncode, applied=2.97):
    """What the sliding block did: held the applied tangential load (to what relative error,
    how many points stick), or stopped with the solver's reason."""
    if not summary["converged"]:
        return f"stops: `{summary['failure']}` (exit code {returncode})"
    T = abs(summary["contact"]["tangential_force_vector"][0])
    sticking = sum(int(r["status"]) == 1 for r in rows)
    # T is carried to Newton's tolerance (1e-8 relative: 1.7e-10 with lagrange, round-off else).
    error = bounded(abs(T - applied), applied, 1e-8, "Newton's tolerance")
    return f"holds: \\|T/{applied} − 1\\| {error}, {sticking} of {len(closed(rows))} points stick"


def block_coulomb(runs, figures):
    """V5: the block below (μ = 0.3) and above (μ = 0.29406) the Coulomb threshold."""
    out = []
    for case, mu in (("T = 0.99 μN (μ = 0.3)", []),
                     ("T = 1.01 μN (μ = 0.29406)", ["Contact/floor/Friction=0.29406"])):
        out.append([case] + [v5_cell(*runs("sliding-block-2d", mu + extra + [
            f"Contact/floor/Formulation/Type={f}"])) for f, extra in V5_SETS.items()])
    return table(["case"] + list(V5_SETS), out)


# ---------------------------------------------------------------- Cattaneo-Mindlin (V4)

CM_ESTAR, CM_RADIUS, CM_MU = 0.5494505494505495, 0.5, 0.3


def cattaneo_mindlin(summary, rows):
    """The stick zone and the shear traction against Cattaneo-Mindlin's for the computed P and
    Q (contact_references.cattaneo_mindlin): c/a both ways, the offset in node spacings, the
    traction error / (mu p0) inside the stick zone (|x| <= 0.9c) and over |x| <= 0.9a."""
    P = summary["contact"]["normal_force"]
    Q = abs(summary["contact"]["tangential_force_vector"][0])
    pts = closed(rows)
    cm = reference_cattaneo_mindlin(pts, P, Q, CM_MU, CM_ESTAR, CM_RADIUS)
    a = cm["a"]
    return dict(P=P, a=a, p0=cm["p0"], ratio=Q / (CM_MU * P), c=cm["c"] / a,
                c_fe=cm["c_fe"] / a, centre=cm["centre"] / a,
                offset=abs(cm["c_fe"] - cm["c"]) / node_spacing(pts),
                stick_err=cm["stick_error"], err=cm["error"])


def cm_run(runs, discretization="node-to-segment", basis="dual"):
    return runs("cattaneo-mindlin-2d", [f"Contact/interface/Discretization={discretization}",
                                        f"Contact/interface/Multiplier Basis={basis}"])


def block_cattaneo_mindlin(runs, figures):
    """V4: the stick zone and shear traction of the shipped scene (node-to-segment)."""
    summary, rows, _ = cm_run(runs)
    e = cattaneo_mindlin(summary, rows)
    return table(["quantity", "Cattaneo–Mindlin", "computed"], [
        ["normal load P, Hertz half-width a, peak p0", "—",
         f"P = {num(e['P'])}, a = {num(e['a'], 3)}, p0 = {num(e['p0'], 3)}"],
        ["Q/(μP)", "—", num(e["ratio"], 3)],
        ["stick zone c/a", num(e["c"]), f"{num(e['c_fe'])} ({num(e['offset'], 2)} node spacing "
         f"off, centred to {num(abs(e['centre']), 1)} a)"],
        ["shear traction inside the stick zone (\\|x\\| ≤ 0.9c), max \\|t − q\\|/(μp0)", "—",
         pct(e["stick_err"])],
        ["shear traction over \\|x\\| ≤ 0.9a", "—", pct(e["err"])],
        ["Newton iterations", "—", newton(summary)]])


def block_cattaneo_mindlin_mortar(runs, figures):
    """V4 with mortar, each multiplier basis, against node-to-segment."""
    out = []
    for name, args in (("node-to-segment", ()), ("mortar, dual basis", ("mortar", "dual")),
                       ("mortar, standard basis", ("mortar", "standard"))):
        summary, rows, _ = cm_run(runs, *args)
        e = cattaneo_mindlin(summary, rows)
        out.append([name, newton(summary), num(e["c_fe"], 3), num(e["offset"], 2),
                    pct(e["stick_err"], 3)])
    return table(["discretization", "Newton its", f"c/a (Cattaneo {num(e['c'])})",
                  "c off by (node spacings)", "shear traction error in the stick zone / μp0"],
                 out)


# ---------------------------------------------------------------- tube joint after each stage

TUBE_STAGES = ((2.0, "expanded and released, 20 °C"), (3.0, "heated to 304 °C"),
               (4.0, "in operation, 15.5 MPa"))


def tube_joint(folder, time):
    """(axial position, pressure, closed) of the joint's slave nodes at TIME, along the tube."""
    rows = list(csv.DictReader(open(os.path.join(folder, f"contact_t{time:g}.csv"))))
    return sorted((float(r["reference_y"]), float(r["pressure"]), int(r["status"]) != 0)
                  for r in rows)


def tube_hoop(folder, time):
    """(axial position, hoop stress) along the tube's mid-wall at TIME: the scene's
    Output/Profiles/tube-mid-wall (axisymmetric: stress_zz is the hoop stress)."""
    rows = csv.DictReader(open(os.path.join(folder, f"profile_tube-mid-wall_t{time:g}.csv")))
    return [(float(r["node_y"]), float(r["stress_zz"])) for r in rows]


def block_tube_stages(runs, figures):
    """The seed's chain, axisymmetric: the joint's contact pressure along the expanded length
    (Output/Contact Times) and the tube's hoop stress at mid-wall (Output/Profiles) after each
    stage, a row per stage and the figure."""
    scene = "tube-expansion-thermal-axisymmetric"
    folder = runs.folder(scene)
    joints = {time: tube_joint(folder, time) for time, _ in TUBE_STAGES}
    hoops = {time: tube_hoop(folder, time) for time, _ in TUBE_STAGES}
    out = []
    for time, stage in TUBE_STAGES:
        points = joints[time]
        closed = [(z, p) for z, p, c in points if c]
        hoop = [h for _, h in hoops[time]]
        out.append([stage, num(time, 2), f"{len(closed)} of {len(points)}",
                    f"{num(min(z for z, _ in closed), 3)} to {num(max(z for z, _ in closed), 3)}",
                    num(sum(p for _, p in closed) / len(closed)), num(max(p for _, p in closed)),
                    num(sum(hoop) / len(hoop)), f"{num(min(hoop))} to {num(max(hoop))}"])
    plot_tube_stages(joints, hoops, os.path.join(figures, "tube-stages-pressure.png"))
    return table(["stage", "t", "closed nodes", "closed over z (mm)", "mean pressure (MPa)",
                  "max pressure (MPa)", "mean hoop stress at mid-wall (MPa)",
                  "hoop stress range (MPa)"], out) + \
        "\n![Joint pressure and tube hoop stress after each stage]" \
        "(figures/tube-stages-pressure.png)\n"


def plot_tube_stages(joints, hoops, path):
    """The nodal contact pressure along the tube after each stage (tube_joint's points by
    time; open nodes hollow at 0), and the tube's mid-wall hoop stress (tube_hoop's)."""
    from matplotlib.figure import Figure
    fig = Figure(figsize=(6.4, 6.4))
    top, bottom = fig.subplots(2, 1, sharex=True)
    for (time, stage), colour in zip(TUBE_STAGES, ("C0", "C1", "C3")):
        points = joints[time]
        top.plot([z for z, _, _ in points], [p for _, p, _ in points], "-", color=colour, lw=0.8,
                 label=f"t = {time:g}: {stage}")
        top.plot([z for z, _, c in points if not c], [0.0 for _, _, c in points if not c], "o",
                 color=colour, mfc="none", ms=4)
        bottom.plot([z for z, _ in hoops[time]], [h for _, h in hoops[time]], ".-",
                    color=colour, lw=0.8, ms=3)
    top.set_ylabel("contact pressure (MPa)")
    top.set_title("Tube-to-tubesheet joint (axisymmetric, mortar): after each stage")
    top.legend(fontsize=8)
    bottom.set_xlabel("axial position z (mm)")
    bottom.set_ylabel("tube hoop stress at mid-wall (MPa)")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


# ---------------------------------------------------------------- 1 rank against 2

def block_ranks_agree(runs, figures):
    """The same scene on 1 and 2 ranks: contact results point by point, iteration counts."""
    out = []
    for scene in ("hertz-2d-two-body", "sliding-block-2d", "hertz-3d"):
        (s1, one, _), (s2, two, _) = runs(scene, ranks=1), runs(scene, ranks=2)
        two = {(r["zone"], r["node"]): r for r in two}
        scale = max(abs(float(r["pressure"])) for r in one)
        worst = max(abs(float(r[f]) - float(two[(r["zone"], r["node"])][f]))
                    for r in one for f in ("pressure", "traction_x", "traction_y", "traction_z"))
        same = all(r["status"] == two[(r["zone"], r["node"])]["status"] for r in one)
        out.append([f"`{scene}`", len(one), "yes" if same else "**no**",
                    bounded(worst, scale), newton(s1), newton(s2)])
    return table(["scene", "contact points", "same statuses", "max difference of p and t / "
                  "max p", "Newton its, 1 rank", "2 ranks"], out)


# ---------------------------------------------------------------- studies

def cell(r, key, digits=3):
    return num(float(r[key]), digits) if r[key] not in ("", None) else "–"


def block_quick_comparison(runs, figures):
    """The quick comparison (`make run`) without its timings."""
    rows = runs.study("quick-comparison", figures)
    out = [[r["Contact/interface/Formulation/Type"], r["Algorithm/Method"],
            r["Contact/interface/Discretization"],
            "yes" if r["status"] == "converged" else f"no: {r['reason']}", r["newton"],
            cell(r, "pressure_error_l2"), cell(r, "shear_error_l2")] for r in rows]
    return table(["formulation", "algorithm", "discretization", "converged", "Newton its",
                  "p err", "τ err"], out)


def block_hertz_2d_study(runs, figures):
    """The worked 2D Hertz study without its timings, in the study's order."""
    rows = runs.study("hertz-2d-formulations", figures, "study-hertz-2d")
    out = [[r["case"], r["status"] if r["status"] == "converged" else f"**{r['reason']}**",
            r["newton"], r["linear_solves"], cell(r, "pressure_error_l2"),
            cell(r, "pressure_error_max"),
            bounded(float(r["max_penetration"])) if r["max_penetration"] else "–",
            f"{r['unknowns_displacement']}+{r['unknowns_contact']}+{r['unknowns_friction']}"]
           for r in rows]
    return table(["case", "result", "Newton its", "linear solves", "p error L2", "p error max",
                  "max penetration", "unknowns (u + λn + λt)"], out)


EXTREMES_PRESETS = ("generalized-newton", "partial-newton", "fixed-point")


def block_extremes(runs, figures):
    """The extremes study: each case under each preset, a row a case. (Rows with the same
    outcomes were merged once; an iteration count that another BLAS kernel set moves within
    its band then split or joined rows, and the check compared the wrong ones.)"""
    rows = runs.study("extremes")
    by_case = {}
    for r in rows:
        outcome = f"✓ {r['newton']}" if r["status"] == "converged" else r["reason"] or r["status"]
        by_case.setdefault(r["case"].rsplit(",Method=", 1)[0], {})[r["Algorithm/Method"]] = (
            outcome, f"{r['unknowns_displacement']}+{r['unknowns_contact']}+"
                     f"{r['unknowns_friction']}")
    return table(["case", "generalized Newton", "partial Newton", "fixed point",
                  "unknowns (u + λn + λt)"],
                 [[case] + [cells[p][0] for p in EXTREMES_PRESETS] +
                  [cells[EXTREMES_PRESETS[0]][1]] for case, cells in by_case.items()])


# ---------------------------------------------------------------- the blocks

# name: (page, function, what it runs)
BLOCKS = {
    "hertz-2d": ("verification.md", block_hertz_2d,
                 "`hertz-2d`, each formulation; figures/hertz2d-pressure.png"),
    "hertz-2d-refinement": ("verification.md", block_hertz_2d_refinement,
                            "`hertz-2d`, 7 contact meshes and loads"),
    "patch-test-nts": ("verification.md", block_patch_test_nts,
                       "`patch-test-2d`, each side as slave × each formulation"),
    "coulomb": ("verification.md", block_coulomb,
                "`sliding-block-2d`, below and above the threshold × each formulation"),
    "cattaneo-mindlin": ("verification.md", block_cattaneo_mindlin, "`cattaneo-mindlin-2d`"),
    "cattaneo-mindlin-mortar": ("verification.md", block_cattaneo_mindlin_mortar,
                                "`cattaneo-mindlin-2d`, node-to-segment and mortar"),
    "tube-stages": ("verification.md", block_tube_stages,
                    "`tube-expansion-thermal-axisymmetric`; figures/tube-stages-pressure.png"),
    "ranks-agree": ("verification.md", block_ranks_agree,
                    "`hertz-2d-two-body`, `sliding-block-2d`, `hertz-3d` on 1 and 2 ranks"),
    "quick-comparison": ("studies.md", block_quick_comparison,
                         "`scenes/studies/quick-comparison.yaml` and its plots"),
    "hertz-2d-study": ("studies.md", block_hertz_2d_study,
                       "`scenes/studies/hertz-2d-formulations.yaml` and its plots"),
    "extremes": ("studies.md", block_extremes, "`scenes/studies/extremes.yaml`"),
}
