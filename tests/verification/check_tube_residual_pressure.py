#!/usr/bin/env python3
"""The tube expansion's residual contact pressure against the elastic-perfectly plastic model of
a hydraulically expanded joint (issue 18; doc/verification.md "Residual pressure against the
expanded-joint model"). scenes/tube-expansion-axisymmetric.yaml is run as that model assumes:
the tube (a = 8.435 to b = 9.525 mm) elastic-perfectly plastic (J2, yield Y = 300 MPa, the
scene's hardening set to 0), the tubesheet sleeve (b + g = 9.625 to c = 15 mm) elastic,
frictionless, expanded by Pe = 200 MPa over the whole length, then released; both tubes open
(free top ends: sigma_z = 0).

The model (Goodier & Schoessow 1943; Krips & Podhorsky 1976; written P*c = (Pe - Pmin) / K by
Laghzale & Bouzid 2009, eq. 1): once the tube is fully plastic it carries a fixed share of the
bore pressure, so at the peak the joint takes p_c = Pe - P_L with P_L the tube's plastic limit
pressure; the release is elastic for tube and sleeve together (a compound cylinder, Lame: Timoshenko
& Goodier, Theory of Elasticity, par. 33, plane stress), which takes T Pe off the interface:

    P*c = (1 - T) Pe - P_L = (Pe - Pmin) / K,  K = 1 / (1 - T),  Pmin = P_L / (1 - T).

P_L here: von Mises with sigma_z = 0, the fully plastic tube's stresses integrated through the
wall (d sigma_r / dr = (sigma_t - sigma_r) / r on the yield surface, from sigma_r(b) = -p_c;
Hill, The Mathematical Theory of Plasticity, ch. V); the closed form (2 / sqrt 3) Y ln(b / a)
(the von Mises plane-strain limit, which this stress range is close to) and Tresca's Y ln(b / a)
are printed beside it. The model's assumptions are checked: no reverse yielding in the tube at the
release (its largest residual von Mises stress below Y), the sleeve elastic (its material).

Compares the mean contact pressure over the middle half of the length (away from the free ends)
at the peak (contact_t1.csv) and after the release (contact.csv); each relative difference must
be below its bound.

usage: check_tube_residual_pressure.py CONTACTLAB SCENE_AXISYMMETRIC OUTDIR PEAK_TOL RESIDUAL_TOL"""
import csv, math, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contactlab_run import converged_run  # noqa: E402

# The scene's geometry and materials (scenes/tube-expansion-axisymmetric.yaml).
A, B, GAP, C, LENGTH = 8.435, 8.435 + 1.09, 0.1, 8.435 + 1.09 + 0.1 + 5.375, 20.0
E_TUBE, E_SLEEVE, NU, YIELD, PE = 205000.0, 204000.0, 0.3, 300.0, 200.0
MODEL = ["Materials/lower/j2-small-strain/Isotropic Hardening Modulus=0",
         "Materials/upper/Type=linear-elastic",
         f"Materials/upper/linear-elastic/E={E_SLEEVE:g}",
         f"Materials/upper/linear-elastic/nu={NU:g}"]


def hoop_on_yield(sr):
    """sigma_t on the von Mises surface with sigma_z = 0, the tensile root (sigma_t > sigma_r)."""
    return 0.5 * (sr + math.sqrt(4 * YIELD * YIELD - 3 * sr * sr))


def fully_plastic_field(pc, n=2000):
    """(r, sigma_r, sigma_t) through the fully plastic tube from r = b (sigma_r = -pc) to a:
    the equilibrium d sigma_r / d ln r = sigma_t - sigma_r integrated by RK4 in ln r."""
    x0, h = math.log(B), (math.log(A) - math.log(B)) / n
    slope = lambda s: hoop_on_yield(s) - s
    sr, field = -pc, []
    for i in range(n + 1):
        field.append((math.exp(x0 + i * h), sr, hoop_on_yield(sr)))
        k1 = slope(sr)
        k2 = slope(sr + h / 2 * k1)
        k3 = slope(sr + h / 2 * k2)
        k4 = slope(sr + h * k3)
        sr += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return field


def peak_contact_pressure():
    """p_c with the fully plastic tube's bore pressure equal to Pe (bisection)."""
    low, high = 0.0, PE
    for _ in range(80):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if -fully_plastic_field(mid)[-1][1] < PE else (low, mid)
    return 0.5 * (low + high)


def lame(ri, ro, pi, po, r):
    """(sigma_r, sigma_t) at r in a cylinder ri..ro under pressures pi inside, po outside."""
    a_ = (pi * ri * ri - po * ro * ro) / (ro * ro - ri * ri)
    b_ = (pi - po) * ri * ri * ro * ro / (ro * ro - ri * ri)
    return a_ - b_ / (r * r), a_ + b_ / (r * r)


def radial_displacement(ri, ro, pi, po, r, e):
    sr, st = lame(ri, ro, pi, po, r)
    return r / e * (st - NU * sr)  # plane stress


def release_transfer():
    """T: the interface pressure on the tube falls by T Pe when Pe is removed from the bore, the
    tube at b and the sleeve at b + g moving together (the sleeve's pressure is the tube's times
    b / (b + g): the same force per unit length)."""
    def mismatch(q):
        return (radial_displacement(A, B, PE, q, B, E_TUBE)
                - radial_displacement(B + GAP, C, q * B / (B + GAP), 0.0, B + GAP, E_SLEEVE))
    m0, m1 = mismatch(0.0), mismatch(1.0)
    return -m0 / (m1 - m0) / PE


def middle_pressure(path):
    rows = list(csv.DictReader(open(path)))
    values = [float(r["pressure"]) for r in rows
              if 0.25 * LENGTH <= float(r["reference_y"]) <= 0.75 * LENGTH]
    return sum(values) / len(values)


if len(sys.argv) != 6:
    sys.exit(__doc__)
exe, scene, out = sys.argv[1:4]
peak_tol, residual_tol = float(sys.argv[4]), float(sys.argv[5])

peak = peak_contact_pressure()
transfer = release_transfer()
residual = peak - transfer * PE
limit = PE - peak  # P_L at the peak's contact pressure
closed_limit = 2 / math.sqrt(3) * YIELD * math.log(B / A)
closed = (1 - transfer) * PE - closed_limit
tresca = (1 - transfer) * PE - YIELD * math.log(B / A)
p_min, k = limit / (1 - transfer), 1 / (1 - transfer)
reverse = max(math.sqrt((sr + dr) ** 2 - (sr + dr) * (st + dt) + (st + dt) ** 2)
              for r, sr, st in fully_plastic_field(peak)
              for dr, dt in [lame(A, B, -PE, -transfer * PE, r)]) / YIELD

summary = converged_run(exe, scene, out, MODEL)
fe_peak = middle_pressure(os.path.join(out, "contact_t1.csv"))
fe_residual = middle_pressure(os.path.join(out, "contact.csv"))
peak_error = abs(fe_peak / peak - 1)
residual_error = abs(fe_residual / residual - 1)
print(f"RESULT model_peak={peak:.4f} fe_peak={fe_peak:.4f} peak_difference={peak_error:.2e} "
      f"model_residual={residual:.4f} fe_residual={fe_residual:.4f} "
      f"residual_difference={residual_error:.2e} T={transfer:.5f} K={k:.4f} Pmin={p_min:.3f} "
      f"P_L={limit:.3f} closed_form_residual={closed:.4f} tresca_residual={tresca:.4f} "
      f"reverse_yield_ratio={reverse:.3f} newton={summary['iterations']['newton']} "
      f"steps={summary['load_steps']['converged']} cuts={summary['load_steps']['cuts']} "
      f"limited_updates={summary['limited_updates']}")
if not reverse < 1:
    sys.exit("FAIL: the model's release is not elastic (reverse yielding): the test is invalid")
if not abs(closed / residual - 1) < 0.01:
    sys.exit("FAIL: the closed form and the integrated limit pressure disagree")
if not (peak_error <= peak_tol and residual_error <= residual_tol):
    sys.exit("FAIL: the expansion differs from the expanded-joint model by more than the bounds")
print("PASS")
