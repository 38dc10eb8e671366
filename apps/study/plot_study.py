#!/usr/bin/python3
"""PNG plots of a study folder (doc/studies.md), with Debian's matplotlib:
  accuracy_vs_time.png  L2 pressure error against wall time, log-log, Pareto front joined,
                        one marker per value of the first axis, one colour per the second;
  newton_per_step.png   Newton iterations per load step of every converged run;
  sensitivity.png       pressure error and Newton iterations against the augmentation or
                        penalty coefficient, when the runs set one (an axis or a case's sets).
usage: plot_study.py STUDY_DIR   (prints the names of the files written)"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.dont_write_bytecode = True  # the scripts may run from the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from study_report import METRICS  # noqa: E402

MARKERS = "os^Dv<>pPXh*"


def number(text):
    try:
        v = float(text)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def main(folder):
    rows = list(csv.DictReader(open(os.path.join(folder, "study.csv"))))
    axes = [c for c in rows[0].keys() if c not in METRICS and c != "case"] if rows else []
    written = []
    ok = [r for r in rows if r["status"] == "converged"]

    def style(r):
        first = sorted({x[axes[0]] for x in rows}) if axes else [""]
        second = sorted({x[axes[1]] for x in rows}) if len(axes) > 1 else [""]
        m = MARKERS[first.index(r[axes[0]]) % len(MARKERS)] if axes else "o"
        c = f"C{second.index(r[axes[1]]) % 10}" if len(axes) > 1 else "C0"
        return m, c

    def seconds(r):  # the solver's own time: without the process start-up, less noisy
        return number(r.get("solver_total_s")) or number(r["wall_s"])

    def error(r):  # the pressure error, else (a shear-only reference) the shear's
        return number(r["pressure_error_l2"]) or number(r.get("shear_error_l2"))

    pts = [r for r in ok if error(r) and seconds(r)]
    if pts:
        fig, ax = plt.subplots(figsize=(7, 5))
        labels = set()
        for r in pts:
            m, c = style(r)
            label = " / ".join(r[a] for a in axes[:2]) if axes else r["case"]
            ax.loglog(seconds(r), error(r), m, color=c,
                      label=None if label in labels else label, markersize=7)
            labels.add(label)
        front = sorted(((seconds(r), error(r)) for r in pts))
        best, line = math.inf, []
        for t, e in front:
            if e < best:
                best = e
                line.append((t, e))
        ax.loglog(*zip(*line), "k--", lw=1, label="Pareto front")
        ax.set_xlabel("solver time (summary.json seconds.total) [s]")
        ax.set_ylabel("contact pressure (else shear) error, relative L2")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, title=" / ".join(a.split("/")[-1] for a in axes[:2]) or None,
                  title_fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(folder, "accuracy_vs_time.png"), dpi=110)
        written.append("accuracy_vs_time.png")

    steps = []
    for r in ok:
        path = os.path.join(r["folder"], "steps.csv")
        if os.path.exists(path):
            steps.append((r, [int(s["newton_iterations"]) for s in csv.DictReader(open(path))]))
    if steps:
        fig, ax = plt.subplots(figsize=(7, 4))
        for r, its in steps:
            m, c = style(r)
            ax.plot(range(1, len(its) + 1), its, "-" + m, color=c, alpha=0.7, markersize=4)
        ax.set_xlabel("load step")
        ax.set_ylabel("Newton iterations")
        ax.set_title("Newton iterations per load step (converged runs)", fontsize=9)
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(folder, "newton_per_step.png"), dpi=110)
        written.append("newton_per_step.png")

    # The coefficient each run sets (an axis or a case's sets): augmentation or penalty.
    def coefficient(r):
        for s in r["sets"].split(";"):
            key, _, value = s.partition("=")
            if any(w in key for w in ("Augmentation", "Penalty")) and number(value):
                formulation = key.split("/")[-2] if "/" in key else ""
                return formulation + " " + key.split("/")[-1], number(value)
        return None

    swept = [(r, coefficient(r)) for r in rows]
    swept = [(r, c) for r, c in swept if c]
    if len(swept) >= 2:
        others = [x for x in axes if not any(w in x for w in ("Augmentation", "Penalty"))]
        groups = {}
        for r, (name, value) in swept:
            key = (name,) + tuple(r[x] for x in others)
            groups.setdefault(key, []).append((value, r))
        fig, (e_ax, n_ax) = plt.subplots(1, 2, figsize=(10, 4))
        errors = []
        for key, members in sorted(groups.items()):
            members.sort(key=lambda m: m[0])
            xs = [v for v, _ in members]
            errs = [number(r["pressure_error_l2"]) if r["status"] == "converged" else None
                    for _, r in members]
            errors += [e for e in errs if e]
            label = " / ".join(k for k in key if k)
            e_ax.loglog(xs, [e if e else math.nan for e in errs], "-o", label=label)
            n_ax.semilogx(xs, [number(r["newton"]) if r["status"] == "converged" else math.nan
                               for _, r in members], "-o", label=label)
            for x, r in members:
                if r["status"] != "converged":
                    n_ax.plot(x, 0, "rx", markersize=9)
        if errors and max(errors) < 3 * min(errors):  # keep a decade in view
            mid = math.sqrt(max(errors) * min(errors))
            e_ax.set_ylim(mid / 10, mid * 10)
        e_ax.set_xlabel("coefficient (r_n or penalty)")
        e_ax.set_ylabel("pressure error (relative L2)")
        n_ax.set_xlabel("coefficient (r_n or penalty)")
        n_ax.set_ylabel("Newton iterations (x at 0: not converged)")
        for x in (e_ax, n_ax):
            x.grid(True, which="both", alpha=0.3)
        e_ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(folder, "sensitivity.png"), dpi=110)
        written.append("sensitivity.png")
    print("\n".join(written))


if __name__ == "__main__":
    main(sys.argv[1])
