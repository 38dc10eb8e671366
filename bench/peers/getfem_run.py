#!/usr/bin/python3
"""GetFEM's side of bench/peers/peers.py: the quarter hemisphere of the peers' mesh pressed on the
rigid plane z = 0, run as a process of its own so that /usr/bin/time measures GetFEM alone.

usage: getfem_run.py MESH.msh OUT.json --delta D --r R [--E 1 --nu 0.3] [--tol T] [--max-iter N]
Writes OUT.json: dofs, multipliers, newton, converged, force (the quarter's), the setup and
solve seconds, and the contact points (reference x, y, z and pressure) of the multiplier.

The model (GetFEM 5.4's python interface, Debian python3-getfem):
- P2 displacement on the imported gmsh tet10 mesh (isoparametric: GetFEM keeps the mesh's
  second-order geometric transformation), linearized isotropic elasticity;
- the integral (continuous) frictionless contact with a rigid obstacle,
  Model.add_integral_contact_with_rigid_obstacle_brick, option 1 = the non-symmetric
  Alart-Curnier augmented Lagrangian, its multiplier (the contact stress) P1 on the curved
  surface (https://getfem.org/userdoc/model_contact_friction.html, "Contact with rigid
  obstacle"; demo: interface/tests/python/demo_static_contact.py, its versions 5-8);
- symmetry (u.n = 0 on x = 0 and y = 0) and the pressing (u.n = -delta on the flat top) as
  normal Dirichlet conditions with P2 multipliers, which on a plane impose them at every P2 node
  (Model.add_normal_Dirichlet_condition_with_multipliers,
  https://getfem.org/python/cmdref_Model.html);
- Model.solve with MUMPS ('lsolver', 'mumps') and GetFEM's default Newton line search."""
import argparse, json, time

import getfem as gf
import numpy as np

# gf.Mesh('import', 'gmsh') makes each physical group of the .geo a region of its tag.
from peers_mesh import CURVED, FLAT, SYM_X, SYM_Y


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mesh")
    ap.add_argument("out")
    ap.add_argument("--delta", type=float, required=True)
    ap.add_argument("--r", type=float, required=True, help="augmentation parameter (E / h)")
    ap.add_argument("--E", type=float, default=1.0)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--tol", type=float, default=1e-8,
                    help="Newton stops at |residual| <= tol x |external load| (GetFEM's 'max_res')")
    ap.add_argument("--max-iter", type=int, default=50)
    args = ap.parse_args()
    start = time.time()
    m = gf.Mesh("import", "gmsh", args.mesh)
    mfu = gf.MeshFem(m, 3)
    mfu.set_classical_fem(2)
    mfd = gf.MeshFem(m, 1)  # scalar P2: the obstacle's signed distance
    mfd.set_classical_fem(2)
    mfl = gf.MeshFem(m, 1)  # scalar P1: the contact stress on the curved surface
    mfl.set_classical_fem(1)
    contact_dofs = mfl.basic_dof_on_region(CURVED)
    mfl_contact = gf.MeshFem("partial", mfl, contact_dofs)
    mim = gf.MeshIm(m, 4)  # degree 4: exact for the P2 stiffness on straight elements

    lam = args.E * args.nu / ((1 + args.nu) * (1 - 2 * args.nu))
    mu = args.E / (2 * (1 + args.nu))
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [mu])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    md.add_initialized_data("press", [-args.delta])
    md.add_normal_Dirichlet_condition_with_multipliers(mim, "u", 2, FLAT, "press")
    md.add_normal_Dirichlet_condition_with_multipliers(mim, "u", 2, SYM_X)
    md.add_normal_Dirichlet_condition_with_multipliers(mim, "u", 2, SYM_Y)
    # The obstacle z <= 0: its signed distance, positive on the body's side, is z.
    md.add_initialized_fem_data("obstacle", mfd, mfd.eval("z"))
    md.add_fem_variable("lambda_n", mfl_contact)
    md.add_initialized_data("r", [args.r])
    md.add_integral_contact_with_rigid_obstacle_brick(mim, "u", "lambda_n", "obstacle", "r",
                                                      CURVED, 1)
    # GetFEM's Newton is relative already: it stops when |residual| / |external load| (the
    # model's approx_external_load, here the Dirichlet data) <= max_res (getfem_model_solvers.h,
    # classical_Newton), like contactlab's Relative Tolerance.
    setup = time.time() - start
    start = time.time()
    nit = md.solve("noisy", "max_iter", args.max_iter, "max_res", args.tol, "lsolver", "mumps")
    solve = time.time() - start
    # solve returns the iteration count (a tuple (nbit, converged) in some versions).
    if isinstance(nit, (tuple, list, np.ndarray)):
        nit = int(np.asarray(nit).ravel()[0])

    # lambda_n is the normal stress sigma_nn: negative in compression.
    force = -gf.asm_generic(mim, 0, "lambda_n", CURVED, md)
    # The partial mesh_fem's dofs are a subset of mfl's: back to mfl's numbering, then its nodes.
    ln = mfl_contact.extension_matrix().mult(md.variable("lambda_n"))[contact_dofs]
    nodes = mfl.basic_dof_nodes(contact_dofs)
    points = [dict(x=float(nodes[0, i]), y=float(nodes[1, i]), z=float(nodes[2, i]),
                   pressure=float(-ln[i])) for i in range(len(ln))]
    json.dump(dict(dofs=int(mfu.nbdof()), multipliers=int(md.nbdof() - mfu.nbdof()),
                   # Model.solve says no more than its count: one that used every iteration
                   # allowed is taken as not converged.
                   newton=int(nit), converged=int(nit) < args.max_iter, force=float(force),
                   setup_seconds=setup, solve_seconds=solve, points=points), open(args.out, "w"))


if __name__ == "__main__":
    main()
