"""Columns, tubes, bearings and clevises of the DC structure
(physics/column.py, physics/bearing.py, physics/clevis.py) against hand
computations."""
import math

import numpy as np
import pytest

from sizing.physics import bearing, clevis, column


def test_euler_column_hand_computed():
    """Solid 10 mm steel bar (E 200 GPa, S_y 250 MPa), 0.5 m, pinned:
    r = d/4 = 2.5 mm, s = 200 > s_1 = sqrt(2 pi^2 200e9 / 250e6) = 125.7;
    P = pi^2 E I / L^2 = 3875.8 N (the screw test's figure, Shigley eq. 4-43)."""
    A, r = column.tube_area(0.01, 0.0), column.tube_radius_of_gyration(0.01, 0.0)
    assert r == pytest.approx(0.0025)
    assert column.transition_slenderness(200e9, 250e6) == pytest.approx(125.66, rel=1e-4)
    P = column.critical_load(200e9, 250e6, A, r, 0.5, 1.0)
    assert P == pytest.approx(3875.8, rel=1e-4)
    # fixed-free: K = 2, a quarter
    assert column.critical_load(200e9, 250e6, A, r, 0.5, column.END_FIXITY["fixed-free"]) == pytest.approx(P / 4)


def test_johnson_column_hand_computed():
    """The same bar 0.1 m long: s = 40 < 125.7, Johnson (Shigley eq. 4-48):
    P = A (S_y - (S_y s / 2 pi)^2 / E) = 7.854e-5 (250e6 - (250e6 x 40 / 2 pi)^2 / 200e9)
      = 7.854e-5 x (250e6 - 12.665e6) = 18640 N."""
    A, r = column.tube_area(0.01, 0.0), column.tube_radius_of_gyration(0.01, 0.0)
    P = column.critical_load(200e9, 250e6, A, r, 0.1, 1.0)
    assert P == pytest.approx(math.pi * 0.01**2 / 4 * (250e6 - (250e6 * 40 / (2 * math.pi)) ** 2 / 200e9), rel=1e-9)
    assert P == pytest.approx(18640, rel=1e-3)
    # below the yield load, and the two curves meet at the transition (tangent there)
    assert P < A * 250e6
    s1 = column.transition_slenderness(200e9, 250e6)
    L1 = s1 * r
    just_below = column.critical_load(200e9, 250e6, A, r, L1 * (1 - 1e-9), 1.0)
    assert just_below == pytest.approx(math.pi**2 * 200e9 * A / s1**2, rel=1e-6)
    assert just_below == pytest.approx(A * 250e6 / 2, rel=1e-6)     # Johnson at s_1 is half the yield load


def test_tube_section_and_stresses_hand_computed():
    """Tube 30 x 26 mm: A = pi (900 - 676) / 4 mm^2 = 175.93 mm^2,
    I = pi (810000 - 456976) / 64 mm^4 = 17329 mm^4 (Roark table A.1).
    1 kN with 1 mm eccentricity: 1000 / 175.93e-6 + 1000 x 1e-3 x 15e-3 / 17329e-12
    = 5.684 + 0.8655 MPa. Hoop stress at 1 MPa: p d / 2 t = 1e6 x 26 / 4 = 6.5 MPa."""
    assert column.tube_area(0.030, 0.026) == pytest.approx(175.929e-6, rel=1e-5)
    assert column.tube_second_moment(0.030, 0.026) == pytest.approx(17329.0e-12, rel=1e-4)
    assert column.bending_stress(1.0, 0.030, 0.026) == pytest.approx(0.015 / 17329.0e-12, rel=1e-4)
    assert column.eccentric_stress(1000.0, 1e-3, 0.030, 0.026) == pytest.approx(5.684e6 + 0.8655e6, rel=1e-3)
    assert column.hoop_stress(1e6, 0.026, 0.002) == pytest.approx(6.5e6)
    # r^2 = I / A
    assert column.tube_radius_of_gyration(0.03, 0.026) ** 2 == pytest.approx(
        column.tube_second_moment(0.03, 0.026) / column.tube_area(0.03, 0.026))


def test_smallest_outer_diameter_inverts_the_euler_load():
    """Solid bar as a pinned Euler column: d = (64 P L^2 / (pi^3 E))^(1/4)."""
    P, L, E = np.array([500.0, 2000.0]), 0.6, 200e9
    cap = lambda D: column.critical_load(E, 250e6, column.tube_area(D, 0.0),
                                         column.tube_radius_of_gyration(D, 0.0), L, 1.0)
    d = column.smallest_outer_diameter(cap, P, 0.0, 1e-3, 0.1)
    assert d == pytest.approx((64 * P * L**2 / (math.pi**3 * E)) ** 0.25, rel=1e-6)
    # a floor that already carries the load is kept
    assert column.smallest_outer_diameter(cap, P, 0.0, 0.05, 0.1) == pytest.approx([0.05, 0.05])


def test_bearing_l10_hand_computed():
    """ISO 281: 40 degree bearing, C = 7.02 kN, pure axial 1 kN:
    P = 0.57 x 1000 = 570 N, L10 = (7020 / 570)^3 10^6 = 1.868e9 rev; at
    10 rev/s, 51 890 h. Static: P0 = 0.26 x 1000, s0 = 3350 / 260 = 12.9."""
    assert bearing.equivalent_load(1000.0) == pytest.approx(570.0)
    assert bearing.l10_revolutions(7020.0, 570.0) == pytest.approx((7020 / 570) ** 3 * 1e6)
    assert bearing.l10_hours(7020.0, 1000.0, 10.0) == pytest.approx((7020 / 570) ** 3 * 1e6 / 36000, rel=1e-9)
    assert bearing.l10_hours(7020.0, 1000.0, 10.0) == pytest.approx(51890, rel=1e-3)
    assert bearing.static_safety(3350.0, 1000.0) == pytest.approx(3350 / 260)
    # a radial load only: P0 is at least F_r
    assert bearing.static_equivalent_load(0.0, 100.0) == pytest.approx(100.0)


def test_clevis_pin_and_eye_hand_computed():
    """10 kN on a 4340 pin (S_y 834 MPa) in double shear: tau = 481.5 MPa,
    d = sqrt(2 x 1e4 / (pi x 481.5e6)) = 3.636 mm; the eye at that pin bears
    F / (d S_y) = 3.298 mm."""
    d = clevis.pin_diameter(1e4, 834e6)
    assert d == pytest.approx(math.sqrt(2e4 / (math.pi * 834e6 / math.sqrt(3))), rel=1e-12)
    assert d == pytest.approx(3.636e-3, rel=1e-3)
    assert clevis.pin_shear_stress(1e4, d) == pytest.approx(834e6 / math.sqrt(3))
    t = clevis.eye_thickness(1e4, d, 834e6)
    assert t == pytest.approx(1e4 / (d * 834e6))
    # the fitting's volume: lugs of total 2 t, 2d x 2d less the hole, plus the pin
    assert clevis.fitting_volume(0.01, 0.005) == pytest.approx(
        2 * 0.005 * (0.02**2 - math.pi / 4 * 1e-4) + math.pi / 4 * 1e-4 * 0.01)


def test_clevis_pin_bending_hand_computed():
    """At the eye thickness t = F / (d S_y) the pin's moment F t / 4 gives
    sigma = 8 F^2 / (pi d^4 S_y): at d = (8/pi)^(1/4) sqrt(F / S_y) it is S_y.
    10 kN, 834 MPa: d = 1.2633 x 3.4627 mm = 4.374 mm, above shear's 3.636 mm."""
    F, Sy = 1e4, 834e6
    d = clevis.pin_bending_diameter(F, Sy)
    assert d == pytest.approx((8 / math.pi) ** 0.25 * math.sqrt(F / Sy))
    assert d == pytest.approx(4.374e-3, rel=1e-3)
    assert d > clevis.pin_diameter(F, Sy)
    t = clevis.eye_thickness(F, d, Sy)
    assert clevis.pin_bending_stress(F, d, t) == pytest.approx(Sy, rel=1e-9)
