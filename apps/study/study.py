#!/usr/bin/python3
"""contactlab study STUDY.yaml [--out DIR] [--retry-failed] [--no-plots]

Runs one scene over the product of the study's axes (and its explicit cases), in `contactlab
batch` processes, as many runs at a time as the cores while the memory allows (Parallel Runs;
or each run its own process: Process Per Run), each run with a time limit, then writes
study.csv, study.md and PNG
plots (doc/studies.md). A failure, a timeout or a crash of one run is recorded with its reason
and the study goes on. Studies resume: a run whose folder already holds the same case's result
is not run again (--retry-failed runs the failed ones again). Started by `contactlab study`,
which passes its own path with --contactlab."""
import argparse
import json
import os
import signal
import subprocess
import sys
import threading
import time

sys.dont_write_bytecode = True  # the scripts may run from the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study_file  # noqa: E402
import study_metrics as metrics  # noqa: E402
import study_process as process  # noqa: E402
import study_report as report  # noqa: E402


def case_folder(out, i, name):
    """The folder of the study's case i (0-based) named `name`."""
    return os.path.join(out, "runs", study_file.run_folder(i + 1, name))


def finished_record(folder, scene, sets, retry_failed):
    """The record of the same case already run in `folder` (to be kept), else None."""
    try:
        done = json.load(open(os.path.join(folder, "case.json"))) == \
            {"scene": scene, "sets": sets} and json.load(open(os.path.join(folder, "record.json")))
    except (OSError, ValueError):
        return None
    if not done or (retry_failed and done["status"] != "converged"):
        return None
    done["resumed"] = True
    return done


def run_case(runner, scene, folder, sets, timeout, retry_failed):
    """Runs one case in `folder` (with `runner`) unless it is already there; returns its
    record."""
    done = finished_record(folder, scene, sets, retry_failed)
    if done:
        return done
    os.makedirs(folder, exist_ok=True)
    case_file, record_file = (os.path.join(folder, f) for f in ("case.json", "record.json"))
    for f in ("summary.json", "record.json"):
        if os.path.exists(os.path.join(folder, f)):
            os.remove(os.path.join(folder, f))
    json.dump({"scene": scene, "sets": sets}, open(case_file, "w"))
    start = time.time()
    code, shared = runner.run(scene, folder, sets, timeout)
    # record.json says which process ran the case: the shared batch one or its own.
    record = {"wall_s": time.time() - start, "returncode": code,
              "process": "batch" if shared else "own"}
    summary = metrics.load_summary(folder)
    non_finite = metrics.non_finite_outputs(folder)
    if code is None:
        record.update(status="timeout", reason=f"timeout ({timeout:g} s)")
    elif code < 0:
        record.update(status="crash", reason=f"crash ({signal.Signals(-code).name})")
    elif summary is None:
        errors = [l.strip() for l in open(os.path.join(folder, "run.log"), errors="replace")
                  if l.startswith("contactlab: error:")]
        if code == 2 and errors:  # the scene (with this case's settings) was refused
            record.update(status="invalid", reason=errors[-1][len("contactlab: error:"):].strip())
        else:
            record.update(status="crash", reason=f"no summary.json (exit code {code})")
    elif non_finite:
        record.update(status="nan-in-output", reason="NaN or infinity in " + ", ".join(non_finite))
    elif summary.get("converged"):
        record.update(status="converged", reason="")
    else:
        record.update(status="failed", reason=summary.get("failure") or "failed")
    json.dump(record, open(record_file, "w"))
    return record


def metrics_row(study, name, point, sets, folder, record, reference):
    row = {"case": name, "axes": point, "sets": ";".join(sets), "folder": folder, **record}
    summary = metrics.load_summary(folder)
    if summary is None:
        return row
    row.update(metrics.cost_metrics(summary))
    if record["status"] != "converged":  # a failed run's contact state is not a solution
        return row
    row["max_penetration"] = (summary.get("contact") or {}).get("max_penetration")
    row["force_balance"] = metrics.force_balance(summary)
    points = metrics.read_contact(folder, study.get("Zone"))
    pressure, shear = metrics.references(study["Reference"], summary, reference["points"])
    if pressure:
        row["pressure_error_l2"], row["pressure_error_max"] = metrics.field_errors(
            points, lambda q: q.pressure, pressure)
    if shear:
        row["shear_error_l2"], row["shear_error_max"] = metrics.field_errors(
            points, lambda q: q.shear, shear)
    row["probe_error"] = metrics.probe_error(summary, reference["summary"])
    return row


class Progress:
    """The "[i/N] case ... status (wall, ETA)" lines, as runs finish (from any thread)."""

    def __init__(self, total):
        self.total, self.spent, self.ran, self.done = total, 0.0, 0, 0
        self.runners = 1
        self.lock = threading.Lock()

    def report(self, i, name, rec):
        with self.lock:
            self.done += 1
            if not rec.get("resumed"):
                self.spent, self.ran = self.spent + rec["wall_s"], self.ran + 1
            left = self.total - self.done
            eta = (f", ETA {self.spent / self.ran * left / self.runners:.0f} s"
                   if self.ran and left else "")
            print(f"[{i + 1}/{self.total}] {name} ... {rec['status']}"
                  f"{' ' + rec['reason'] if rec['reason'] else ''} ({rec['wall_s']:.1f} s"
                  f"{', done earlier' if rec.get('resumed') else ''}{eta})", flush=True)


def most_runs_at_once(setting, cases):
    """Parallel Runs as a number: the cores for automatic, at most one a case, at least 1."""
    return max(1, min(process.usable_cores() if setting == "automatic" else setting, cases))


def parallel_runs(setting, summaries, remaining):
    """How many runs go at once (Parallel Runs; `summaries`: of the runs done so far, whose
    peak memory decides for automatic: that many copies must fit in half the machine's)."""
    runners = most_runs_at_once(setting, remaining)
    if setting != "automatic" or runners == 1:
        return runners
    peak = max([s.get("peak_memory_mb") or 0 for s in summaries if s] or [0])
    memory = process.memory_mb()
    return 1 if not peak or not memory or peak * runners > memory / 2 else runners


def run_all(study, todo, out, args, runners):
    """The reference run (if any), then every case, with progress; the rows, in case order.
    `runners` holds one Runner; more are added when the runs go in parallel."""
    reference = {"points": None, "summary": None}
    if study["Reference"]["Type"] == "run":
        folder = os.path.join(out, "reference")
        # Usually the finest run: alone, with every BLAS thread (the runners have a share).
        alone = runners[0] if len(runners) == 1 else process.Runner(
            args.contactlab, study["Process Per Run"])
        rec = run_case(alone, study["Scene"], folder,
                       study["Sets"] + [str(s) for s in study["Reference"]["Sets"]],
                       study["Timeout"], args.retry_failed)
        if alone is not runners[0]:
            alone.close()
        print(f"[reference] {rec['status']} {rec['reason']} ({rec['wall_s']:.1f} s)", flush=True)
        if rec["status"] != "converged":
            print("contactlab: warning: the reference run did not converge: no accuracy "
                  "columns", file=sys.stderr)
        else:
            reference = {"points": metrics.read_contact(folder, study.get("Zone")),
                         "summary": metrics.load_summary(folder)}

    progress = Progress(len(todo))
    records = {}

    def folder_of(i):
        return case_folder(out, i, todo[i][0])

    def run(i, runner):
        name, _, sets, scene = todo[i]
        records[i] = run_case(runner, scene, folder_of(i), study["Sets"] + sets,
                              study["Timeout"], args.retry_failed)
        progress.report(i, name, records[i])

    # Parallel Runs automatic: the first case runs alone, its peak memory (and the reference
    # run's) decides; the other runners start meanwhile, with their share of the BLAS threads.
    first, count = 0, len(runners)
    if todo and study["Parallel Runs"] == "automatic" and count > 1:
        for runner in runners[1:]:
            runner.start()
        run(0, runners[0])
        first = 1
        summaries = [metrics.load_summary(os.path.join(out, "reference")),
                     metrics.load_summary(folder_of(0))]
        count = parallel_runs("automatic", summaries, len(todo) - 1)
        if count < len(runners):
            for runner in runners[count:]:
                runner.close()
            del runners[count:]
            if count == 1:  # alone after all: every BLAS thread
                runners[0].close()
                runners[0] = process.Runner(args.contactlab, study["Process Per Run"])
    if count > 1:
        progress.runners = count
        print(f"contactlab study: {count} runs at a time", flush=True)
    # Runs go to the runners in a fixed order, not to whichever is free: a run's results may
    # depend on the linear solver the run before it in its process left, so the assignment must
    # not depend on timing. Dealt back and forth (runner 0, 1, ..., 1, 0, 0, 1, ...), so that
    # neither a trend along the cases nor an axis that alternates (partial, generalized Newton)
    # loads one runner more than the others.
    def runner_of(i):
        turn, seat = divmod(i - first, count)
        return seat if turn % 2 == 0 else count - 1 - seat

    lanes = [[i for i in range(first, len(todo)) if runner_of(i) == k] for k in range(count)]
    errors = []

    def lane(k):
        try:
            for i in lanes[k]:
                run(i, runners[k])
        except BaseException as e:  # raised again by the main thread
            errors.append(e)

    threads = [threading.Thread(target=lane, args=(k,), daemon=True) for k in range(1, count)]
    for t in threads:
        t.start()
    for i in lanes[0]:  # in the main thread: an interruption stops the study at once
        run(i, runners[0])
    for t in threads:
        while t.is_alive():
            t.join(0.2)  # in short waits, so that Ctrl-C reaches the main thread
    if errors:
        raise errors[0]
    return [metrics_row(study, name, point, study["Sets"] + sets, folder_of(i), records[i],
                        reference) for i, (name, point, sets, _) in enumerate(todo)]


def main():
    ap = argparse.ArgumentParser(prog="contactlab study", description=__doc__.split("\n")[2])
    ap.add_argument("study")
    ap.add_argument("--contactlab", required=True, help=argparse.SUPPRESS)
    ap.add_argument("--out", help="output folder (default: study-<Name>)")
    ap.add_argument("--retry-failed", action="store_true", help="run failed cases again")
    ap.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    args = ap.parse_args()
    try:
        study = study_file.read_study(args.study)
    except study_file.StudyError as e:
        print(f"contactlab: error: {e}", file=sys.stderr)
        return 2
    if args.out == "":
        print("contactlab: error: --out needs a folder, not an empty value", file=sys.stderr)
        return 2
    out = os.path.abspath(args.out or f"study-{study['Name']}")
    os.makedirs(os.path.join(out, "runs"), exist_ok=True)
    todo = study_file.cases(study)
    axes = list(study["Axes"])
    print(f"contactlab study {study['Name']}: {len(todo)} run(s) of {study['Scene']} "
          f"-> {out}", flush=True)

    # As many runners as may be needed (automatic: the cores, if the first run's memory allows);
    # a resumed study counts only the runs it has left (none left: no process is started).
    left = sum(finished_record(case_folder(out, i, name), scene, study["Sets"] + sets,
                               args.retry_failed) is None
               for i, (name, _, sets, scene) in enumerate(todo))
    count = most_runs_at_once(study["Parallel Runs"], left)
    env = process.blas_share(count)
    runners = [process.Runner(args.contactlab, study["Process Per Run"], env)
               for _ in range(count)]
    try:
        rows = run_all(study, todo, out, args, runners)
    except BaseException:
        for runner in runners:
            runner.stop()
        raise
    for runner in runners:
        runner.close()

    report.write_csv(os.path.join(out, "study.csv"), rows, axes)
    # The table first: the plots take a second more (matplotlib's import alone half of it).
    converged = sum(r["status"] == "converged" for r in rows)
    print(f"\ncontactlab study {study['Name']}: {converged} of {len(rows)} converged\n")
    print("\n".join(report.terminal_table(rows, axes, bool(study["Cases"]))), flush=True)
    plots = []
    if not args.no_plots:
        plot = subprocess.run([sys.executable, os.path.join(os.path.dirname(
            os.path.abspath(__file__)), "plot_study.py"), out], capture_output=True, text=True)
        if plot.returncode != 0:
            print("contactlab: warning: no plots: " + plot.stderr.strip().splitlines()[-1]
                  if plot.stderr.strip() else "contactlab: warning: no plots", file=sys.stderr)
        # One line a plot: its file name, a tab, its caption (what each encoding means).
        plots = [tuple(line.split("\t", 1)) for line in plot.stdout.splitlines()
                 if line.split("\t")[0].endswith(".png") and "\t" in line]
    report.write_md(os.path.join(out, "study.md"), study, rows, axes, plots)
    print(f"\nstudy.md  {os.path.join(out, 'study.md')}  (sorted table, Pareto front, "
          "recommendation, plots)")
    if plots:
        print(f"plots     {out}/{{{','.join(p for p, _ in plots)}}}")
    series = [r["folder"] for r in rows if os.path.exists(os.path.join(r["folder"], "result.pvd"))]
    if series:
        print(f"ParaView  {os.path.join(out, 'runs', '*', 'result.pvd')}  ({len(series)} "
              "series, one per run that wrote one)")
    sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
