#!/usr/bin/env python3
"""SIGTERM and SIGINT end a run cleanly: after the first converged step, the signal stops the
run at its next Newton iterate; summary.json says `failure: interrupted`, the exit code is
128 + signal, the VTK series (after its rest frame), steps.csv and contact.csv describe the same
converged steps, and no temporary file is left.

usage: check_interrupt.py CONTACTLAB SCENES_DIR WORKDIR"""
import csv, json, os, re, shutil, signal, subprocess, sys, time

exe, scenes, work = sys.argv[1:4]
failures = 0
for sig in (signal.SIGTERM, signal.SIGINT):
    out = os.path.join(work, sig.name)
    shutil.rmtree(out, ignore_errors=True)
    # Many small steps of a 3D contact scene: seconds each, far from done after the first.
    cmd = [exe, "run", os.path.join(scenes, "hertz-3d.yaml"), "--out", out,
           "--set", "Load Steps/Steps=40"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while not os.path.exists(os.path.join(out, "steps.csv")) and time.time() < deadline:
        if proc.poll() is not None:
            break
        time.sleep(0.05)
    proc.send_signal(sig)
    stdout, stderr = proc.communicate(timeout=120)
    problems = []
    if proc.returncode != 128 + sig.value:
        problems.append(f"exit code {proc.returncode}, not {128 + sig.value}")
    summary = json.load(open(os.path.join(out, "summary.json")))
    if summary["failure"] != "interrupted" or sig.name not in (summary["message"] or ""):
        problems.append(f"summary failure {summary['failure']!r}: {summary['message']!r}")
    steps = list(csv.DictReader(open(os.path.join(out, "steps.csv"))))
    pvd = re.findall(r'file="([^"]+)"', open(os.path.join(out, "result.pvd")).read())
    # result.pvd: the rest frame at t = 0, then one frame per converged step.
    if not (len(steps) == len(pvd) - 1 == summary["load_steps"]["converged"] >= 1):
        problems.append(f"steps.csv {len(steps)} rows, result.pvd {len(pvd)} frames, summary "
                        f"{summary['load_steps']['converged']} converged")
    vtus = sorted(f for f in os.listdir(out) if f.endswith(".vtu"))
    if vtus != sorted(pvd):
        problems.append(f"VTK files {vtus} against result.pvd {pvd}")
    temporaries = [f for f in os.listdir(out) if ".tmp." in f]
    if temporaries:
        problems.append(f"temporaries left: {temporaries}")
    print(f"{'ok  ' if not problems else 'FAIL'} {sig.name}: exit {proc.returncode}, "
          f"{len(steps)} step(s) kept: {summary['message']}")
    for p in problems:
        print("       " + p)
    failures += bool(problems)
print(f"{2 - failures} passed, {failures} failed")
sys.exit(1 if failures else 0)
