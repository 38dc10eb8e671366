#!/usr/bin/env python3
"""Checkpoints (apps/RunCheckpoint): a run killed after step K and continued with
`contactlab run --restart DIR`, and a chained run (scene A to t_K, then scene B with
`Initial State: {From: A's folder}` to the end), each end at the same state as one
uninterrupted run: displacements, contact pressure and tractions, stresses and plastic strain
of the last frame, bitwise (the same operations in the same order), and the continued run's
outputs hold every step once (steps.csv rows 1..N, result.pvd frames at the same times).

The scenes are small versions of scenes/cattaneo-mindlin-2d.yaml (Coulomb friction with the
augmented Lagrangian and with penalty: the slip history matters) and scenes/plastic-strip-2d.yaml (J2 plasticity loaded past yield and unloaded:
the internal variables matter). Their loads are tables of absolute times, so that scene A's
shorter End Time does not rescale them, and the steps are 1/8, exact in binary, so that A's
last time is the long run's.

usage: check_restart.py CONTACTLAB CASE WORKDIR [--ranks N]
       (CASE: friction | friction-penalty | friction-fixed-point | plasticity | slow-dynamics)"""
import argparse, csv, json, os, shutil, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import contactlab_run, read_grid, result_frames  # noqa: E402

FRICTION = """contactlab:
  Name: restart-friction
  Mesh:
    Type: roller-on-base
    roller-on-base:
      Contact Point: [0.0, 0.0]
      Radius: 1.0
      Base: disc
      Element: quad8
      Size Contact: 0.04
      Size Far: 0.3
      Fine Radius: 0.15
      Transition Length: 0.5
  Materials:
    roller: {Type: linear-elastic, linear-elastic: {E: 1.0, nu: 0.3}}
    base: {Type: linear-elastic, linear-elastic: {E: 1.0, nu: 0.3}}
  Dirichlet:
    press:
      Group: roller-flat
      Components: y
      Value: -0.02
      Function: table
      Times: [0.0, 0.25, 1.0]
      Factors: [0.0, 1.0, 1.0]
    shift:
      Group: roller-flat
      Components: x
      Value: 0.004
      Function: table
      Times: [0.0, 0.25, 1.0]
      Factors: [0.0, 0.0, 1.0]
    base: {Group: base-bottom, Components: xy, Value: 0.0}
  Contact:
    interface:
      Slave: roller-curved
      Master: base-top
      Friction: 0.3
      Formulation:
        Type: augmented-lagrangian
        augmented-lagrangian: {Normal Augmentation: 100.0, Tangential Augmentation: 1000.0}
  Load Steps: {Steps: 8, End Time: 1.0}
  # The uninterrupted run solves step K+1's first systems with step K's factors corrected by
  # low-rank updates, the continued run with fresh ones: the same solutions to round-off, which
  # then decides a count now and then (34 Newton iterations against 33 with the penalty law
  # under OpenBLAS's Cooperlake (AVX-512) kernels). Without the reuse the two runs are the same
  # operations: bitwise, which is what shows that the checkpoint holds the whole state.
  Linear Solver: {mumps: {Factorization Reuse: never}}
"""

PLASTICITY = """contactlab:
  Name: restart-plasticity
  Mesh:
    Type: rectangle
    rectangle: {Lx: 10.0, Ly: 1.0, nx: 2, ny: 4, Element: quad4}
  Materials:
    body:
      Type: j2-small-strain
      j2-small-strain: {E: 200000.0, nu: 0.3, Yield Stress: 250.0, Isotropic Hardening Modulus: 1000.0, Kinematic Hardening Modulus: 1000.0}
  Dirichlet:
    hold: {Group: left, Components: x}
    pin: {Group: corner-bl, Components: y}
    pull:
      Group: right
      Components: x
      Value: 0.05
      Function: table
      Times: [0.0, 0.5, 1.0]
      Factors: [0.0, 1.0, 0.4]
  Load Steps: {Steps: 8, End Time: 1.0}
"""

# The penalty law carries its friction history in the checkpoint's contact/resistance (the
# multiplier laws in their multipliers).
FRICTION_PENALTY = FRICTION.replace("Name: restart-friction", "Name: restart-friction-penalty").replace(
    """        Type: augmented-lagrangian
        augmented-lagrangian: {Normal Augmentation: 100.0, Tangential Augmentation: 1000.0}""",
    """        Type: penalty
        penalty: {Normal Penalty: 1000.0, Tangential Penalty: 1000.0}""")
# The fixed point extrapolates each step's start from the last step (Newton/Extrapolation
# 'automatic'), as does the plastic strip without contact: the checkpoint's last_step carries
# that step, multipliers included, so that the continued run's next step starts the same.
FRICTION_FIXED_POINT = FRICTION.replace(
    "Name: restart-friction", "Name: restart-friction-fixed-point").replace(
    "  Load Steps:", "  Algorithm: {Method: fixed-point}\n  Load Steps:")
# Slow dynamics measures each step's inertia from a predictor that moves with the last step's
# velocity: the checkpoint's last_step/slow_dynamics_previous carries the state before the last
# one, so that the continued run's first predictor is the uninterrupted run's.
SLOW_DYNAMICS = FRICTION.replace("Name: restart-friction", "Name: restart-slow-dynamics").replace(
    "linear-elastic: {E: 1.0, nu: 0.3}", "linear-elastic: {E: 1.0, nu: 0.3, density: 1.0}").replace(
    "  Load Steps:",
    "  Algorithm: {Regularization: slow-dynamics, slow-dynamics: {Time Scale: 3.0e-3}}\n"
    "  Load Steps:")
SCENES = {"friction": FRICTION, "friction-penalty": FRICTION_PENALTY,
          "friction-fixed-point": FRICTION_FIXED_POINT, "plasticity": PLASTICITY,
          "slow-dynamics": SLOW_DYNAMICS}

# Fields of the last frame compared (those the frame has).
FIELDS = ["displacement", "contact_pressure", "tangential_traction", "slip", "stress",
          "equivalent_plastic_strain"]


def fail(message):
    sys.exit("FAIL: " + message)


def run(cmd_args, ranks, env=None):
    cmd = list(cmd_args)
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--oversubscribe"] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               **(env or {}))
    return cmd, subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)


def must_succeed(cmd, proc):
    if proc.returncode != 0:
        fail(f"{' '.join(cmd)} exited with {proc.returncode}\n{proc.stdout}\n{proc.stderr}")


def last_frame_fields(out):
    import vtk.util.numpy_support as ns
    grid = read_grid(result_frames(out)[-1][1])
    fields = {}
    for data in (grid.GetPointData(), grid.GetCellData()):
        for name in FIELDS:
            array = data.GetArray(name)
            if array is not None:
                fields[name] = ns.vtk_to_numpy(array)
    return fields


def compare(reference, other, what):
    """The largest difference relative to each field's largest magnitude; FAIL above 1e-12."""
    worst = 0.0
    a, b = last_frame_fields(reference), last_frame_fields(other)
    if sorted(a) != sorted(b):
        fail(f"{what}: fields {sorted(b)}, the uninterrupted run's {sorted(a)}")
    for name in a:
        scale = max(abs(a[name]).max(), 1e-300)
        diff = abs(a[name] - b[name]).max() / scale
        worst = max(worst, diff)
        if diff > 1e-12:
            fail(f"{what}: {name} differs from the uninterrupted run's by {diff:.3e} (relative)")
    bitwise = all((a[n] == b[n]).all() for n in a)
    print(f"ok   {what}: {', '.join(sorted(a))} equal to the uninterrupted run's "
          f"({'bitwise' if bitwise else f'to {worst:.1e} relative'})")


def check_file_layout(out, k):
    """checkpoint.h5 as doc/scenes.md describes it, read with h5py: the step, its time, and per
    node id the displacement of the run's last frame."""
    import h5py
    import vtk.util.numpy_support as ns
    with h5py.File(os.path.join(out, "checkpoint.h5"), "r") as f:
        if f.attrs["step"] != k or f.attrs["time"] != k / 8:
            fail(f"checkpoint.h5 says step {f.attrs['step']}, t = {f.attrs['time']}")
        u = dict(zip(f["nodes/id"][:], f["nodes/displacement"][:]))
    grid = read_grid(result_frames(out)[-1][1])
    ids = ns.vtk_to_numpy(grid.GetPointData().GetArray("node_id")).astype(int)
    frame = ns.vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    dim = len(next(iter(u.values())))
    for i, node in enumerate(ids):
        if (u[node] != frame[i][:dim]).any():
            fail(f"checkpoint.h5: node {node}'s displacement {u[node]}, the frame's {frame[i]}")
    print(f"ok   checkpoint.h5 read with h5py: step {k}, t = {k / 8}, the displacements of the "
          f"last frame by node id")


def step_times(out):
    rows = list(csv.DictReader(open(os.path.join(out, "steps.csv"))))
    return [(int(r["step"]), r["time"]) for r in rows]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("app")
    parser.add_argument("case", choices=sorted(SCENES))
    parser.add_argument("work")
    parser.add_argument("--ranks", type=int, default=1)
    args = parser.parse_args()
    exe, ranks, k = args.app, args.ranks, 5
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    scene = os.path.join(args.work, f"{args.case}.yaml")
    open(scene, "w").write(SCENES[args.case])
    full, killed = os.path.join(args.work, "full"), os.path.join(args.work, "killed")
    first, second = os.path.join(args.work, "chain-a"), os.path.join(args.work, "chain-b")

    # 1. The reference: one uninterrupted run.
    must_succeed(*run([exe, "run", scene, "--out", full, "--quiet"], ranks))

    # 2. Killed by SIGKILL right after step K's outputs and checkpoint, then continued.
    cmd, proc = run([exe, "run", scene, "--out", killed, "--quiet"], ranks,
                    env={"CONTACTLAB_TEST_KILL_AFTER_STEP": str(k)})
    if proc.returncode == 0 or os.path.exists(os.path.join(killed, "summary.json")):
        fail(f"the run was not killed after step {k} (exit {proc.returncode})")
    if len(step_times(killed)) != k:
        fail(f"the killed run's steps.csv has {len(step_times(killed))} rows, not {k}")
    # What a writer killed mid-file leaves: a temporary, removed by the continued run.
    open(os.path.join(killed, ".steps.csv.tmp.999999"), "w").write("half a file")
    must_succeed(*run([exe, "run", "--restart", killed, "--quiet"], ranks))
    left = [f for f in os.listdir(killed) if ".tmp." in f]
    if left:
        fail(f"the continued run left temporaries: {left}")
    if step_times(killed) != step_times(full):
        fail(f"the continued steps.csv lists {step_times(killed)}, the uninterrupted run's "
             f"{step_times(full)}")
    times = [t for t, _ in result_frames(killed)]
    if times != [t for t, _ in result_frames(full)]:
        fail(f"the continued result.pvd has frames at {times}")
    print(f"ok   restart after a kill at step {k}: steps.csv and result.pvd hold each of the "
          f"{len(times) - 1} steps once")
    # progress.log: the killed run's lines, then the continued run's after a separator.
    log = open(os.path.join(killed, "progress.log")).read().splitlines()
    if "  (continued from the checkpoint)" not in log or "converged in" not in log[-1]:
        fail(f"the continued run's progress.log does not continue the killed run's: {log[-3:]}")
    print("ok   progress.log continues the killed run's")
    # summary.json counts the whole run: every count the uninterrupted run's.
    counts = lambda out: {key: json.load(open(os.path.join(out, "summary.json")))[key]
                          for key in ("iterations", "linear_solves", "load_steps", "cycling")}
    if counts(killed) != counts(full):
        fail(f"the continued run's summary counts {counts(killed)}, the uninterrupted run's "
             f"{counts(full)}")
    print("ok   the continued run's summary.json counts the whole run")
    compare(full, killed, f"restart after a kill at step {k}")

    # 3. Chained: A to t_K = K/8 in K steps of 1/8, then B from A's checkpoint to the end.
    must_succeed(*run([exe, "run", scene, "--out", first, "--quiet", "--set",
                       f"Load Steps/End Time={k / 8}", "--set", f"Load Steps/Steps={k}"], ranks))
    must_succeed(*run([exe, "run", scene, "--out", second, "--quiet", "--set",
                       f"Initial State/From={first}"], ranks))
    if [s for s, _ in step_times(second)] != list(range(k + 1, 9)):
        fail(f"the chained run's steps are {step_times(second)}, not {k + 1}..8")
    compare(full, second, f"chained run (A to step {k}, B from A's checkpoint)")
    check_file_layout(first, k)
    print("7 passed, 0 failed")


if __name__ == "__main__":
    main()
