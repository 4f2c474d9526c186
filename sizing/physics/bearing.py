"""Rolling bearings carrying the screw's thrust: rating life and static safety.

Basic rating life (ISO 281:2007, eq. 1 for ball bearings):

    L10 = (C / P)^3  10^6 revolutions

with the equivalent dynamic load P = X F_r + Y F_a. A single-row angular
contact ball bearing of 40 degree contact angle under a mostly axial load
(F_a / F_r > e = 1.14) has X = 0.35, Y = 0.57 (ISO 281 table 3, the 40
degree row; the values SKF prints for its 72 B and 73 B series). Mounted as
a back-to-back pair at the screw's fixed end, each direction of thrust is
carried by one bearing of the pair.

Static (ISO 76): P_0 = X_0 F_r + Y_0 F_a with X_0 = 0.5, Y_0 = 0.26 (40
degrees), safety s_0 = C_0 / P_0.

Vectorised over candidates; SI (N, revolutions, s).
"""
from __future__ import annotations

import numpy as np

# ISO 281 table 3 / ISO 76, single row, 40 degree contact angle, F_a / F_r > e
AXIAL_FACTOR = 0.57
STATIC_AXIAL_FACTOR = 0.26


def equivalent_load(axial, radial=0.0):
    """Equivalent dynamic load (N) of a 40 degree angular contact bearing
    under a mostly axial load: 0.35 F_r + 0.57 F_a."""
    return 0.35 * np.abs(np.asarray(radial, float)) + AXIAL_FACTOR * np.abs(np.asarray(axial, float))


def static_equivalent_load(axial, radial=0.0):
    """Equivalent static load (N): 0.5 F_r + 0.26 F_a, at least F_r."""
    Fr, Fa = np.abs(np.asarray(radial, float)), np.abs(np.asarray(axial, float))
    return np.maximum(0.5 * Fr + STATIC_AXIAL_FACTOR * Fa, Fr)


def l10_revolutions(dynamic_rating, equivalent):
    """Basic rating life (revolutions), ISO 281: (C / P)^3 10^6."""
    return (np.asarray(dynamic_rating, float) / np.maximum(np.asarray(equivalent, float), 1e-9)) ** 3 * 1e6


def l10_hours(dynamic_rating, axial, rev_per_second):
    """Rating life (h) of a 40 degree angular contact bearing under a pure
    axial load turning at ``rev_per_second``."""
    return l10_revolutions(dynamic_rating, equivalent_load(axial)) / np.asarray(rev_per_second) / 3600.0


def static_safety(static_rating, axial):
    """s_0 = C_0 / P_0 under a pure axial load (-)."""
    return np.asarray(static_rating, float) / np.maximum(static_equivalent_load(axial), 1e-9)
