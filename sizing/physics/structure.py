"""The force path of a piezohydraulic actuator: plates, frame, packing.

Every member between the stacks and the output is a spring in series
(docs/formats.md, ``force_path``); stiffness is referred to the
wide piston (force on the wide piston / its volume-equivalent displacement).

End caps (Roark, Formulas for Stress and Strain, 7th ed., Table 11.2, cases
10a simply supported and 10b fixed edge, uniform pressure q over the whole
plate, radius a, thickness t, D = E t^3 / (12 (1 - nu^2))):

    clamped:            w(r) = q (a^2 - r^2)^2 / (64 D),     y_c = q a^4 / (64 D)
    simply supported:   w(r) = q (a^2 - r^2) ((5+nu)/(1+nu) a^2 - r^2) / (64 D),
                        y_c = (5+nu) q a^4 / (64 D (1+nu))

For the oil what counts is the volume the plate sweeps, so the stiffness is
the force q pi a^2 over the *mean* deflection (volume / pi a^2). Integrating
w(r) 2 pi r dr over the plate (derivation in tests/physics/test_structure.py):

    clamped:            w_mean = y_c / 3             = q a^4 / (192 D)
    simply supported:   w_mean = (7+nu)/(3 (5+nu)) y_c = (7+nu) q a^4 / (192 D (1+nu))

so k = 192 pi D / a^2 (clamped) and 192 pi D (1+nu) / ((7+nu) a^2)
(simply supported). A bolted cap lies between the two; the verdict uses
the simply supported value (the softer, conservative one) and the clamped
value is reported beside it.

Shear (Reissner-Mindlin, first-order shear deformation): for an
axisymmetric circular plate under uniform pressure the shear deflection
adds, for both edge conditions, w_s(r) = q (a^2 - r^2) / (4 k G t), k = 5/6,
G = E / (2 (1 + nu)) (Reddy, Theory and Analysis of Elastic Plates and
Shells, 2nd ed., sec. 3.x, the Kirchhoff-Mindlin relation w_M = w_K +
M_K / (k G t); Ike, Math. Models Eng. 4(2) 2018, doi 10.21595/mme.2018.19825;
Roark 7th ed. sec. 11.12 gives the same centre value, K_sa = 0.30 = 1/(4 k)).
Its mean over the plate is q a^2 / (8 k G t), so its compliance, referred
to a piston of the plate's area, is 1 / (8 pi k G t), independent of a.
Validity: the model is used up to t/a = MINDLIN_MAX_THICKNESS_RATIO; a
thicker "plate" is a block, not a plate, and a member sized beyond it is
ruled out (``structure_out_of_range``).

Stress: the simply supported plate peaks at its centre,
sigma = 3 (3+nu) q a^2 / (8 t^2) (Roark 10a); the clamped one at its edge,
3 q a^2 / (4 t^2) (Roark 10b), which is smaller for any nu >= 0, so the
simply supported centre is the envelope used to size for stress.

Frame: tie rods of total section A_f and length L_f in tension, k = E A_f / L_f.

Stack packing: the smallest circle holding n equal circles (best known
packings, E. Specht, packomania.com, after Graham, Lubachevsky et al.,
Discrete Math. 181 (1998) 139-154), ratio D/d for n = 1..20; beyond 20 the
hexagonal-density bound D/d = 1 + sqrt(n / 0.9069) * 1.05 is used (assumed:
5 % above the density limit, covers the tabulated n = 20 value).

Everything is plain arithmetic on numpy arrays (or on cvxpy expressions,
where a function is a monomial), SI units.
"""
from __future__ import annotations

import math

import numpy as np

EDGES = ("simply_supported", "clamped", "flange")
SHEAR_CORRECTION = 5.0 / 6.0        # k of first-order shear deformation (Reissner, Mindlin)
MINDLIN_MAX_THICKNESS_RATIO = 0.5   # t/a: thickness over radius up to which a plate is a plate here
PLATE_MODEL = "mindlin"

# D/d of the smallest circle holding n unit circles, n = 1..20 (packomania).
PACKING_RATIO = (1.0, 2.0, 2.1547005, 2.4142136, 2.7013016, 3.0, 3.0, 3.3047649, 3.6131259,
                 3.8130256, 3.9238044, 4.0296019, 4.2360680, 4.3284285, 4.5213558, 4.6154256,
                 4.7920337, 4.8637033, 4.8637033, 5.1223207)
HEX_DENSITY = math.pi / (2 * math.sqrt(3))      # 0.9069, densest packing of the plane


def flexural_rigidity(E, t, nu):
    """D = E t^3 / (12 (1 - nu^2)), N m."""
    return np.asarray(E) * np.asarray(t) ** 3 / (12.0 * (1.0 - np.asarray(nu) ** 2))


def plate_centre_deflection(q, a, t, E, nu, edge="simply_supported"):
    """Centre deflection of a circular plate under uniform pressure q (m), Roark 10a/10b."""
    D = flexural_rigidity(E, t, nu)
    y = np.asarray(q) * np.asarray(a) ** 4 / (64.0 * D)
    if edge == "clamped":
        return y
    return y * (5.0 + np.asarray(nu)) / (1.0 + np.asarray(nu))


def mean_deflection_factor(nu, edge="simply_supported"):
    """w_mean / y_centre: 1/3 clamped, (7+nu)/(3 (5+nu)) simply supported."""
    if edge == "clamped":
        return np.full_like(np.asarray(nu, dtype=float), 1.0 / 3.0)
    nu = np.asarray(nu, dtype=float)
    return (7.0 + nu) / (3.0 * (5.0 + nu))


def edge_restraint(edge, restraint=None):
    """The edge's rotational restraint beta = k_theta a / D: 0 simply
    supported, inf clamped, the stated ``restraint`` for a flange."""
    if edge == "clamped":
        return np.inf
    if edge == "flange":
        if restraint is None:
            raise ValueError("a flange edge needs its rotational restraint k_theta a / D")
        return restraint
    if edge != "simply_supported":
        raise ValueError(f"unknown plate edge {edge!r}: one of {', '.join(EDGES)}")
    return 0.0


def edge_name(restraint) -> str:
    """The edge a restraint beta stands for."""
    return "simply_supported" if restraint == 0 else "clamped" if math.isinf(restraint) else "flange"


def plate_compliance_factor(nu, edge="simply_supported", restraint=None):
    """c in 1/k = c a^2 / D: (7+nu)/(192 pi (1+nu)) simply supported,
    1/(192 pi) clamped, from k = q pi a^2 / w_mean. An edge held by a
    rotational spring k_theta = beta D / a (a bolted flange whose stiffness
    grows with the plate's own, stated as beta) carries the edge moment
    M_r(a) = k_theta w'(a): with w = q r^4 / (64 D) + C1 r^2 + C2,
    C1 = -q a^2 (beta + 3 + nu) / (32 D (1 + nu + beta)), and the mean
    deflection is q a^4 / D ((beta + 3 + nu) / (64 (1 + nu + beta)) - 1/96):
    the simply supported value at beta = 0, the clamped one as beta -> inf
    (derived in tests/physics/test_plate_edges.py)."""
    nu = np.asarray(nu, dtype=float)
    beta = np.asarray(edge_restraint(edge, restraint), dtype=float)
    finite = np.where(np.isinf(beta), 0.0, beta)
    share = np.where(np.isinf(beta), 1.0, (finite + 3.0 + nu) / (1.0 + nu + finite))
    return (share / 64.0 - 1.0 / 96.0) / math.pi


def shear_modulus(E, nu):
    """G = E / (2 (1 + nu)), Pa."""
    return np.asarray(E) / (2.0 * (1.0 + np.asarray(nu)))


def plate_shear_compliance(t, E, nu):
    """Mindlin shear compliance of a circular plate under uniform pressure,
    referred to a piston of its own area: 1 / (8 pi k G t), m/N."""
    return 1.0 / (8.0 * math.pi * SHEAR_CORRECTION * shear_modulus(E, nu) * np.asarray(t))


def plate_shear_centre_deflection(q, a, t, E, nu):
    """Centre shear deflection q a^2 / (4 k G t), m (both edge conditions)."""
    return np.asarray(q) * np.asarray(a) ** 2 / (4.0 * SHEAR_CORRECTION * shear_modulus(E, nu) * np.asarray(t))


def plate_stiffness(a, t, E, nu, edge="simply_supported", model=PLATE_MODEL, restraint=None):
    """Stiffness of a circular plate under uniform pressure, referred to a
    piston of the plate's own area: force / volume-equivalent displacement
    (N/m). ``model``: "mindlin" (bending plus shear) or "kirchhoff" (bending);
    ``restraint``: a flange's beta (``plate_compliance_factor``)."""
    bending = plate_compliance_factor(nu, edge, restraint) * np.asarray(a) ** 2 / flexural_rigidity(E, t, nu)
    shear = plate_shear_compliance(t, E, nu) if model == "mindlin" else 0.0
    return 1.0 / (bending + shear)


def thickness_ratio(t, a):
    """t / a of a circular plate."""
    return np.asarray(t, dtype=float) / np.asarray(a, dtype=float)


def plate_in_range(t, a):
    """True where the plate is inside the validity of the plate model."""
    return thickness_ratio(t, a) <= MINDLIN_MAX_THICKNESS_RATIO * (1.0 + 1e-5)   # the sizer's tolerance


def plate_stress(q, a, t, nu):
    """Peak bending stress, simply supported centre (the envelope of both
    edge conditions): 3 (3+nu) q a^2 / (8 t^2), Pa."""
    return 3.0 * (3.0 + np.asarray(nu)) / 8.0 * np.asarray(q) * np.asarray(a) ** 2 / np.asarray(t) ** 2


def plate_thickness_for_stiffness(k, a, E, nu, edge="simply_supported", model=PLATE_MODEL, restraint=None):
    """Thickness that gives stiffness k (N/m) to a plate of radius a (m).
    With shear, 1/k = P u^3 + Q u in u = 1/t: a depressed cubic with one
    real root (Cardano), P the bending and Q the shear coefficient."""
    P = plate_compliance_factor(nu, edge, restraint) * np.asarray(a) ** 2 * 12.0 * (1.0 - np.asarray(nu) ** 2) / np.asarray(E)
    k = np.asarray(k, dtype=float)
    if model != "mindlin":
        return (P * k) ** (1.0 / 3.0)
    K = 1.0 / np.where(k > 0, k, 1.0)
    Q = plate_shear_compliance(1.0, E, nu)
    half = K / (2.0 * P)
    root = np.sqrt(half**2 + (Q / (3.0 * P)) ** 3)
    u = np.cbrt(half + root) + np.cbrt(half - root)
    return np.where(k > 0, 1.0 / u, 0.0)          # no stiffness asked: no thickness


def plate_thickness_for_stress(q, a, allowable, nu):
    """Thickness that keeps the plate's peak stress at ``allowable`` (m)."""
    return np.asarray(a) * np.sqrt(3.0 * (3.0 + np.asarray(nu)) / 8.0 * np.asarray(q) / np.asarray(allowable))


def rod_stiffness(E, area, length):
    """Axial stiffness E A / L of a bar or a set of tie rods (N/m)."""
    return np.asarray(E) * np.asarray(area) / np.asarray(length)


def series(*stiffnesses):
    """Springs in series: 1 / sum(1 / k_i). Infinite members drop out."""
    compliance = sum(1.0 / np.asarray(k, dtype=float) for k in stiffnesses)
    return 1.0 / compliance


def packing_ratio(n):
    """D/d of the smallest circle that holds n circles of diameter d."""
    n = np.asarray(n, dtype=int)
    table = np.asarray(PACKING_RATIO)
    beyond = 1.0 + 1.05 * np.sqrt(np.maximum(n, 1) / HEX_DENSITY)
    return np.where(n <= len(table), table[np.clip(n, 1, len(table)) - 1], beyond)


def packing_diameter(n, stack_diameter, spacing=0.0):
    """Bore needed to place n stacks of ``stack_diameter`` with ``spacing``
    between neighbours (m): D/d (d + spacing)."""
    return packing_ratio(n) * (np.asarray(stack_diameter) + np.asarray(spacing))


def stacks_that_fit(bore, stack_diameter, spacing=0.0):
    """How many stacks fit under a piston of diameter ``bore`` (count)."""
    ratio = np.asarray(bore, dtype=float) / (np.asarray(stack_diameter) + np.asarray(spacing))
    table = np.asarray(PACKING_RATIO)
    n_table = np.searchsorted(table, ratio + 1e-9, side="right")
    # beyond the table: invert the density bound
    n_beyond = np.floor(HEX_DENSITY * ((ratio - 1.0) / 1.05) ** 2 + 1e-9).astype(int)
    return np.where(ratio >= table[-1], np.maximum(n_beyond, len(table)), n_table)


def overhang_volume(a, b, t, E, nu):
    """Volume a piston plate sweeps per pascal where it overhangs the stacks
    that carry it, m^3/Pa: stacks packed within radius b push a plate of
    radius a loaded by the oil over its whole face, so the ring b < r < a
    bends as a cantilever strip of length L = a - b (Timoshenko: bending
    x^2 (6 L^2 - 4 L x + x^2) / (24 D) and shear (L x - x^2 / 2) / (k G t)
    per unit pressure at x from the stacks; the hoop stiffening of the ring
    is left out, which errs soft). Integrated over 2 pi (b + x) dx:
    2 pi / (24 D) (6/5 b L^5 + 13/15 L^6) + 2 pi / (k G t) (b L^3 / 3 + 5 L^4 / 24).
    Inside the packing the stacks' reactions meet the pressure where it
    acts, and the plate between them is left out."""
    L = np.maximum(np.asarray(a, float) - np.asarray(b, float), 0.0)
    b = np.asarray(b, float)
    D = flexural_rigidity(E, t, nu)
    kGt = SHEAR_CORRECTION * shear_modulus(E, nu) * np.asarray(t)
    bending = 2 * np.pi / (24 * D) * (1.2 * b * L**5 + 13.0 / 15.0 * L**6)
    shear = 2 * np.pi / kGt * (b * L**3 / 3 + 5 * L**4 / 24)
    return bending + shear
