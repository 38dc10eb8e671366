#!/usr/bin/env python3
"""Uniqueness-diagnostic benchmark (issue 6): `contactlab critical-mu` on the frictional 3D
Hertz (scenes/hertz-3d-friction.yaml) at three contact mesh sizes, up to about 1 000 contact
points. For each: the run's time (its load steps, without the diagnostic), the diagnostic's
time, the patterns examined and how, and the critical factors. The table goes to stdout and,
with --doc, into doc/performance.md between the bench:critical-mu markers.

usage: critical_mu.py CONTACTLAB SCENES_DIR WORKDIR [--doc doc/performance.md] [--quick]
--quick: the coarsest mesh only (a smoke run)."""
import datetime, os, re, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import runs

exe, scenes, work = runs.positional(__doc__, 3)
doc = sys.argv[sys.argv.index("--doc") + 1] if "--doc" in sys.argv else None
sizes = [0.02] if "--quick" in sys.argv else [0.02, 0.016, 0.014]


def factor(value):
    return "none" if value is None else f"{value:.4g}"


rows = []
header = ("| Size Contact | contact points | unknowns | Newton its | run s | diagnostic s "
          "| diagnostic / run | ambiguous points | patterns (by updates) | k | adjacent factor "
          "| slipping factor | μ_crit | verdict |")
print(header)
print("|" + "---|" * 14)
for size in sizes:
    out = os.path.join(work, f"hertz-3d-friction-{size}")
    scene = os.path.join(scenes, "hertz-3d-friction.yaml")
    s, _, done = runs.run(exe, "critical-mu", scene, out, [f"Mesh/half-sphere/Size Contact={size}"])
    try:
        c = s["critical_mu"]
    except (TypeError, KeyError):
        print(f"| {size} | failed: {done.stderr.strip()[-200:]} |" + " |" * 12)
        continue
    unknowns = sum(s["unknowns"].values())
    diagnostic = c["seconds"]
    run = s["seconds"]["total"] - diagnostic
    mu = next(iter(c["zones"].values()), None)
    row = (f"| {size} | {s['contact_points']} | {unknowns} | {s['iterations']['newton']} "
           f"| {run:.1f} | {diagnostic:.1f} | {diagnostic / run:.2f} | {c['ambiguous_points']} "
           f"| {c['patterns_examined']} ({c['patterns_updated']}) | {c['friction_rows']} "
           f"| {factor(c['adjacent_factor'])} | {factor(c['slipping_factor'])} | {factor(mu)} "
           f"| {c['verdict']} |")
    print(row, flush=True)
    rows.append(row)

if doc and rows:
    start, end = "<!-- bench:critical-mu:start -->", "<!-- bench:critical-mu:end -->"
    table = "\n".join([header, "|" + "---|" * 14] + rows) + "\n"
    block = (f"{start}\nMeasured {datetime.date.today()} by `bench/critical_mu.py` "
             f"(one rank):\n\n{table}{end}")
    text = open(doc).read()
    if start not in text:
        sys.exit(f"{doc}: no {start} marker")
    open(doc, "w").write(re.sub(re.escape(start) + ".*?" + re.escape(end), lambda m: block,
                                text, flags=re.S))
