"""Members in compression and bending: columns (Euler, Johnson), tubes.

Column (Shigley, Mechanical Engineering Design, 9th ed., sec. 4-11 to 4-13):
a column of area A, radius of gyration r, length L and effective-length
factor K (end conditions: ``END_FIXITY``) has the slenderness s = K L / r.
Above the transition slenderness s_1 = sqrt(2 pi^2 E / S_y) it buckles
elastically (Euler, Shigley eq. 4-43):

    P_cr = pi^2 E A / s^2

and below it the parabola of J. B. Johnson (Shigley eq. 4-48), tangent to
Euler's curve at s_1 and equal to the yield load at s = 0:

    P_cr = A (S_y - (S_y s / (2 pi))^2 / E)

For steel (E 205 GPa, S_y 250-834 MPa) s_1 is 126 to 70: "Johnson below a
slenderness of about 100".

Thin- and thick-walled tube (Roark, Formulas for Stress and Strain, 7th ed.,
table A.1 and sec. 8): outer diameter D, bore d,
A = pi (D^2 - d^2) / 4, I = pi (D^4 - d^4) / 64, r = sqrt(I / A),
bending stress at the outer fibre sigma_b = M (D / 2) / I; under an axial
force P applied with an eccentricity e the outer fibre carries
P / A + P e (D / 2) / I (the secant formula's first term, Shigley eq. 4-51,
exact while P << P_cr). Hoop stress of a thin tube under internal pressure
p: sigma_h = p d / (2 t) (Roark table 13.1 case 1b).

Vectorised over candidates; SI (m, N, Pa).
"""
from __future__ import annotations

import numpy as np

# effective-length factor K (theoretical values, Shigley table 4-2)
END_FIXITY = {"fixed-free": 2.0, "pinned-pinned": 1.0, "fixed-pinned": 0.7, "fixed-fixed": 0.5}


def tube_area(outer, bore):
    """Section area of a tube (m^2); bore 0 is a solid bar."""
    return np.pi / 4 * (np.asarray(outer) ** 2 - np.asarray(bore) ** 2)


def tube_second_moment(outer, bore):
    """Second moment of area about a diameter (m^4)."""
    return np.pi / 64 * (np.asarray(outer) ** 4 - np.asarray(bore) ** 4)


def tube_radius_of_gyration(outer, bore):
    """r = sqrt(I / A) = sqrt(D^2 + d^2) / 4 (m)."""
    return np.sqrt(np.asarray(outer) ** 2 + np.asarray(bore) ** 2) / 4.0


def transition_slenderness(elastic_modulus, yield_strength):
    """s_1 = sqrt(2 pi^2 E / S_y): Euler above, Johnson below (-)."""
    return np.sqrt(2 * np.pi**2 * np.asarray(elastic_modulus) / np.asarray(yield_strength))


def critical_load(elastic_modulus, yield_strength, area, radius_of_gyration, length, k=1.0):
    """Critical load of a column (N): Euler above the transition slenderness,
    Johnson below. ``k`` is the effective-length factor (``END_FIXITY``)."""
    E, Sy, A = (np.asarray(x, float) for x in (elastic_modulus, yield_strength, area))
    s = np.asarray(k) * np.asarray(length) / np.asarray(radius_of_gyration)
    euler = np.pi**2 * E * A / np.maximum(s, 1e-12) ** 2
    johnson = A * (Sy - (Sy * s / (2 * np.pi)) ** 2 / E)
    return np.where(s >= transition_slenderness(E, Sy), euler, johnson)


def eccentric_stress(force, eccentricity, outer, bore):
    """Outer-fibre stress (Pa) of a tube under an axial force applied with
    an eccentricity: P / A + P e (D / 2) / I."""
    P = np.abs(np.asarray(force, float))
    return P / tube_area(outer, bore) + bending_stress(P * np.asarray(eccentricity), outer, bore)


def bending_stress(moment, outer, bore):
    """Outer-fibre bending stress (Pa) of a tube under a moment: M (D/2) / I."""
    return np.asarray(moment) * np.asarray(outer) / 2 / tube_second_moment(outer, bore)


def hoop_stress(pressure, bore, wall):
    """Hoop stress (Pa) of a thin tube under internal pressure: p d / (2 t)."""
    return np.asarray(pressure) * np.asarray(bore) / (2 * np.asarray(wall))


def smallest_outer_diameter(capacity, need, bore, lowest, highest, iterations=60):
    """The smallest outer diameter D in [lowest, highest] with
    ``capacity(D) >= need`` (capacity rising with D), by bisection over the
    arrays; ``highest`` where even it falls short (the caller checks)."""
    lo = np.broadcast_to(np.asarray(lowest, float), np.broadcast(lowest, need, bore).shape).copy()
    hi = np.broadcast_to(np.asarray(highest, float), lo.shape).copy()
    ok_lo = capacity(lo) >= need
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        good = capacity(mid) >= need
        hi = np.where(good, mid, hi)
        lo = np.where(good, lo, mid)
    return np.where(ok_lo, np.asarray(lowest, float) + 0 * lo, hi)
