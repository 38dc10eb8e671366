#!/usr/bin/env python3
"""The study report's choices (apps/study/study_report.py, issue 61), on made-up rows:
- errors that differ by round-off (3e-15 apart) or within the report's tolerance are the same
  accuracy: the Pareto front (study.md's ★) and "the most accurate" keep the cheaper run only;
  errors that really differ keep both ends of the front;
- a shear-only reference names its columns, the front and the recommendation after the shear
  traction, not the pressure.

usage: check_study_report.py STUDY_SCRIPTS_DIR WORKDIR"""
import os, shutil, sys

scripts, work = sys.argv[1:3]
sys.dont_write_bytecode = True
sys.path.insert(0, scripts)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import study_report as report  # noqa: E402
from checklist import Checklist  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
checklist = Checklist()
check = checklist.check


def row(case, seconds, pressure=None, shear=None, status="converged"):
    return {"case": case, "axes": {"Method": case}, "sets": "", "folder": "", "status": status,
            "reason": "", "wall_s": seconds + 0.5, "solver_total_s": seconds,
            "pressure_error_l2": pressure, "shear_error_l2": shear, "newton": 5}


def cases(rows):
    return sorted(r["case"] for r in rows)


study = {"Name": "made-up", "Scene": "scene.yaml", "Accuracy Target": 1e-20,
         "Reference": {"Type": "run"}}

# Round-off: the patch test's errors, the slower run 3e-15 "more accurate".
rows = [row("slow", 2.0, pressure=1e-15), row("fast", 1.0, pressure=4e-15)]
check(f"errors 3e-15 apart: the front is the cheaper run ({cases(report.pareto(rows))})",
      cases(report.pareto(rows)) == ["fast"])
check(f"and the most accurate is the cheaper ({report.most_accurate(rows)['case']})",
      report.most_accurate(rows)["case"] == "fast")
text = report.recommendation(study, rows, [])
check(f"the recommendation names it ({text.splitlines()[0]})",
      "the most accurate is fast" in text)
# Within the relative tolerance: 3 digits alike.
rows = [row("slow", 2.0, pressure=0.031200), row("fast", 1.0, pressure=0.031201)]
check(f"errors 3e-5 apart relatively: the front is the cheaper run "
      f"({cases(report.pareto(rows))})", cases(report.pareto(rows)) == ["fast"])
# Errors that differ: the cheap and the accurate ends both stay; a dominated run does not.
rows = [row("slow", 2.0, pressure=0.01), row("fast", 1.0, pressure=0.03),
        row("worse", 3.0, pressure=0.02), row("failed", 0.1, status="failed")]
check(f"errors that differ: both ends of the front ({cases(report.pareto(rows))})",
      cases(report.pareto(rows)) == ["fast", "slow"])
check("and the most accurate is the accurate one", report.most_accurate(rows[:3])["case"] == "slow")

# A shear-only reference: the columns and sentences say shear.
rows = [row("a", 1.0, shear=0.02), row("b", 2.0, shear=0.01)]
path = os.path.join(work, "study.md")
report.write_md(path, study, rows, [], [])
md = open(path).read()
head = next(line for line in md.splitlines() if line.startswith("|  | case"))
check(f"shear-only: the table's error columns are the shear's ({head})",
      "shear error L2" in head and "p error" not in head)
check("shear-only: the front and the sort name the shear error, never the pressure's",
      "L2 shear error" in md and "pressure" not in md)
check(f"shear-only: the recommendation says shear ({report.recommendation(study, rows, [])})",
      "shear error" in report.recommendation(study, rows, []))
sys.exit(1 if checklist.failures else 0)
