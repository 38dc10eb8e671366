"""study.csv and study.md from the runs' metrics: the table sorted by cost at equal accuracy,
the Pareto front of (solver time, error), and a recommendation computed from the data; and the
compact table `contactlab study` prints on the terminal at the end. The error is the contact
pressure's, or the shear traction's for a shear-only reference (`measured`)."""
import csv
import math
import textwrap

import study_file

METRICS = ["status", "reason", "sets", "wall_s", "solver_total_s", "assembly_s", "contact_s",
           "linear_solve_s", "newton", "status_its", "threshold_its", "geometry_its",
           "linear_solves", "cycling_events", "steps", "cuts", "peak_memory_mb",
           "unknowns_displacement", "unknowns_contact", "unknowns_friction",
           "geometric_terms",
           "pressure_error_l2", "pressure_error_max", "shear_error_l2", "shear_error_max",
           "max_penetration", "force_balance",
           "probe_error", "folder"]


# The width the terminal table keeps to; past it, failure reasons move below the table.
TERMINAL_WIDTH = 100


def _num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def write_csv(path, rows, axes):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case"] + axes + METRICS)
        for r in rows:
            w.writerow([r["case"]] + [r["axes"].get(a, "") for a in axes]
                       + ["" if r.get(m) is None else r[m] for m in METRICS])


def cost(r):
    """The solver's own time (summary.json seconds.total): the process start-up, the same for
    every run, left out. The wall time when the run wrote no summary."""
    return r["solver_total_s"] if _num(r.get("solver_total_s")) else r["wall_s"]


def accuracy(r):
    """The run's error: the L2 pressure error, else (a shear-only reference) the shear's."""
    for key in ("pressure_error_l2", "shear_error_l2"):
        if _num(r.get(key)):
            return r[key]
    return None


def measured(rows):
    """What the runs' errors measure: "pressure", "shear" (a shear-only reference) or None."""
    for key, what in (("pressure_error_l2", "pressure"), ("shear_error_l2", "shear")):
        if any(_num(r.get(key)) for r in rows):
            return what
    return None


# Two errors this close are the same accuracy: runs that solve the same discrete problem differ
# by round-off or by their solvers' tolerances (a patch test's errors are all round-off, 3e-15
# apart), which is no reason to prefer the slower. Relative: the report prints 3 digits;
# absolute: far below any discretization error a study compares.
ERROR_RTOL, ERROR_ATOL = 1e-3, 1e-10


def same_error(a, b):
    return abs(a - b) <= ERROR_RTOL * max(abs(a), abs(b)) + ERROR_ATOL


def more_accurate(a, b):
    """Error a is smaller than b beyond the tolerance."""
    return a < b and not same_error(a, b)


def pareto(rows, cost=cost, error=accuracy):
    """Converged runs not dominated in (cost, error): none at most as costly and at least as
    accurate, and cheaper or more accurate (errors compared within the tolerance, so of two
    runs with the same error only the cheaper is on the front)."""
    pts = [r for r in rows if r["status"] == "converged" and _num(error(r))]

    def dominates(o, r):
        as_accurate = not more_accurate(error(r), error(o))
        return cost(o) <= cost(r) and as_accurate and (
            cost(o) < cost(r) or more_accurate(error(o), error(r)))
    return [r for r in pts if not any(o is not r and dominates(o, r) for o in pts)]


def most_accurate(rows):
    """Of the runs with the smallest error (within the tolerance), the cheapest."""
    best = min(accuracy(r) for r in rows)
    return min((r for r in rows if same_error(accuracy(r), best)), key=cost)


def _accuracy_class(r):
    """Runs within the same decade of error count as equally accurate."""
    e = accuracy(r)
    return math.floor(math.log10(e)) if _num(e) and e > 0 else -99


def _fmt(v, digits=3):
    if v is None or v == "":
        return "–"
    if isinstance(v, float):
        return f"{v:.{digits}g}"
    return str(v)


def recommendation(study, rows, axes):
    target = study["Accuracy Target"]
    what = f"{measured(rows)} error" if measured(rows) else "error"
    lines = []
    good = [r for r in rows if r["status"] == "converged"]
    accurate = [r for r in good if _num(accuracy(r))
                and accuracy(r) <= target]
    if accurate:
        best = min(accurate, key=cost)
        lines.append(f"- **Fastest within a {what} of {target:g}**: {best['case']} "
                     f"({cost(best):.3g} s, {what} {accuracy(best):.3g}).")
    elif good and any(_num(accuracy(r)) for r in good):
        best = most_accurate([r for r in good if _num(accuracy(r))])
        lines.append(f"- **No run reaches a {what} of {target:g}**; the most accurate is "
                     f"{best['case']} ({what} {accuracy(best):.3g}, "
                     f"{cost(best):.3g} s).")
    elif good:
        best = min(good, key=cost)
        lines.append(f"- **Fastest converged run** (no accuracy reference): {best['case']} "
                     f"({cost(best):.3g} s).")
    for axis in axes:
        values = sorted({r["axes"][axis] for r in rows if axis in r["axes"]})
        if len(values) < 2:
            continue
        rate = {v: (sum(1 for r in rows if r["axes"].get(axis) == v and r["status"] == "converged"),
                    sum(1 for r in rows if r["axes"].get(axis) == v)) for v in values}
        text = ", ".join(f"{v} {rate[v][0]}/{rate[v][1]}" for v in values)
        if len({rate[v][0] / rate[v][1] for v in values}) == 1:
            lines.append(f"- **{axis}**: no value more robust than another (converged runs: "
                         f"{text}).")
            continue
        top = max(rate[v][0] / rate[v][1] for v in values)
        most = ", ".join(v for v in values if rate[v][0] / rate[v][1] == top)
        lines.append(f"- **Most robust {axis}**: {most} (converged runs: {text}).")
    failed = [r for r in rows if r["status"] != "converged"]
    if failed:
        reasons = {}
        for r in failed:
            reasons.setdefault(r["reason"] or r["status"], []).append(r["case"])
        lines.append("- **Where methods break**: " + "; ".join(
            f"{why}: {len(names)} run(s) ({', '.join(names[:4])}{', …' if len(names) > 4 else ''})"
            for why, names in sorted(reasons.items())) + ".")
    return "\n".join(lines)


def axis_name(key):
    """A scene key path's short name for a column or a legend: its last component, or its
    parent's when the last only names the choice (Contact/z/Formulation/Type -> Formulation,
    Algorithm/Method -> Algorithm)."""
    parts = key.split("/")
    return parts[-2] if len(parts) > 1 and parts[-1] in ("Type", "Method") else parts[-1]


def terminal_table(rows, axes, explicit_cases):
    """The comparison as plain text, in the study's order: one column per axis (and the case,
    when the study lists cases), converged or the failure reason, Newton iterations, wall
    seconds and the errors the reference gives. Returns the lines."""
    errors = [(key, head, what) for key, head, what in (
        ("pressure_error_l2", "p err", "contact pressure"),
        ("shear_error_l2", "τ err", "shear traction")) if any(_num(r.get(key)) for r in rows)]
    head = [axis_name(a) for a in axes] + (["case"] if explicit_cases else []) + \
        ["converged", "Newton", "wall s"] + [h for _, h, _ in errors]
    names = len(axes) + bool(explicit_cases)  # the columns that name a run

    def cells(r, reason):
        ok = r["status"] == "converged"
        return [r["axes"].get(a, "") for a in axes] + (
            [study_file.explicit_case(r["case"], r["axes"])] if explicit_cases else []) + [
            "yes" if ok else (r["reason"] or r["status"]) if reason else "no",
            _fmt(r.get("newton")), f"{r['wall_s']:.1f}"] + [
            _fmt(r.get(key)) if ok else "–" for key, _, _ in errors]

    def layout(reason):
        table = [head] + [cells(r, reason) for r in rows]
        widths = [max(len(line[i]) for line in table) for i in range(len(head))]
        return ["  ".join(c.ljust(w) if i <= names else c.rjust(w)  # numbers to the right
                          for i, (c, w) in enumerate(zip(line, widths))).rstrip()
                for line in table], widths

    lines, widths = layout(reason=True)
    inline = sum(widths) + 2 * (len(widths) - 1) <= TERMINAL_WIDTH
    if not inline:
        lines, widths = layout(reason=False)
    lines.insert(1, "  ".join("-" * w for w in widths))
    failed = {}
    for r in rows:
        if r["status"] != "converged" and not inline:
            failed.setdefault(r["reason"] or r["status"], []).append(" / ".join(
                cells(r, False)[:names]))
    for why, names in failed.items():
        lines += textwrap.wrap(f"not converged ({why}): {'; '.join(names)}", TERMINAL_WIDTH,
                               subsequent_indent="  ")
    if errors:
        lines.append(", ".join(h for _, h, _ in errors) + ": relative L2 error against the "
                     "reference of the " + " and ".join(what for _, _, what in errors))
    return lines


def write_md(path, study, rows, axes, plots):
    front = {id(r) for r in pareto(rows)}
    order = sorted(rows, key=lambda r: (r["status"] != "converged", _accuracy_class(r),
                                        cost(r) if _num(cost(r)) else 1e300))
    what = f"{measured(rows)} error" if measured(rows) else "error"
    out = [f"# Study {study['Name']}", ""]
    if study.get("Description"):
        out += [str(study["Description"]), ""]
    ref = study["Reference"]
    out += [f"Scene `{study['Scene']}`, {len(rows)} runs; reference: "
            + {"analytic": f"analytic field `{ref.get('Name')}`",
               "run": "the reference run (`reference/`)",
               "none": "none (no accuracy columns)"}[ref["Type"]] + ".", "",
            (f"Sorted by accuracy class (decade of the L2 {what}), then by cost (solver s: "
             "summary.json seconds.total; wall s adds the process start-up); ★ marks the Pareto "
             f"front of (solver s, L2 {what}), errors within {ERROR_RTOL:g} of each other (or "
             f"{ERROR_ATOL:g}) counting as equal." if measured(rows) else
             "Sorted by cost (solver s: summary.json seconds.total; wall s adds the process "
             "start-up)."), ""]
    # The error columns of what the reference measures: a shear-only reference has no pressure
    # error, and no reference none.
    errors = [(key, head) for key, head in (
        ("pressure_error_l2", "p error L2"), ("pressure_error_max", "p error max"),
        ("shear_error_l2", "shear error L2"), ("shear_error_max", "shear error max"))
        if any(_num(r.get(key)) for r in rows)]
    head = ["", "case", "result", "wall s", "solver s", "Newton its", "linear solves", "cycling"] \
        + [h for _, h in errors] + ["max penetration", "unknowns (u + λn + λt)"]
    out += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in order:
        unknowns = "+".join(_fmt(r.get(k)) for k in
                            ("unknowns_displacement", "unknowns_contact", "unknowns_friction"))
        result = "converged" if r["status"] == "converged" else f"**{r['reason'] or r['status']}**"
        out.append("| " + " | ".join([
            "★" if id(r) in front else "", r["case"], result, _fmt(r["wall_s"]),
            _fmt(r.get("solver_total_s")),
            _fmt(r.get("newton")), _fmt(r.get("linear_solves")), _fmt(r.get("cycling_events"))]
            + [_fmt(r.get(key)) for key, _ in errors]
            + [_fmt(r.get("max_penetration")), unknowns]) + " |")
    out += ["", "## Recommendation", "", recommendation(study, rows, axes), ""]
    if plots:
        out += ["## Plots", ""]
        for name, caption in plots:
            out += [f"[{name}]({name}): {caption}", "", f"![{caption}]({name})", ""]
    open(path, "w").write("\n".join(out))
