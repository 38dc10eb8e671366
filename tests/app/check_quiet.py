#!/usr/bin/env python3
"""--quiet (issue 61): `run`, `validate` and `critical-mu` print, besides warnings and errors,
only their answer (the closing line and where the results are, validate's verdict,
critical-mu's mu_crit and verdict); the informational lines (the model's size, coefficients
left to contactlab, an earlier run's files removed, the uniqueness check's details) go through
one place that --quiet silences. Without --quiet the same lines print, so that the test sees
them silenced, not lost.

usage: check_quiet.py CONTACTLAB SCENES_DIR WORKDIR"""
import os, re, shutil, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402

exe, scenes, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
checklist = Checklist()
check = checklist.check
ENV = dict(os.environ, OPENBLAS_NUM_THREADS="1")

# What a quiet command may print: warnings and errors on stderr, its answer on stdout.
ANSWER = re.compile(r"contactlab: \S+ (converged in|FAILED)|  (results|summary): |"
                    r".*: valid \(|contactlab: critical-mu: (critical factor|no critical mu|"
                    r"locally unique|possibly non-unique|not computed)")


def run(*args):
    return subprocess.run([exe, *args], capture_output=True, text=True, env=ENV, timeout=300)


def informational(r):
    """The lines --quiet must drop: stderr's that are not a warning or an error, stdout's that
    are not the answer."""
    err = [line for line in r.stderr.splitlines()
           if not line.startswith(("contactlab: warning:", "contactlab: error:"))]
    return err + [line for line in r.stdout.splitlines() if not ANSWER.match(line)]


def answer(r):
    return [re.sub(r", [0-9.e+-]+ s$", "", line) for line in r.stdout.splitlines()
            if ANSWER.match(line)]


# The automatic coefficients' notes, the size, the removed files of an earlier run (run twice).
cgs4 = os.path.join(scenes, "nafems-cgs4-2d.yaml")
strut = os.path.join(scenes, "strut-2d.yaml")
out = os.path.join(work, "cgs4")
commands = [("run", ["run", cgs4, "--out", out, "--set", "Output/VTK=false"]),
            ("run again into its folder", ["run", cgs4, "--out", out, "--set",
                                           "Output/VTK=false"]),
            ("validate", ["validate", cgs4]),
            ("critical-mu", ["critical-mu", strut, "--out", os.path.join(work, "strut")])]
for label, args in commands:
    loud = run(*args)
    quiet = run(*args, "--quiet")
    said = informational(loud)
    left = informational(quiet)
    check(f"{label}: {len(said)} informational line(s) without --quiet, none with it "
          f"({left[:3]})", loud.returncode == quiet.returncode and said and not left)
    check(f"{label}: the answer is the same either way (but the run's seconds)",
          answer(loud) == answer(quiet))
    if label == "critical-mu":
        verdicts = [line for line in quiet.stdout.splitlines() if "unique" in line]
        check(f"critical-mu: one verdict, worded once ({verdicts})",
              len(verdicts) == 1 and verdicts[0].count("unique") == 1)
sys.exit(1 if checklist.failures else 0)
