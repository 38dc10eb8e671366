"""`contactlab run` as the test scripts start it: on one rank, or under mpirun on several (as root
too, as the CI runs), with the output captured. Imported by scripts in tests/app and
tests/verification (they put tests/ on sys.path)."""
import os
import subprocess


def contactlab_run(exe, scene, out, sets=(), ranks=1, options=(), timeout=900):
    """Runs `exe run [SCENE] --out OUT [options] --set S ...` (no SCENE when `scene` is None: the
    built-in one) on `ranks` ranks; returns the command and its CompletedProcess."""
    cmd = [exe, "run"] + ([scene] if scene is not None else []) + ["--out", out] + list(options)
    for s in sets:
        cmd += ["--set", s]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--oversubscribe"] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return cmd, subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
