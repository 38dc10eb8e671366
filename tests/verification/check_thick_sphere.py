#!/usr/bin/env python3
"""Runs scenes/thick-sphere-axisymmetric.yaml (a hollow sphere a <= r <= b under internal
pressure p, an axisymmetric model of its quarter meridian section, von Mises perfect
plasticity) or scenes/thick-sphere-3d.yaml (an eighth of it in 3D, gmsh's tet10) on several meshes and compares it with the elastic-plastic solution of R. Hill,
The Mathematical Theory of Plasticity (1950), ch. V, section 2 (the spherical shell). Spherical
symmetry makes sigma_theta = sigma_phi, so Tresca's and von Mises' conditions are both
sigma_theta - sigma_r = sigma_y, and the stresses are statically determined for any nu:

  plastic front c:   p = 2 sigma_y ln(c/a) + (2 sigma_y / 3)(1 - c^3/b^3)
  a <= r <= c:       sigma_r = -p + 2 sigma_y ln(r/a), sigma_theta = sigma_r + sigma_y
  c <= r <= b:       sigma_r = -q (b^3/r^3 - 1) c^3/(b^3 - c^3), sigma_theta = q (b^3/(2 r^3) + 1)
                     c^3/(b^3 - c^3), q = (2 sigma_y / 3)(1 - c^3/b^3) (Lame's sphere)
  first yield        p_e = (2 sigma_y / 3)(1 - a^3/b^3);  limit pressure p_L = 2 sigma_y ln(b/a)

The outer displacement is Lame's, u(b) = sigma_y c^3 (1 - nu) / (E b^2); inside, the plastic
zone's volume change is elastic, (1/r^2) d(r^2 u)/dr = (1 - 2 nu) tr(sigma) / E, so
a^2 u(a) = c^2 u(c) - (1 - 2 nu)/E int_a^c s^2 tr(sigma)(s) ds.

In the (x, y) = (r sin, r cos)-plane of the model the sphere's radial direction at the angle t
from the x axis (the equator) is (cos t, sin t); sigma_r and the meridional sigma_theta are the
in-plane principal stresses, the hoop stress (the output's zz slot) is sigma_phi = sigma_theta.

usage: check_thick_sphere.py CONTACTLAB SCENE OUTDIR CASE [options] [--set key=value ...]
CASE:
  hill         on each mesh (--factors scale the scene's divisions, or divide its Size Factor in
               3D): every cell's average stress against Hill's averaged over the same cell
               (the ring's volume weight 2 pi x), max |error| / p of sigma_r, sigma_theta,
               sigma_phi (3D: against Hill's at the cell's centroid, sigma_r, the tangential
               mean and the largest Cartesian component of the difference); the mean radial
               displacement of every node on the bore and on the outside, relative. The finest
               mesh within --tol and --u-tol, and each error below its value on the coarsest.
  small-strain-limit
               the finite-strain material (simo-miehe, the follower pressure on the current bore)
               at the scene's E and at 10 E: its displacements differ from Hill's small-strain
               solution at first order in the strain, so the difference must fall by 5 to 20
               times, and below --u-tol at 10 E.
  limit        p = 1.05 p_L over 20 steps: the run must end with a named failure, its last
               converged pressure within [0.97, 1 + TOL] p_L.
Prints "RESULT ..." lines for doc/verification.md."""
import argparse, csv, json, math, os, re, shutil, sys

import numpy as np
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import contactlab_run, read_grid, result_frames  # noqa: E402
from annular_cells import (cell_average, polar_cells, pressurized_ring_sector,  # noqa: E402
                           radial_displacements)

ap = argparse.ArgumentParser()
ap.add_argument("exe"); ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("case", choices=["hill", "small-strain-limit", "limit"])
ap.add_argument("--factors", default="0.5,1,2", help="hill: the meshes, as multiples of the "
                "scene's divisions")
ap.add_argument("--tol", type=float, default=0.01)
ap.add_argument("--u-tol", type=float, default=0.005)
ap.add_argument("--ranks", type=int, default=1)
ap.add_argument("--set", action="append", default=[])
args = ap.parse_args()

scene = yaml.safe_load(open(args.scene))["contactlab"]
block = next(iter(scene["Materials"]))
three_d = scene["Mesh"]["Type"] == "file"
if three_d:
    # An eighth of the shell meshed by gmsh: a and b from the .geo, the mesh scaled by Size Factor.
    geo = open(os.path.join(os.path.dirname(args.scene), scene["Mesh"]["file"]["Path"])).read()
    a, b = (float(re.search(rf"^{name} = ([0-9.eE+-]+);", geo, re.M).group(1)) for name in "ab")
    material = scene["Materials"][block]["j2-small-strain"]
    E, nu, sy = float(material["E"]), float(material["nu"]), float(material["Yield Stress"])
    p = float(scene["Loads"]["bore"]["Value"])
else:
    mesh, material, a, b, E, nu, sy, p = pressurized_ring_sector(args.scene)
assert float(material.get("Isotropic Hardening Modulus", 0.0)) == 0.0, "perfect plasticity only"


class HillSphere:
    """The analytic spherical shell: stresses at radius r, u(a) and u(b)."""

    def __init__(self, E, p):
        self.E, self.p = E, p
        self.limit = 2 * sy * math.log(b / a)
        self.first_yield = 2 * sy / 3 * (1 - a**3 / b**3)
        assert self.first_yield < p < self.limit, "the shell must be partly plastic"
        lo, hi = a, b
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if self.pressure(mid) < p else (lo, mid)
        self.c = c = 0.5 * (lo + hi)
        self.q = 2 * sy / 3 * (1 - c**3 / b**3)
        x, w = np.polynomial.legendre.leggauss(40)
        s = a + (c - a) * (x + 1) / 2
        trace = np.array([self.stress(r)[0] + 2 * self.stress(r)[1] for r in s])
        integral = (c - a) / 2 * float(np.sum(w * s * s * trace))
        self.u_a = (c * c * self.elastic_u(c) - (1 - 2 * nu) / E * integral) / (a * a)
        self.u_b = self.elastic_u(b)

    def pressure(self, c):
        return 2 * sy * math.log(c / a) + 2 * sy / 3 * (1 - c**3 / b**3)

    def elastic_u(self, r):
        c, q = self.c, self.q
        return q * c**3 / (self.E * (b**3 - c**3)) * ((1 - 2 * nu) * r + (1 + nu) * b**3 / (2 * r * r))

    def stress(self, r):
        """sigma_r, sigma_theta (= sigma_phi) at r."""
        if r <= self.c:
            sr = -self.p + 2 * sy * math.log(r / a)
            return sr, sr + sy
        k = self.q * self.c**3 / (b**3 - self.c**3)
        return -k * (b**3 / r**3 - 1), k * (b**3 / (2 * r**3) + 1)

    def cell_average(self, r1, r2, t1, t2):
        """(sigma_r, sigma_theta, sigma_phi) averaged over the cell as its output is: the
        Cartesian components, weighted by the ring's volume, rotated at the middle angle."""
        return cell_average(lambda r: (*self.stress(r), self.stress(r)[1]), r1, r2, t1, t2,
                            kinks=[self.c], ring=True)


def run(out, sets):
    shutil.rmtree(out, ignore_errors=True)
    cmd, done = contactlab_run(args.exe, args.scene, out, list(args.set) + sets, args.ranks,
                               options=["--quiet"], timeout=600)
    summary_path = os.path.join(out, "summary.json")
    if not os.path.exists(summary_path):
        sys.exit(f"FAIL: {' '.join(cmd)} wrote no summary.json\n{done.stderr}")
    return done, json.load(open(summary_path))


def bore_and_outside(grid):
    """The mean radial displacement of the nodes on r = a and on r = b (gmsh's nodes on the
    curved faces lie on the sphere to its geometry's tolerance)."""
    radial = radial_displacements(grid, (a, b), 1e-6 if three_d else 1e-9)
    return np.mean(radial[a]), np.mean(radial[b])


def stress_errors(grid, ref):
    """max |cell average - Hill's over the cell| / p of sigma_r, sigma_theta, sigma_phi; in 3D,
    against Hill's stress at the cell's centroid: sigma_r, the tangential mean and the largest
    Cartesian component of the difference."""
    worst = np.zeros(3)
    if three_d:
        stress = grid.GetCellData().GetArray("stress")
        for i in range(grid.GetNumberOfCells()):
            ids = grid.GetCell(i).GetPointIds()
            x = np.mean([grid.GetPoint(ids.GetId(j)) for j in range(ids.GetNumberOfIds())], axis=0)
            r = float(np.linalg.norm(x))
            n = x / r
            s = stress.GetTuple(i)  # Voigt xx yy zz xy yz xz
            fe = np.array([[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]])
            sr, st = ref.stress(r)
            exact = st * np.eye(3) + (sr - st) * np.outer(n, n)
            radial = n @ fe @ n
            worst = np.maximum(worst, np.abs([radial - sr, (np.trace(fe) - radial) / 2 - st,
                                              np.max(np.abs(fe - exact))]) / p)
        return worst
    for r1, r2, t1, t2, fe, _ in polar_cells(grid):
        worst = np.maximum(worst, np.abs(fe - ref.cell_average(r1, r2, t1, t2)) / p)
    return worst


def scaled(factor):
    if three_d:
        return [f"Mesh/file/Size Factor={1 / factor!r}"]
    return [f"Mesh/ring-sector/Radial Divisions={round(factor * mesh['Radial Divisions'])}",
            f"Mesh/ring-sector/Circumferential Divisions="
            f"{round(factor * mesh['Circumferential Divisions'])}"]


if args.case == "limit":
    ref = HillSphere(E, p)
    pressure = 1.05 * ref.limit
    done, summary = run(args.out, [f"Loads/bore/Value={pressure!r}", "Load Steps/Steps=20"])
    assert done.returncode == 1 and summary["failure"], f"exit {done.returncode}: a named failure expected"
    rows = list(csv.DictReader(open(os.path.join(args.out, "steps.csv"))))
    reached = float(rows[-1]["time"]) * pressure if rows else 0.0
    print(f"RESULT limit: {summary['failure']} at p = 1.05 p_L; last converged {reached:.6g} = "
          f"{reached / ref.limit:.5f} p_L (p_L = {ref.limit:.6g})")
    if not 0.97 * ref.limit <= reached <= (1 + args.tol) * ref.limit:
        sys.exit(f"FAIL: last converged pressure {reached / ref.limit:.5f} p_L, not within "
                 f"[0.97, {1 + args.tol}] p_L")
    print("ok")
    sys.exit(0)

if args.case == "small-strain-limit":
    finite = [f"Materials/{block}/Type=simo-miehe", f"Materials/{block}/simo-miehe/nu={nu!r}",
              f"Materials/{block}/simo-miehe/Yield Stress={sy!r}"]
    differences = []
    for stiffer in (1, 10):
        ref = HillSphere(stiffer * E, p)
        out = os.path.join(args.out, f"E{stiffer}")
        done, summary = run(out, finite + [f"Materials/{block}/simo-miehe/E={stiffer * E!r}"])
        assert done.returncode == 0, f"{stiffer} E: {summary['failure']}: {summary['message']}"
        ua, ub = bore_and_outside(read_grid(result_frames(out)[-1][1]))
        differences.append(max(abs(ua / ref.u_a - 1), abs(ub / ref.u_b - 1)))
        print(f"RESULT simo-miehe, E = {stiffer * E:g}: u(a) {ua / ref.u_a - 1:+.2e}, u(b) "
              f"{ub / ref.u_b - 1:+.2e} from Hill's small strain (u(a) / a = {ref.u_a / a:.1e}), "
              f"{summary['iterations']['newton']} Newton iterations")
    ratio = differences[0] / differences[1]
    print(f"RESULT the difference falls {ratio:.1f} times with the strain")
    problems = []
    if not 5 <= ratio <= 20:
        problems.append(f"the difference falls {ratio:.3g} times for 10 times smaller strains")
    if differences[1] > args.u_tol:
        problems.append(f"at 10 E the displacements are {differences[1]:.3g} from Hill's")
    assert not problems, "; ".join(problems)
    print("ok")
    sys.exit(0)

ref = HillSphere(E, p)
print(f"reference: p = {p:g} = {p / ref.limit:.4f} p_L, first yield {ref.first_yield:.6g}, "
      f"c = {ref.c:.6g}, u(a) = {ref.u_a:.7g}, u(b) = {ref.u_b:.7g}")
labels = (["sigma_r", "sigma_t (mean)", "any component"] if three_d
          else ["sigma_r", "sigma_theta", "sigma_phi"])
table = []
for factor in [float(f) for f in args.factors.split(",")]:
    out = os.path.join(args.out, f"factor-{factor:g}")
    done, summary = run(out, scaled(factor))
    assert done.returncode == 0, f"factor {factor}: {summary['failure']}: {summary['message']}"
    grid = read_grid(result_frames(out)[-1][1])
    ua, ub = bore_and_outside(grid)
    errors = np.concatenate([stress_errors(grid, ref), [abs(ua / ref.u_a - 1), abs(ub / ref.u_b - 1)]])
    table.append(errors)
    print(f"RESULT factor {factor:g} ({summary['dofs']} dofs, "
          f"{summary['iterations']['newton']} Newton iterations): stresses / p: sigma_r "
          f"{errors[0]:.2e}, {labels[1]} {errors[1]:.2e}, {labels[2]} {errors[2]:.2e}; u(a) "
          f"{ua / ref.u_a - 1:+.2e}, u(b) {ub / ref.u_b - 1:+.2e}")
problems = []
finest, coarsest = table[-1], table[0]
if max(finest[:3]) > args.tol:
    problems.append(f"stress error {max(finest[:3]):.3g} p > {args.tol} p on the finest mesh")
if max(finest[3:]) > args.u_tol:
    problems.append(f"displacement error {max(finest[3:]):.3g} > {args.u_tol} on the finest mesh")
for name, fine, coarse in zip(labels + ["u(a)", "u(b)"], finest, coarsest):
    if fine > 1e-6 and not fine < coarse:
        problems.append(f"{name}'s error does not shrink under refinement ({coarse:.3g} -> {fine:.3g})")
assert not problems, "; ".join(problems)
print("ok")
