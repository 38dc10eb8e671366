#!/usr/bin/env python3
"""The Python module against the command: the same scene run by `contactlab run` and by
`contactlab.run()` in a Python process (import, MPI start, the run, the summary), each a whole
process timed from outside, median of N, and the ratio. A small scene measures the start-up the
module adds; a larger one, that the run itself costs the same.

usage: python_module.py CONTACTLAB BUILD_PYTHON_DIR SCENES_DIR WORKDIR [--runs N] [--doc FILE]"""
import argparse, os, shutil, statistics, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import docblock  # noqa: E402

CASES = [("hertz-2d", {}), ("hertz-3d", {})]


def timed(cmd, env):
    start = time.perf_counter()
    done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=1800)
    if done.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed:\n{done.stdout}\n{done.stderr}")
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("contactlab")
    ap.add_argument("python_dir")
    ap.add_argument("scenes")
    ap.add_argument("work")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--doc")
    args = ap.parse_args()
    env = dict(os.environ, PYTHONPATH=args.python_dir, OPENBLAS_NUM_THREADS="1")
    rows = ["| scene | `contactlab run` (s) | `contactlab.run()` from Python (s) | ratio |",
            "|---|---|---|---|"]
    for name, sets in CASES:
        scene = os.path.join(args.scenes, name + ".yaml")
        out = os.path.join(args.work, name)
        shutil.rmtree(out, ignore_errors=True)
        command = [args.contactlab, "run", scene, "--out", out + "-command", "--quiet",
                   "--set", "Output/VTK=false"]
        script = (f"import contactlab; contactlab.run({scene!r}, out={out + '-python'!r}, "
                  "quiet=True, set={'Output/VTK': False})")
        python = ["/usr/bin/python3", "-c", script]
        a, b = [], []
        timed(command, env), timed(python, env)  # warm-up
        for _ in range(args.runs):  # in turn, so that a drift of the machine hits both
            a.append(timed(command, env))
            b.append(timed(python, env))
        ca, cb = statistics.median(a), statistics.median(b)
        ratios = sorted(y / x for x, y in zip(a, b))
        rows.append(f"| {name} | {ca:.2f} | {cb:.2f} | {statistics.median(ratios):.2f} "
                    f"({ratios[0]:.2f}-{ratios[-1]:.2f}) |")
        print(rows[-1], flush=True)
    table = "\n".join(rows) + "\n\n"
    print(table)
    if args.doc:
        docblock.write(args.doc, "python-module", "bench/python_module.py", table)


if __name__ == "__main__":
    main()
