#!/usr/bin/env python3
"""The blade root's mesh convergence (doc/verification.md, "Blade root"): scenes/blade-root-2d.yaml
at flank sizes h, node-to-segment and mortar, printing the table's rows: dofs, contact dofs,
Newton iterations and wall time of each discretization, its peak contact pressure, and, from the
node-to-segment run's contact.csv, the pressure in the middle of the lower lobe's flank and the
normal force each lobe's flank carries on one side (x > 0): the trapezoid rule of the nodal
pressures along the flank and its fillets, in reference arc length.

usage: blade_root.py CONTACTLAB OUTDIR [h ...]   (default h: 0.5 0.25 0.125 0.0625 0.03125)"""
import csv, os, sys

import numpy as np

import runs

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "scenes", "blade-root-2d.yaml")


def lobes(contact_csv):
    """The right side's flank points grouped by lobe (sorted by reference y, lobes split where y
    jumps by more than 2 mm), each lobe's points in order along the flank."""
    rows = [r for r in csv.DictReader(open(contact_csv)) if float(r["reference_x"]) > 0]
    rows.sort(key=lambda r: float(r["reference_y"]))
    groups, last = [], None
    for r in rows:
        y = float(r["reference_y"])
        if last is None or y - last > 2.0:
            groups.append([])
        groups[-1].append(r)
        last = y
    return groups


def flank_figures(contact_csv):
    """(mid-flank pressure of the lower lobe, [force of each lobe from the highest down])."""
    forces, mid = [], None
    for k, points in enumerate(lobes(contact_csv)):
        x = np.array([[float(r["reference_x"]), float(r["reference_y"])] for r in points])
        p = np.array([float(r["pressure"]) for r in points])
        s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(x, axis=0), axis=1))])
        forces.append(float(np.trapz(p, s)))
        if k == 0:  # the lowest radius: the lower lobe
            mid = float(np.interp(0.5 * s[-1], s, p))
    return mid, forces[::-1]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    exe, out = sys.argv[1], sys.argv[2]
    sizes = [float(h) for h in sys.argv[3:]] or [0.5, 0.25, 0.125, 0.0625, 0.03125]
    print("| h (mm) | dofs | contact dofs | NTS: Newton, time | NTS peak | mortar: Newton, time "
          "| mortar peak | lower flank mid | force upper / lower lobe |")
    print("|---|---|---|---|---|---|---|---|---|")
    for h in sizes:
        cells = {}
        for disc in ("node-to-segment", "mortar"):
            folder = os.path.join(out, f"h{h:g}-{disc}")
            summary, wall, done = runs.run(
                exe, "run", SCENE, folder,
                [f"Mesh/blade-root/Size Flank={h:g}", f"Contact/lobes/Discretization={disc}"],
                quiet=True)
            if summary is None or not summary.get("converged", True):
                sys.exit(f"h = {h:g}, {disc}: the run failed:\n{done.stderr[-2000:]}")
            cells[disc] = (summary, wall, folder)
        s, wall, folder = cells["node-to-segment"]
        m, mwall, _ = cells["mortar"]
        mid, forces = flank_figures(os.path.join(folder, "contact.csv"))
        print(f"| {h:g} | {s['dofs']} | {s['unknowns']['contact_multipliers']} | "
              f"{s['iterations']['newton']}, {wall:.1f} s | {s['contact']['max_pressure']:.0f} | "
              f"{m['iterations']['newton']}, {mwall:.1f} s | {m['contact']['max_pressure']:.0f} | "
              f"{mid:.0f} | {' / '.join(f'{f:.1f}' for f in forces)} |", flush=True)


if __name__ == "__main__":
    main()
