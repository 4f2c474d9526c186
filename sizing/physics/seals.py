"""Seal friction: running (Coulomb) friction grows with the seal's
circumference and with pressure; breakaway (static) friction is a multiple
of it. Catalog data per metre of circumference (catalogs/seals.toml)."""
from __future__ import annotations

import numpy as np


def running_friction(friction_per_length, diameter, pressure=0.0, pressure_coefficient=0.0):
    """Running friction of one seal on a rod or piston of ``diameter`` (N)."""
    circumference = np.pi * np.asarray(diameter)
    return circumference * (np.asarray(friction_per_length) + np.asarray(pressure_coefficient) * np.asarray(pressure))


def breakaway_friction(running, breakaway_ratio):
    """Static friction that must be overcome to start sliding (N)."""
    return np.asarray(running) * np.asarray(breakaway_ratio)
