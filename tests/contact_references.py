"""The analytic contact references the checks and the documentation compare against, and the
error measures they report (tests/verification/check_contact.py, doc/doc_blocks.py): Hertz's
line and point contact, Cattaneo-Mindlin's partial slip. Rows are contact.csv's."""
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
        q = mu * p0 * math.sqrt(max(0.0, 1 - (x / a) ** 2))
        if abs(x) < c:
            q -= mu * p0 * (c / a) * math.sqrt(1 - (x / c) ** 2)
        e = abs(abs(float(r["traction_x"])) - q) / (mu * p0)
        err = max(err, e)
        if abs(x) <= 0.9 * c:
            inner = max(inner, e)
    return dict(a=a, p0=p0, c=c, c_fe=c_fe,
                centre=(max(stick) + min(stick)) / 2 if stick else 0.0,
                stick_error=inner, error=err)
