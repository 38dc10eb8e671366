#!/usr/bin/env python3
"""Runs scenes/thick-cylinder-2d.yaml (a quarter of a thick tube a <= r <= b under internal
pressure p, plane strain, von Mises plasticity) and compares it with the elastic-plastic
solution of R. Hill, The Mathematical Theory of Plasticity (1950), ch. V, k = sigma_y / sqrt(3):

  plastic front c:   p = k (1 - c^2/b^2) + 2k/(1 + h) [ln(c/a) + (h/2)(c^2/a^2 - 1)]
  a <= r <= c:       sigma_r = -p + 2k/(1 + h) [ln(r/a) + (h c^2/2)(1/a^2 - 1/r^2)]
                     sigma_theta = sigma_r + 2k (1 + h c^2/r^2) / (1 + h)
  c <= r <= b:       sigma_r = -k (c^2/b^2)(b^2/r^2 - 1), sigma_theta = k (c^2/b^2)(b^2/r^2 + 1)
  limit pressure     p_L = 2k ln(b/a)  (perfect plasticity)

with h = H / (3G) for linear isotropic hardening H (h = 0: Hill's perfectly plastic tube; with
hardening the plastic zone's strain is u = C/r, incompressible, and q = sigma_y + H p follows
from the equivalent strain (2/sqrt 3) C/r^2). Both assume sigma_z = (sigma_r + sigma_theta)/2 in
the plastic zone, exact for an incompressible material; the scene's nu = 0.49 leaves an
O((1 - 2 nu)^2) error. The elastic zone is Lame's solution (any nu): sigma_z = nu (sigma_r +
sigma_theta), u = r (1 + nu)/E [(1 - 2 nu) A + B/r^2] with A = k c^2/b^2, B = k c^2; inside, the
elastic volume change 3 (1 - 2 nu) m / E (m = (sigma_r + sigma_theta)/2) integrates to
a u(a) = c u(c) - 3 (1 - 2 nu)/E int_a^c s m(s) ds.

usage: check_thick_cylinder.py CONTACTLAB SCENE OUTDIR CASE [options] [--set key=value ...]
CASE:
  hill    every cell's average stress (sigma_r, sigma_theta, sigma_z, rotated at the cell's
          middle angle) against the analytic average over the same annular cell; TOL bounds
          max |error| / p of sigma_r and sigma_theta (sigma_z is reported, bounded by 2 TOL);
          the plastic front (the outermost cell with plastic strain) within one element of c;
          the inner and outer radial displacements within --u-tol relative.
  limit   the pressure (--pressure, or the scene's) is above p_L (perfect plasticity): the run
          must stop with a named failure, its last converged pressure at most (1 + TOL) p_L
          and at least --reach p_L (with step cuts it closes in on the FE collapse load).
Options: --pressure P, --hardening H and --nu NU set the scene's load, isotropic hardening
modulus and Poisson ratio (and the reference's); --plot PNG draws the stresses against r; --ranks N.
Prints "RESULT ..." lines for doc/verification.md."""
import argparse, csv, json, math, os, shutil, sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import contactlab_run, read_grid, result_frames  # noqa: E402
from annular_cells import (cell_average, polar_cells, pressurized_ring_sector,  # noqa: E402
                           radial_displacements, to_polar as toPolar)

ap = argparse.ArgumentParser()
ap.add_argument("exe"); ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("case", choices=["hill", "limit"])
ap.add_argument("--tol", type=float, default=0.01)
ap.add_argument("--u-tol", type=float, default=0.005)
ap.add_argument("--u-min-excess", type=float,
                help="u(b) must exceed Hill's by at least this (relative): the follower "
                     "pressure's load grows with the bore, which a dead load or a small-strain "
                     "run would not show")
ap.add_argument("--pressure", type=float)
ap.add_argument("--hardening", type=float)
ap.add_argument("--nu", type=float)
ap.add_argument("--material", choices=["j2-small-strain", "simo-miehe"], default="j2-small-strain",
                help="simo-miehe: the same tube in finite strain (F = Fe Fp, Hencky, follower "
                     "pressure on the deformed bore); its strains are ~1e-3, so Hill's small-strain "
                     "solution holds to that order")
ap.add_argument("--ranks", type=int, default=1)
ap.add_argument("--reach", type=float, default=0.0,
                help="limit: the last converged pressure must reach this fraction of p_L")
ap.add_argument("--plot")
ap.add_argument("--profile-tol", type=float, default=0.01,
                help="hill: the scene's radial profile against Hill averaged as it, / p")
ap.add_argument("--set", action="append", default=[])
args = ap.parse_args()

mesh, material, a, b, E, nu, sy, p = pressurized_ring_sector(args.scene)
H = float(material.get("Isotropic Hardening Modulus", 0.0))
sets = list(args.set)
if args.pressure is not None:
    p = args.pressure
    sets.append(f"Loads/bore/Value={p!r}")
if args.hardening is not None:
    H = args.hardening
    sets.append(f"Materials/body/j2-small-strain/Isotropic Hardening Modulus={H!r}")
if args.nu is not None:
    nu = args.nu
    sets.append(f"Materials/body/j2-small-strain/nu={nu!r}")
if args.material == "simo-miehe":
    # The j2-small-strain keys above are rewritten into the simo-miehe sublist (same names).
    sets = [x.replace("Materials/body/j2-small-strain/", "Materials/body/simo-miehe/") for x in sets]
    sets += ["Materials/body/Type=simo-miehe", f"Materials/body/simo-miehe/E={E!r}",
             f"Materials/body/simo-miehe/nu={nu!r}", f"Materials/body/simo-miehe/Yield Stress={sy!r}"]
    if H and args.hardening is None:
        sets.append(f"Materials/body/simo-miehe/Isotropic Hardening Modulus={H!r}")
assert float(material.get("Kinematic Hardening Modulus", 0.0)) == 0.0, "isotropic hardening only"


class Hill:
    """The analytic tube: stresses and radial displacement at radius r."""

    def __init__(self, a, b, E, nu, sy, H, p):
        self.a, self.b, self.E, self.nu, self.p = a, b, E, nu, p
        self.k = sy / math.sqrt(3)
        self.h = H / (3 * E / (2 * (1 + nu)))
        self.limit = 2 * self.k * math.log(b / a) if H == 0 else math.inf
        if p <= self.pressure(a):
            raise ValueError(f"p = {p} does not yield the tube (first yield at {self.pressure(a)})")
        lo, hi = a, b
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if self.pressure(mid) < p else (lo, mid)
        self.c = 0.5 * (lo + hi)
        c, k = self.c, self.k
        self.A, self.B = k * c * c / (b * b), k * c * c
        # a u(a) = c u(c) - 3 (1 - 2 nu)/E int_a^c s m(s) ds (Gauss-Legendre, m smooth there)
        x, w = np.polynomial.legendre.leggauss(40)
        s = a + (c - a) * (x + 1) / 2
        m = np.array([sum(self.stress(r)[:2]) / 2 for r in s])
        integral = (c - a) / 2 * float(np.sum(w * s * m))
        self.c_u_c = c * self.elasticDisplacement(c)
        self.a_u_a = self.c_u_c - 3 * (1 - 2 * nu) / E * integral

    def pressure(self, c):
        k, h, a, b = self.k, self.h, self.a, self.b
        return k * (1 - c * c / (b * b)) + 2 * k / (1 + h) * (
            math.log(c / a) + h / 2 * (c * c / (a * a) - 1))

    def elasticDisplacement(self, r):
        return r * (1 + self.nu) / self.E * ((1 - 2 * self.nu) * self.A + self.B / (r * r))

    def stress(self, r):
        """sigma_r, sigma_theta, sigma_z at r."""
        k, h, a, b, c = self.k, self.h, self.a, self.b, self.c
        if r <= c:
            sr = -self.p + 2 * k / (1 + h) * (math.log(r / a) + h * c * c / 2 * (1 / a**2 - 1 / r**2))
            st = sr + 2 * k * (1 + h * c * c / (r * r)) / (1 + h)
            return sr, st, (sr + st) / 2
        sr, st = self.A - self.B / (r * r), self.A + self.B / (r * r)
        return sr, st, self.nu * (sr + st)

    def displacement(self, r):
        if r >= self.c:
            return self.elasticDisplacement(r)
        assert r == self.a, "inside the plastic zone only u(a) is computed"
        return self.a_u_a / self.a

    def cellAverage(self, r1, r2, t1, t2):
        """Average of the Cartesian stress (xx, yy, zz, xy) over the annular cell, rotated back
        to polar components at the middle angle: what the cell's Voigt average becomes."""
        return cell_average(self.stress, r1, r2, t1, t2, kinks=[self.c])


ref = Hill(a, b, E, nu, sy, H, p)
print(f"reference: p = {p:g}, k = {ref.k:.6g}, h = H/3G = {ref.h:.6g}, c = {ref.c:.6g}, "
      f"p_L = {ref.limit:.6g} (p/p_L = {p / ref.limit:.4f}), u(a) = {ref.displacement(a):.6g}, "
      f"u(b) = {ref.displacement(b):.6g}")

shutil.rmtree(args.out, ignore_errors=True)
cmd, run = contactlab_run(args.exe, args.scene, args.out, sets, args.ranks, timeout=600)
print(" ".join(cmd)); print(run.stdout, run.stderr)
summary = json.load(open(os.path.join(args.out, "summary.json")))

if args.case == "limit":
    assert p > ref.limit, f"p = {p} is not above the limit pressure {ref.limit}"
    assert run.returncode == 1, f"exit code {run.returncode}: expected a named failure"
    assert summary["converged"] is False and summary["failure"], summary["failure"]
    rows = list(csv.DictReader(open(os.path.join(args.out, "steps.csv"))))
    reached = float(rows[-1]["time"]) * p if rows else 0.0  # the last converged pressure
    print(f"RESULT limit failure {summary['failure']} at p = {p:g} = {p / ref.limit:.4f} p_L; "
          f"last converged {reached:.6g} = {reached / ref.limit:.5f} p_L, "
          f"{summary['load_steps']['cuts']} cuts")
    # Displacement elements give an upper bound: the discrete tube may carry a hair above p_L.
    assert reached <= (1 + args.tol) * ref.limit, f"converged at {reached}, above p_L = {ref.limit}"
    assert reached >= args.reach * ref.limit, f"stopped at {reached} < {args.reach} p_L"
    print("ok")
    sys.exit(0)

assert run.returncode == 0, f"exit code {run.returncode}"
assert summary["converged"] is True and summary["failure"] is None

# The last result: cells with their radial and angular extent, stress and plastic strain.
grid = read_grid(result_frames(args.out)[-1][1])
stress = grid.GetCellData().GetArray("stress")
cells = [dict(r1=r1, r2=r2, t1=t1, t2=t2, fe=fe, plastic=plastic)
         for r1, r2, t1, t2, fe, plastic in polar_cells(grid)]
assert all(c["plastic"] is not None for c in cells)
worst = np.zeros(3)
for cell in cells:
    cell["exact"] = ref.cellAverage(cell["r1"], cell["r2"], cell["t1"], cell["t2"])
    cell["error"] = (cell["fe"] - cell["exact"]) / p
    worst = np.maximum(worst, np.abs(cell["error"]))
rings = sorted({round(c["r1"], 9) for c in cells})
print(" r1       r2       sigma_r (FE, exact)      sigma_theta (FE, exact)  sigma_z (FE, exact)"
      "      plastic")
for r1 in rings:
    ring = [c for c in cells if round(c["r1"], 9) == r1]
    c = max(ring, key=lambda c: np.max(np.abs(c["error"])))
    print(f" {c['r1']:.5f}  {c['r2']:.5f}  " + "  ".join(
        f"{c['fe'][i]:10.4f} {c['exact'][i]:10.4f}" for i in range(3)) +
        f"  {c['plastic']:.3g}")

# The plastic front: the outermost ring of cells holding plastic strain.
outermost = max((c for c in cells if c["plastic"] > 0), key=lambda c: c["r2"])
width = outermost["r2"] - outermost["r1"]
fraction = summary["plasticity"]["plastic_volume_fraction"]
c_fraction = math.sqrt(a * a + fraction * (b * b - a * a))

# Radial displacements at the inner and outer radius (every node there).
radial = radial_displacements(grid, (a, b))
u_error = {side: (np.mean(v) - ref.displacement(side)) / ref.displacement(side)
           for side, v in radial.items()}
spread = max(np.ptp(v) for v in radial.values()) / ref.displacement(a)

print(f"RESULT stresses max |error| / p: sigma_r {worst[0]:.2e}, sigma_theta {worst[1]:.2e}, "
      f"sigma_z {worst[2]:.2e} over {len(cells)} cells")
print(f"RESULT plastic front c = {ref.c:.5f}: outermost plastic cell [{outermost['r1']:.5f}, "
      f"{outermost['r2']:.5f}]; from the plastic area fraction {fraction:.5f}: c = "
      f"{c_fraction:.5f} ({(c_fraction - ref.c) / width:+.2f} element)")
print(f"RESULT u(a) = {np.mean(radial[a]):.7g} (exact {ref.displacement(a):.7g}, "
      f"{u_error[a]:+.2e}), u(b) = {np.mean(radial[b]):.7g} (exact {ref.displacement(b):.7g}, "
      f"{u_error[b]:+.2e}); axisymmetry: spread {spread:.1e} of u(a)")

# Output/Profiles/radial (the scene's): sigma along a radius in cylindrical components. Each
# row must be the average of the cells around its node (VTK's cell stresses), rotated at the
# node (to round-off: the profile's lookup, averaging and rotation), and within PROFILE_TOL p
# of Hill's field averaged the same way (each cell's exact average, in Cartesian components,
# averaged over the cells around the node, rotated at the node). Against Hill's stresses at the
# node's radius itself the rows are off by up to 0.12 p: a nodal average of cell averages mixes
# sigma_r and sigma_theta by the mean sin^2 over the cells' angles (5 % of sigma_theta -
# sigma_r with 22.5-degree cells: 14.4 in the plastic zone) and is first order at the faces.
profile_path = os.path.join(args.out, "profile_radial.csv")
if os.path.exists(profile_path):
    points = {}
    for i in range(grid.GetNumberOfPoints()):
        points[tuple(round(v, 9) for v in grid.GetPoint(i)[:2])] = i
    around = {}
    for i in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(i).GetPointIds()
        for j in range(ids.GetNumberOfIds()):
            around.setdefault(ids.GetId(j), []).append(i)
    lookup, hill = 0.0, np.zeros(2)
    for row in csv.DictReader(open(profile_path)):
        x, y = float(row["node_x"]), float(row["node_y"])
        node = points[(round(x, 9), round(y, 9))]
        mean = np.mean([stress.GetTuple(c) for c in around[node]], axis=0)
        polar = toPolar([mean[0], mean[1], mean[2], mean[3]], math.atan2(y, x))
        got = np.array([float(row["stress_rr"]), float(row["stress_tt"]), float(row["stress_zz"])])
        lookup = max(lookup, float(np.max(np.abs(got - polar))) / p)
        cartesian = []
        for c in around[node]:
            sr, st, sz = cells[c]["exact"]
            tm = 0.5 * (cells[c]["t1"] + cells[c]["t2"])
            cs, sn = math.cos(tm), math.sin(tm)
            cartesian.append([sr * cs * cs + st * sn * sn, sr * sn * sn + st * cs * cs, sz,
                              (sr - st) * sn * cs])
        exact = toPolar(np.mean(cartesian, axis=0), math.atan2(y, x))
        hill = np.maximum(hill, np.abs(got[:2] - exact[:2]) / p)
    print(f"RESULT profile 'radial': against the cells around each node {lookup:.1e} p; against "
          f"Hill averaged as the profile: sigma_r {hill[0]:.2e} p, sigma_theta {hill[1]:.2e} p")
    if lookup > 1e-9:
        sys.exit(f"FAIL: profile_radial.csv differs from the cells around its nodes ({lookup:.3g} p)")
    if max(hill) > args.profile_tol:
        sys.exit(f"FAIL: profile_radial.csv is {max(hill):.3g} p from Hill (> {args.profile_tol} p)")

if args.plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    r = np.linspace(a, b, 400)
    exact = np.array([ref.stress(x) for x in r])
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    labels = ["$\\sigma_r$", "$\\sigma_\\theta$", "$\\sigma_z$"]
    for i, color in enumerate(["C0", "C3", "C2"]):
        ax.plot(r, exact[:, i], color=color, label=labels[i] + " Hill")
        # Each cell's average at its centroid's radius 2/3 (r2^3 - r1^3) / (r2^2 - r1^2), with
        # Hill's field averaged over the same cell (a wedge's average of the rotating tensor
        # mixes in sin^2 of the half angle, 1.3 % of sigma_theta - sigma_r at 22.5 degrees).
        centroid = [2 / 3 * (c["r2"]**3 - c["r1"]**3) / (c["r2"]**2 - c["r1"]**2) for c in cells]
        ax.plot(centroid, [c["fe"][i] for c in cells], "o", color=color, mfc="none", ms=6,
                label=labels[i] + " contactlab, cell averages")
        ax.plot(centroid, [c["exact"][i] for c in cells], "+", color="k", ms=5,
                label="Hill, averaged over each cell" if i == 2 else None)
    ax.axvline(ref.c, color="grey", ls="--", lw=0.8)
    ax.text(ref.c, ax.get_ylim()[1], f" plastic front c = {ref.c:.4f}", color="grey", va="top")
    ax.set_xlabel("r")
    ax.set_ylabel("stress")
    hard = f", H = {H:g}" if H else " (perfectly plastic)"
    ax.set_title(f"Thick tube a = {a:g}, b = {b:g}, p = {p:g} = {p / ref.limit:.3f} $p_L${hard}"
                 if H == 0 else f"Thick tube a = {a:g}, b = {b:g}, p = {p:g}{hard}", fontsize=10)
    ax.legend(fontsize=8, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.13))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.plot, dpi=110)
    print("plot:", args.plot)

problems = []
if worst[0] > args.tol or worst[1] > args.tol:
    problems.append(f"sigma_r / sigma_theta error {max(worst[:2]):.3g} p > {args.tol} p")
if worst[2] > 2 * args.tol:
    problems.append(f"sigma_z error {worst[2]:.3g} p > {2 * args.tol} p")
if not outermost["r1"] - width <= ref.c <= outermost["r2"] + width:
    problems.append(f"plastic front [{outermost['r1']}, {outermost['r2']}] not within one element "
                    f"of c = {ref.c}")
for side, e in u_error.items():
    if abs(e) > args.u_tol:
        problems.append(f"u({side:g}) off by {e:.3g} (relative), more than {args.u_tol}")
if args.u_min_excess is not None and not u_error[b] >= args.u_min_excess:
    problems.append(f"u({b:g}) exceeds Hill's by {u_error[b]:.3g}, less than {args.u_min_excess}: "
                    "the load did not follow the widening bore")
assert not problems, "; ".join(problems)
print("ok")
