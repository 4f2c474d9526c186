"""Force path members: circular plates (Roark), series springs,
circle packing, seals at pressure. Every check is against a hand
calculation or an independent numerical integration written here."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from sizing.physics import seals, structure

E_AL, NU_AL = 68.9e9, 0.33      # 6061-T6 (catalogs/materials.toml, MatWeb)


def w_clamped(r, q, a, D):
    # Roark 7th ed. Table 11.2 case 10b (fixed edge, uniform load), written out here
    return q * (a**2 - r**2) ** 2 / (64 * D)


def w_simply(r, q, a, D, nu):
    # Roark Table 11.2 case 10a (simply supported edge, uniform load)
    return q * (a**2 - r**2) * ((5 + nu) / (1 + nu) * a**2 - r**2) / (64 * D)


def test_centre_deflection_matches_roark_both_edges():
    q, a, t = 1e6, 0.17, 0.054
    D = E_AL * t**3 / (12 * (1 - NU_AL**2))
    assert structure.plate_centre_deflection(q, a, t, E_AL, NU_AL, "clamped") == pytest.approx(w_clamped(0, q, a, D))
    assert structure.plate_centre_deflection(q, a, t, E_AL, NU_AL) == pytest.approx(w_simply(0, q, a, D, NU_AL))


@pytest.mark.parametrize("edge", ["clamped", "simply_supported"])
def test_mean_deflection_by_numerical_integration(edge):
    """Volume swept / plate area, integrated numerically (scipy quad), against
    the closed forms y_c/3 (clamped) and (7+nu)/(3(5+nu)) y_c (simply supported)."""
    q, a, D, nu = 2e6, 0.1, 5e5, NU_AL
    w = (lambda r: w_clamped(r, q, a, D)) if edge == "clamped" else (lambda r: w_simply(r, q, a, D, nu))
    volume, _ = integrate.quad(lambda r: w(r) * 2 * math.pi * r, 0.0, a)
    mean = volume / (math.pi * a**2)
    assert mean / w(0.0) == pytest.approx(float(structure.mean_deflection_factor(nu, edge)), rel=1e-10)
    t = (12 * (1 - nu**2) * D / E_AL) ** (1 / 3)
    k = structure.plate_stiffness(a, t, E_AL, nu, edge, model="kirchhoff")
    assert k == pytest.approx(q * math.pi * a**2 / mean, rel=1e-9)


def test_simply_supported_edge_carries_no_moment():
    """Independent check of the case-10a deflection: the radial moment
    M_r = -D (w'' + nu w'/r) vanishes at the edge, and the plate's shear
    D d/dr(w'' + w'/r) carries the load inside radius r, q pi r^2 / (2 pi r)
    = q r / 2 (equilibrium of a central disc)."""
    q, a, D, nu = 1e6, 0.2, 1e6, 0.3
    h = 1e-5
    w = lambda r: w_simply(r, q, a, D, nu)  # noqa: E731
    d1 = lambda r: (w(r + h) - w(r - h)) / (2 * h)  # noqa: E731
    d2 = lambda r: (w(r + h) - 2 * w(r) + w(r - h)) / h**2  # noqa: E731
    assert abs(d2(a) + nu * d1(a) / a) * D < 1e-6 * q * a**2
    lap = lambda r: d2(r) + d1(r) / r  # noqa: E731
    for r in (0.05, 0.1, 0.15):
        shear = D * (lap(r + 1e-3) - lap(r - 1e-3)) / 2e-3
        assert shear == pytest.approx(q * r / 2, rel=1e-3)


def test_reviewers_end_cap_figures():
    """docs/models.md: a 54 mm aluminium cap over a 340 mm bore is
    3.9e9 N/m simply supported and 2.1e10 N/m clamped. By hand:
    D = 68.9e9 x 0.054^3 / (12 x (1 - 0.33^2)) = 1.0849e7 / 10.693 = 1.0146e6 N m;
    clamped k = 192 pi D / a^2 = 192 pi 1.0146e6 / 0.17^2 = 2.118e10 N/m;
    simply supported k = clamped x (1 + nu) / (7 + nu) = 2.118e10 x 1.33 / 7.33 = 3.84e9 N/m."""
    D = 68.9e9 * 0.054**3 / (12 * (1 - 0.33**2))
    assert D == pytest.approx(1.0146e6, rel=1e-3)
    assert structure.plate_stiffness(0.17, 0.054, E_AL, NU_AL, "clamped", model="kirchhoff") == pytest.approx(2.1e10, rel=0.02)
    assert structure.plate_stiffness(0.17, 0.054, E_AL, NU_AL, model="kirchhoff") == pytest.approx(3.9e9, rel=0.02)


def test_blocked_force_with_the_cap_in_series():
    """The reviewer's first-round best design: 9 x 4.33e8 N/m, 180 um, R 233,
    340 mm bore, 54 mm aluminium cap: 2625 N ideal-with-oil falls to 1400 N
    (cap simply supported) ... 2260 N (clamped). Here the stacks alone: 3006 N;
    with the cap 3.83e9 N/m in series: 3.897e9 x 3.83e9 / 7.73e9 = 1.93e9 N/m."""
    k_s = 9 * 4.33e8
    for edge, expected in (("simply_supported", 3.897e9 * 3.83e9 / (3.897e9 + 3.83e9)),
                           ("clamped", 3.897e9 * 2.11e10 / (3.897e9 + 2.11e10))):
        k = structure.series(k_s, structure.plate_stiffness(0.17, 0.054, E_AL, NU_AL, edge, model="kirchhoff"))
        assert k == pytest.approx(expected, rel=0.01)
    ideal = k_s * 180e-6 / 233
    assert ideal == pytest.approx(3010, rel=1e-3)


def test_series_springs():
    assert structure.series(2.0, 2.0) == pytest.approx(1.0)
    assert structure.series(1.0, 2.0, 2.0) == pytest.approx(0.5)
    assert structure.series(5.0, np.inf) == pytest.approx(5.0)      # an absent member drops out
    assert structure.rod_stiffness(200e9, 1e-4, 0.5) == pytest.approx(4e7)


def test_thickness_rules_invert_stiffness_and_stress():
    t = structure.plate_thickness_for_stiffness(1e10, 0.15, E_AL, NU_AL)
    assert structure.plate_stiffness(0.15, t, E_AL, NU_AL) == pytest.approx(1e10)
    t = structure.plate_thickness_for_stress(2e7, 0.15, 138e6, NU_AL)
    assert structure.plate_stress(2e7, 0.15, t, NU_AL) == pytest.approx(138e6)
    # Roark 10a centre stress by hand: 3 (3.33) / 8 x 1e6 x 0.1^2 / 0.01^2 = 124.9 MPa
    assert structure.plate_stress(1e6, 0.1, 0.01, 0.33) == pytest.approx(124.875e6)


def test_circle_packing_by_hand_geometry():
    # n = 2: side by side, D = 2 d; n = 3: centres on an equilateral triangle of
    # side d, circumradius d / sqrt(3), D = d (1 + 2 / sqrt(3)); n = 4: a square
    # of side d, D = d (1 + sqrt(2)); n = 7: hexagon around one, D = 3 d.
    d = 0.056
    assert structure.packing_diameter(2, d) == pytest.approx(2 * d)
    assert structure.packing_diameter(3, d) == pytest.approx(d * (1 + 2 / math.sqrt(3)), rel=1e-6)
    assert structure.packing_diameter(4, d) == pytest.approx(d * (1 + math.sqrt(2)), rel=1e-6)
    assert structure.packing_diameter(7, d) == pytest.approx(3 * d)
    assert structure.stacks_that_fit(3 * d, d) == 7
    assert structure.stacks_that_fit(2.999 * d, d) == 5
    n = np.arange(1, 40)
    D = structure.packing_diameter(n, d)
    assert np.all(np.diff(D) >= 0)
    assert np.array_equal(structure.stacks_that_fit(D * (1 + 1e-9), d) >= n, np.ones_like(n, dtype=bool))
    # area bound: n circles of diameter d cannot cover more than the big circle, n d^2 <= D^2
    assert np.all(n * d**2 <= D**2 * (1 + 1e-9))


def test_seal_friction_at_pressure_matches_the_review():
    """docs/models.md: at 3.1 MPa (the 1210 N case on the
    first-round best design, 340 mm bore, R 233) an FKM narrow seal runs
    about 99 N instead of 12 N, the wide seal about 1.5 kN instead of 187 N.
    By hand: narrow bore sqrt(0.34^2 / 233) = 22.27 mm, pi d = 0.0700 m;
    175 N/m x 0.0700 = 12.2 N; + 4e-4 x 3.1e6 x 0.0700 = 86.8 N -> 99 N.
    Wide: pi 0.34 = 1.068 m x (175 + 1240) N/m = 1511 N."""
    d_n = 0.34 / math.sqrt(233)
    run, brk = seals.friction_at_pressure(175.0, 4e-4, d_n, 3.1e6, breakaway_ratio=3.0)
    assert float(seals.running_friction(175.0, d_n)) == pytest.approx(12.2, abs=0.1)
    assert run == pytest.approx(99.0, abs=0.5) and brk == pytest.approx(3 * run)
    wide, _ = seals.friction_at_pressure(175.0, 4e-4, 0.34, 3.1e6)
    assert wide == pytest.approx(1511, rel=0.005)
    out = seals.output_seal_force(175.0, 4e-4, 0.34, d_n, 233.0, 3.1e6)
    assert out == pytest.approx(run + wide / 233.0)


def test_surface_tip_equivalent_mass():
    """The hinged 15 x 10 x 1/16 in aluminium surface: m = 2700 x 0.381 x
    0.254 x 1.5875e-3 = 0.415 kg; its inertia about the hinge, integrated
    here strip by strip (int r^2 dm), over the chord squared, is m/3 =
    0.138 kg at the tip (the review's 0.14 kg)."""
    from sizing.physics import load
    b, c, t, rho = 15 * 0.0254, 10 * 0.0254, 0.0625 * 0.0254, 2700.0
    inertia, _ = integrate.quad(lambda r: r**2 * rho * b * t, 0.0, c)
    assert load.tip_equivalent_mass(b, c, t, rho) == pytest.approx(inertia / c**2, rel=1e-12)
    assert load.tip_equivalent_mass(b, c, t) == pytest.approx(0.1383, abs=5e-4)


# --- thick plates: Reissner-Mindlin shear ------------------------------------
def test_mindlin_centre_deflection_ratio_matches_the_published_table():
    """First-order shear deformation, clamped circular plate under uniform
    load: w_M(0) / w_K(0) = 1 + (8/3) (t/a)^2 / (k (1 - nu)) from
    w_M = q a^4/(64 D) + q a^2/(4 k G t). Reddy (Theory and Analysis of
    Elastic Plates and Shells, 2nd ed., axisymmetric FSDT table, nu = 0.3,
    k = 5/6) lists 1.0457 at t/a = 0.1 and 1.1829 at t/a = 0.2."""
    q, a, nu, E = 1e6, 0.1, 0.3, 70e9
    for t_over_a, published in ((0.1, 1.0457), (0.2, 1.1829)):
        t = t_over_a * a
        bending = structure.plate_centre_deflection(q, a, t, E, nu, edge="clamped")
        shear = structure.plate_shear_centre_deflection(q, a, t, E, nu)
        assert (bending + shear) / bending == pytest.approx(published, abs=1e-4)


def test_mindlin_roark_shear_coefficient():
    """Roark 7th ed. sec. 11.12: the shear deflection of a plate under uniform
    load over its whole face is K_sa q a^2 / (t G), K_sa = 0.30, both edges."""
    q, a, t, E, nu = 2e6, 0.12, 0.03, 68.9e9, 0.33
    G = E / (2 * (1 + nu))
    assert structure.plate_shear_centre_deflection(q, a, t, E, nu) == pytest.approx(0.30 * q * a**2 / (t * G), rel=1e-12)


@pytest.mark.parametrize("edge", ["simply_supported", "clamped"])
def test_mindlin_stiffness_by_numerical_integration(edge):
    """The plate's stiffness is q pi a^2 over the mean of w_K(r) + w_s(r),
    w_s = q (a^2 - r^2) / (4 k G t), integrated numerically, below t/a = 0.5."""
    q, a, nu, E = 2e6, 0.1, NU_AL, E_AL
    G = E / (2 * (1 + nu))
    for t_over_a in (0.05, 0.2, 0.45):
        t = t_over_a * a
        D = E * t**3 / (12 * (1 - nu**2))
        wk = (lambda r: w_clamped(r, q, a, D)) if edge == "clamped" else (lambda r: w_simply(r, q, a, D, nu))
        volume, _ = integrate.quad(lambda r: (wk(r) + q * (a**2 - r**2) / (4 * 5 / 6 * G * t)) * 2 * math.pi * r, 0, a)
        k = structure.plate_stiffness(a, t, E, nu, edge)
        assert k == pytest.approx(q * math.pi * a**2 / (volume / (math.pi * a**2)), rel=0.05)
        assert k == pytest.approx(q * math.pi * a**2 / (volume / (math.pi * a**2)), rel=1e-8)


def test_the_reviewers_thick_cap_loses_stiffness_to_shear():
    """PHYSICS-NOTES (third review): at t/a of order one the thin-plate figure
    is far too stiff. At t/a = 1.2 the shear term is, by hand,
    (1/(8 pi k G t)) / (c a^2 / D) = D / (8 pi k G t c a^2) with
    c = (7+nu)/(192 pi (1+nu)), which reduces to
    (t/a)^2 4 (1+nu) / (k (1-nu) (7+nu)) = 1.44 x 5.32 / 4.0925 = 1.872 for
    6061-T6 (nu 0.33): the shear compliance outweighs the bending one."""
    a, E, nu = 0.1, E_AL, NU_AL
    t = 1.2 * a
    k_thin = structure.plate_stiffness(a, t, E, nu, model="kirchhoff")
    k_thick = structure.plate_stiffness(a, t, E, nu)
    D = E * t**3 / (12 * (1 - nu**2))
    c = (7 + nu) / (192 * math.pi * (1 + nu))
    ratio = (D / (8 * math.pi * 5 / 6 * E / (2 * (1 + nu)) * t)) / (c * a**2)
    assert k_thin / k_thick == pytest.approx(1 + ratio, rel=1e-9)
    assert ratio == pytest.approx(1.872, rel=1e-3)
    assert not structure.plate_in_range(t, a) and structure.plate_in_range(0.5 * a, a)


def test_mindlin_thickness_rule_inverts_the_stiffness():
    for k in (1e8, 1e10, 1e12):
        t = structure.plate_thickness_for_stiffness(k, 0.15, E_AL, NU_AL)
        assert structure.plate_stiffness(0.15, t, E_AL, NU_AL) == pytest.approx(k, rel=1e-9)
        assert t > structure.plate_thickness_for_stiffness(k, 0.15, E_AL, NU_AL, model="kirchhoff")
