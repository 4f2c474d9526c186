"""Sizes and masses of the hydraulic stage from its two bore areas.

Every formula uses only +, *, / and ** with positive constants, so the same
function evaluates numpy arrays and builds cvxpy geometric-program
expressions (posynomials) in ``technologies/piezohydraulic/convex.py``.

Assumed construction (stated in reports): 6061-T6 aluminium, design stress
half the 276 MPa yield; pistons and end caps are simply supported circular
plates, t = r sqrt(3 (3 + nu) p / (8 sigma)); thin-walled cylinders,
t = p r / sigma; 3 mm minimum wall for machining.
"""
from __future__ import annotations

import math

ALUMINIUM_DENSITY = 2700.0        # kg/m^3, 6061-T6
DESIGN_STRESS = 138e6             # Pa, half the 276 MPa yield of 6061-T6
PLATE_FACTOR = math.sqrt(3 * (3 + 0.33) / 8)
MIN_WALL = 3e-3                   # m
ROD_EXTRA_LENGTH = 0.03           # m, narrow piston beyond the stroke (seal land, eye)
MACHINING_USD_PER_KG = 60.0       # assumed shop rate for the aluminium parts
FIXED_HYDRAULIC_USD = 1500.0      # assumed: fill, bleed, assembly, test


def radius(area):
    return (area / math.pi) ** 0.5


def plate_thickness(area, pressure):
    return PLATE_FACTOR * radius(area) * (pressure / DESIGN_STRESS) ** 0.5 + MIN_WALL


def wall_thickness(area, pressure):
    return pressure * radius(area) / DESIGN_STRESS + MIN_WALL


def wide_piston_mass(wide_area, pressure):
    return ALUMINIUM_DENSITY * wide_area * plate_thickness(wide_area, pressure)


def narrow_piston_mass(narrow_area, stroke):
    return ALUMINIUM_DENSITY * narrow_area * (stroke + ROD_EXTRA_LENGTH)


def casing_mass(wide_area, narrow_area, pressure, wide_gap, stroke):
    """Wide cylinder wall + narrow cylinder wall. The end cap and the stack
    base plate are members of the force path, sized for stiffness and
    stress in their own material (technologies/piezohydraulic/force_path.py)."""
    wide_length = plate_thickness(wide_area, pressure) + wide_gap + 0.01
    narrow_length = stroke + ROD_EXTRA_LENGTH
    wide_wall = ALUMINIUM_DENSITY * 2 * math.pi * radius(wide_area) * wall_thickness(wide_area, pressure) * wide_length
    narrow_wall = ALUMINIUM_DENSITY * 2 * math.pi * radius(narrow_area) * wall_thickness(narrow_area, pressure) * narrow_length
    return wide_wall + narrow_wall


def hydraulic_mass(wide_area, narrow_area, pressure, wide_gap, stroke, oil_density):
    """Metal and oil of the amplifier stage (kg)."""
    oil = oil_density * (wide_area * wide_gap + narrow_area * stroke)
    return (wide_piston_mass(wide_area, pressure) + narrow_piston_mass(narrow_area, stroke)
            + casing_mass(wide_area, narrow_area, pressure, wide_gap, stroke) + oil)


def hydraulic_volume(wide_area, narrow_area, pressure, wide_gap, stroke):
    """Envelope of the amplifier stage (m^3)."""
    wide = wide_area * (2 * plate_thickness(wide_area, pressure) + wide_gap + 0.01)
    narrow = narrow_area * (stroke + ROD_EXTRA_LENGTH) * 4.0  # bore plus wall and rod travel
    return wide + narrow
