"""Hydraulic stroke amplifier: static figures (seed eqs. 4-10, corrected).

Mass conservation through the narrowing (eqs. 4-5): y = R x, R = A_w / A_n.
Pascal's principle at rest (eq. 10 without flow): F_wide = R F_narrow.
Added here (docs/models.md): the oil column is a spring beta A_w^2 / V in
series with the stacks; the output mass is reflected to the stacks by R^2.
Flow loss (eq. 8) is direction-aware: a sudden contraction on extension and a
Borda-Carnot expansion on return.
"""
from __future__ import annotations

import numpy as np


def area(diameter):
    return np.pi * np.asarray(diameter) ** 2 / 4.0


def area_ratio(wide_diameter, narrow_diameter):
    """R = A_wide / A_narrow from the two bores (eq. 5)."""
    return (np.asarray(wide_diameter) / np.asarray(narrow_diameter)) ** 2


def contraction_loss_coefficient(ratio):
    """Sharp-edged sudden contraction, referred to the narrow velocity:
    K = 0.5 (1 - 1/R) (Weisbach's fit, as in Idelchik / the seed's ref. 19)."""
    return 0.5 * (1.0 - 1.0 / np.asarray(ratio))


def expansion_loss_coefficient(ratio):
    """Borda-Carnot sudden expansion, referred to the narrow velocity:
    K = (1 - 1/R)^2."""
    return (1.0 - 1.0 / np.asarray(ratio)) ** 2


def pressure_drop(narrow_velocity, density, ratio, k_contract, k_expand):
    """p_wide - p_narrow for flow at narrow-piston velocity u (Pa), eq. 8-9
    with u|u| (docs/models.md, corrections to the seed, item 5) so that on return the loss resists the
    motion, and the loss coefficient of the flow's own direction."""
    u = np.asarray(narrow_velocity)
    k = np.where(u >= 0.0, k_contract, k_expand)
    return 0.5 * np.asarray(density) * u * np.abs(u) * ((1.0 - 1.0 / np.asarray(ratio) ** 2) + k)


def fluid_stiffness(bulk_modulus, wide_area, oil_volume):
    """Oil column stiffness felt by the wide piston, beta A_w^2 / V (N/m)."""
    return np.asarray(bulk_modulus) * np.asarray(wide_area) ** 2 / np.asarray(oil_volume)


def series(k1, k2):
    k1, k2 = np.asarray(k1, float), np.asarray(k2, float)
    return k1 * k2 / (k1 + k2)


def static_figures(n_stacks, stack_stiffness, stack_free_stroke, ratio,
                   wide_area=None, oil_volume=None, bulk_modulus=None,
                   wide_mass=0.0, narrow_mass=0.0):
    """Static figures of a piezohydraulic actuator, vectorised over candidates.

    n_stacks, stack_stiffness (N/m), stack_free_stroke (m, per stack at the
    drive voltage), ratio (-). With wide_area (m^2), oil_volume (m^3) and
    bulk_modulus (Pa) the fluid spring is included in the compliant figures.
    Returns a dict of arrays, SI.
    """
    k_stacks = np.asarray(n_stacks) * np.asarray(stack_stiffness, float)
    x = np.asarray(stack_free_stroke, float)
    R = np.asarray(ratio, float)
    out = {
        "free_stroke_m": R * x,
        "blocked_force_N": k_stacks * x / R,
        "stack_force_N": k_stacks * x,
        "output_stiffness_N_m": k_stacks / R**2,
        "work_J": k_stacks * x**2,
    }
    k_wide = k_stacks
    if wide_area is not None:
        out["blocked_pressure_Pa"] = k_stacks * x / np.asarray(wide_area)
        if oil_volume is not None and bulk_modulus is not None:
            k_fluid = fluid_stiffness(bulk_modulus, wide_area, oil_volume)
            k_wide = series(k_stacks, k_fluid)
            out["fluid_stiffness_N_m"] = k_fluid
            out["compliance_force_fraction"] = k_wide / k_stacks
            out["blocked_force_compliant_N"] = k_wide * x / R
            out["blocked_pressure_Pa"] = k_wide * x / np.asarray(wide_area)
            out["output_stiffness_N_m"] = k_wide / R**2
    reflected = np.asarray(wide_mass) + R**2 * np.asarray(narrow_mass)
    with np.errstate(divide="ignore"):
        out["natural_frequency_Hz"] = np.sqrt(k_wide / reflected) / (2 * np.pi)
    out["reflected_mass_kg"] = reflected
    return out
