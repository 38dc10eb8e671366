#!/usr/bin/env python3
"""Axisymmetric verification (Geometry/Type: axisymmetric; x = r, y = z, per full ring).

usage: check_axisymmetric.py CONTACTLAB SCENE OUTDIR CASE [options] [--set key=value ...]
CASE:
  lame        scenes/axisymmetric-thick-cylinder.yaml (a <= r <= b, internal pressure p, plane
              strain) at the radial divisions --divisions, against Lame's solution (Timoshenko &
              Goodier, Theory of Elasticity, 3rd ed. 1970, section 28): A = p a^2/(b^2 - a^2),
              B = p a^2 b^2/(b^2 - a^2), sigma_rr = A - B/r^2, sigma_tt = A + B/r^2,
              sigma_zz = 2 nu A, u_r = (1 + nu)/E ((1 - 2 nu) A r + B/r). Errors: the largest
              nodal |u_r - u| / u(a), and the largest |cell average - exact average| / p of
              sigma_rr (xx), sigma_tt (the hoop stress, output slot zz) and sigma_zz (yy), the
              averages weighted by r as the kernel's (2 pi r dA). The finest mesh's errors must be
              below --tol, and each error's mean rate from the coarsest to the finest mesh at
              least --min-rate (unless the finest is below 1e-9, round-off).
  spin        the same cylinder without pressure, spinning about its axis (a centrifugal load
              rho omega^2 r, here rho omega^2 = 10, on --divisions' last mesh), against the
              rotating long cylinder in plane strain (Timoshenko & Goodier, section 32, with
              k = (3 - 2 nu) rho omega^2 / (8 (1 - nu))): sigma_rr = k (b^2 + a^2 - a^2 b^2/r^2 - r^2),
              sigma_tt = k (b^2 + a^2 + a^2 b^2/r^2 - (1 + 2 nu) r^2 / (3 - 2 nu)),
              sigma_zz = nu (sigma_rr + sigma_tt), u_r = r (sigma_tt - nu (sigma_rr + sigma_zz))/E:
              the largest nodal u_r error / u(a) and cell-average stress errors / (rho omega^2 b^2)
              below --tol.
  shrink-fit  scenes/shrink-fit-axisymmetric.yaml: an inner ring a <= r <= b + delta pressed into
              an outer ring b <= r <= c (same E, nu), frictionless contact on r = b, open ends
              (sigma_zz = 0: each ring held axially on its bottom face only). The interface
              pressure (Budynas & Nisbett, Shigley's Mechanical Engineering Design, 9th ed.,
              section 3-16, eq. 3-57, equal materials):
                  p = E delta / b * (c^2 - b^2)(b^2 - a^2) / (2 b^2 (c^2 - a^2))
              (first order in delta / b; the model's contact radius is b). Checked: every
              closed contact point's pressure in contact.csv within --tol of p (a pressure:
              force per area of the ring), the interface's normal force against 2 pi b L p within
              --force-tol (a full ring's force), the outer ring's cells along its bore against
              Lame's hoop stress (p (c^2 + b^2)/(c^2 - b^2) at r = b) averaged over each cell
              within --tol p, and the axial reactions zero (open ends) within 1e-6 of the force.
  thermal-fit the same rings meshed touching (the inner one a <= r <= b, Gap 0) and fitted by
              differential thermal expansion instead: both heated uniformly from 20 to 304 degC
              (the seed's steam-generator operation), the inner ring (Alloy 690 tube, alpha_in =
              14e-6/K) expanding more than the outer one (ferritic tubesheet, alpha_out =
              12.5e-6/K). A uniform temperature expands each free ring without stress, so the
              rings meet the interference delta = (alpha_in - alpha_out) dT b of the shrink fit,
              and the same checks apply with that delta (for equal materials the small-strain
              solution is exactly the classical p: both rings have radius b). With
              --tabulated-e both rings' E is a table in T, 200000 at 20 degC and 180000 at 304:
              the pressure is then the one of E(304) = 180000. With --finite-strain both rings
              are Saint Venant-Kirchhoff (the same E, nu; F = F_e F_theta): the classical
              pressure holds to first order in alpha dT (4e-3 here: the rings' radii and length
              grow by it), so its force tolerance is of that order.
Prints "RESULT ..." lines for doc/verification.md."""
import argparse, csv, json, math, os, sys

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import converged_run, read_grid, result_frames  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("exe"); ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("case", choices=["lame", "spin", "shrink-fit", "thermal-fit"])
ap.add_argument("--tol", type=float, default=1e-3)
ap.add_argument("--force-tol", type=float, default=2e-3,
                help="shrink-fit: the interface's normal force, relative")
ap.add_argument("--pressure", type=float, help="lame: the bore's pressure (the scene's: 100)")
ap.add_argument("--element")
ap.add_argument("--finite-strain", action="store_true",
                help="lame: the tube in Saint Venant-Kirchhoff with a dead pressure (the "
                     "finite-strain axisymmetric kernel), Lame's solution to its strains")
ap.add_argument("--divisions", default="2,4,8,16")
ap.add_argument("--tabulated-e", action="store_true",
                help="thermal-fit: E tabulated in T (200000 at 20 degC, 180000 at 304)")
ap.add_argument("--min-rate", type=float, default=1.5)
ap.add_argument("--set", action="append", default=[])
args = ap.parse_args()
scene = yaml.safe_load(open(args.scene))["contactlab"]
assert scene["Geometry"]["Type"] == "axisymmetric"


def cells(grid):
    """Each cell's (corners [(r, z)...] counter-clockwise, stress Voigt 6); VTK lists a cell's
    corners first, its mid-side nodes after (the cells here have straight sides)."""
    stress = grid.GetCellData().GetArray("stress")
    out = []
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        corners = 3 if cell.GetCellType() in (5, 22) else 4  # VTK_TRIANGLE, VTK_QUADRATIC_TRIANGLE
        ids = cell.GetPointIds()
        points = [grid.GetPoint(ids.GetId(k))[:2] for k in range(corners)]
        out.append((points, [stress.GetComponent(c, k) for k in range(6)]))
    return out


def ring_average(f, corners, n=10):
    """int f r dA / int r dA over the straight-sided cell (its triangles from the first corner,
    each by Gauss-Legendre in the collapsed square): the kernel's 2 pi r weighted average."""
    import numpy as np
    x, w = np.polynomial.legendre.leggauss(n)
    s, t = np.meshgrid((x + 1) / 2, (x + 1) / 2)
    ws = np.outer(w, w) / 4
    num = den = 0.0
    for k in range(1, len(corners) - 1):
        (x0, y0), (x1, y1), (x2, y2) = corners[0], corners[k], corners[k + 1]
        jac = abs((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0))
        # (s, t) in [0, 1]^2 -> the triangle: xi = s (1 - t), eta = t, dA = jac (1 - t) ds dt
        xi, eta = s * (1 - t), t
        r = x0 + (x1 - x0) * xi + (x2 - x0) * eta
        weight = ws * jac * (1 - t) * r
        num += float(np.sum(weight * f(r)))
        den += float(np.sum(weight))
    return num / den


def lame():
    mesh = scene["Mesh"]["rectangle"]
    material = scene["Materials"]["body"]["linear-elastic"]
    a = float(mesh["Origin"][0]); b = a + float(mesh["Lx"])
    E, nu = float(material["E"]), float(material["nu"])
    p = float(scene["Loads"]["bore"]["Value"])
    if args.pressure is not None:
        p = args.pressure
        args.set.append(f"Loads/bore/Value={p!r}")
    if args.finite_strain:
        # The same tube in finite strain (Saint Venant-Kirchhoff, the same E and nu, a dead
        # pressure): Lame's solution up to its strains, ~1e-3 here.
        args.set += ["Materials/body/Type=saint-venant-kirchhoff",
                     f"Materials/body/saint-venant-kirchhoff/E={E!r}",
                     f"Materials/body/saint-venant-kirchhoff/nu={nu!r}", "Loads/bore/Follower=false"]
    A, B = p * a * a / (b * b - a * a), p * a * a * b * b / (b * b - a * a)
    u = lambda r: (1 + nu) / E * ((1 - 2 * nu) * A * r + B / r)
    exact = {0: lambda r: A - B / r**2, 2: lambda r: A + B / r**2, 1: lambda r: 2 * nu * A + 0 * r}
    names = {0: "sigma_rr", 2: "sigma_tt", 1: "sigma_zz"}
    element = args.element or mesh["Element"]
    rows = []
    for n in [int(d) for d in args.divisions.split(",")]:
        out = os.path.join(args.out, f"{element}-{n}")
        sets = args.set + [f"Mesh/rectangle/nx={n}", f"Mesh/rectangle/Element={element}"]
        summary = converged_run(args.exe, args.scene, out, sets)
        grid = read_grid(result_frames(out)[-1][1])
        disp = grid.GetPointData().GetArray("displacement")
        eu = max(abs(disp.GetComponent(i, 0) - u(grid.GetPoint(i)[0]))
                 for i in range(grid.GetNumberOfPoints())) / u(a)
        es = {k: 0.0 for k in names}
        for corners, s in cells(grid):
            for k in names:
                es[k] = max(es[k], abs(s[k] - ring_average(exact[k], corners)) / p)
        rows.append((n, eu, es, summary["time"]["total"] if "time" in summary else float("nan")))
        print(f"RESULT lame {element} nr={n}: max |u_r err|/u(a) = {eu:.3e}, " +
              ", ".join(f"max |{names[k]} err|/p = {es[k]:.3e}" for k in names))
    failures = []
    n, eu, es, _ = rows[-1]
    for label, e in [("u_r", eu)] + [(names[k], es[k]) for k in names]:
        if not e < args.tol:
            failures.append(f"{element} nr={n}: {label} error {e:.3e} >= {args.tol}")
    if len(rows) < 2:
        return failures
    # The rate over the whole sequence, not per halving: the coarsest meshes are pre-asymptotic.
    (n1, eu1, es1, _), (n2, eu2, es2, _) = rows[0], rows[-1]
    for label, e1, e2 in [("u_r", eu1, eu2)] + [(names[k], es1[k], es2[k]) for k in names]:
        rate = math.log(e1 / max(e2, 1e-300)) / math.log(n2 / n1)
        print(f"RESULT lame {element} rate {label} nr {n1}->{n2}: {rate:.2f}")
        if e2 > 1e-9 and rate < args.min_rate:
            failures.append(f"{element} {label} nr {n1}->{n2}: rate {rate:.2f} < {args.min_rate}")
    return failures


def spin():
    mesh = scene["Mesh"]["rectangle"]
    material = scene["Materials"]["body"]["linear-elastic"]
    a = float(mesh["Origin"][0]); b = a + float(mesh["Lx"])
    E, nu = float(material["E"]), float(material["nu"])
    rho, omega = 1e-3, 100.0
    k = (3 - 2 * nu) * rho * omega**2 / (8 * (1 - nu))
    srr = lambda r: k * (b * b + a * a - a * a * b * b / r**2 - r * r)
    stt = lambda r: k * (b * b + a * a + a * a * b * b / r**2 - (1 + 2 * nu) / (3 - 2 * nu) * r * r)
    szz = lambda r: nu * (srr(r) + stt(r))
    u = lambda r: r * (stt(r) - nu * (srr(r) + szz(r))) / E
    n = int(args.divisions.split(",")[-1])
    element = args.element or mesh["Element"]
    sets = args.set + ["Loads/bore/Value=0", "Loads/spin/Type=centrifugal",
                       f"Loads/spin/Density={rho!r}", f"Loads/spin/Angular Velocity={omega!r}",
                       f"Mesh/rectangle/nx={n}", f"Mesh/rectangle/Element={element}"]
    converged_run(args.exe, args.scene, args.out, sets)
    grid = read_grid(result_frames(args.out)[-1][1])
    disp = grid.GetPointData().GetArray("displacement")
    eu = max(abs(disp.GetComponent(i, 0) - u(grid.GetPoint(i)[0]))
             for i in range(grid.GetNumberOfPoints())) / u(a)
    scale = rho * omega**2 * b * b
    es = max(abs(s[k] - ring_average(f, corners)) / scale for corners, s in cells(grid)
             for k, f in [(0, srr), (2, stt), (1, szz)])
    print(f"RESULT spin {element} nr={n}: max |u_r err|/u(a) = {eu:.3e}, max stress err / "
          f"(rho omega^2 b^2) = {es:.3e}")
    return [f"{label} error {e:.3e} >= {args.tol}" for label, e in [("u_r", eu), ("stress", es)]
            if not e < args.tol]


def shrink_fit(thermal=False):
    mesh = scene["Mesh"]["stacked-blocks-2d"]
    material = scene["Materials"]["lower"]["linear-elastic"]
    assert scene["Materials"]["upper"]["linear-elastic"] == material, "equal materials"
    E = float(material["E"])
    a = float(mesh["Origin"][0]); L = float(mesh["Width"])
    delta = -float(mesh["Gap"]); b = a + float(mesh["Lower Height"]) - delta
    c = b + float(mesh["Upper Height"])
    if thermal:
        # The seed's materials and operating temperature (EDF R&D 2012): Alloy 690 tube inside a
        # ferritic tubesheet, from 20 to 304 degC.
        alpha_in, alpha_out, T_ref, T = 14e-6, 12.5e-6, 20.0, 304.0
        delta = (alpha_in - alpha_out) * (T - T_ref) * b
        args.set += ["Mesh/stacked-blocks-2d/Gap=0", f"Mesh/stacked-blocks-2d/Lower Height={b - a!r}"]
        for block, alpha in [("lower", alpha_in), ("upper", alpha_out)]:
            law = f"Materials/{block}/linear-elastic"
            args.set += [f"{law}/Thermal Expansion={alpha!r}", f"{law}/Reference Temperature={T_ref!r}",
                         f"Temperature/{block}/Value={T!r}"]
            if args.finite_strain:
                finite = f"Materials/{block}/saint-venant-kirchhoff"
                args.set += [f"Materials/{block}/Type=saint-venant-kirchhoff",
                             f"{finite}/E={E!r}", f"{finite}/nu={float(material['nu'])!r}",
                             f"{finite}/Thermal Expansion={alpha!r}",
                             f"{finite}/Reference Temperature={T_ref!r}"]
            if args.tabulated_e:
                args.set += [f"{law}/E=1", f"{law}/Temperature Tables/Temperatures=[{T_ref}, {T}]",
                             f"{law}/Temperature Tables/E=[200000, 180000]"]
        if args.tabulated_e:
            E = 180000.0
        print(f"RESULT thermal-fit delta = (alpha_in - alpha_out) dT b = {delta:.6g}, E(T) = {E:g}")
    p = E * delta / b * (c * c - b * b) * (b * b - a * a) / (2 * b * b * (c * c - a * a))
    force = 2 * math.pi * b * L * p
    # The same small-strain theory on the rings as meshed (the inner one's outer radius b + delta,
    # nu no longer cancelling): how much of the error is the formula's first order in delta / b.
    nu = float(material["nu"]); d = b if thermal else b + delta
    exact = delta * E / (b * ((c * c + b * b) / (c * c - b * b) + nu) +
                         d * ((d * d + a * a) / (d * d - a * a) - nu))
    print(f"RESULT shrink-fit classical p = {p:.6g}; the meshed rings' small-strain p = {exact:.6g} "
          f"({exact / p - 1:+.1e})")
    summary = converged_run(args.exe, args.scene, args.out, args.set)
    failures = []
    # contact.csv's status: 0 free (ContactPointResult.hpp).
    pressures = [float(r["pressure"]) for r in csv.DictReader(open(os.path.join(args.out, "contact.csv")))
                 if r["status"] != "0"]
    if not pressures:
        return ["no contact point closed"]
    worst = max(abs(q - p) for q in pressures) / p
    print(f"RESULT shrink-fit reference p = {p:.6g}; {len(pressures)} closed points, pressure "
          f"{min(pressures):.6g} to {max(pressures):.6g}: max |p_i - p| / p = {worst:.3e}")
    if not worst < args.tol:
        failures.append(f"contact pressure error {worst:.3e} >= {args.tol}")
    normal = float(summary["contact"]["normal_force"])
    ef = abs(normal - force) / force
    print(f"RESULT shrink-fit normal force {normal:.6g} against 2 pi b L p = {force:.6g}: "
          f"relative error {ef:.3e}")
    if not ef < args.force_tol:
        failures.append(f"normal force error {ef:.3e} >= {args.force_tol}")
    grid = read_grid(result_frames(args.out)[-1][1])
    hoop = (c * c + b * b) / (c * c - b * b) * p
    # The outer ring's cells along its bore, against Lame's hoop stress averaged over each.
    A, B = p * b * b / (c * c - b * b), p * b * b * c * c / (c * c - b * b)
    eh, count = 0.0, 0
    for corners, s in cells(grid):
        if abs(min(r for r, z in corners) - b) < 1e-9 * b:
            count += 1
            eh = max(eh, abs(s[2] - ring_average(lambda r: A + B / r**2, corners)) / p)
    if count == 0:
        return failures + ["no cell of the outer ring at the bore"]
    print(f"RESULT shrink-fit outer ring's hoop stress (bore value {hoop:.6g}) in its {count} bore "
          f"cells: max |error| / p = {eh:.3e}")
    if not eh < args.tol:
        failures.append(f"hoop stress error {eh:.3e} >= {args.tol}")
    for name, reaction in summary["reactions"].items():
        if not abs(reaction[1]) < 1e-6 * force:
            failures.append(f"axial reaction {name} = {reaction[1]} is not zero (open ends)")
        print(f"RESULT shrink-fit reaction {name}: {reaction}")
    return failures


failures = {"lame": lame, "spin": spin, "shrink-fit": shrink_fit,
            "thermal-fit": lambda: shrink_fit(thermal=True)}[args.case]()
if failures:
    sys.exit("FAIL:\n  " + "\n  ".join(failures))
print("ok")
