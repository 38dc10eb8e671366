#!/usr/bin/python3
"""PNG plots of a study folder (doc/studies.md), with Debian's matplotlib, each written only
when the study holds what it shows:
  accuracy_vs_time.png  the pressure (else shear) error against the solver's time, the Pareto
                        front dashed; marker, colour and fill by the axes whose values differ,
                        marker size by the mesh size when an axis sets one (a study with a
                        reference and converged runs);
  newton_per_step.png   Newton iterations per load step of the converged runs: one panel per
                        value of the axis with the most values, colour and line style by the
                        others, a legend;
  sensitivity.png       the error and the Newton iterations against the augmentation or penalty
                        coefficient, when the runs set two or more values of one.
An axis is logarithmic where its values span a decade or more.
usage: plot_study.py STUDY_DIR   (prints a line per file written: its name, a tab, its caption)"""
import collections
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.ticker import (FuncFormatter, LogLocator, MaxNLocator,  # noqa: E402
                               NullFormatter)

sys.dont_write_bytecode = True  # the scripts may run from the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from study_file import explicit_case  # noqa: E402
from study_report import METRICS, axis_name, pareto  # noqa: E402

MARKERS = "os^Dv<>pPXh*"
LINE_STYLES = ["-", "--", ":", "-."]
MAX_PANELS = 30  # past it, panels are too small to read: that axis goes to colour instead
COEFFICIENT_WORDS = ("Augmentation", "Penalty")

# One way the runs differ: an axis (key: its scene path) or the explicit case (key: None).
Dimension = collections.namedtuple("Dimension", "name key value values")


def number(text):
    try:
        v = float(text)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def scale(values):
    """'log' where the values are positive and span a decade or more; else 'linear' (a zero,
    e.g. a load step that needed no iteration, has no place on a log axis)."""
    v = [x for x in values if x is not None]
    return "log" if v and min(v) > 0 and max(v) >= 10 * min(v) else "linear"


def set_scale(axis, kind, values):
    """`axis` (ax.xaxis or ax.yaxis) linear, or log by the values' span. A log axis over a few
    decades has ticks at 1, 2 and 5 of each, labelled as plain numbers: with matplotlib's
    defaults a span of one or two decades shows one label or none."""
    kind = scale(values) if kind == "auto" else kind
    (axis.axes.set_xscale if axis is axis.axes.xaxis else axis.axes.set_yscale)(kind)
    v = [x for x in values if x is not None and x > 0]
    if kind == "linear" and v and all(float(x).is_integer() for x in v):  # counts
        axis.set_major_locator(MaxNLocator(integer=True))
    if kind == "log" and v and max(v) < 1e4 * min(v):
        axis.set_major_locator(LogLocator(subs=(1, 2, 5)))
        axis.set_major_formatter(FuncFormatter(lambda x, _: f"{x:g}"))
        axis.set_minor_formatter(NullFormatter())


def shown(value):
    return value if value != "" else "–"


def dimensions(rows, axes, study_rows):
    """The axes, then the explicit case, whose values differ among `rows`, values in the
    study's order (that of `study_rows`, every run)."""
    def case(r):
        return explicit_case(r["case"], {a: r[a] for a in axes})

    dims = [Dimension(axis_name(a), a, lambda r, a=a: r[a], None) for a in axes]
    dims.append(Dimension("case", None, case, None))
    for i, d in enumerate(dims):
        present = {d.value(r) for r in rows}
        dims[i] = d._replace(values=[v for v in dict.fromkeys(map(d.value, study_rows))
                                     if v in present])
    return [d for d in dims if len(d.values) > 1]


def is_mesh_size(dim):
    return dim.key is not None and dim.key.startswith("Mesh/") and \
        all(number(v) is not None for v in dim.values)


def palette(n):
    if n <= 10:
        return [f"C{i}" for i in range(n)]
    cmap = plt.get_cmap("tab20" if n <= 20 else "viridis")
    return [cmap(i / max(1, n - 1) if n > 20 else i) for i in range(n)]


class Colours:
    """Colour by the joint value of some dimensions, with the legend's entries."""

    def __init__(self, dims, rows, study_rows):
        self.dims = dims
        present = {self.key(r) for r in rows}
        self.keys = [k for k in dict.fromkeys(map(self.key, study_rows)) if k in present]
        self.colours = dict(zip(self.keys, palette(len(self.keys))))

    def key(self, r):
        return tuple(d.value(r) for d in self.dims)

    @property
    def name(self):
        return " / ".join(d.name for d in self.dims)

    def __call__(self, r):
        return self.colours[self.key(r)]

    def legend(self, marker="s"):
        if not self.dims:
            return []
        return [header(self.name)] + [
            (Line2D([], [], color=self.colours[k], marker=marker, linestyle="none"),
             " / ".join(shown(v) for v in k)) for k in self.keys]


def described(encodings):
    """'; marker: Formulation, colour: Algorithm' for the (what, dimension name) pairs used."""
    used = [f"{what}: {name}" for what, name in encodings if name]
    return "; " + ", ".join(used) if used else ""


def header(title):
    return Line2D([], [], linestyle="none"), title + ":"


def legend(fig, entries):
    if entries:
        box = fig.legend(*zip(*entries), loc="upper left", bbox_to_anchor=(1.0, 0.97),
                         fontsize=8, frameon=False, handlelength=2.2)
        for text in box.get_texts():
            if text.get_text().endswith(":"):  # a section's title (header())
                text.set_fontweight("bold")


def save(fig, folder, name):
    fig.savefig(os.path.join(folder, name), dpi=110, bbox_inches="tight")
    plt.close(fig)


def seconds(r):  # the solver's own time: without the process start-up, less noisy
    return number(r.get("solver_total_s")) or number(r["wall_s"])


def error(r):  # the pressure error, else (a shear-only reference) the shear's
    return number(r["pressure_error_l2"]) or number(r.get("shear_error_l2"))


def error_label(rows):
    which = "contact pressure" if any(number(r["pressure_error_l2"]) for r in rows) \
        else "shear traction"
    return f"{which} error (relative L2)"


def accuracy_vs_time(folder, rows, axes):
    pts = [r for r in rows if r["status"] == "converged" and error(r) and seconds(r)]
    if not pts:
        return None
    dims = dimensions(pts, axes, rows)
    mesh = next((d for d in dims if is_mesh_size(d)), None)
    others = [d for d in dims if d is not mesh]
    marker = others[0] if others and len(others[0].values) <= len(MARKERS) else None
    rest = [d for d in others if d is not marker]
    # Filled or open for a two-valued axis, when another axis is left for the colour.
    fill = next((d for d in reversed(rest) if len(d.values) == 2), None) if len(rest) > 1 \
        else None
    colours = Colours([d for d in rest if d is not fill], pts, rows)
    sizes = sorted(mesh.values, key=number) if mesh else []

    fig, ax = plt.subplots(figsize=(7, 5))
    for r in pts:
        m = MARKERS[marker.values.index(marker.value(r))] if marker else "o"
        size = 5 + 8 * sizes.index(mesh.value(r)) / max(1, len(sizes) - 1) if mesh else 8
        open_ = fill is not None and fill.values.index(fill.value(r)) == 1
        ax.plot(seconds(r), error(r), m, color=colours(r), markersize=size, alpha=0.85,
                markerfacecolor="none" if open_ else colours(r), markeredgewidth=1.5)
    # study.md's front (its ★), errors compared within the report's tolerance.
    front = sorted((seconds(r), error(r)) for r in pareto(pts, cost=seconds, error=error))
    ax.plot(*zip(*front), "k--", lw=1)
    set_scale(ax.xaxis, "auto", [seconds(r) for r in pts])
    set_scale(ax.yaxis, "auto", [error(r) for r in pts])
    ax.set_xlabel("solver time (summary.json seconds.total) [s]")
    ax.set_ylabel(error_label(pts))
    ax.grid(True, which="both", alpha=0.3)
    failed = sum(r["status"] != "converged" for r in rows)
    ax.set_title(f"accuracy against cost, {len(pts)} converged runs"
                 + (f" ({failed} not converged: not shown)" if failed else ""), fontsize=9)

    fig.tight_layout()
    entries = [(Line2D([], [], color="k", linestyle="--"), "Pareto front")]
    if marker:
        entries += [header(marker.name)] + [
            (Line2D([], [], color="k", marker=MARKERS[i], linestyle="none"), shown(v))
            for i, v in enumerate(marker.values)]
    entries += colours.legend()
    if fill:
        entries += [header(fill.name)] + [
            (Line2D([], [], color="k", marker="o", linestyle="none",
                    markerfacecolor="k" if i == 0 else "none"), shown(v))
            for i, v in enumerate(fill.values)]
    if mesh:
        entries += [header(mesh.name)] + [
            (Line2D([], [], color="k", marker="o", linestyle="none",
                    markersize=5 + 8 * i / max(1, len(sizes) - 1)), v)
            for i, v in enumerate(sizes)]
    legend(fig, entries)
    save(fig, folder, "accuracy_vs_time.png")
    return ("accuracy_vs_time.png", f"{error_label(pts)} against the solver's time, converged "
            "runs, Pareto front dashed" + described(
                [("marker", marker and marker.name), ("colour", colours.name),
                 ("filled/open", fill and fill.name), ("marker size", mesh and mesh.name)]))


def newton_per_step(folder, rows, axes):
    runs = []
    for r in rows:
        path = os.path.join(r["folder"], "steps.csv")
        if r["status"] == "converged" and os.path.exists(path):
            runs.append((r, [int(s["newton_iterations"]) for s in csv.DictReader(open(path))]))
    if not runs:
        return None
    dims = dimensions([r for r, _ in runs], axes, rows)
    facet = max((d for d in dims if len(d.values) <= MAX_PANELS), key=lambda d: len(d.values),
                default=None)
    rest = [d for d in dims if d is not facet]
    style = rest[1] if len(rest) > 1 and len(rest[1].values) <= len(LINE_STYLES) else None
    colours = Colours([d for d in rest if d is not style], [r for r, _ in runs], rows)

    panels = facet.values if facet else [""]
    ncols = min(len(panels), 3 if len(panels) <= 9 else 6)
    nrows = math.ceil(len(panels) / ncols)
    fig, grid = plt.subplots(nrows, ncols, figsize=(3.4 * ncols, 2.4 * nrows + 0.8),
                             sharex=True, sharey=True, squeeze=False)
    for ax, value in zip(grid.flat, panels):
        members = [(r, its) for r, its in runs if not facet or facet.value(r) == value]
        # Runs with the same counts would hide each other: each is shifted a little along x.
        width = min(0.5, 0.12 * len(members))
        for j, (r, its) in enumerate(members):
            shift = (j / max(1, len(members) - 1) - 0.5) * width if len(members) > 1 else 0
            k = style.values.index(style.value(r)) if style else 0
            ax.plot([s + 1 + shift for s in range(len(its))], its, LINE_STYLES[k],
                    marker=MARKERS[k], color=colours(r), markersize=4, alpha=0.85)
        if facet:
            ax.set_title(f"{facet.name} = {shown(value)}", fontsize=8)
        ax.grid(True, alpha=0.3)
        ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    for ax in grid.flat[len(panels):]:
        ax.set_visible(False)
    set_scale(grid.flat[0].yaxis, "auto", [i for _, its in runs for i in its])
    for ax in grid[:, 0]:
        ax.set_ylabel("Newton iterations")
    for ax in grid.flat[max(0, len(panels) - ncols):len(panels)]:
        ax.set_xlabel("load step")
        ax.tick_params(labelbottom=True)
    failed = sum(r["status"] != "converged" for r in rows)
    fig.suptitle(f"Newton iterations per load step, {len(runs)} converged runs"
                 + (f" ({failed} not converged: not shown)" if failed else ""), fontsize=10)
    fig.tight_layout()
    entries = colours.legend(marker="o")
    if style:
        entries += [header(style.name)] + [
            (Line2D([], [], color="k", linestyle=LINE_STYLES[i], marker=MARKERS[i]), shown(v))
            for i, v in enumerate(style.values)]
    legend(fig, entries)
    save(fig, folder, "newton_per_step.png")
    return ("newton_per_step.png", "Newton iterations per load step of the converged runs"
            + described([("panels", facet and facet.name), ("colour", colours.name),
                         ("line style", style and style.name)]))


def coefficients(r):
    """The augmentation and penalty coefficients a run sets, {key: value}, the last setting
    of a key winning (the study's Sets come first, then the case's and the axes'); those of
    another formulation than the run's own Type, when it sets one, left out."""
    found, formulation = {}, None
    for s in r["sets"].split(";"):
        key, _, value = s.partition("=")
        if key.endswith("Formulation/Type"):
            formulation = value
        elif any(w in key.split("/")[-1] for w in COEFFICIENT_WORDS) and number(value):
            found[key] = number(value)
    return {k: v for k, v in found.items()
            if formulation is None or k.split("/")[-2] == formulation}


def sensitivity(folder, rows, axes):
    """Only for a coefficient the study varies: two or more values of the same key."""
    values = collections.defaultdict(set)
    for r in rows:
        for key, v in coefficients(r).items():
            values[key].add(v)
    swept = [k for k in values if len(values[k]) > 1]
    if not swept:
        return None
    others = [a for a in axes if a not in swept]
    groups = collections.defaultdict(list)
    for r in rows:
        key = next((k for k in swept if k in coefficients(r)), None)
        if key:
            groups[(key,) + tuple(r[a] for a in others)].append((coefficients(r)[key], r))

    # Without a reference there is no error: the iterations' panel alone.
    with_error = any(error(r) for members in groups.values() for _, r in members
                     if r["status"] == "converged")
    fig, panels = plt.subplots(1, 1 + with_error, figsize=(10 if with_error else 5.5, 4),
                               squeeze=False)
    e_ax, n_ax = (panels[0][0] if with_error else None), panels[0][-1]
    errors, iterations, failures = [], [], 0
    for i, (key, members) in enumerate(groups.items()):
        members.sort(key=lambda m: m[0])
        xs = [v for v, _ in members]
        ok = [r["status"] == "converged" for _, r in members]
        errs = [error(r) if good else None for (_, r), good in zip(members, ok)]
        its = [number(r["newton"]) if good else None for (_, r), good in zip(members, ok)]
        errors += [e for e in errs if e]
        iterations += [n for n in its if n]
        failures += ok.count(False)
        name = " ".join(key[0].split("/")[-2:])
        label = " / ".join([name] + [f"{axis_name(a)} {v}" for a, v in zip(others, key[1:])
                                     if v != ""])
        # Each next line's marks smaller, so that a line drawn over an equal one shows both.
        style = dict(color=f"C{i % 10}", marker=MARKERS[i % len(MARKERS)], label=label,
                     markersize=max(3.0, 9 - 1.5 * i))
        if e_ax:
            e_ax.plot(xs, [e if e else math.nan for e in errs], "-", **style)
        n_ax.plot(xs, [n if n else math.nan for n in its], "-", **style)
        n_ax.plot([x for x, good in zip(xs, ok) if not good],
                  [0] * ok.count(False), "rx", markersize=9)
    for ax in panels[0]:
        set_scale(ax.xaxis, "log", [v for members in groups.values() for v, _ in members])
        ax.set_xlabel("coefficient (r_n or penalty)")
        ax.grid(True, alpha=0.3)
    if e_ax:
        set_scale(e_ax.yaxis, "auto", errors)
        e_ax.set_ylabel(error_label(rows))
    # A log scale would hide the failures' marks at 0.
    set_scale(n_ax.yaxis, "linear" if failures else "auto", iterations)
    n_ax.set_ylabel("Newton iterations" + (" (x at 0: not converged)" if failures else ""))
    fig.tight_layout()
    legend(fig, list(zip(*n_ax.get_legend_handles_labels())))
    save(fig, folder, "sensitivity.png")
    return ("sensitivity.png", (f"{error_label(rows)} and " if with_error else "")
            + "Newton iterations against " + ", ".join(" ".join(k.split("/")[-2:]) for k in swept))


def drawn_in_child(plot, folder, rows, axes):
    """(pid, pipe): `plot` drawn in a forked process (matplotlib imported once, in the parent),
    which writes its output line, if any, to the pipe and exits 1 on an error."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(read)
        code = 1
        try:
            written = plot(folder, rows, axes)
            os.write(write, ("\t".join(written) + "\n" if written else "").encode())
            code = 0
        except BaseException:
            import traceback
            traceback.print_exc()
        finally:
            sys.stderr.flush()
            os._exit(code)
    os.close(write)
    return pid, read


def main(folder):
    rows = list(csv.DictReader(open(os.path.join(folder, "study.csv"))))
    axes = [c for c in rows[0].keys() if c not in METRICS and c != "case"] if rows else []
    # Each plot in a process of its own, at once: the study's cores are free by now, and the
    # figures of a 100-run study take about as long to draw as matplotlib to import.
    children = [drawn_in_child(plot, folder, rows, axes)
                for plot in (accuracy_vs_time, newton_per_step, sensitivity)]
    failed = False
    for pid, read in children:
        with os.fdopen(read) as lines:
            sys.stdout.write(lines.read())
        failed |= os.waitpid(pid, 0)[1] != 0
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
