#!/usr/bin/env python3
"""Algorithms benchmark (issue 4): each algorithm preset x Newton driver / line search x
cycling treatment on the frictional pad (scenes/pad-2d.yaml, mu = 0.45 and 1.0) and the
frictional 3D Hertz (scenes/hertz-3d-friction.yaml). One `contactlab run` per case; the table
(result, iterations per loop, linear solves, cycling events, wall time) goes to stdout and,
with --doc, into doc/performance.md between the bench:algorithms markers.

usage: algorithms.py CONTACTLAB SCENES_DIR WORKDIR [--doc doc/performance.md] [--quick]
--quick: the pad at mu = 0.45 only, plain driver and NOX Backtrack (a smoke run)."""
import datetime, os, re, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import runs

exe, scenes, work = runs.positional(__doc__, 3)
doc = sys.argv[sys.argv.index("--doc") + 1] if "--doc" in sys.argv else None
quick = "--quick" in sys.argv

cases = [("pad-2d", "pad-2d", ["Contact/floor/Friction=0.45"], "μ = 0.45")]
if not quick:
    cases += [("pad-2d", "pad-2d", ["Contact/floor/Friction=1.0"], "μ = 1.0"),
              ("hertz-3d-friction", "hertz-3d-friction", [], "μ = 0.3")]
drivers = [("plain", None), ("nox", "Full Step"), ("nox", "Backtrack"), ("nox", "Polynomial"),
           ("nox", "More'-Thuente")]
if quick:
    drivers = [drivers[0], drivers[2]]
methods = ["fixed-point", "partial-newton", "generalized-newton"]
treatments = ["none", "automatic", "forced"]

rows = []
header = ("| scene | method | Newton (line search) | cycling treatment | result | Newton its "
          "| status its | threshold its | geometry its | linear solves | cycling events | wall s |")
print(header)
print("|" + "---|" * 12)
for label, scene, sets, what in cases:
    for method in methods:
        for driver, search in drivers:
            for treatment in treatments:
                name = f"{label}-{what}-{method}-{driver}-{search}-{treatment}"
                out = os.path.join(work, re.sub(r"[^A-Za-z0-9.-]+", "_", name))
                # Each Newton alone: without the default retry of a failed last step with
                # Backtrack (doc/algorithms.md "Line search retry").
                options = [f"Algorithm/Method={method}",
                           f"Algorithm/Cycling Treatment={treatment}", f"Newton/Driver={driver}",
                           "Newton/Line Search Retry=never"]
                if search:
                    options.append(f"Newton/Line Search={search}")
                s, wall, _ = runs.run(exe, "run", os.path.join(scenes, scene + ".yaml"), out,
                                      options + sets, timeout=1800)
                if s is None:
                    result, counts = "no summary", ["-"] * 6
                else:
                    it = s["iterations"]
                    result = "converged" if s["converged"] else s["failure"]
                    counts = [it["newton"], it["status"], it["threshold"], it["geometry"],
                              s["linear_solves"], sum(s["cycling"].values())]
                line = (f"| {label} {what} | {method} | {driver}" +
                        (f" ({search})" if search else "") + f" | {treatment} | {result} | " +
                        " | ".join(str(c) for c in counts) + f" | {wall:.1f} |")
                print(line, flush=True)
                rows.append(line)

if doc:
    table = header + "\n|" + "---|" * 12 + "\n" + "\n".join(rows) + "\n"
    start, end = "<!-- bench:algorithms:start -->", "<!-- bench:algorithms:end -->"
    block = (f"{start}\nMeasured {datetime.date.today()} by `bench/algorithms.py` "
             f"(one rank, MUMPS):\n\n{table}{end}")
    text = open(doc).read()
    if start not in text:
        sys.exit(f"{doc} has no {start} marker")
    text = re.sub(re.escape(start) + ".*?" + re.escape(end), lambda m: block, text, flags=re.S)
    open(doc, "w").write(text)
    print(f"bench: {doc} updated")
