"""Hydraulic fluid properties against temperature.

Viscosity: ASTM D341 (Walther) through the catalog's 40 and 100 degC
kinematic viscosities: log10(log10(nu + 0.7)) = A - B log10(T), nu in cSt,
T in K. Bulk modulus falls linearly with temperature at the catalog's
fractional coefficient. Entrained air lowers the effective bulk modulus
(Wood's mixture rule for a gas fraction at pressure p).
"""
from __future__ import annotations

import numpy as np

KELVIN = 273.15


def walther_coefficients(nu40_m2s, nu100_m2s):
    """A, B of ASTM D341 from two kinematic viscosities (m^2/s)."""
    z40 = np.log10(np.log10(np.asarray(nu40_m2s) * 1e6 + 0.7))
    z100 = np.log10(np.log10(np.asarray(nu100_m2s) * 1e6 + 0.7))
    t40, t100 = np.log10(40 + KELVIN), np.log10(100 + KELVIN)
    B = (z40 - z100) / (t100 - t40)
    A = z40 + B * t40
    return A, B


def kinematic_viscosity(nu40_m2s, nu100_m2s, temperature_degC):
    """Kinematic viscosity at temperature (m^2/s), ASTM D341."""
    A, B = walther_coefficients(nu40_m2s, nu100_m2s)
    z = A - B * np.log10(np.asarray(temperature_degC) + KELVIN)
    return (10 ** (10 ** z) - 0.7) * 1e-6


def bulk_modulus_at(bulk_modulus, coefficient, temperature_degC, reference_degC=25.0):
    """Bulk modulus at temperature: linear fractional change per K (Pa)."""
    factor = 1.0 + np.asarray(coefficient) * (np.asarray(temperature_degC) - reference_degC)
    return np.asarray(bulk_modulus) * np.maximum(factor, 0.05)


def density_at(density_15C, thermal_expansion, temperature_degC):
    """Density at temperature from volumetric expansion (kg/m^3)."""
    return np.asarray(density_15C) / (1.0 + np.asarray(thermal_expansion) * (np.asarray(temperature_degC) - 15.0))


def effective_bulk_modulus(bulk_modulus, air_fraction, pressure, polytropic=1.4):
    """Oil with a free-air volume fraction at absolute pressure p (Pa):
    1/beta_e = (1-a)/beta + a/(kappa p). Ten percent of the oil's modulus is
    reached with well under 1% air at a few bar (docs/models.md)."""
    a = np.asarray(air_fraction)
    gas = polytropic * np.maximum(np.asarray(pressure), 1e3)
    return 1.0 / ((1.0 - a) / np.asarray(bulk_modulus) + a / gas)
