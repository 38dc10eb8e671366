#!/usr/bin/env python3
"""cmake/install-deps.sh (the first thing `make run` does on a fresh machine) prints one line
per phase, not apt's and dpkg's progress (some 1 800 lines there): that goes to the log the
script names; a failing phase ends the script with its exit code and the end of the log. Run
against stand-ins for dpkg-query (every package missing), apt-get (many lines, failing on
request) and sudo, first on PATH.

usage: check_install_deps.py SOURCE_DIR WORKDIR"""
import os, shutil, stat, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402

source, work = sys.argv[1:3]
shutil.rmtree(work, ignore_errors=True)
bin_dir = os.path.join(work, "bin")
os.makedirs(bin_dir)
checklist = Checklist()
check = checklist.check

STAND_INS = {
    "dpkg-query": "#!/bin/sh\nexit 1\n",  # nothing installed
    "sudo": '#!/bin/sh\nexec "$@"\n',
    # 600 lines a call, as apt and dpkg print them; exits 100 in the phase FAIL_AT names.
    "apt-get": """#!/bin/sh
i=0
while [ $i -lt 600 ]; do echo "Unpacking libfake$i (1.0-1) ..."; i=$((i + 1)); done
case " $* " in
  *" update "*) phase=update ;;
  *" --download-only "*) phase=download ;;
  *) phase=install ;;
esac
echo "apt-get $phase finished"
[ "$phase" = "$FAIL_AT" ] && { echo "E: Sub-process /usr/bin/dpkg returned an error code (1)"; exit 100; }
exit 0
""",
}
for name, text in STAND_INS.items():
    path = os.path.join(bin_dir, name)
    open(path, "w").write(text)
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)


def install(log, fail_at=""):
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"],
               CONTACTLAB_DEPS_LOG=log, FAIL_AT=fail_at)
    return subprocess.run([os.path.join(source, "cmake", "install-deps.sh")], env=env,
                          capture_output=True, text=True, timeout=120)


packages = [line.strip() for line in open(os.path.join(source, "cmake", "debian-packages.txt"))
            if line.strip() and not line.startswith("#")]
log = os.path.join(work, "build", "install-deps.log")
r = install(log)
shown = (r.stdout + r.stderr).splitlines()
print("\n".join(shown))
check(f"a fresh machine: exit 0 ({r.returncode})", r.returncode == 0)
check(f"one line per phase and one to say where the log is ({len(shown)} lines)",
      len(shown) == 4 and all(line.startswith("contactlab:") for line in shown))
check("the first line names the log", log in shown[0] if shown else False)
logged = open(log).read() if os.path.exists(log) else ""
check("apt's output is in the log, every phase's",
      all(f"apt-get {p} finished" in logged for p in ("update", "download", "install"))
      and logged.count("Unpacking libfake599") == 3)

log = os.path.join(work, "failing", "install-deps.log")
r = install(log, fail_at="install")
shown = (r.stdout + r.stderr).splitlines()
print("\n".join(shown))
check(f"a failing install: its exit code (100, got {r.returncode})", r.returncode == 100)
check("the failure says which phase and where the log is",
      f"installing {len(packages)} package(s) failed" in r.stderr and log in r.stderr)
check("the end of the log follows, dpkg's error with it",
      "returned an error code" in r.stderr and len(shown) < 40)
sys.exit(1 if checklist.failures else 0)
