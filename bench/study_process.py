#!/usr/bin/env python3
"""A study's runs the default way (as many at a time as the cores, each `contactlab batch`
process taking its share of the runs: Parallel Runs automatic), in one batch process one at a
time (Parallel Runs: 1), and each in a process of its own, one at a time (Process Per Run: true):
the study's wall time each way, and against one `contactlab run` of its first case (the issue's
"a 100-run study costs <= 3x one run"). Checks that the default and a process per run give every
run the same status, Newton iterations and contact force (to the solvers' tolerances: a run on
one mesh may be solved through corrections of the last run's factors; see differences()) and
exits non-zero otherwise.

Studies: the shipped quick comparison (18 runs, 2D), the 2D Hertz formulation study (18), the
extremes (78), 100 runs of the 2D Hertz scene (50 augmentations x 2 algorithms) and 9 runs of the 3D Hertz scene in tet10 at 46 572 dofs (3 augmentations x 3
algorithms). About 8 minutes in all.

usage: study_process.py CONTACTLAB SCENES WORK [--only NAME ...] [--doc DOC]"""
import argparse, csv, json, os, shutil, subprocess, sys, time

import docblock
import runs

HERTZ_2D_100 = """contactlab-study:
  Name: hertz-2d-100
  Scene: {scenes}/hertz-2d.yaml
  Sets: ["Output/VTK=false"]
  Axes:
    Contact/floor/Formulation/augmented-lagrangian/Normal Augmentation: [{augmentations}]
    Algorithm/Method: [partial-newton, generalized-newton]
"""
HERTZ_3D = """contactlab-study:
  Name: hertz-3d-tet10
  Scene: {scenes}/hertz-3d.yaml
  Sets: ["Output/VTK=false", "Mesh/half-sphere/Element=tet10"]
  Axes:
    Contact/floor/Formulation/augmented-lagrangian/Normal Augmentation: [20, 50, 100]
    Algorithm/Method: [partial-newton, generalized-newton, fixed-point]
"""


def studies(scenes, work):
    """(name, study file) of each measured study."""
    shipped = os.path.join(scenes, "studies")
    out = [(n, os.path.join(shipped, n + ".yaml"))
           for n in ("quick-comparison", "hertz-2d-formulations", "extremes")]
    augmentations = ", ".join(f"{10 ** (4 * k / 49):.4g}" for k in range(50))  # 1 to 1e4
    for name, text in (("hertz-2d-100", HERTZ_2D_100), ("hertz-3d-tet10", HERTZ_3D)):
        path = os.path.join(work, name + ".yaml")
        open(path, "w").write(text.format(scenes=os.path.abspath(scenes),
                                          augmentations=augmentations))
        out.append((name, path))
    return out


def with_settings(path, work, suffix, **settings):
    """A copy of the study file with `settings` (its Scene made absolute)."""
    import yaml
    doc = yaml.safe_load(open(path))
    s = doc["contactlab-study"]
    s["Scene"] = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(path)), s["Scene"]))
    for case in s.get("Cases", []):
        if "Scene" in case:
            case["Scene"] = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(path)),
                                                          case["Scene"]))
    s.update(settings)
    copy = os.path.join(work, os.path.basename(path).replace(".yaml", f"-{suffix}.yaml"))
    yaml.safe_dump(doc, open(copy, "w"), sort_keys=False)
    return copy


def run_study(exe, path, out):
    shutil.rmtree(out, ignore_errors=True)
    start = time.time()
    done = subprocess.run([exe, "study", path, "--out", out, "--no-plots"], capture_output=True,
                          text=True, timeout=7200)
    wall = time.time() - start
    if done.returncode != 0:
        sys.exit(f"{path}: the study failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    rows = list(csv.DictReader(open(os.path.join(out, "study.csv"))))
    return wall, rows


def force(row):
    try:
        return json.load(open(os.path.join(row["folder"], "summary.json")))["contact"]["normal_force"]
    except (OSError, ValueError, KeyError, TypeError):
        return None


def differences(shared, own):
    """Runs whose outcome differs between the two ways beyond the solvers' tolerances, and
    those that differ within them. A run in the shared process may be solved through
    corrections of the last run's factors, exact to the solver's tolerance but not bitwise: the
    contact force then agrees to Newton's tolerance (1e-8 on the residual; the penalty runs'
    stiff terms amplify it: 5.3e-7 relative measured on the quick comparison, bound 1e-5), and
    a run whose Newton path goes through cycling treatments (round-off decides them,
    doc/algorithms.md "Round-off") may take a few iterations more or fewer (within 3 or 20 %,
    the docs' band)."""
    beyond, within = [], []
    for a, b in zip(shared, own):
        fa, fb = force(a), force(b)
        na, nb = int(a["newton"]), int(b["newton"])
        chaotic = int(a.get("cycling_events") or 0) + int(b.get("cycling_events") or 0) > 0
        close = (fa is None or abs(fa - fb) <= 1e-5 * max(abs(fa), abs(fb), 1e-300))
        same = (a["status"] == b["status"] and (fa is None) == (fb is None) and close and
                (na == nb or chaotic and abs(na - nb) <= max(3, 0.2 * max(na, nb))))
        text = f"{a['case']}: {a['status']} {na} {fa!r} / {b['status']} {nb} {fb!r}"
        if not same:
            beyond.append(text)
        elif na != nb or fa != fb:
            within.append(text)
    return beyond, within


def one_run(exe, path, first_sets, work):
    """Wall seconds of one `contactlab run` of the study's first case."""
    import yaml
    s = yaml.safe_load(open(path))["contactlab-study"]
    scene = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(path)), s["Scene"]))
    summary, wall, done = runs.run(exe, "run", scene, os.path.join(work, "one-run"), first_sets)
    return wall


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("scenes")
    ap.add_argument("work")
    ap.add_argument("--only", nargs="+")
    ap.add_argument("--doc")
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    exe = os.path.abspath(args.exe)
    table = ("| study | runs (converged) | process per run s | one process s | default s | "
             "speed-up | one run s | default / one run | outcomes differing |\n"
             "|---|---|---|---|---|---|---|---|---|\n")
    failed = False
    for name, path in studies(args.scenes, args.work):
        if args.only and name not in args.only:
            continue
        own_wall, own = run_study(exe, with_settings(path, args.work, "own", **{
            "Process Per Run": True, "Parallel Runs": 1}), os.path.join(args.work, name + "-own"))
        serial_wall, _ = run_study(exe, with_settings(path, args.work, "serial", **{
            "Parallel Runs": 1}), os.path.join(args.work, name + "-serial"))
        shared_wall, shared = run_study(exe, path, os.path.join(args.work, name + "-shared"))
        differ, roundoff = differences(shared, own)
        failed |= bool(differ)
        single = one_run(exe, path, shared[0]["sets"].split(";") if shared[0]["sets"] else [],
                         args.work)
        converged = sum(row["status"] == "converged" for row in shared)
        line = (f"| {name} | {len(shared)} ({converged}) | {own_wall:.1f} | {serial_wall:.1f} | "
                f"{shared_wall:.1f} | {own_wall / shared_wall:.2f} | {single:.2f} | "
                f"{shared_wall / single:.1f} | {len(differ)} |")
        print(line, flush=True)
        for d in differ:
            print("  differs: " + d)
        for d in roundoff:
            print("  differs within the solvers' tolerances: " + d)
        table += line + "\n"
    print(table)
    if args.doc:
        docblock.write(args.doc, "study-process", "bench/study_process.py", table)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
