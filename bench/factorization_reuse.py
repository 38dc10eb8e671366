#!/usr/bin/env python3
"""MUMPS' factorization reuse (`Linear Solver/mumps/Factorization Reuse`): the 3D Hertz model of
scenes/hertz-3d.yaml in tet10, run with `automatic` (the default: low-rank corrections of the
last factorization) and with `never` (a factorization per Newton iteration), on 1 and 2 ranks.
Prints the table of doc/performance.md "Factorization reuse" and the speed-up of each pair;
checks that both settings take the same Newton iterations and give the same contact force (to
1e-12 relative), and exits non-zero otherwise.

usage: factorization_reuse.py CONTACTLAB SCENES WORK [--size H] [--ranks 1 2] [--doc DOC]
  --size: Mesh/half-sphere/Size Contact (0.012: 129 780 dofs, ~5 minutes for the four runs;
          0.02: 46 572 dofs, ~1 minute)"""
import argparse, os, sys

import docblock
import runs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("scenes")
    ap.add_argument("work")
    ap.add_argument("--size", default="0.012")
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--doc")
    args = ap.parse_args()
    scene = os.path.join(args.scenes, "hertz-3d.yaml")
    rows, failed = [], False
    header = ("| Size Contact | ranks | unknowns | reuse | Newton | factorizations | corrections | "
              "corrections s | linear solve s | total s | peak MiB | speed-up |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for ranks in args.ranks:
        pair = {}
        for reuse in ("never", "automatic"):
            out = os.path.join(args.work, f"np{ranks}-{reuse}")
            sets = ["Mesh/half-sphere/Element=tet10", f"Mesh/half-sphere/Size Contact={args.size}",
                    f"Linear Solver/mumps/Factorization Reuse={reuse}"]
            summary, wall, done = runs.run(args.exe, "run", scene, out, sets, quiet=True,
                                           ranks=ranks)
            if summary is None or not summary["converged"]:
                sys.exit(f"{out}: the run failed:\n{done.stdout}{done.stderr}")
            pair[reuse] = summary
        never, auto = pair["never"], pair["automatic"]
        speedup = never["seconds"]["total"] / auto["seconds"]["total"]
        for reuse, s in (("never", never), ("automatic", auto)):
            w, u = s["linear_work"], s["unknowns"]
            rows.append(
                f"| {args.size} | {ranks} | {u['displacement']} + {u['contact_multipliers']} | "
                f"{reuse} | {s['iterations']['newton']} | {w['factorizations']} | "
                f"{w['corrections']} | {w['correction_seconds']:.1f} | "
                f"{s['seconds']['linear_solve']:.1f} | {s['seconds']['total']:.1f} | "
                f"{s['peak_memory_mb']:.0f} | {'' if reuse == 'never' else f'{speedup:.2f}'} |")
        force = (never["contact"]["normal_force"], auto["contact"]["normal_force"])
        same = (never["iterations"] == auto["iterations"]
                and abs(force[1] / force[0] - 1) <= 1e-12)
        print(f"{ranks} rank(s): automatic / never total time {1 / speedup:.2f} "
              f"(speed-up {speedup:.2f}); Newton {auto['iterations']['newton']} / "
              f"{never['iterations']['newton']}; contact force {force[1]!r} / {force[0]!r}"
              + ("" if same else "  MISMATCH"))
        failed |= not same
    table = header + "\n".join(rows) + "\n"
    print(table)
    if args.doc:
        docblock.write(args.doc, "factorization-reuse", "bench/factorization_reuse.py", table)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
