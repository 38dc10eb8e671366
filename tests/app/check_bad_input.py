#!/usr/bin/env python3
"""Bad input: each case must give a non-zero exit, one clear sentence on stderr that names the
file, key or element and the valid choices, and no output folder at all.

usage: check_bad_input.py CONTACTLAB WORKDIR"""
import os, shutil, subprocess, sys

exe, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

GOOD = """contactlab:
  Name: bad-input
  Mesh:
    Type: rectangle
    rectangle: {Lx: 2.0, Ly: 1.0, nx: 4, ny: 2, Element: quad4}
  Materials:
    body:
      Type: linear-elastic
      linear-elastic: {E: 100.0, nu: 0.3}
  Dirichlet:
    fix: {Group: bottom, Components: xy}
  Loads:
    p: {Type: pressure, Group: top, Value: 1.0}
"""

# gmsh 2.2 mesh: two quads, the second one numbered clockwise (inverted).
INVERTED_MSH = """$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "bottom"
2 2 "body"
$EndPhysicalNames
$Nodes
6
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
$EndNodes
$Elements
4
1 1 2 1 1 1 2
2 1 2 1 1 2 3
3 3 2 2 1 1 2 5 4
4 3 2 2 1 2 5 6 3
$EndElements
"""

CONTACT = GOOD.replace("""  Dirichlet:
    fix: {Group: bottom, Components: xy}
""", """  Dirichlet:
    fix: {Group: top, Components: xy}
""").replace("    p: {Type: pressure, Group: top, Value: 1.0}\n", "    g: {Type: body-force, Vector: [0, -1]}\n") + """  Contact:
    floor:
      Slave: bottom
      Obstacle: {Type: plane, Point: [0.0, 0.0], Normal: [0.0, 1.0]}
      Formulation:
        Type: augmented-lagrangian
        augmented-lagrangian: {Normal Augmentation: 100.0}
"""

def contact_with(old, new):
    assert old in CONTACT, old
    return CONTACT.replace(old, new)

# GOOD as an axisymmetric model off the axis (x = r in [1, 3]).
AXI = GOOD.replace("rectangle: {Lx:", "rectangle: {Origin: [1.0, 0.0], Lx:") + \
    "  Geometry: {Type: axisymmetric}\n"


def scene_with(old, new):
    assert old in GOOD, old
    return GOOD.replace(old, new)

# Checkpoints (Initial State, --restart): an earlier run to start from, and a file in a
# checkpoint's place that is not one.
earlier = os.path.join(work, "earlier-run")
open(os.path.join(work, "earlier.yaml"), "w").write(GOOD)
subprocess.run([exe, "run", os.path.join(work, "earlier.yaml"), "--out", earlier, "--quiet"],
               check=True, capture_output=True, timeout=120,
               env=dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1"))
not_checkpoint = os.path.join(work, "not-a-checkpoint")
os.makedirs(not_checkpoint)
open(os.path.join(not_checkpoint, "checkpoint.h5"), "w").write("not HDF5\n")

cases = [
    ("missing scene file", None, ["does-not-exist.yaml"], ["does-not-exist.yaml", "does not exist"]),
    ("missing mesh file",
     scene_with("Type: rectangle\n    rectangle: {Lx: 2.0, Ly: 1.0, nx: 4, ny: 2, Element: quad4}",
                "Type: file\n    file: {Path: nowhere.msh}"),
     [], ["nowhere.msh", "does not exist"]),
    ("malformed YAML", GOOD.replace("{E: 100.0, nu: 0.3}", "{E: 100.0, nu: [0.3}"), [],
     ["malformed YAML", "scene.yaml", "line"]),
    ("unknown key", scene_with("{E: 100.0, nu: 0.3}", "{E: 100.0, nu: 0.3, Youngs: 3}"), [],
     ["scene.yaml", "unknown key 'Youngs'", "Materials/body/linear-elastic", "valid keys: E, nu"]),
    ("unknown top-level key", GOOD + "  Solverr: {}\n", [], ["unknown key 'Solverr'", "valid keys"]),
    ("unknown Type name", GOOD + "  Linear Solver: {Type: superlu}\n", [],
     ["'superlu'", "Linear Solver/Type", "mumps", "klu2", "belos"]),
    ("unknown material type", scene_with("Type: linear-elastic", "Type: rubber"), [],
     ["'rubber'", "Materials/body/Type", "linear-elastic"]),
    ("unknown element type", scene_with("Element: quad4", "Element: quad5"), [],
     ["quad5", "Mesh/rectangle/Element", "quad4"]),
    ("E <= 0", scene_with("E: 100.0", "E: -5.0"), [], ["Materials/body", "E must be > 0"]),
    ("nu outside (-1, 0.5)", scene_with("nu: 0.3", "nu: 0.5"), [], ["Materials/body", "(-1, 0.5)"]),
    # Axisymmetric models (Geometry/Type: axisymmetric, x = r): the half-plane x >= 0, 2D,
    # the axis held radially, a centrifugal load about the axis.
    ("axisymmetric node at x < 0",
     AXI.replace("Origin: [1.0, 0.0]", "Origin: [-1.0, 0.0]"), [],
     ["node 1 at (-1, 0)", "x < 0", "x = r >= 0"]),
    ("axisymmetric axis not held", AXI.replace("Origin: [1.0, 0.0]", "Origin: [0.0, 0.0]"), [],
     ["node 4 at (0, 1)", "on the axis", "Dirichlet condition on x"]),
    ("axisymmetric 3D", GOOD.replace(
        "Type: rectangle\n    rectangle: {Lx: 2.0, Ly: 1.0, nx: 4, ny: 2, Element: quad4}",
        "Type: box\n    box: {Origin: [1, 0, 0], nx: 1, ny: 1, nz: 1, Element: hex8}").replace(
        "Group: top", "Group: zmax").replace("Group: bottom", "Group: zmin") + "  Geometry: {Type: axisymmetric}\n", [],
     ["needs a 2D mesh", "3D"]),
    # Plane stress (Geometry/Type: plane-stress): 2D, pressures dead.
    ("plane-stress follower pressure",
     GOOD.replace("Type: linear-elastic\n      linear-elastic:", "Type: neo-hookean\n      neo-hookean:")
     + "  Geometry: {Type: plane-stress}\n",
     [], ["load 'p'", "plane-stress model has no follower pressure", "Follower: false"]),
    ("plane-stress 3D", GOOD.replace(
        "Type: rectangle\n    rectangle: {Lx: 2.0, Ly: 1.0, nx: 4, ny: 2, Element: quad4}",
        "Type: box\n    box: {nx: 1, ny: 1, nz: 1, Element: hex8}").replace(
        "Group: top", "Group: zmax").replace("Group: bottom", "Group: zmin") + "  Geometry: {Type: plane-stress}\n", [],
     ["plane-stress model needs a 2D mesh", "3D"]),
    ("axisymmetric spin axis", AXI.replace(
        "    p: {Type: pressure, Group: top, Value: 1.0}\n",
        "    p: {Type: pressure, Group: top, Value: 1.0}\n"
        "    spin: {Type: centrifugal, Density: 1, Angular Velocity: 1, Centre: [1, 0]}\n"),
     [], ["spin", "spins about its own axis", "Centre with x = 0"]),
    ("missing boundary group", scene_with("Group: bottom", "Group: bottm"), [],
     ["scene.yaml", "'bottm'", "fix", "bottom, right, top, left"]),
    ("wrong value type", scene_with("nx: 4", "nx: four"), [], ["Mesh/rectangle/nx", "integer"]),
    ("inverted element",
     scene_with("Type: rectangle\n    rectangle: {Lx: 2.0, Ly: 1.0, nx: 4, ny: 2, Element: quad4}",
                "Type: file\n    file: {Path: inverted.msh}").replace(
         "    p: {Type: pressure, Group: top, Value: 1.0}\n", "    g: {Type: body-force, Vector: [0, -1]}\n"),
     [], ["inverted", "element 1 (gmsh tag 4)", "block 'body'", "inverted.msh"]),
    ("bad --set", GOOD, ["--set", "Mesh/rectangle/nx"], ["--set", "key=value"]),
    # A material under another name than its block's, where the contact's automatic coefficients
    # (which read the blocks' materials) come first, with and without friction.
    ("material names no block, contact automatic",
     contact_with("augmented-lagrangian: {Normal Augmentation: 100.0}", "augmented-lagrangian: {}")
     .replace("    body:\n      Type: linear-elastic", "    bdy:\n      Type: linear-elastic"), [],
     ["material given for block 'bdy'", "its blocks are: body"]),
    ("material names no block, friction",
     contact_with("Slave: bottom", "Slave: bottom\n      Friction: 0.3")
     .replace("    body:\n      Type: linear-elastic", "    bdy:\n      Type: linear-elastic"), [],
     ["material given for block 'bdy'", "its blocks are: body"]),
    ("load times decreasing", GOOD + "  Load Steps: {Times: [0.5, 0.2, 1]}\n", [],
     ["Load Steps/Times", "increase (0.2 after 0.5)"]),
    ("load times and steps", GOOD + "  Load Steps: {Times: [0.5, 1], Steps: 4}\n", [],
     ["Steps and Times both given", "leave Steps out"]),
    ("load times past end time", GOOD + "  Load Steps: {Times: [0.5, 2], End Time: 1}\n", [],
     ["End Time (1) is not the last entry of Load Steps/Times (2)"]),
    ("contact: unknown slave group", contact_with("Slave: bottom", "Slave: botom"), [],
     ["Contact/floor/Slave", "'botom'", "bottom, right, top, left"]),
    ("contact: No Contact Group not a group",
     contact_with("Slave: bottom", "Slave: bottom\n      No Contact Group: botom"), [],
     ["Contact/floor/No Contact Group", "'botom' is not a boundary group"]),
    ("contact: No Contact Group without a slave node",
     contact_with("Slave: bottom", "Slave: bottom\n      No Contact Group: top"), [],
     ["Contact/floor/No Contact Group", "'top' holds no node of Slave 'bottom'"]),
    ("contact: slave is a volume block", contact_with("Slave: bottom", "Slave: body"), [],
     ["Contact/floor/Slave", "'body' is not a boundary group"]),
    ("contact: master and obstacle", contact_with("Slave: bottom", "Slave: bottom\n      Master: top"),
     [], ["Contact/floor", "either Master", "not both"]),
    ("contact: neither master nor obstacle",
     contact_with("      Obstacle: {Type: plane, Point: [0.0, 0.0], Normal: [0.0, 1.0]}\n", ""), [],
     ["Contact/floor", "Master boundary group or an Obstacle"]),
    ("contact: slave == master",
     contact_with("      Obstacle: {Type: plane, Point: [0.0, 0.0], Normal: [0.0, 1.0]}\n",
                  "      Master: bottom\n"), [], ["Contact/floor", "the same group 'bottom'"]),
    ("contact: negative friction", contact_with("Slave: bottom", "Slave: bottom\n      Friction: -0.1"),
     [], ["Contact/floor/Friction", ">= 0"]),
    ("contact: negative augmentation",
     contact_with("{Normal Augmentation: 100.0}", "{Normal Augmentation: -100.0}"), [],
     ["Contact/floor/Formulation/augmented-lagrangian", "r_n", "Normal Augmentation"]),
    # The augmented Lagrangian's r_t is automatic (from the model's h); penalty's is the model.
    ("contact: friction without tangential coefficient",
     contact_with("Slave: bottom", "Slave: bottom\n      Friction: 0.3").replace(
         "Type: augmented-lagrangian\n        augmented-lagrangian: {Normal Augmentation: 100.0}",
         "Type: penalty\n        penalty: {Normal Penalty: 100.0}"), [],
     ["Tangential Penalty", "Friction > 0"]),
    ("contact: unknown formulation", contact_with("Type: augmented-lagrangian", "Type: mortar-magic"),
     [], ["'mortar-magic'", "Contact/floor/Formulation/Type", "penalty", "lagrange"]),
    ("contact: misspelt key", contact_with("Slave: bottom", "Slave: bottom\n      Frction: 0.3"), [],
     ["unknown key 'Frction'", "Contact/floor", "Friction"]),
    ("contact: sphere of radius 0",
     contact_with("{Type: plane, Point: [0.0, 0.0], Normal: [0.0, 1.0]}",
                  "{Type: sphere, Point: [0.0, -1.0], Radius: 0.0}"), [],
     ["Contact/floor/Obstacle", "Radius must be > 0"]),
    ("contact: initial statuses without multipliers",
     contact_with("Slave: bottom", "Slave: bottom\n      Initial Contact: all").replace(
         "Type: augmented-lagrangian\n        augmented-lagrangian: {Normal Augmentation: 100.0}",
         "Type: penalty\n        penalty: {Normal Penalty: 100.0}"), [],
     ["Contact/floor/Initial Contact", "penalty", "multipliers"]),
    ("contact: an unknown discretization",
     contact_with("Slave: bottom", "Slave: bottom\n      Discretization: segment-to-segment"),
     [], ["Discretization", "segment-to-segment", "automatic", "mortar"]),
    ("critical mu tolerance out of range", GOOD + "  Output: {Critical Mu Tolerance: 2.0}\n", [],
     ["Output/Critical Mu Tolerance", "[0, 1)"]),
    ("contact times beyond the end", GOOD + "  Output: {Contact Times: [0.5, 2.0]}\n", [],
     ["Output/Contact Times: 2 is not in (0, End Time = 1]"]),
    ("contact times not increasing", GOOD + "  Output: {Contact Times: [0.5, 0.5]}\n", [],
     ["Output/Contact Times must increase (0.5 after 0.5)"]),
    ("line search without the NOX driver", GOOD + "  Newton: {Line Search: Backtrack}\n", [],
     ["Newton/Line Search 'Backtrack'", "Driver: nox"]),
    ("a mesh that would exhaust memory", scene_with("nx: 4, ny: 2", "nx: 100000, ny: 100000"), [],
     ["Mesh", "rectangle", "about 1e+10 elements", "Max Elements"]),
    ("empty scene file", "\n# nothing\n", [], ["scene.yaml", "the file is empty"]),
    ("scene file is a directory", None, ["."], ["is a directory"]),
    ("tab in the indentation", GOOD.replace("  Name: bad-input", "\tName: bad-input"), [],
     ["scene.yaml", "line 2", "tab in the indentation"]),
    ("duplicate key", GOOD.replace("  Materials:", "  Name: again\n  Materials:"), [],
     ["scene.yaml", "line 6", "'Name'", "given twice", "first at line 2"]),
    ("2D: a z component of a load", scene_with("    p: {Type: pressure, Group: top, Value: 1.0}\n",
                                                "    p: {Type: traction, Group: top, Vector: [0, -1, 5]}\n"),
     [], ["Loads/p/Vector", "z component", "2D"]),
    ("follower pressure on a small-strain block",
     scene_with("Group: top, Value: 1.0}", "Group: top, Value: 1.0, Follower: true}"), [],
     ["load 'p'", "Follower: true", "block 'body'", "'linear-elastic' is small-strain"]),
    ("follower on a traction",
     scene_with("    p: {Type: pressure, Group: top, Value: 1.0}\n",
                "    p: {Type: traction, Group: top, Vector: [0, -1], Follower: false}\n"), [],
     ["Loads/p/Follower", "only a pressure", "dead load"]),
    ("follower pressure with a symmetric solver",
     scene_with("Type: linear-elastic\n      linear-elastic: {E: 100.0, nu: 0.3}",
                "Type: neo-hookean\n      neo-hookean: {E: 100.0, nu: 0.3}")
     + "  Linear Solver: {Type: mumps, mumps: {Mode: symmetric-indefinite}}\n", [],
     ["Linear Solver/mumps", "'symmetric-indefinite'", "Mode: general", "load 'p'", "not symmetric",
      "Follower: false"]),
    ("follower pressure with conjugate gradients",
     scene_with("Type: linear-elastic\n      linear-elastic: {E: 100.0, nu: 0.3}",
                "Type: neo-hookean\n      neo-hookean: {E: 100.0, nu: 0.3}")
     + "  Linear Solver: {Type: belos}\n", [],
     ["Linear Solver/belos", "Method 'cg'", "gmres", "load 'p'"]),
    ("2D: a z displacement", scene_with("Components: xy", "Components: z"), [],
     ["Dirichlet/fix/Components", "'z'", "2D"]),
    ("a table function with unequal lists",
     GOOD.replace("Value: 1.0}", "Value: 1.0, Function: table, Times: [0.0, 1.0], "
                  "Factors: [0.0, 1.0, 0.0]}"), [],
     ["Loads/p/Function table", "same length"]),
    ("a table function whose times go back",
     GOOD.replace("Value: 1.0}", "Value: 1.0, Function: table, Times: [0.0, 1.0, 0.5], "
                  "Factors: [0.0, 1.0, 0.0]}"), [],
     ["Loads/p/Times", "strictly increasing", "entry 3"]),
    ("table times without a table",
     GOOD.replace("Value: 1.0}", "Value: 1.0, Times: [0.0, 1.0], Factors: [0.0, 1.0]}"), [],
     ["Loads/p/Times", "Function: table"]),
    ("symmetry on an unknown group",
     GOOD + "  Symmetry:\n    cut: {Group: leftt}\n", [],
     ["scene.yaml", "symmetry condition 'cut'", "'leftt'"]),
    ("2D: a symmetry normal with z",
     GOOD + "  Symmetry:\n    cut: {Group: left, Normal: [1.0, 0.0, 1.0]}\n", [],
     ["Symmetry/cut/Normal", "z component"]),
    ("a symmetry normal that is not the group's",
     GOOD + "  Symmetry:\n    cut: {Group: left, Normal: [1.0, 1.0]}\n", [],
     ["symmetry condition 'cut'", "off the plane", "planar"]),
    ("tie on an unknown group",
     GOOD + "  Ties:\n    t: {Groups: [left, rightt]}\n", [],
     ["scene.yaml", "tie 't'", "'rightt'"]),
    ("tie of groups with different node counts",
     GOOD + "  Ties:\n    t: {Groups: [left, top]}\n", [],
     ["tie 't'", "group 'top' has 5 nodes", "'left' 3", "one to one"]),
    ("tie with a coefficient missing",
     GOOD + "  Ties:\n    t: {Groups: [left, right], Coefficients: [1.0]}\n", [],
     ["tie 't'", "1 coefficients for 2 groups", "one per group"]),
    ("tie with a right side on held nodes",
     GOOD + "  Ties:\n    t: {Groups: [left, right], Value: 0.1}\n", [],
     ["tie 't': the equation of node", "leaves no dof to make dependent",
      "tie 't' has a right side (Value 0.1)", "Dirichlet condition"]),
    ("2D: a tie in z",
     GOOD + "  Ties:\n    t: {Groups: [left, right], Components: z}\n", [],
     ["Ties/t/Components", "'z'", "2D"]),
    ("spring on an unknown group",
     GOOD + "  Springs:\n    hold: {Group: topp, Components: x, Stiffness: 1.0}\n", [],
     ["scene.yaml", "spring 'hold'", "'topp'"]),
    ("spring with a negative stiffness",
     GOOD + "  Springs:\n    hold: {Group: top, Components: x, Stiffness: -1.0}\n", [],
     ["Springs/hold/Stiffness", "> 0"]),
    ("spring without a stiffness", GOOD + "  Springs:\n    hold: {Group: top, Components: x}\n",
     [], ["Springs/hold/Stiffness", "> 0"]),
    ("2D: a spring in z", GOOD + "  Springs:\n    hold: {Group: top, Components: z, Stiffness: 1.0}\n",
     [], ["Springs/hold/Components", "'z'", "2D"]),
    ("point load on an unknown group",
     scene_with("    p: {Type: pressure, Group: top, Value: 1.0}\n",
                "    f: {Type: point-load, Group: tip, Vector: [0, -1]}\n"), [],
     ["scene.yaml", "point load 'f'", "'tip'"]),
    ("2D: a z component of a point load",
     scene_with("    p: {Type: pressure, Group: top, Value: 1.0}\n",
                "    f: {Type: point-load, Group: top, Vector: [0, -1, 2]}\n"), [],
     ["Loads/f/Vector", "z component", "2D"]),
    ("Distribution on a pressure",
     scene_with("Group: top, Value: 1.0}", "Group: top, Value: 1.0, Distribution: per-node}"), [],
     ["Loads/p/Distribution", "point-load only"]),
    ("point group farther than its tolerance",
     GOOD + "  Point Groups:\n    tip: {Point: [2.5, 0.5], Tolerance: 0.01}\n", [],
     ["Point Groups/tip/Point", "0.5", "Tolerance"]),
    ("point group named like a mesh group",
     GOOD + "  Point Groups:\n    top: {Point: [0.0, 1.0]}\n", [],
     ["Point Groups/top", "already has a group named 'top'"]),
    ("contact: initial penetration deeper than an element",
     contact_with("Point: [0.0, 0.0]", "Point: [0.0, 0.9]"), [],
     ["initial penetration larger than an element", "'bottom'", "zone floor"]),
    ("Initial State from a folder without a checkpoint",
     GOOD + f"  Initial State: {{From: {work}/no-such-run}}\n", [],
     ["Initial State/From", "no-such-run/checkpoint.h5", "no such file"]),
    ("Initial State from a file that is not a checkpoint",
     GOOD + f"  Initial State: {{From: {not_checkpoint}}}\n", [],
     ["Initial State/From", "checkpoint.h5", "not an HDF5 file"]),
    ("Initial State from another mesh",
     scene_with("nx: 4", "nx: 8") + f"  Initial State: {{From: {earlier}}}\n", [],
     ["Initial State/From", "the checkpoint's mesh has 15 nodes, this scene's 27",
      "a run starts from a checkpoint of the same mesh"]),
    ("Initial State at End Time", GOOD + f"  Initial State: {{From: {earlier}}}\n", [],
     ["Initial State/From", "the checkpoint is at t = 1", "nothing to run"]),
    # Temperature: a block of Materials, a law that takes one, tables that are functions of T.
    ("temperature of an unknown block", GOOD + "  Temperature:\n    tube: {Value: 304.0}\n", [],
     ["scene.yaml", "Temperature/tube", "'tube' is not a block of Materials", "blocks: body"]),
    ("temperature table without a column",
     scene_with("Type: linear-elastic\n      linear-elastic: {E: 100.0, nu: 0.3}",
                "Type: neo-hookean\n      neo-hookean: {E: 100.0, Temperature Tables: "
                "{Temperatures: [20, 304]}}"), [],
     ["Materials/body", "Temperature Tables has Temperatures but no parameter column"]),
    ("temperature table with Times but a ramp",
     GOOD + "  Temperature:\n    body: {Value: 304.0, Times: [0, 1], Factors: [0, 1]}\n", [],
     ["Temperature/body/Times and Factors belong to Function: table"]),
    ("E and its temperature table",
     scene_with("{E: 100.0, nu: 0.3}", "{E: 100.0, nu: 0.3, Temperature Tables: "
                "{Temperatures: [20, 304], E: [100, 90]}}"), [],
     ["Materials/body", "give E or Temperature Tables/E, not both"]),
    ("temperature table out of order",
     scene_with("{E: 100.0, nu: 0.3}", "{nu: 0.3, Temperature Tables: "
                "{Temperatures: [304, 20], E: [90, 100]}}"), [],
     ["Materials/body", "Temperature Tables/E", "strictly increasing"]),
]

open(os.path.join(work, "inverted.msh"), "w").write(INVERTED_MSH)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
failures = 0
for name, scene, extra, expected in cases:
    out = os.path.join(work, "out-" + name.replace(" ", "-"))
    if scene is not None:
        path = os.path.join(work, "scene.yaml")
        open(path, "w").write(scene)
        args = [path] + extra
    else:
        args = [os.path.join(work, extra[0])] + extra[1:]
    run = subprocess.run([exe, "run"] + args + ["--out", out], capture_output=True, text=True,
                         env=env, timeout=120)
    err = run.stderr.strip()
    problems = []
    if run.returncode != 2:
        problems.append(f"exit code {run.returncode}, not 2 (bad input)")
    lines = [l for l in err.splitlines() if l.strip()]
    if not lines or not lines[0].startswith("contactlab: error:"):
        problems.append("no 'contactlab: error:' line")
    elif name != "bad --set" and len(lines) != 1:
        problems.append(f"{len(lines)} lines on stderr instead of one")
    for e in expected:
        if e not in err:
            problems.append(f"message lacks {e!r}")
    if os.path.exists(out):
        problems.append("an output folder was created")
    status = "ok  " if not problems else "FAIL"
    print(f"{status} {name}: {err.splitlines()[0] if err else '(no message)'}")
    for p in problems:
        print("       " + p)
    failures += bool(problems)

# --restart: a folder without a checkpoint, and a scene changed since the checkpoint, are bad
# input that leaves the folder as it was.
changed = os.path.join(work, "changed.yaml")
open(changed, "w").write(GOOD)
changed_run = os.path.join(work, "changed-run")
subprocess.run([exe, "run", changed, "--out", changed_run, "--quiet"], check=True,
               capture_output=True, timeout=120, env=env)
open(changed, "w").write(scene_with("Value: 1.0", "Value: 2.0"))
restart_cases = [
    ("--restart without a checkpoint", os.path.join(work, "no-such-run"),
     ["--restart", "no-such-run/checkpoint.h5", "no such file"]),
    ("--restart of a changed scene", changed_run,
     ["--restart", "changed.yaml", "is not the one the checkpoint was written with",
      "Initial State: {From:"]),
]
for name, folder, expected in restart_cases:
    before = sorted((f, os.path.getmtime(os.path.join(folder, f)))
                    for f in (os.listdir(folder) if os.path.isdir(folder) else []))
    run = subprocess.run([exe, "run", "--restart", folder], capture_output=True, text=True,
                         env=env, timeout=120)
    err = run.stderr.strip()
    problems = [f"message lacks {e!r}" for e in expected if e not in err]
    if run.returncode != 2:
        problems.append(f"exit code {run.returncode}, not 2")
    after = sorted((f, os.path.getmtime(os.path.join(folder, f)))
                   for f in (os.listdir(folder) if os.path.isdir(folder) else []))
    if after != before:
        problems.append("the run folder changed")
    print(f"{'ok  ' if not problems else 'FAIL'} {name}: {err.splitlines()[0] if err else '(no message)'}")
    for p in problems:
        print("       " + p)
    failures += bool(problems)
    cases.append(name)

# The output folder is checked before anything is solved: a file in its place, a file on its
# path, or a folder that cannot be written is bad input (exit 2, one sentence, nothing solved).
good = os.path.join(work, "good.yaml")
open(good, "w").write(GOOD)
blocker = os.path.join(work, "a-file")
open(blocker, "w").write("not a folder\n")
readonly = os.path.join(work, "read-only")
os.makedirs(readonly)
os.chmod(readonly, 0o500)
folder_cases = [("output folder is a file", blocker, ["a-file", "is a file, not a folder"]),
                ("output folder under a file", os.path.join(blocker, "out"),
                 ["a-file' is a file, not a folder"])]
if os.geteuid() != 0:  # root writes anywhere
    folder_cases.append(("output folder not writable", os.path.join(readonly, "out"),
                         ["read-only", "Permission denied"]))
for name, out, expected in folder_cases:
    run = subprocess.run([exe, "run", good, "--out", out], capture_output=True, text=True, env=env,
                         timeout=120)
    err = run.stderr.strip()
    problems = [f"message lacks {e!r}" for e in expected if e not in err]
    if run.returncode != 2:
        problems.append(f"exit code {run.returncode}, not 2")
    if "step 1" in run.stderr or "converged" in run.stdout:
        problems.append("the scene was solved before the folder was checked")
    print(f"{'ok  ' if not problems else 'FAIL'} {name}: {err.splitlines()[0] if err else '(no message)'}")
    for p in problems:
        print("       " + p)
    failures += bool(problems)
    cases.append(name)

# A new run into an older run's folder removes what that run wrote and this one rewrites: no
# stale step outlives it (a 1-step run after a 3-step run leaves no result_000002.vtu).
stale_dir = os.path.join(work, "stale")
os.makedirs(stale_dir)
for f in ["result_000002.vtu", ".steps.csv.tmp.123", "summary.json", "notes.txt"]:
    open(os.path.join(stale_dir, f), "w").write("stale-marker\n")
run = subprocess.run([exe, "run", good, "--out", stale_dir], capture_output=True, text=True,
                     env=env, timeout=120)
left = sorted(os.listdir(stale_dir))
problems = []
if run.returncode != 0:
    problems.append(f"exit code {run.returncode}: {run.stderr.strip()}")
for f in ["result_000002.vtu", ".steps.csv.tmp.123"]:
    if f in left:
        problems.append(f"stale {f} left")
if "notes.txt" not in left:
    problems.append("a file the run does not write (notes.txt) was removed")
if "stale-marker" in open(os.path.join(stale_dir, "summary.json")).read():
    problems.append("summary.json is the old one")
print(f"{'ok  ' if not problems else 'FAIL'} stale outputs of an earlier run: {left}")
for p in problems:
    print("       " + p)
failures += bool(problems)
cases.append("stale outputs")
print(f"{len(cases) - failures} passed, {failures} failed")
sys.exit(1 if failures else 0)
