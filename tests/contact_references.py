"""The analytic contact references the checks and the documentation compare against, and the
error measures they report (tests/verification/check_contact.py, doc/doc_blocks.py): Hertz's
line and point contact, Cattaneo-Mindlin's partial slip (line contact) and Mindlin's (point
contact). Rows are contact.csv's."""
import math


def hertz(P, estar, radius, dim):
    """Hertz's contact half-width (radius in 3D) a and peak pressure p0 for the load P: per unit
    length in 2D, a = sqrt(4PR/(pi E*)), p0 = 2P/(pi a); in 3D a = (3PR/(4E*))^(1/3),
    p0 = 3P/(2 pi a^2)."""
    if dim == 2:
        a = math.sqrt(4 * P * radius / (math.pi * estar))
        return a, 2 * P / (math.pi * a)
    a = (3 * P * radius / (4 * estar)) ** (1 / 3)
    return a, 3 * P / (2 * math.pi * a * a)


def contact_radius(row, dim):
    """A point's distance from the contact centre: |x| in 2D, sqrt(x^2 + y^2) in 3D."""
    x = float(row["x"])
    return abs(x) if dim == 2 else math.hypot(x, float(row["y"]))


def hertz_pressure_errors(rows, a, p0, dim):
    """|p - p_H| / p0 at the points: max and rms over r <= 0.9a, max beyond (the edge points),
    and the number of points inside the contact (r < a)."""
    err = edge = sq = 0.0
    n = 0
    for r in rows:
        x = contact_radius(r, dim)
        e = abs(float(r["pressure"]) - p0 * math.sqrt(max(0.0, 1 - (x / a) ** 2))) / p0
        if x <= 0.9 * a:
            err = max(err, e)
            sq += e * e
            n += 1
        else:
            edge = max(edge, e)
    return dict(max=err, rms=math.sqrt(sq / max(n, 1)), edge=edge,
                inside=sum(contact_radius(r, dim) < a for r in rows))


def node_spacing(closed):
    """The median spacing of the closed points along x."""
    xs = sorted(float(r["x"]) for r in closed)
    return sorted(b - x for x, b in zip(xs, xs[1:]))[len(xs) // 2]


def partial_slip_traction(x, a, c):
    """Cattaneo's and Mindlin's shear traction along Q at distance x from the centre, / (mu p0):
    sqrt(1 - x^2/a^2), less (c/a) sqrt(1 - x^2/c^2) inside the stick zone |x| < c (the same
    form for a line contact and a point contact; only c's law differs)."""
    v = math.sqrt(max(0.0, 1 - (x / a) ** 2))
    return v - (c / a) * math.sqrt(1 - (x / c) ** 2) if abs(x) < c else v


def cattaneo_mindlin(closed, P, Q, mu, estar, radius):
    """The 2D partial-slip state of the closed points against Cattaneo-Mindlin for the computed
    P and Q: a, p0, the stick half-width c and the computed one c_fe (half the extent of the
    stick points) with its centre, and the shear traction error |t - q| / (mu p0) over
    |x| <= 0.9c (stick) and over |x| <= 0.9a (all)."""
    a, p0 = hertz(P, estar, radius, 2)
    c = a * math.sqrt(1 - Q / (mu * P))
    stick = [float(r["x"]) for r in closed if int(r["status"]) == 1]
    c_fe = (max(stick) - min(stick)) / 2 if stick else 0.0
    err = inner = 0.0
    for r in closed:
        x = float(r["x"])
        if abs(x) > 0.9 * a:
            continue
        e = abs(abs(float(r["traction_x"])) / (mu * p0) - partial_slip_traction(x, a, c))
        err = max(err, e)
        if abs(x) <= 0.9 * c:
            inner = max(inner, e)
    return dict(a=a, p0=p0, c=c, c_fe=c_fe,
                centre=(max(stick) + min(stick)) / 2 if stick else 0.0,
                stick_error=inner, error=err)


def mindlin_3d(closed, P, Q, mu, estar, radius, bins=4):
    """The 3D partial-slip state of the closed points against Mindlin's for a sphere on a
    similar body under the computed P and the tangential force Q along x (signed: the
    tractions' sign) (Johnson, Contact Mechanics, 1985, section 7.1):
    stick radius c = a (1 - Q/(mu P))^(1/3), shear traction along Q
      q(r) = mu p0 sqrt(1 - r^2/a^2) - mu p0 (c/a) sqrt(1 - r^2/c^2) for r < c,
             mu p0 sqrt(1 - r^2/a^2) for c < r < a.
    The computed stick radius c_fe is the area-equivalent one, a sqrt(stick / closed points);
    the node spacing h = a sqrt(pi / closed points). A nodal traction scatters about q by the
    mesh's noise (on tet4 at a / h = 6: 0.2 mu p0 RMS, as the pressure scatters about Hertz's),
    so the profile is compared ring by ring: the mean traction of the points in each ring of
    width a / BINS that lies within 0.9 c, against the mean of q at the same points; `profile`
    is the largest |difference| / (mu p0)."""
    a, p0 = hertz(P, estar, radius, 3)
    c = a * (1 - abs(Q) / (mu * P)) ** (1 / 3)
    stick = [r for r in closed if int(r["status"]) == 1]
    c_fe = a * math.sqrt(len(stick) / len(closed))
    rings = {}
    for r in closed:
        x = contact_radius(r, 3)
        k = int(x / a * bins)
        if (k + 1) * a / bins <= 0.9 * c:
            t = float(r["traction_x"]) * math.copysign(1.0, Q) / (mu * p0)
            rings.setdefault(k, []).append((t, partial_slip_traction(x, a, c)))
    profile = max(abs(sum(t for t, _ in v) - sum(ref for _, ref in v)) / len(v)
                  for v in rings.values())
    return dict(a=a, p0=p0, c=c, c_fe=c_fe, h=a * math.sqrt(math.pi / len(closed)),
                rings=len(rings), profile=profile)
