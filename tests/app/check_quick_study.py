#!/usr/bin/python3
"""What `make run` shows (issue 20), and the study plots. Runs
  - a reduced copy of scenes/studies/quick-comparison.yaml (its scene, settings and reference;
    2 formulations x 2 presets x both discretizations instead of 3 x 3 x 2): the terminal
    table must list every run with the values of study.csv, then where study.md, the plots
    and the ParaView series are;
  - two small Hertz 2D studies, one with an augmentation axis and a mesh-size axis against
    the analytic reference, one with the augmentation axis and no reference.
For each study, the PNGs written must be exactly those its axes call for (sensitivity.png only
with a coefficient axis, accuracy_vs_time.png only with a reference), each not blank, linked
from study.md, with a caption naming every axis that varies.

usage: check_quick_study.py CONTACTLAB STUDIES_DIR WORKDIR"""
import csv
import os
import re
import shutil
import subprocess
import sys

import matplotlib.image
import numpy
import yaml

exe, studies, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402

checklist = Checklist()
check, failures = checklist.check, checklist.failures


def run_study(name, study):
    path = os.path.join(work, name + ".yaml")
    yaml.safe_dump({"contactlab-study": study}, open(path, "w"), sort_keys=False)
    out = os.path.join(work, name)
    r = subprocess.run([exe, "study", path, "--out", out], capture_output=True, text=True,
                       timeout=300)
    print(r.stdout[-4000:], r.stderr[-2000:])
    check(f"{name}: the study exits 0", r.returncode == 0)
    return out, r.stdout


def not_blank(png):
    """Some pixels away from the background (the corner's colour): axes, marks, text."""
    image = matplotlib.image.imread(png)[:, :, :3]
    differs = numpy.abs(image - image[0, 0]).sum(axis=2) > 0.1
    return differs.mean() > 0.01


def check_plots(name, out, expected, axis_names):
    written = sorted(f for f in os.listdir(out) if f.endswith(".png"))
    check(f"{name}: the plots written are {expected} ({written})", written == sorted(expected))
    md = open(os.path.join(out, "study.md")).read()
    for png in written:
        check(f"{name}: {png} is not blank", not_blank(os.path.join(out, png)))
        caption = re.search(r"^\[" + re.escape(png) + r"\]\(" + re.escape(png) + r"\): (.*)$",
                            md, re.M)
        check(f"{name}: study.md links {png} with a caption",
              caption is not None and f"]({png})" in md.replace(caption.group(0), ""))
        if caption and png != "sensitivity.png":  # sensitivity: the coefficient is its x axis
            missing = [a for a in axis_names if a not in caption.group(1)]
            check(f"{name}: {png}'s caption names every axis that varies (missing {missing})",
                  not missing)
    return md


# The quick comparison, reduced.
quick = yaml.safe_load(open(os.path.join(studies, "quick-comparison.yaml")))["contactlab-study"]
quick["Scene"] = os.path.join(os.path.abspath(studies), quick["Scene"])
axes = quick["Axes"]
for key in list(axes)[:2]:
    axes[key] = axes[key][:2]
check("the quick comparison crosses formulations, presets and discretizations",
      [k.split("/")[-1] for k in axes] == ["Type", "Method", "Discretization"]
      and quick["Axes"][list(axes)[2]] == ["node-to-segment", "mortar"])
out, stdout = run_study("quick", quick)
rows = list(csv.DictReader(open(os.path.join(out, "study.csv"))))
lines = stdout.splitlines()
head = next((i for i, l in enumerate(lines) if l.startswith("Formulation")), None)
check("the terminal table has its header",
      head is not None and re.split(r"\s{2,}", lines[head]) ==
      ["Formulation", "Algorithm", "Discretization", "converged", "Newton", "wall s", "p err",
       "τ err"])
table = [re.split(r"\s{2,}", l.strip()) for l in lines[head + 2:head + 2 + len(rows)]] \
    if head is not None else []

def result(r, shown):  # a failure's reason, or "no" where the reasons go below the table
    return shown == "yes" if r["status"] == "converged" else shown in ("no", r["reason"])


check(f"the table lists every run as study.csv does ({len(table)} rows of {len(rows)})",
      len(table) == len(rows) and all(
          t[:3] + t[4:6] == [r[k] for k in axes] + [r["newton"], f"{float(r['wall_s']):.1f}"]
          and result(r, t[3]) for t, r in zip(table, rows)))
check("the table stays within 100 columns",
      all(len(l) <= 100 for l in lines[head:head + 2 + len(rows)]) if head is not None
      else False)
converged = [r for r in rows if r["status"] == "converged"]
check(f"runs converge ({len(converged)} of {len(rows)}) and the table gives their errors",
      converged and all(t[6] == f"{float(r['pressure_error_l2']):.3g}" for t, r in
                        zip(table, rows) if r["status"] == "converged"))
where = {l.split()[0]: l for l in lines if l.split() and l.split()[0] in
         ("study.md", "plots", "ParaView")}
check("it says where study.md, the plots and the ParaView series are",
      sorted(where) == ["ParaView", "plots", "study.md"]
      and os.path.join(out, "study.md") in where["study.md"]
      and "accuracy_vs_time.png" in where["plots"] and "result.pvd" in where["ParaView"])
check("every converged run wrote its ParaView series",
      all(os.path.exists(os.path.join(r["folder"], "result.pvd")) for r in converged))
check_plots("quick", out, ["accuracy_vs_time.png", "newton_per_step.png"],
            ["Formulation", "Algorithm", "Discretization"])

# A coefficient axis and a mesh-size axis, against the analytic reference.
hertz = {"Name": "hertz", "Scene": os.path.join(os.path.abspath(studies), "../hertz-2d.yaml"),
         "Timeout": 60, "Sets": ["Output/VTK=false"],
         "Axes": {"Contact/floor/Formulation/augmented-lagrangian/Normal Augmentation": [1, 1e4],
                  "Mesh/half-disc/Size Contact": [0.02, 0.01]},
         "Reference": {"Type": "analytic", "Name": "hertz-2d", "Radius": 1.0, "E": 1.0,
                       "nu": 0.3, "Centre": [0.0]}}
out, _ = run_study("coefficient-mesh", hertz)
md = check_plots("coefficient-mesh", out,
                 ["accuracy_vs_time.png", "newton_per_step.png", "sensitivity.png"],
                 ["Normal Augmentation", "Size Contact"])
check("accuracy_vs_time encodes the mesh size", "marker size: Size Contact" in md)

# No reference: no accuracy plot; the sensitivity plot without its error panel.
hertz.update(Name="no-reference", Reference={"Type": "none"})
del hertz["Axes"]["Mesh/half-disc/Size Contact"]
out, _ = run_study("no-reference", hertz)
md = check_plots("no-reference", out, ["newton_per_step.png", "sensitivity.png"],
                 ["Normal Augmentation"])
check("without a reference the sensitivity plot shows only the iterations",
      re.search(r"\[sensitivity.png\]\(sensitivity.png\): Newton iterations against", md)
      is not None)
sys.exit(1 if failures else 0)
