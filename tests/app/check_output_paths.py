#!/usr/bin/env python3
"""Paths built from the input (issue 61): nothing a user writes makes contactlab write, or
remove, outside the folder it was told to use. For each source of a path:
- Name (results/<Name>) and Output/Profiles/<name> (profile_<name>.csv): a plain name, or one
  sentence and exit 2 ('../../../escaped' wrote outside results/, an empty Name made results/
  itself the folder whose earlier files a run removed);
- --out, --restart and the study's --out: a folder, not an empty value; the study's Name
  (study-<Name>) as the scene's;
- the output folder's clean-up: a run removes what the earlier run's manifest lists, nothing
  else (not a file named like an output, not a listed path outside the folder); a folder
  without a manifest loses only files named as a run's outputs;
- a .geo script (and what it Includes): no command that writes, runs a program or ends the
  process (gmsh runs them at `validate` too);
- Output/Directory, Initial State/From, a mesh file's path: any folder or file the user names
  (read, or written only through the manifest), nothing refused.

usage: check_output_paths.py CONTACTLAB SCENES_DIR WORKDIR"""
import os, shutil, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402

exe, scenes, work = (os.path.abspath(a) for a in sys.argv[1:4])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
checklist = Checklist()
check = checklist.check
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OPENBLAS_NUM_THREADS="1")

SCENE = """contactlab:
  Name: paths
  Mesh:
    Type: rectangle
    rectangle: {Lx: 2.0, Ly: 1.0, nx: 4, ny: 2, Element: quad4}
  Materials:
    body: {Type: linear-elastic, linear-elastic: {E: 100.0, nu: 0.3}}
  Dirichlet:
    fix: {Group: bottom, Components: xy}
  Loads:
    p: {Type: pressure, Group: top, Value: 1.0}
"""


def contactlab(*args, cwd=work):
    return subprocess.run([exe, *args], capture_output=True, text=True, cwd=cwd, env=ENV,
                          timeout=300)


def tree(folder):
    """Every file and folder under `folder`, relative to it."""
    found = set()
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            found.add(os.path.relpath(os.path.join(root, name), folder))
    return found


def refused(label, r, *words, before=None):
    """Exit 2, one sentence naming `words`, and nothing new under work."""
    err = r.stderr.strip()
    new = sorted(tree(work) - before) if before is not None else []
    check(f"{label}: exit 2, one sentence with {list(words)}, nothing written "
          f"({r.returncode}; {err.splitlines()[0] if err else 'no message'}; new: {new})",
          r.returncode == 2 and err.startswith("contactlab: error:") and
          len(err.splitlines()) <= 1 + err.count("usage:") * 99 and
          all(w in err for w in words) and not new)


# 1. Names that become a folder or a file name.
deep = os.path.join(work, "a", "b", "c")
os.makedirs(deep)
scene = os.path.join(work, "scene.yaml")
open(scene, "w").write(SCENE)
results = os.path.join(deep, "results")
os.makedirs(results)
for f in ("summary.json", "steps.csv", "notes.txt"):  # files of the user's in results/
    open(os.path.join(results, f), "w").write("the user's\n")
for name in ("../../../escaped", "", ".", "a/b", "  "):
    for command in ("run", "validate"):
        before = tree(work)
        r = contactlab(command, scene, "--set", f"Name={name}", cwd=deep)
        refused(f"{command} with Name {name!r}", r, "Name", before=before)
check("results/ keeps every file of its own",
      sorted(os.listdir(results)) == ["notes.txt", "steps.csv", "summary.json"])
profile = SCENE + """  Output:
    Profiles:
      "../../up": {From: [0.0, 0.5], To: [2.0, 0.5], Points: 3}
"""
open(os.path.join(work, "profile.yaml"), "w").write(profile)
before = tree(work)
refused("a profile named '../../up'",
        contactlab("run", os.path.join(work, "profile.yaml"), "--out", "profile-run"),
        "Output/Profiles", "'../../up'", before=before)
for option in ("--out", "--restart"):
    before = tree(work)
    refused(f"{option} ''", contactlab("run", scene, option, ""), option, before=before)

# 2. The clean-up of an earlier run's folder: what its manifest lists, nothing else.
folder = os.path.join(work, "folder")
r = contactlab("run", scene, "--out", folder, "--quiet", "--set", "Load Steps/Steps=3")
manifest = os.path.join(folder, ".contactlab-outputs")
listed = open(manifest).read().split() if os.path.exists(manifest) else []
check(f"a run lists what it wrote in its manifest ({len(listed)} names)",
      r.returncode == 0 and sorted(listed) == sorted(set(os.listdir(folder)) - {
          ".contactlab-outputs"}))
# Files a user put there, named like outputs the run did not write; a manifest edited to name
# a file outside the folder.
users = ["contact_t5.csv", "profile_mine.csv", "result_000009.vtu", "notes.txt"]
for f in users:
    open(os.path.join(folder, f), "w").write("the user's\n")
victim = os.path.join(work, "victim.txt")
open(victim, "w").write("outside\n")
open(manifest, "a").write("../victim.txt\n/etc/hostname\n..\n")
r = contactlab("run", scene, "--out", folder, "--quiet", "--set", "Load Steps/Steps=1")
left = set(os.listdir(folder))
check(f"the next run removes the earlier run's files (result_000003.vtu gone: "
      f"{'result_000003.vtu' not in left})", r.returncode == 0 and "result_000003.vtu" not in left)
check(f"and keeps the files it did not write ({sorted(set(users) - left)} removed)",
      set(users) <= left)
check("a manifest naming a file outside the folder removes nothing there",
      os.path.exists(victim))
# A folder of a run from before manifests: only the run's output names go.
older = os.path.join(work, "older")
os.makedirs(older)
for f in ("result_000007.vtu", "summary.json", ".steps.csv.tmp.42", "notes.txt", "plot.png"):
    open(os.path.join(older, f), "w").write("older\n")
r = contactlab("run", scene, "--out", older, "--quiet", "--set", "Load Steps/Steps=1")
left = set(os.listdir(older))
check(f"a folder without a manifest loses only the run's output names ({sorted(left)})",
      r.returncode == 0 and "result_000007.vtu" not in left and ".steps.csv.tmp.42" not in left
      and {"notes.txt", "plot.png"} <= left)

# 3. .geo scripts: gmsh runs them when the scene is read, `validate` too.
geo_dir = os.path.join(work, "geo")
os.makedirs(geo_dir)
shutil.copy(os.path.join(scenes, "nafems-cgs4-2d.yaml"), geo_dir)
base = open(os.path.join(scenes, "nafems-cgs4-2d.geo")).read()
geo = os.path.join(geo_dir, "nafems-cgs4-2d.geo")
open(geo, "w").write(base)
r = contactlab("validate", "nafems-cgs4-2d.yaml", cwd=geo_dir)
check(f"the scene's own script is meshed ({r.returncode})", r.returncode == 0)
for label, command, words in [
        ("System", 'System "touch ran";', ["line", "'System' runs a program"]),
        ("Save", 'Save "saved.msh";', ["'Save' writes a file"]),
        ("CreateDir", 'CreateDir "made";', ["'CreateDir' creates a folder"]),
        ("Printf >", 'Printf("x") > "printed.txt";', ["'Printf' writes a file"]),
        ("Exit", "Exit;", ["'Exit' ends the process"]),
        ("an Include of a script that writes", 'Include "inc.geo";', ["inc.geo", "'Save'"]),
        ("a computed Include", 'Include StrCat("in", "c.geo");', ["computed path"])]:
    open(geo, "w").write(base + "\n" + command + "\n")
    open(os.path.join(geo_dir, "inc.geo"), "w").write('Save "from-include.msh";\n')
    before = tree(work)
    refused(f".geo with {label}", contactlab("validate", "nafems-cgs4-2d.yaml", cwd=geo_dir),
            "nafems-cgs4-2d.yaml", *words, before=before)
open(geo, "w").write(base + '\nPrint.Width = 640;\nPrintf("no file");\n')
r = contactlab("validate", "nafems-cgs4-2d.yaml", cwd=geo_dir)
check(f"print options and a Printf to the terminal are not refused ({r.stderr.strip()[-200:]})",
      r.returncode == 0)

# 4. The study's folder names.
study = os.path.join(work, "study.yaml")
open(study, "w").write(f"""contactlab-study:
  Name: ../../escaped-study
  Scene: {scene}
  Axes: {{Load Steps/Steps: [1]}}
""")
before = tree(work)
refused("study Name '../../escaped-study'", contactlab("study", study, cwd=deep), "Name",
        before=before)
open(study, "w").write(f"""contactlab-study:
  Name: fine
  Scene: {scene}
  Axes: {{Load Steps/Steps: [1]}}
""")
before = tree(work)
refused("study --out ''", contactlab("study", study, "--out", ""), "--out", before=before)
sys.exit(1 if checklist.failures else 0)
