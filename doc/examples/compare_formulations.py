"""Hertz 2D with each contact formulation, from Python: the contact pressure against Hertz's
profile, and a plot of both (OUT/compare_formulations.png).

A half disc (R = 1, E = 1, nu = 0.3, plane strain) pressed on a rigid plane: for the line load P
the simulation reaches, Hertz gives the half-width a = sqrt(4 P R / (pi E*)) and the pressure
p(x) = p0 sqrt(1 - (x/a)^2), p0 = 2 P / (pi a), E* = E / (1 - nu^2) (Johnson, Contact Mechanics,
1985, section 4.3). Run with the module on the path:

    PYTHONPATH=build/python /usr/bin/python3 doc/examples/compare_formulations.py [OUT]

The suite runs it (python.example) and it fails if a formulation's peak pressure is more than
3 % from Hertz's p0.
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import contactlab  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
scene = os.path.join(here, "..", "..", "scenes", "hertz-2d.yaml")
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join("results", "compare-formulations")
figure = os.path.join(out, "compare_formulations.png")
E_star, R = 1.0 / (1 - 0.3**2), 1.0

# Penalty has no automatic coefficient (eps_n sets the penetration, so it is the model's): 100 E/h
# with the contact facets' h = 0.005; the others' coefficients are automatic or change only the
# Newton path.
settings = {"penalty": {"Contact/floor/Formulation/penalty/Normal Penalty": 2e4},
            "lagrange": {}, "augmented-lagrangian": {}, "normal-field-augmented-lagrangian": {}}
rows, curves = [], {}
for name, extra in settings.items():
    sim = contactlab.run(scene, set={"Contact/floor/Formulation/Type": name, "Output/VTK": False,
                                     **extra}, out=os.path.join(out, name), quiet=True)
    P = sim.history["normal_force"][-1]
    a = np.sqrt(4 * P * R / (np.pi * E_star))
    p0 = 2 * P / (np.pi * a)
    points = sim.contact_points()
    x, p = points["reference"][:, 0], points["pressure"]
    order = np.argsort(x)
    curves[name] = (x[order] / a, p[order] / p0)
    rows.append((name, sim.report["iterations"], P, p.max() / p0 - 1))

print(f"{'formulation':36s} {'Newton':>6s} {'load P':>10s} {'peak / p0 - 1':>14s}")
for name, iterations, P, error in rows:
    print(f"{name:36s} {iterations:6d} {P:10.6f} {error:+14.2%}")

s = np.linspace(-1, 1, 201)
plt.figure(figsize=(6, 3.6))
plt.plot(s, np.sqrt(1 - s**2), "k-", lw=2, label="Hertz")
# Open markers of different shapes and sizes: the formulations agree, so their points overlap.
for (name, (xs, ps)), marker, size in zip(curves.items(), "osD^", (9, 7, 5, 3)):
    plt.plot(xs, ps, marker, ms=size, mfc="none", label=name)
plt.xlim(-1.5, 1.5)
plt.xlabel("x / a")
plt.ylabel("p / p0")
plt.legend(fontsize=7)
plt.title("Hertz 2D, contact pressure by formulation")
plt.tight_layout()
plt.savefig(figure, dpi=120)
print("figure:", figure)

worst = max(abs(error) for *_, error in rows)
if worst > 0.03:
    sys.exit(f"a peak pressure is {worst:.1%} from Hertz's p0 (limit 3 %)")
