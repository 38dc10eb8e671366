"""Under mpirun: a Simulation on every rank gives the single-rank run's answers (rank 0 holds
the displacements). argv: the scene, the output folder, the reference file (written by this
script on one rank, read on more)."""
import sys

import numpy as np

import contactlab

scene, out, reference = sys.argv[1], sys.argv[2], sys.argv[3]
sim = contactlab.run(scene, set={"Load Steps/Steps": 2, "Output/VTK": False}, out=out,
                     quiet=True)
assert sim.report["converged"], sim.report
force = sim.history["normal_force"][-1]
u = sim.displacement()
if contactlab.rank() == 0:
    assert u.shape[0] == len(sim.node_ids()), u.shape
    if contactlab.ranks() == 1:
        np.savetxt(reference, [force, np.max(np.abs(u))])
    else:
        f1, u1 = np.loadtxt(reference)
        assert abs(force - f1) <= 1e-8 * abs(f1), (force, f1)
        assert abs(np.max(np.abs(u)) - u1) <= 1e-8 * u1, (np.max(np.abs(u)), u1)
    print(f"rank 0 of {contactlab.ranks()}: contact force {force:.10g}")
else:
    assert u.size == 0
