"""Aerodynamic load of the hinged control surface (seed Figure 7).

A flat plate of span b and chord c, hinged at its leading edge and driven at
its trailing edge (the tip), under a uniform pressure p: the hinge moment is
p b c^2 / 2, so the tip force is F = p b c / 2 (docs/models.md: 484 N at
10 kPa and 1210 N for the 15 x 10 in surface at 25 kPa).
"""
from __future__ import annotations

import numpy as np


def tip_force(dynamic_pressure, span, chord):
    """Force the actuator must hold at the tip of the surface (N)."""
    return np.asarray(dynamic_pressure) * np.asarray(span) * np.asarray(chord) / 2.0


def deflection_angle(tip_travel, chord):
    """Surface deflection (rad) for a tip travel along the arc."""
    return np.arcsin(np.clip(np.asarray(tip_travel) / np.asarray(chord), -1.0, 1.0))


SURFACE_DENSITY = 2700.0   # kg/m^3, assumed: aluminium surface skin (the seed gives only its thickness)


def tip_equivalent_mass(span, chord, thickness, density=SURFACE_DENSITY):
    """Mass at the tip that has the hinged plate's inertia about its hinge:
    I / c^2 = (rho b c t) c^2 / 3 / c^2 = rho b c t / 3 (kg). The 15 x 10 x
    1/16 in aluminium surface: 0.415 kg, 0.138 kg at the tip."""
    return np.asarray(density) * np.asarray(span) * np.asarray(chord) * np.asarray(thickness) / 3.0
