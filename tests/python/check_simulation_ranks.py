"""Under mpirun: a Simulation on every rank gives the single-rank run's answers (rank 0 holds the
displacements and the nodal stresses). argv: the scene, the output folder, the reference file
(written by this script on one rank, read on more)."""
import sys

import numpy as np

import contactlab

scene, out, reference = sys.argv[1], sys.argv[2], sys.argv[3]
sim = contactlab.run(scene, set={"Load Steps/Steps": 2, "Output/VTK": False}, out=out,
                     quiet=True)
assert sim.report["converged"], sim.report
force = sim.history["normal_force"][-1]
u = sim.displacement()
stress = sim.nodal_fields()["stress"]  # its elements' averages, from either rank's elements
if contactlab.rank() == 0:
    assert u.shape[0] == len(sim.node_ids()), u.shape
    assert stress.shape == (len(sim.node_ids()), 6) and np.all(np.isfinite(stress)), stress.shape
    values = [force, np.max(np.abs(u)), np.max(np.abs(stress)), np.sum(np.abs(stress))]
    if contactlab.ranks() == 1:
        np.savetxt(reference, values)
    else:
        for got, want in zip(values, np.loadtxt(reference)):
            assert abs(got - want) <= 1e-8 * abs(want), (values, want)
    print(f"rank 0 of {contactlab.ranks()}: contact force {force:.10g}")
else:
    assert u.size == 0 and stress.size == 0
