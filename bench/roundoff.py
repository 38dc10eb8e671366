#!/usr/bin/env python3
"""Round-off sweep: runs the regression gold (tests/regression/iterations.csv) under several
OpenBLAS kernel sets (OPENBLAS_CORETYPE) and prints, per row, the counts that differ between
them. A count that moves is decided by round-off, not by the algorithm: the gold must not pin it
exactly (doc/algorithms.md "Round-off"). Kernel sets this CPU cannot run are skipped.

usage: bench/roundoff.py [--build build] [--cores Haswell,SkylakeX,Zen,Prescott] [--rows 3,20]
"""
import argparse, csv, os, shutil, subprocess, sys, tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
ap = argparse.ArgumentParser()
ap.add_argument("--build", default=os.path.join(root, "build"))
ap.add_argument("--cores", default="Haswell,SkylakeX,Zen,Prescott")
ap.add_argument("--rows", default="", help="comma-separated row indices of the gold (default all)")
args = ap.parse_args()

gold = os.path.join(root, "tests", "regression", "iterations.csv")
rows = list(csv.DictReader(open(gold)))
keep = [int(i) for i in args.rows.split(",") if i] or list(range(len(rows)))
flags = open("/proc/cpuinfo").read()
work = tempfile.mkdtemp(prefix="roundoff-")
results = {}
for core in args.cores.split(","):
    if core == "SkylakeX" and "avx512f" not in flags or core in ("Haswell", "Zen") and "avx2" not in flags:
        print(f"skip {core}: this CPU lacks its instructions")
        continue
    subset = os.path.join(work, f"gold-{core}.csv")
    with open(subset, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
        w.writeheader()
        w.writerows(rows[i] for i in keep)
    env = dict(os.environ, OPENBLAS_CORETYPE=core)
    subprocess.run([sys.executable, os.path.join(root, "tests", "regression", "check_iterations.py"),
                    os.path.join(args.build, "apps", "contactlab"), os.path.join(root, "scenes"),
                    os.path.join(work, core), subset, "--update"], env=env, check=True,
                   capture_output=True)
    results[core] = list(csv.DictReader(open(subset)))
    print(f"ran {core}")
fields = ["newton", "status", "threshold", "geometry", "linear_solves", "steps", "cuts", "cycling",
          "failure"]
moved = 0
for j, i in enumerate(keep):
    r = rows[i]
    diffs = [f"{k}: " + " ".join(f"{c}={results[c][j][k]}" for c in results) for k in fields
             if len({results[c][j][k] for c in results}) > 1]
    if diffs:
        moved += 1
        print(f"row {i} {r['scene']} {r['formulation']} {r['sets']} (tolerance {r['tolerance']}):")
        for d in diffs:
            print("    " + d)
print(f"{moved} of {len(keep)} rows move with the kernels ({', '.join(results)})")
shutil.rmtree(work, ignore_errors=True)
