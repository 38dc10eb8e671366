#!/usr/bin/env python3
"""Runs a contact scene with the contactlab command and compares its contact results with a
reference nobody on this project wrote (doc/verification.md, cases V1-V7).

usage: check_contact.py CONTACTLAB SCENE OUTDIR RANKS CASE TOL [--set key=value ...]
CASE:
  hertz-2d   V1: pressure at the contact nodes against Hertz's profile for the computed line
             load P (a = sqrt(4PR/(pi E*)), p0 = 2P/(pi a)); TOL bounds max|p - p_H| / p0 over
             the nodes with |x| <= 0.9 a; the edge nodes, where p_H has an infinite slope, are
             reported (and bounded by 3 TOL). Needs at least 10 nodes in the contact width.
  hertz-3d   V2: the same with a = (3PR/(4E*))^(1/3), p0 = 3P/(2 pi a^2), r = sqrt(x^2 + y^2).
  hertz-axisymmetric  V2 on an axisymmetric section (x = r, P per full ring): the 3D formulas
             with r = |x|; the point on the axis, where p = p0, is bounded by TOL too.
  cattaneo-mindlin  V4 (2D): stick-zone half-width c against a sqrt(1 - Q/(mu P)) within TOL
             node spacings, and the shear traction against Cattaneo-Mindlin's q(x) within
             5 % of mu p0 (--traction-tol) over |x| <= 0.9 c (the kinks of q at c and a are reported, not
             bounded). Needs --mu (and --estar, --radius for two bodies).
  mindlin-3d  V4 in 3D (a sphere on a similar body): the area-equivalent stick radius against
             Mindlin's c = a (1 - Q/(mu P))^(1/3) within TOL node spacings, and the shear
             traction's ring means over r <= 0.9 c against Mindlin's q(r) within --traction-tol
             of mu p0. Needs --mu and --estar.
  patch      V3: uniform pressure PRESSURE on the interface (--pressure); TOL bounds the max
             relative deviation over the closed points.
  holds      V5 below the threshold: the run converges, the floor carries the applied
             tangential load (--tangential, TOL relative) and some point sticks (an elastic
             block redistributes its traction: most points may end at the threshold).
  no-equilibrium  V5 above the threshold under load control: no static equilibrium exists, so
             the run must stop with a named reason (exit code 1, failure not null) and keep
             its last converged step.
  named-failure  a run that has no solution to report (e.g. the NAFEMS roller under the fixed
             point with its geometry in Newton: its first solve, the statuses frozen open,
             throws the roller through its block): it must stop with a named reason whose
             message contains --message-contains, not report a state as converged.
Prints one line "RESULT case h error" for the documentation tables."""
import argparse, csv, json, math, os, shutil, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import contactlab_run  # noqa: E402
from contact_references import (cattaneo_mindlin, hertz, hertz_pressure_errors,  # noqa: E402
                                mindlin_3d, node_spacing)

ap = argparse.ArgumentParser()
ap.add_argument("exe"); ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("ranks", type=int); ap.add_argument("case"); ap.add_argument("tol", type=float)
ap.add_argument("--set", action="append", default=[])
ap.add_argument("--message-contains", default="", help="named-failure: text the message must hold")
ap.add_argument("--automatic-rn", action="store_true",
                help="expect summary.json to report the automatic r_n of every zone")
ap.add_argument("--E", type=float, default=1.0); ap.add_argument("--nu", type=float, default=0.3)
ap.add_argument("--radius", type=float, default=1.0)
ap.add_argument("--estar", type=float, default=0.0,
                help="E* of two elastic bodies (default: E / (1 - nu^2), a rigid master)")
ap.add_argument("--pressure", type=float, default=0.0)
ap.add_argument("--uniform", action="store_true",
                help="patch: bound the spread about the mean pressure (penalty's value differs "
                     "from the exact one by its compliance; mortar must still be uniform)")
ap.add_argument("--tangential", type=float, default=0.0)
ap.add_argument("--mu", type=float, default=0.0)
ap.add_argument("--traction-tol", type=float, default=0.05,
                help="cattaneo-mindlin: bound on the stick-zone shear traction error / mu p0")
ap.add_argument("--metric", choices=["max", "rms"], default="max",
                help="Hertz: bound the max or the root mean square of the interior error")
args = ap.parse_args()

shutil.rmtree(args.out, ignore_errors=True)
cmd, run = contactlab_run(args.exe, args.scene, args.out, args.set, args.ranks)
print(" ".join(cmd)); print(run.stdout, run.stderr)
summary = json.load(open(os.path.join(args.out, "summary.json")))
# The formulation a --set asks for is the one that ran (a key the scene ignored would verify
# the scene's own formulation under another's name).
for s in args.set:
    key, _, value = s.partition("=")
    parts = key.split("/")
    if len(parts) == 4 and parts[0] == "Contact" and parts[2:] == ["Formulation", "Type"]:
        ran = summary["formulation"][parts[1]]["type"]
        assert ran == value, f"Contact/{parts[1]} ran {ran}, not the {value} asked for"
# Normal Augmentation left at 0: summary.json reports the r_n that ran (E / h, > 0) per zone.
if args.automatic_rn:
    for zone, f in summary["formulation"].items():
        rn = f.get("automatic_normal_augmentation")
        assert rn is not None and rn > 0, f"Contact/{zone}: no automatic r_n in summary.json"
        print(f"automatic r_n of {zone}: {rn:g}")

if args.case == "named-failure":
    assert run.returncode == 1, f"exit code {run.returncode}: expected a named failure"
    assert summary["converged"] is False and summary["failure"], summary["failure"]
    assert args.message_contains in summary["message"], summary["message"]
    print("RESULT named-failure", summary["failure"])
    sys.exit(0)

if args.case == "no-equilibrium":
    assert run.returncode == 1, f"exit code {run.returncode}: expected a named failure"
    assert summary["converged"] is False and summary["failure"], summary["failure"]
    print("RESULT no-equilibrium failure", summary["failure"])
    sys.exit(0)

assert run.returncode == 0, f"exit code {run.returncode}"
assert summary["converged"] is True
rows = list(csv.DictReader(open(os.path.join(args.out, "contact.csv"))))
closed = [r for r in rows if int(r["status"]) != 0]
assert closed, "no contact point closed: contact switched off?"
contact = summary["contact"]


def partial_slip_loads():
    """P, the signed Q along x and Q/(mu P) of a partial-slip state: asserts 0.05 < Q/(mu P) <
    0.95 and that some closed points stick and some slip."""
    P, Q = contact["normal_force"], contact["tangential_force_vector"][0]
    ratio = abs(Q) / (args.mu * P)
    assert 0.05 < ratio < 0.95, f"Q/(mu P) = {ratio}: not a partial-slip state"
    assert any(int(r["status"]) == 1 for r in closed) and any(
        int(r["status"]) == 2 for r in closed), "partial slip expected: both stick and slip points"
    return P, Q, ratio


if args.case in ("hertz-2d", "hertz-3d", "hertz-axisymmetric"):
    P = contact["normal_force"]
    Estar = args.estar or args.E / (1 - args.nu ** 2)
    dim = 2 if args.case == "hertz-2d" else 3
    a, p0 = hertz(P, Estar, args.radius, dim)
    # An axisymmetric section's rows are 2D: r = |x|.
    e = hertz_pressure_errors(rows, a, p0, 2 if args.case == "hertz-axisymmetric" else dim)
    if args.case == "hertz-axisymmetric":
        axis = [r for r in rows if abs(float(r["reference_x"])) <= 1e-12]
        assert axis, "no contact point on the axis"
        axis_error = abs(float(axis[0]["pressure"]) - p0) / p0
        print(f"pressure on the axis {float(axis[0]['pressure']):.6g}, p0 {p0:.6g}: "
              f"error {axis_error:.4g} p0")
        assert axis_error <= args.tol, f"pressure error on the axis {axis_error} > {args.tol}"

    assert e["inside"] >= 10, f"only {e['inside']} nodes in the contact width 2a = {2 * a}"
    err, rms, edge = e["max"], e["rms"], e["edge"]
    # Mesh size: the area per contact node inside the contact zone (2D: the width per node).
    h = (2 * a / e["inside"] if dim == 2 else
         a / e["inside"] if args.case == "hertz-axisymmetric" else
         math.sqrt(math.pi * a * a / e["inside"]))
    print(f"P = {P:.6g}, a = {a:.6g}, p0 = {p0:.6g}, nodes in the contact zone: {e['inside']}, "
          f"|p - p_H| / p0: max {err:.4g}, rms {rms:.4g} (|x| <= 0.9a), max {edge:.4g} (edge), "
          f"max penetration {contact['max_penetration']:.3g}")
    print(f"RESULT {args.case} h={h:.4g} a/h={a / h:.1f} max={err:.4g} rms={rms:.4g} "
          f"edge={edge:.4g} penetration={contact['max_penetration']:.3g} "
          f"newton={summary['iterations']['newton']}")
    measured = err if args.metric == "max" else rms
    assert measured <= args.tol, f"pressure error ({args.metric}) {measured} > {args.tol}"
    assert edge <= 3 * max(args.tol, err), f"edge pressure error {edge} > {3 * max(args.tol, err)}"
elif args.case == "cattaneo-mindlin":
    P, Q, ratio = partial_slip_loads()
    Q = abs(Q)
    Estar = args.estar or args.E / (1 - args.nu ** 2)
    h = node_spacing(closed)
    cm = cattaneo_mindlin(closed, P, Q, args.mu, Estar, args.radius)
    a, c, c_fe, inner, err = cm["a"], cm["c"], cm["c_fe"], cm["stick_error"], cm["error"]
    print(f"P = {P:.6g}, Q = {Q:.6g}, Q/(mu P) = {ratio:.4f}, a = {a:.5g}, c/a: Cattaneo-Mindlin "
          f"{c / a:.4f}, computed {c_fe / a:.4f} (centre {cm['centre']:.3g}), "
          f"h = {h:.3g}, traction error {inner:.4g} mu p0 (|x| <= 0.9c), {err:.4g} (|x| <= 0.9a)")
    print(f"RESULT cattaneo-mindlin Q/muP={ratio:.3f} c/a={c / a:.4f} fe={c_fe / a:.4f} "
          f"dc/h={abs(c_fe - c) / h:.2f} traction={inner:.4g} (stick zone) {err:.4g} (0.9a)")
    assert inner <= args.traction_tol, \
        f"traction error in the stick zone {inner} > {args.traction_tol} mu p0"
    assert abs(c_fe - c) <= args.tol * h, f"stick zone {c_fe} vs {c}: more than {args.tol} node spacings ({h})"
elif args.case == "mindlin-3d":
    P, Q, ratio = partial_slip_loads()
    Estar = args.estar or args.E / (1 - args.nu ** 2)
    m = mindlin_3d(closed, P, Q, args.mu, Estar, args.radius)
    a, c, c_fe, h = m["a"], m["c"], m["c_fe"], m["h"]
    e = hertz_pressure_errors(rows, a, m["p0"], 3)
    print(f"P = {P:.6g}, Q = {abs(Q):.6g}, Q/(mu P) = {ratio:.4f}, a = {a:.5g}, "
          f"closed points {len(closed)}, h = {h:.3g}; c/a: Mindlin {c / a:.4f}, computed "
          f"{c_fe / a:.4f} (area-equivalent), |c_fe - c| = {abs(c_fe - c) / h:.2f} h; shear "
          f"traction's ring means (r <= 0.9c, {m['rings']} rings) within {m['profile']:.4g} "
          f"mu p0; pressure rms {e['rms']:.4g} p0")
    print(f"RESULT mindlin-3d Q/muP={ratio:.3f} c/a={c / a:.4f} fe={c_fe / a:.4f} "
          f"dc/h={abs(c_fe - c) / h:.2f} profile={m['profile']:.4g} "
          f"newton={summary['iterations']['newton']}")
    assert m["profile"] <= args.traction_tol, \
        f"shear traction's ring means {m['profile']} > {args.traction_tol} mu p0 off Mindlin's"
    assert abs(c_fe - c) <= args.tol * h, f"stick radius {c_fe} vs {c}: more than {args.tol} h ({h})"
elif args.case == "patch":
    target = args.pressure
    if args.uniform:
        target = sum(float(r["pressure"]) for r in closed) / len(closed)
        print(f"mean pressure {target:.10g} (exact {args.pressure:.10g})")
    err = max(abs(float(r["pressure"]) - target) / target for r in closed)
    print(f"max relative pressure deviation {err:.4g} over {len(closed)} closed points")
    print(f"RESULT patch - {err:.6g}")
    assert err <= args.tol, f"patch test deviation {err} > {args.tol}"
elif args.case == "holds":
    sticking = [r for r in closed if int(r["status"]) == 1]
    assert sticking, "no point sticks: the block slides"
    T = abs(contact["tangential_force_vector"][0])
    N = contact["normal_force"]
    print(f"N = {N:.6g}, T = {T:.6g}, T/N = {T / N:.6g}, {len(sticking)} of {len(closed)} stick")
    print(f"RESULT holds {abs(T - args.tangential) / args.tangential:.6g}")
    assert abs(T - args.tangential) <= args.tol * args.tangential, (T, args.tangential)
else:
    sys.exit(f"unknown case {args.case}")
