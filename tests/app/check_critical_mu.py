#!/usr/bin/env python3
"""`contactlab critical-mu`: the critical friction coefficient of the converged state's status
pattern, in the output and summary.json, the same on 1 and 2 ranks; a frictionless scene says
why it is not computed.

usage: check_critical_mu.py CONTACTLAB SCENES_DIR WORKDIR"""
import json, os, shutil, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import contactlab_run  # noqa: E402

exe, scenes, work = sys.argv[1:4]


def run(scene, ranks):
    out = os.path.join(work, f"{scene}-np{ranks}")
    shutil.rmtree(out, ignore_errors=True)
    _, r = contactlab_run(exe, os.path.join(scenes, scene + ".yaml"), out, ranks=ranks,
                          timeout=300, command="critical-mu")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "critical-mu" in r.stdout, r.stdout
    return json.load(open(os.path.join(out, "summary.json")))["critical_mu"]


one, two = run("pad-2d", 1), run("pad-2d", 2)
print("pad-2d:", one)
assert one["computed"] and two["computed"]
assert one["patterns_examined"] >= 1 and one["verdict"] in ("locally unique", "possibly non-unique")
mu = 0.45
crit = one["zones"]["floor"]
assert crit is not None and abs(crit - mu * one["factor"]) <= 1e-12 * crit
assert crit > mu, "the pad at mu = 0.45 is below its critical mu"
assert abs(two["zones"]["floor"] - crit) <= 1e-8 * crit, (crit, two["zones"]["floor"])

# Output/Critical Mu Check: the same check after every step of `run`, in steps.csv.
out = os.path.join(work, "pad-2d-check")
shutil.rmtree(out, ignore_errors=True)
r = subprocess.run([exe, "run", os.path.join(scenes, "pad-2d.yaml"), "--out", out, "--set",
                    "Output/Critical Mu Check=true"], capture_output=True, text=True, timeout=300)
assert r.returncode == 0, r.stdout + r.stderr
import csv
rows = list(csv.DictReader(open(os.path.join(out, "steps.csv"))))
last = float(rows[-1]["critical_mu"])
print("pad-2d per step:", [row["critical_mu"] for row in rows])
assert abs(last - crit) <= 1e-8 * crit, (last, crit)
check = json.load(open(os.path.join(out, "summary.json")))["critical_mu_check"]
assert check == {"steps_checked": len(rows), "possibly_non_unique": 0}, check

# One verdict from both checks (doc/algorithms.md, "The verdict"): the pad is below its critical
# mu with agreeing signs; the strut at mu = 1 is above its mu_crit = 0.618 while the signs around
# its state agree, and three states were found there: possibly non-unique, said once.
assert one["verdict"] == "locally unique", one
out = os.path.join(work, "strut-2d")
shutil.rmtree(out, ignore_errors=True)
_, r = contactlab_run(exe, os.path.join(scenes, "strut-2d.yaml"), out, timeout=300,
                      command="critical-mu")
strut = json.load(open(os.path.join(out, "summary.json")))["critical_mu"]
print("strut-2d:", strut)
assert strut["verdict"] == "possibly non-unique" and "mu_crit" in strut["verdict_reason"], strut
said = [line for line in r.stdout.splitlines() if "unique" in line]
assert len(said) == 1 and said[0].count("unique") == 1, r.stdout

frictionless = run("hertz-2d", 1)
print("hertz-2d:", frictionless)
assert frictionless["computed"] is False and "friction" in frictionless["reason"]

# The check uses the scene's own linear solver: one without determinants is refused before the
# run, with a sentence that names the solvers that have them.
out = os.path.join(work, "pad-2d-belos")
r = subprocess.run([exe, "critical-mu", os.path.join(scenes, "pad-2d.yaml"), "--out", out, "--set",
                    "Linear Solver/Type=belos"], capture_output=True, text=True, timeout=300)
assert r.returncode == 2, r.stdout + r.stderr
assert "Linear Solver 'belos'" in r.stderr and "mumps" in r.stderr, r.stderr
assert not os.path.exists(os.path.join(out, "summary.json")), "refused runs write nothing"
print("ok")
