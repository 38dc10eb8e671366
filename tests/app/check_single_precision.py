#!/usr/bin/env python3
"""Linear Solver/mumps/Precision (linear/MumpsSolverPrecision.cpp): a 3D model above the flop
threshold (hertz-3d in tet10 at Size Contact 0.03, 25 203 dofs: ~1e10 predicted factorization
flops) is factorized in single precision by default, its solves refined in double, and ends on
the state of the same run in double: the same Newton iterations and contact force to 1e-10
relative (the refined solves meet a backward error of 1e-13; a direct solve in double, 1e-16),
on 1 and 2 ranks. The default hertz-3d (tet4, 6 348 dofs) stays in double under automatic.

usage: check_single_precision.py CONTACTLAB SCENES_DIR WORKDIR"""
import os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import converged_run  # noqa: E402

exe, scenes, work = sys.argv[1:4]
scene = os.path.join(scenes, "hertz-3d.yaml")
tet10 = ["Mesh/half-sphere/Element=tet10", "Mesh/half-sphere/Size Contact=0.03", "Output/VTK=false"]
failures = 0


def check(name, ok, detail):
    global failures
    failures += not ok
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {detail}")


for ranks in (1, 2):
    double = converged_run(exe, scene, os.path.join(work, f"double-np{ranks}"),
                           tet10 + ["Linear Solver/mumps/Precision=double"], ranks)
    auto = converged_run(exe, scene, os.path.join(work, f"automatic-np{ranks}"), tet10, ranks)
    wd, wa = double["linear_work"], auto["linear_work"]
    f0, f1 = double["contact"]["normal_force"], auto["contact"]["normal_force"]
    check(f"{ranks} rank(s): automatic factorizes in single",
          wa["single_precision_factorizations"] == wa["factorizations"] > 0
          and wa["double_precision_fallbacks"] == 0, str(wa))
    check(f"{ranks} rank(s): double never does", wd["single_precision_factorizations"] == 0
          and wd["refinement_steps"] == 0, str(wd))
    check(f"{ranks} rank(s): same Newton iterations",
          auto["iterations"] == double["iterations"],
          f"{auto['iterations']} vs {double['iterations']}")
    check(f"{ranks} rank(s): same contact force", abs(f1 - f0) <= 1e-10 * abs(f0),
          f"{f1!r} vs {f0!r}")

small = converged_run(exe, scene, os.path.join(work, "small"), [], 1)
check("hertz-3d tet4 below the threshold: double",
      small["linear_work"]["single_precision_factorizations"] == 0, str(small["linear_work"]))
sys.exit(1 if failures else 0)
