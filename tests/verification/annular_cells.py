"""Averages of a radially symmetric stress field over the annular cells of a ring-sector mesh,
as the check scripts of the thick tube and the hollow sphere compare them with the cells'
average stresses (imported by check_thick_cylinder.py and check_thick_sphere.py)."""
import math

import numpy as np


def to_polar(s, t):
    """(xx, yy, zz, xy) -> (radial, tangential, zz) at the angle t from the x axis."""
    cs, sn = math.cos(t), math.sin(t)
    return np.array([s[0] * cs * cs + s[1] * sn * sn + 2 * s[3] * sn * cs,
                     s[0] * sn * sn + s[1] * cs * cs - 2 * s[3] * sn * cs, s[2]])


def cell_average(stress, r1, r2, t1, t2, kinks=(), ring=False):
    """The Cartesian (xx, yy, zz, xy) average of stress(r) = (radial, tangential, zz) over the
    cell r1 <= r <= r2, t1 <= t <= t2, rotated back to polar components at the middle angle:
    what the cell's average output becomes. The radial integral is split at the kinks inside
    the cell; ring weights the area by x = r cos t (an axisymmetric model's volume)."""
    x, w = np.polynomial.legendre.leggauss(12)
    cuts = [r1] + [k for k in kinks if r1 < k < r2] + [r2]
    total, volume = np.zeros(4), 0.0
    for lo, hi in zip(cuts[:-1], cuts[1:]):
        for xr, wr in zip(x, w):
            r = lo + (hi - lo) * (xr + 1) / 2
            sr, st, sz = stress(r)
            for xt, wt in zip(x, w):
                t = t1 + (t2 - t1) * (xt + 1) / 2
                cs, sn = math.cos(t), math.sin(t)
                weight = wr * wt * r * (hi - lo) * (t2 - t1) / 4 * (r * cs if ring else 1.0)
                total += weight * np.array([sr * cs * cs + st * sn * sn,
                                            sr * sn * sn + st * cs * cs, sz, (sr - st) * sn * cs])
                volume += weight
    return to_polar(total / volume, 0.5 * (t1 + t2))


def polar_cells(grid):
    """Each cell of a VTK grid as (r1, r2, t1, t2, its stress in polar components at the middle
    angle, its equivalent plastic strain or None)."""
    stress = grid.GetCellData().GetArray("stress")
    plastic = grid.GetCellData().GetArray("equivalent_plastic_strain")
    cells = []
    for i in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(i).GetPointIds()
        pts = np.array([grid.GetPoint(ids.GetId(j))[:2] for j in range(ids.GetNumberOfIds())])
        r, t = np.hypot(pts[:, 0], pts[:, 1]), np.arctan2(pts[:, 1], pts[:, 0])
        s = stress.GetTuple(i)  # Voigt xx yy zz xy yz xz
        cells.append((r.min(), r.max(), t.min(), t.max(),
                      to_polar([s[0], s[1], s[2], s[3]], 0.5 * (t.min() + t.max())),
                      plastic.GetTuple1(i) if plastic is not None else None))
    return cells


def radial_displacements(grid, radii, tolerance=1e-9):
    """{radius: [the radial displacement of every node at that distance from the origin, within
    tolerance times the largest radius]} (2D or 3D)."""
    u = grid.GetPointData().GetArray("displacement")
    radial = {side: [] for side in radii}
    for i in range(grid.GetNumberOfPoints()):
        x = grid.GetPoint(i)
        r = math.sqrt(x[0] ** 2 + x[1] ** 2 + x[2] ** 2)
        for side in radial:
            if abs(r - side) < tolerance * max(radii):
                d = u.GetTuple(i)
                radial[side].append(sum(d[k] * x[k] for k in range(len(d))) / r)
    return radial


def pressurized_ring_sector(path):
    """The scene's ring-sector mesh and the constants of its J2 block 'body' under the pressure
    'bore': (mesh section, material section, a, b, E, nu, sigma_y, p)."""
    import yaml
    scene = yaml.safe_load(open(path))["contactlab"]
    mesh = scene["Mesh"]["ring-sector"]
    material = scene["Materials"]["body"]["j2-small-strain"]
    return (mesh, material, float(mesh["Inner Radius"]), float(mesh["Outer Radius"]),
            float(material["E"]), float(material["nu"]), float(material["Yield Stress"]),
            float(scene["Loads"]["bore"]["Value"]))
