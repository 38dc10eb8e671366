#!/usr/bin/env python3
"""Ironing benchmark (issue 16): scenes/ironing-2d.yaml (a neo-Hookean roller pressed into a
soft neo-Hookean block, then dragged along it) with each algorithm preset. Newton iterations
per load step, split into the pressing steps (t <= 0.3) and the sliding ones, from steps.csv;
the table goes to stdout and, with --doc, into doc/performance.md between the bench:ironing
markers.

usage: ironing.py CONTACTLAB SCENES_DIR WORKDIR [--doc doc/performance.md]"""
import csv, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import docblock, runs

exe, scenes, work = runs.positional(__doc__, 3)
doc = sys.argv[sys.argv.index("--doc") + 1] if "--doc" in sys.argv else None
PRESS_END = 0.3  # the scene's press Stop Time

header = ("| preset | result | steps (cuts) | Newton its | per pressing step, mean (max) "
          "| per sliding step, mean (max) | geometry updates | linear solves | wall s |\n"
          "|---|---|---|---|---|---|---|---|---|\n")
print(header, end="")
table = header


def per_step(rows):
    its = [int(r["newton_iterations"]) for r in rows]
    return f"{sum(its) / len(its):.1f} ({max(its)})" if its else "–"


for method in ["fixed-point", "partial-newton", "generalized-newton"]:
    out = os.path.join(work, method)
    s, wall, _ = runs.run(exe, "run", os.path.join(scenes, "ironing-2d.yaml"), out,
                          [f"Algorithm/Method={method}"], quiet=True)
    try:
        steps = list(csv.DictReader(open(os.path.join(out, "steps.csv")))) if s else []
    except OSError:
        s, steps = None, []
    if s is None:
        line = f"| `{method}` | no summary |" + " – |" * 6 + f" {wall:.1f} |"
    else:
        it = s["iterations"]
        press = [r for r in steps if float(r["time"]) <= PRESS_END + 1e-9]
        slide = [r for r in steps if float(r["time"]) > PRESS_END + 1e-9]
        cuts = sum(int(r["cuts"]) for r in steps)
        result = "converged" if s["converged"] else f"`{s['failure']}`"
        line = (f"| `{method}` | {result} | {len(steps)} ({cuts}) | {it['newton']} | "
                f"{per_step(press)} | {per_step(slide)} | {it['geometry']} | "
                f"{s['linear_solves']} | {wall:.1f} |")
    print(line, flush=True)
    table += line + "\n"

if doc:
    docblock.write(doc, "ironing", "bench/ironing.py", table)
    print(f"bench: {doc} updated")
