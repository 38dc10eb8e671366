#!/usr/bin/env python3
"""Runs an ironing scene (scenes/ironing-3d.yaml: a stiff die pressed into a soft slab, then
dragged along it with Coulomb friction) and checks what holds whatever the mesh and material:

- the run converges;
- the die's equilibrium: the reactions of the die's prescribed back (every Dirichlet group
  whose name is not SLAB) equal the contact force on the slave surface (the last row of
  steps.csv, sum w (p n + t)), and the slab's support reaction is its opposite, within TOL of
  |contact force|: the reported force history is the force the die feels;
- Coulomb at every contact point of contact.csv: |t| = mu p where it slips, |t| <= mu p where it
  sticks, zero traction where open (to 1e-6 of the largest pressure);
- no penetration deeper than 1e-3 of the die's press depth (the augmented Lagrangian's
  multipliers converge; a penalty run would need a looser bound).

usage: check_ironing.py CONTACTLAB SCENE OUTDIR TOL [--ranks N] [--set key=value ...]
Prints "RESULT ..." lines for doc/verification.md."""
import csv, json, math, os, sys

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checklist import Checklist  # noqa: E402
from contactlab_run import converged_run, scene_check_arguments  # noqa: E402

ap = scene_check_arguments()
ap.add_argument("--slab", default="slab", help="the Dirichlet group that holds the slab")
args = ap.parse_args()

summary = converged_run(args.app, args.scene, args.out, args.set, args.ranks)

scene = yaml.safe_load(open(args.scene))["contactlab"]
zones = list(scene["Contact"].values())
if len(zones) != 1:
    sys.exit("FAIL: the check expects one contact zone")
mu = float(zones[0].get("Friction", 0.0))
press = max(abs(float(d.get("Value", 0.0))) for d in scene["Dirichlet"].values())

checklist = Checklist()
check = checklist.check
last = list(csv.DictReader(open(os.path.join(args.out, "steps.csv"))))[-1]
force = [float(last[f"contact_force_{c}"]) for c in "xyz"][: summary["dimension"]]
size = math.sqrt(sum(f * f for f in force))
reactions = summary["reactions"]
die = [sum(r[i] for name, r in reactions.items() if name != args.slab)
       for i in range(len(force))]
slab = reactions[args.slab]
die_error = math.dist(die, force) / size
slab_error = math.sqrt(sum((s + f) ** 2 for s, f in zip(slab, force))) / size
check(f"die reactions {die} = contact force {force}: {die_error:.1e} <= {args.tol}",
      die_error <= args.tol)
check(f"slab reaction {slab} = -contact force: {slab_error:.1e} <= {args.tol}",
      slab_error <= args.tol)

points = list(csv.DictReader(open(os.path.join(args.out, "contact.csv"))))
pmax = max(float(p["pressure"]) for p in points)
worst = 0.0
for p in points:
    t = math.sqrt(sum(float(p[f"traction_{c}"]) ** 2 for c in "xyz"))
    bound = mu * float(p["pressure"])
    excess = {"2": abs(t - bound), "1": max(t - bound, 0.0), "0": t}.get(p["status"], 0.0)
    worst = max(worst, excess / pmax)
check(f"Coulomb at every point: off by {worst:.1e} of the largest pressure <= 1e-6",
      worst <= 1e-6)
penetration = summary["contact"]["max_penetration"]
check(f"penetration {penetration:.2e} <= 1e-3 x {press}", penetration <= 1e-3 * press)

c = summary["contact"]
print(f"RESULT dofs={summary['dofs']} newton={summary['iterations']['newton']} "
      f"geometry={summary['iterations']['geometry']} steps={summary['load_steps']['converged']} "
      f"seconds={summary['seconds']['total']:.1f}")
print(f"RESULT contact_force={[round(f, 3) for f in force]} normal_force={c['normal_force']:.3f} "
      f"stick={c['stick_points']} slip={c['slip_points']} penetration={penetration:.2e}")
print(f"RESULT die_balance={die_error:.1e} slab_balance={slab_error:.1e} coulomb={worst:.1e}")
sys.exit(1 if checklist.failures else 0)
