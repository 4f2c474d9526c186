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


def friction_at_pressure(friction_per_length, pressure_coefficient, diameter, pressure, breakaway_ratio=1.0):
    """Running and breakaway friction of one seal at ``pressure`` (Pa), N.

    Running: pi d (f_0 + c_p p), the catalog's friction_per_length f_0 plus
    its friction_pressure_coefficient c_p times the sealed pressure (a lip
    or O-ring is pressed on by the pressure over its contact width: mu w p
    per metre). Breakaway: the running value times the breakaway ratio.
    Returns (running, breakaway).
    """
    running = running_friction(friction_per_length, diameter, np.abs(pressure), pressure_coefficient)
    return running, breakaway_friction(running, breakaway_ratio)


def output_seal_force(f0, cp, wide_diameter, narrow_diameter, ratio, pressure):
    """Seal friction the output must overcome at a chamber pressure p (N):
    the narrow seal directly plus the wide seal through the ratio (its force
    is divided by R at the output, Pascal's principle)."""
    narrow = running_friction(f0, narrow_diameter, pressure, cp)
    wide = running_friction(f0, wide_diameter, pressure, cp)
    return narrow + wide / np.asarray(ratio)
