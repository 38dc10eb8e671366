#!/usr/bin/env python3
"""Every shipped scene (scenes/*.yaml) under each algorithm preset, everything else as the scene
says: what a user who switches `Algorithm/Method` on a scene meets. One `contactlab run` per case
(VTK off, one rank); the table (outcome or named failure, Newton iterations, fixed-point updates,
wall time) goes to stdout and, with --doc, into doc/algorithms.md between the
bench:scene-presets markers. About 6 minutes.

usage: scene_presets.py CONTACTLAB SCENES_DIR WORKDIR [--doc doc/algorithms.md] [--only NAME ...]
--only: those scenes only (a smoke run; not with --doc)."""
import glob, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import docblock
import runs

exe, scenes, work = runs.positional(__doc__, 3)
doc = sys.argv[sys.argv.index("--doc") + 1] if "--doc" in sys.argv else None
only = sys.argv[sys.argv.index("--only") + 1:] if "--only" in sys.argv else None
if doc and only:
    sys.exit("scene_presets.py: --only writes no table into a doc")
METHODS = [("PF", "fixed-point"), ("NP", "partial-newton"), ("NG", "generalized-newton")]


def cell(summary, wall):
    """'✓ N (s/t/g) wall' or the failure's name."""
    if summary is None:
        return "no summary"
    if not summary["converged"]:
        return f"`{summary['failure']}`"
    its = summary["iterations"]
    loops = "/".join(str(its[k]) for k in ("status", "threshold", "geometry"))
    return f"✓ {its['newton']} ({loops}), {wall:.1f} s"


rows, failures = [], 0
for path in sorted(glob.glob(os.path.join(scenes, "*.yaml"))):
    name = os.path.splitext(os.path.basename(path))[0]
    if only and name not in only:
        continue
    cells = []
    for short, method in METHODS:
        summary, wall, _ = runs.run(exe, "run", path, os.path.join(work, f"{name}-{short}"),
                                    [f"Algorithm/Method={method}"], quiet=True, timeout=900)
        cells.append(cell(summary, wall))
        failures += not (summary and summary["converged"])
        print(name, method, cells[-1], flush=True)
    rows.append(f"| {name} | " + " | ".join(cells) + " |")

header = ("| scene | fixed point | partial Newton | generalized Newton |\n"
          "|---|---|---|---|\n")
table = (header + "\n".join(rows) + "\n\n"
         f"{len(rows) * len(METHODS) - failures} of {len(rows) * len(METHODS)} runs converge "
         "(✓ Newton iterations (status / threshold / geometry updates), wall).\n")
print(table)
if doc:
    docblock.write(doc, "scene-presets", "bench/scene_presets.py", table)
    print(f"bench: {doc} updated")
