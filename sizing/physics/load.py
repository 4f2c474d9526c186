"""Aerodynamic load of the hinged control surface (seed Figure 7).

A flat plate of span b and chord c, hinged at its leading edge and driven at
its trailing edge (the tip), under a uniform pressure p: the hinge moment is
p b c^2 / 2, so the tip force is F = p b c / 2 (PHYSICS-NOTES: 484 N at
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
