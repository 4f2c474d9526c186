"""Thermal expansion of the enclosed oil (PHYSICS-NOTES, "100 degC").

A sealed hydraulic amplifier holds a fixed mass of oil. Heated by dT it grows
by V alpha_T dT; the stacks hold the wide piston, so the growth comes out at
the narrow piston as a drift of V alpha_T dT / A_narrow. With
V = A_wide g + A_narrow S (wide chamber gap g, narrow bore over the stroke S)
the drift is alpha_T dT (g R + S): large ratios make it huge.
"""
from __future__ import annotations

import numpy as np


def oil_volume(wide_area, narrow_area, wide_gap, stroke):
    """Enclosed oil volume (m^3): wide chamber plus the narrow bore."""
    return np.asarray(wide_area) * np.asarray(wide_gap) + np.asarray(narrow_area) * np.asarray(stroke)


def output_drift(oil_volume_m3, thermal_expansion, delta_T, narrow_area):
    """Output displacement from heating the enclosed oil by delta_T (m)."""
    return np.asarray(oil_volume_m3) * np.asarray(thermal_expansion) * np.asarray(delta_T) / np.asarray(narrow_area)
