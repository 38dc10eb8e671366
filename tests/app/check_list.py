#!/usr/bin/env python3
"""`contactlab list [AXIS]` (issue 61): the whole reference (doc/scenes.md embeds it) had lines
up to 1 495 characters and `list formulation` printed all 552 lines. Now every line is within
100 columns, each AXIS prints its part alone (the parts make up the whole), and an unknown
axis is one sentence naming the valid ones, exit 2.

usage: check_list.py CONTACTLAB"""
import os, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402

exe = sys.argv[1]
checklist = Checklist()
check = checklist.check


def listing(*axis):
    return subprocess.run([exe, "list", *axis], capture_output=True, text=True, timeout=60)


whole = listing()
lines = whole.stdout.splitlines()
widest = max(lines, key=len)
check(f"list: {len(lines)} lines, the widest {len(widest)} columns ({widest[:60]}...)",
      whole.returncode == 0 and len(widest) <= 100)
AXES = {"sections": "### Geometry", "mesh": "### Mesh — mesh source registry",
        "material": "### Materials/<block> — material registry",
        "element-technology":
            "### Materials/<block>/Element Technology — element technology registry",
        "formulation": "### Contact/<zone>/Formulation — formulation registry",
        "discretization": "### Contact/<zone>/Discretization — contact discretization registry",
        "linear-solver": "### Linear Solver — linear solver registry"}
parts = []
for axis, heading in AXES.items():
    r = listing(axis)
    headings = [line for line in r.stdout.splitlines() if line.startswith("### ")]
    check(f"list {axis}: {len(r.stdout.splitlines())} lines, headed '{heading}', no other "
          "registry", r.returncode == 0 and r.stdout.startswith(heading) and
          (axis == "sections" or headings == [heading]))
    parts.append(r.stdout)
check("the parts make up the whole listing", all(part in whole.stdout for part in parts)
      and sum(len(p) for p in parts) >= 0.95 * len(whole.stdout))
r = listing("meshes")
check(f"list meshes: exit 2, one sentence naming the valid axes ({r.stderr.strip()})",
      r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and
      all(axis in r.stderr for axis in AXES))
r = listing("mesh", "material")
check(f"list with two axes: exit 2 ({r.returncode})", r.returncode == 2)
sys.exit(1 if checklist.failures else 0)
