#!/usr/bin/env python3
"""MUMPS' precision of the factors (`Linear Solver/mumps/Precision`): each case run with `double`
and with `automatic` (the default: single-precision factors, solves refined in double by GMRES,
from 1e10 predicted factorization flops), one rank, VTK off. Prints the table of
doc/performance.md "Single-precision factors": Newton iterations, factorizations (single ones),
refinement steps, factorization and linear-solve seconds, total seconds, peak memory, the
contact force and its relative difference, and the speed-up of each pair. Checks that the
elastic cases (3D Hertz) take the same Newton iterations and give the same contact force to
1e-10 relative (the refined solves are as accurate as direct ones, so a path may differ only in
round-off), and exits non-zero otherwise; the frictional plastic tube is chaotic (its path
moves with round-off, doc/algorithms.md "Round-off"), so its force is reported, not checked.

usage: single_precision.py CONTACTLAB SCENES WORK [--cases hertz-46k hertz-130k tube-seed]
                           [--doc DOC]
  hertz-46k: hertz-3d in tet10 at Size Contact 0.02, 46 572 dofs (~20 s for the pair);
  hertz-130k: the same at 0.012, 129 780 dofs (~2 minutes);
  tube-seed: tube-expansion-3d at the seed's size, hex27 mortar, mu = 0.3, 129 294 dofs +
             4 251 multipliers (about an hour for the pair: bench/run.sh --large)"""
import argparse, os, sys

import docblock
import runs
import tube_sizes

TUBE_SEED = ["Contact/joint/Friction=0.3"] + tube_sizes.SEED_MESH
CASES = {
    "hertz-46k": ("hertz-3d.yaml", ["Mesh/half-sphere/Element=tet10",
                                    "Mesh/half-sphere/Size Contact=0.02"], True),
    "hertz-130k": ("hertz-3d.yaml", ["Mesh/half-sphere/Element=tet10",
                                     "Mesh/half-sphere/Size Contact=0.012"], True),
    "tube-seed": ("tube-expansion-3d.yaml", TUBE_SEED, False),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("scenes")
    ap.add_argument("work")
    ap.add_argument("--cases", nargs="+", default=["hertz-46k", "hertz-130k"],
                    choices=sorted(CASES))
    ap.add_argument("--doc")
    args = ap.parse_args()
    header = ("| case | unknowns | precision | Newton | factorizations (single) | refinement steps | "
              "factorization s | linear solve s | total s | peak MiB | contact force | "
              "difference | speed-up |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    rows, failed = [], False
    for case in args.cases:
        scene, sets, checked = CASES[case]
        pair = {}
        for precision in ("double", "automatic"):
            out = os.path.join(args.work, f"{case}-{precision}")
            summary, _, done = runs.run(
                args.exe, "run", os.path.join(args.scenes, scene), out,
                sets + [f"Linear Solver/mumps/Precision={precision}"], quiet=True,
                timeout=4 * 3600)
            if summary is None or not summary["converged"]:
                sys.exit(f"{out}: the run failed:\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
            pair[precision] = summary
        double, auto = pair["double"], pair["automatic"]
        speedup = double["seconds"]["total"] / auto["seconds"]["total"]
        forces = [s["contact"]["normal_force"] for s in (double, auto)]
        difference = abs(forces[1] / forces[0] - 1)
        for precision, s in (("double", double), ("automatic", auto)):
            w, u = s["linear_work"], s["unknowns"]
            rows.append(
                f"| {case} | {u['displacement']} + {u['contact_multipliers']} | {precision} | "
                f"{s['iterations']['newton']} | {w['factorizations']} "
                f"({w['single_precision_factorizations']}) | {w['refinement_steps']} | "
                f"{w['factorization_seconds']:.1f} | {s['seconds']['linear_solve']:.1f} | "
                f"{s['seconds']['total']:.1f} | {s['peak_memory_mb']:.0f} | "
                f"{s['contact']['normal_force']:.9g} | "
                f"{'' if precision == 'double' else f'{difference:.1e}'} | "
                f"{'' if precision == 'double' else f'{speedup:.2f}'} |")
        same = (double["iterations"] == auto["iterations"] and difference <= 1e-10)
        print(f"{case}: automatic / double total time {1 / speedup:.2f} (speed-up {speedup:.2f}); "
              f"Newton {auto['iterations']['newton']} / {double['iterations']['newton']}; "
              f"contact force {forces[1]!r} / {forces[0]!r}"
              + ("" if same or not checked else "  MISMATCH"), flush=True)
        failed |= checked and not same
    table = header + "\n".join(rows) + "\n"
    print(table)
    if args.doc:
        docblock.write(args.doc, "single-precision", "bench/single_precision.py", table)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
