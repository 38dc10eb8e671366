#!/usr/bin/env python3
"""The seed's blade-root table in its shape (doc/performance.md, "Blade root"): the 3D slice
scenes/blade-root-3d.yaml (frictionless mortar, Saint Venant-Kirchhoff, the centrifugal load)
under the fixed point (PF), partial Newton (NP) and generalized Newton (NG). Per run: the outcome
(or the failure's name), Newton iterations, linear solves, wall time, peak memory, the blade's
contact resultant and the peak contact pressure, each with its deviation from the fixed point's.
The seed (Code_Aster 2012, 600 000 dofs of which 18 000 in contact, MUMPS, one processor): PF
40 h, NP 34 h, NG 5 h 30, in 24 GB.

usage: blade_root_seed.py CONTACTLAB OUTDIR [--size default|seed] [--doc DOC] [--reuse]
--size seed refines to the seed's 600 000 dofs: Size Flank 0.125 mm (the 2D section's 6 666
nodes) swept in 29 layers (30 node planes: 599 940 dofs). --doc writes the table into DOC's
<!-- bench:blade-root-SIZE:start/end --> block."""
import argparse, json, os

import docblock
import runs

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "scenes", "blade-root-3d.yaml")
METHODS = [("PF", "fixed-point"), ("NP", "partial-newton"), ("NG", "generalized-newton")]
SIZES = {"default": [],
         "seed": ["Mesh/blade-root/Size Flank=0.125", "Mesh/blade-root/Layers=29"]}


def deviation(value, reference):
    if value is None or reference is None:
        return "–"
    return f"{100 * (value - reference) / reference:+.2g} %"


def duration(seconds):
    return f"{seconds:.1f} s" if seconds < 120 else f"{seconds / 60:.1f} min"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("exe")
    parser.add_argument("out")
    parser.add_argument("--size", choices=sorted(SIZES), default="default")
    parser.add_argument("--reuse", action="store_true",
                        help="take the runs already in OUTDIR (their summary.json) instead of "
                             "running them again; wall is then the run's own total")
    parser.add_argument("--doc")
    args = parser.parse_args()
    lines = ["| method | outcome | dofs (contact) | Newton | linear solves | wall | peak memory "
             "| contact resultant | vs PF | peak pressure | vs PF |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    reference_force = reference_peak = None
    for short, method in METHODS:
        folder = os.path.join(args.out, f"{args.size}-{method}")
        summary_file = os.path.join(folder, "summary.json")
        if args.reuse and os.path.exists(summary_file):
            summary = json.load(open(summary_file))
            wall, done = summary["seconds"]["total"], None
        else:
            summary, wall, done = runs.run(args.exe, "run", SCENE, folder,
                                           SIZES[args.size] + [f"Algorithm/Method={method}"],
                                           quiet=True, timeout=4 * 3600)
        if summary is None:
            lines.append(f"| {short} | no summary: {done.stderr.strip()[-200:] if done else ''} "
                         "| | | | | | | | | |")
            print(lines[-1], flush=True)
            continue
        ok = summary.get("converged", False)
        force = -summary["contact"]["normal_force_vector"][1] if ok else None
        peak = summary["contact"].get("max_pressure") if ok else None
        if short == "PF":
            reference_force, reference_peak = force, peak
        compare = short != "PF"
        lines.append(
            f"| {short} | {'converged' if ok else 'fails: ' + str(summary.get('failure'))} | "
            f"{summary['dofs']} ({summary['unknowns']['contact_multipliers']}) | "
            f"{summary['iterations']['newton']} | {summary['linear_solves']} | "
            f"{duration(wall)} | "
            f"{summary.get('peak_memory_mb', 0) / 1024:.1f} GB | "
            + (f"{force:.2f} N | {deviation(force, reference_force) if compare else '–'} | "
               f"{peak:.1f} MPa | {deviation(peak, reference_peak) if compare else '–'} |"
               if ok else "– | – | – | – |"))
        print(lines[-1], flush=True)
    if args.doc:
        docblock.write(args.doc, f"blade-root-{args.size}",
                       f"bench/blade_root_seed.py --size {args.size}", "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
