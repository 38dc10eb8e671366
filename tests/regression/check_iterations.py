#!/usr/bin/env python3
"""Regression: the iteration counts of the shipped scenes, pinned in iterations.csv, so that a
change in convergence (Newton iterations, status / threshold / geometry fixed-point updates,
linear solves, converged steps, step cuts, cycling events, the failure's name) shows up even
when the answer stays within the verification tolerances.

usage: check_iterations.py CONTACTLAB SCENES_DIR WORKDIR GOLD [--update | --shard K/N]
--shard K/N runs the rows whose index is K modulo N only (the suite runs the gold in shards, so
that no single test runs long enough to time out on a busy machine).
Each gold row names a scene, its formulation (`-` for the scene's own) and `;`-separated
--set arguments (e.g. an algorithm preset); the run must reproduce every count exactly, except in
rows with a `tolerance` > 0: runs whose path goes through a cycling (non-converging) Newton are
chaotic, so the last bits of round-off (the BLAS kernels OpenBLAS picks for the CPU) change their
counts; there each count must lie within tolerance x gold of the gold value (the failure's name
stays exact, or one of `a|b`: where round-off decides how a chaotic path fails). A row's `unpinned` column (`;`-separated fields) names counts that are not compared
at all: counts of events along a failing run's path that round-off decides and no band bounds
(bench/roundoff.py measured 3 to 33 cycling events on one row across kernel sets;
doc/algorithms.md "Round-off"). --update rewrites GOLD from the current code, keeping each row's
tolerance and unpinned fields (review the diff: a change must be explained)."""
import csv, json, os, shutil, subprocess, sys

exe, scenes, work, gold = sys.argv[1:5]
update = "--update" in sys.argv[5:]
rows = list(csv.DictReader(open(gold)))
shard, shards = 0, 1
if "--shard" in sys.argv[5:]:
    shard, shards = map(int, sys.argv[sys.argv.index("--shard") + 1].split("/"))
    if update or not 0 <= shard < shards:
        sys.exit("--shard K/N: 0 <= K < N, and not with --update (which rewrites the whole gold)")
fields = ["newton", "status", "threshold", "geometry", "linear_solves", "steps", "cuts",
          "cycling", "failure"]
failures, out_rows = [], []
for index, row in enumerate(rows):
    if index % shards != shard:
        continue
    out = os.path.join(work, f"{index:02d}-{row['scene']}")
    shutil.rmtree(out, ignore_errors=True)
    cmd = [exe, "run", os.path.join(scenes, row["scene"] + ".yaml"), "--out", out]
    if row["formulation"] != "-":
        cmd += ["--set", f"{row['zone']}/Formulation/Type={row['formulation']}"]
    cmd += [arg for s in row["sets"].split(";") if s for arg in ("--set", s)]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    summary = json.load(open(os.path.join(out, "summary.json")))
    it = summary["iterations"]
    got = {"newton": it["newton"], "status": it["status"], "threshold": it["threshold"],
           "geometry": it["geometry"], "linear_solves": summary["linear_solves"],
           "steps": summary["load_steps"]["converged"], "cuts": summary["load_steps"]["cuts"],
           "cycling": sum(summary["cycling"].values()), "failure": summary["failure"] or "-"}
    new = dict(row, **{k: str(v) for k, v in got.items()})
    new.setdefault("tolerance", "0")
    new.setdefault("unpinned", "")
    out_rows.append(new)
    band = float(row.get("tolerance") or 0)
    unpinned = set(filter(None, (row.get("unpinned") or "").split(";")))

    # A failing chaotic path's last iterate, hence the failure's name, can also be round-off's:
    # `a|b` in the gold accepts either (a converging run, or another failure, still differs).
    accepted_failures = row["failure"].split("|")
    if got["failure"] in accepted_failures:
        new["failure"] = row["failure"]

    def differs(k):
        if k in unpinned:
            return False
        if k == "failure":
            return got[k] not in accepted_failures
        if band == 0:
            return str(got[k]) != row[k]
        return abs(got[k] - int(row[k])) > band * int(row[k])

    diff = [f"{k} {row[k]} -> {got[k]}" for k in fields if differs(k)]
    print(f"{'ok  ' if not diff else 'DIFF'} {row['scene']} {row['formulation']} {row['sets']}: "
          + (", ".join(diff) if diff else ", ".join(f"{k} {got[k]}" for k in fields)))
    if diff:
        failures.append(row["scene"])
if update:
    with open(gold, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["scene", "formulation", "zone", "sets"] + fields +
                           ["tolerance", "unpinned"], lineterminator="\n")
        w.writeheader()
        w.writerows(out_rows)
    print("updated", gold)
    sys.exit(0)
sys.exit(1 if failures else 0)
