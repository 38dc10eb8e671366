#!/usr/bin/env python3
"""Runs a blade-root scene (scenes/blade-root-2d.yaml: a fir-tree root held in its disc slot
only by frictionless contact on the lobe flanks, both bodies spinning) and checks the force
balance that holds whatever the mesh:

  contact resultant on the blade  + centrifugal resultant on the blade            = 0
  support reactions (hub, cuts)   + centrifugal resultants on the blade and disc  = 0

The centrifugal resultants are integrated here from the written mesh and displacement,
independently of the code's assembly: rho omega^2 int (X + u - c) dA0 over each block (the scene's
finite-strain blocks take the follower load, r at the current position; --dead takes X), with a
2 x 2 Gauss rule on quad4 cells (exact for the bilinear integrand) or the centroid on tri3.
The swept 3D model (hex8, spinning about z, scenes/blade-root-3d.yaml) integrates the in-plane
part of x - c over volumes by a 2 x 2 x 2 rule (exact for the trilinear integrand); its blade and
disc are held along z on their faces, so the in-plane balances stand as in 2D, and the z
reactions, which only hold the Poisson expansion, sum to zero within TOL too.
Each error is |sum| / |centrifugal resultant of the blade|; TOL bounds both.

usage: check_blade_root.py CONTACTLAB SCENE OUTDIR TOL [--ranks N] [--dead] [--set key=value ...]
Prints "RESULT ..." lines for doc/verification.md (dofs, contact dofs, Newton iterations, wall
time, the balance errors and the peak contact pressure)."""
import json, os, sys

import numpy as np
import vtk
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import (converged_run, read_grid, result_frames,  # noqa: E402
                            scene_check_arguments)

ap = scene_check_arguments()
ap.add_argument("--dead", action="store_true")
args = ap.parse_args()

summary = converged_run(args.app, args.scene, args.out, args.set, args.ranks)

scene = yaml.safe_load(open(args.scene))["contactlab"]
spins = [l for l in scene["Loads"].values() if l.get("Type") == "centrifugal"]
if len(spins) != 1 or spins[0].get("Block", ""):
    sys.exit("FAIL: the check expects one centrifugal load on every block")
rho_w2 = float(spins[0]["Density"]) * float(spins[0]["Angular Velocity"]) ** 2
if [float(a) for a in spins[0].get("Axis", [0, 0, 1])] != [0.0, 0.0, 1.0]:
    sys.exit("FAIL: the check expects the spin axis along z")
centre = np.array([float(c) for c in spins[0].get("Centre", [0, 0])][:2])

# The last output of the series.
grid = read_grid(result_frames(args.out)[-1][1])
dim = summary["dimension"]
points = np.array([grid.GetPoint(i)[:dim] for i in range(grid.GetNumberOfPoints())])
disp = grid.GetPointData().GetArray("displacement")
u = np.array([disp.GetTuple(i)[:dim] for i in range(grid.GetNumberOfPoints())])
position = points if args.dead else points + u
blocks = grid.GetCellData().GetArray("material")

g = 1 / np.sqrt(3)
gauss = [(-g, -g), (g, -g), (g, g), (-g, g)]
corners = np.array([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                    (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)], dtype=float)


def hexahedron_moment(X, x):
    """int (x - c) dV0 over a hex8 cell (VTK corner order), in-plane components."""
    m = np.zeros(2)
    for q in corners * g:
        N = 0.125 * np.prod(1 + corners * q, axis=1)
        dN = np.array([[0.125 * corners[a, d] * np.prod([1 + corners[a, e] * q[e]
                                                            for e in range(3) if e != d])
                        for d in range(3)] for a in range(8)])
        m += np.linalg.det(X.T @ dN) * (N @ x[:, :2] - centre)
    return m


moment = {}  # block -> int (x - c) dA0 (dV0 in 3D), in-plane
top_block, top_y = None, -np.inf
for c in range(grid.GetNumberOfCells()):
    cell = grid.GetCell(c)
    ids = [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]
    X, x = points[ids], position[ids]
    block = int(blocks.GetValue(c))
    if X[:, 1].max() > top_y:
        top_block, top_y = block, X[:, 1].max()
    if cell.GetCellType() == vtk.VTK_QUAD:
        m = np.zeros(2)
        for xi, eta in gauss:
            N = 0.25 * np.array([(1 - xi) * (1 - eta), (1 + xi) * (1 - eta),
                                 (1 + xi) * (1 + eta), (1 - xi) * (1 + eta)])
            dN = 0.25 * np.array([[-(1 - eta), -(1 - xi)], [(1 - eta), -(1 + xi)],
                                  [(1 + eta), (1 + xi)], [-(1 + eta), (1 - xi)]])
            J = X.T @ dN
            m += np.linalg.det(J) * (N @ x - centre)
    elif cell.GetCellType() == vtk.VTK_TRIANGLE:
        area = 0.5 * np.cross(X[1] - X[0], X[2] - X[0])
        m = area * (x.mean(axis=0) - centre)
    elif cell.GetCellType() == vtk.VTK_HEXAHEDRON:
        m = hexahedron_moment(X, x)
    else:
        sys.exit("FAIL: the check integrates quad4, tri3 and hex8 cells only")
    moment[block] = moment.get(block, np.zeros(2)) + m

blade = np.append(rho_w2 * moment[top_block], [0.0] * (dim - 2))  # the highest block
total = np.append(rho_w2 * sum(moment.values()), [0.0] * (dim - 2))
contact = np.array(summary["contact"]["normal_force_vector"][:dim])
# The supports: the hub, the symmetry planes of the radial cuts when the scene has them, and in
# 3D the z supports of the front and back faces (z only: the blade's do not enter its in-plane
# balance with the contact).
hub = sum(np.array(force[:dim]) for force in summary["reactions"].values())
contact_error = np.linalg.norm((contact + blade)[:2]) / np.linalg.norm(blade)
hub_error = np.linalg.norm(hub + total) / np.linalg.norm(blade)

disc = summary["discretization"]
print(f"RESULT discretization={list(disc.values())[0]} dofs={summary['dofs']} "
      f"contact_dofs={summary['unknowns']['contact_multipliers']} "
      f"newton={summary['iterations']['newton']} geometry={summary['iterations']['geometry']} "
      f"seconds={summary['seconds']['total']:.2f}")
print(f"RESULT blade_load=({blade[0]:.6g}, {blade[1]:.6g}) contact=({contact[0]:.6g}, "
      f"{contact[1]:.6g}) supports=({', '.join(f'{h:.6g}' for h in hub)}) "
      f"total_load=({total[0]:.6g}, {total[1]:.6g})")
print(f"RESULT contact_balance_error={contact_error:.3e} hub_balance_error={hub_error:.3e} "
      f"max_pressure={summary['contact']['max_pressure']:.6g}")
failed = [name for name, e in (("contact", contact_error), ("hub", hub_error)) if not e <= args.tol]
if failed:
    sys.exit(f"FAIL: the {' and '.join(failed)} balance is off by more than {args.tol}")
print("PASS")
