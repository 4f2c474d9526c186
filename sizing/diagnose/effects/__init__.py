"""The library of candidate unmodelled effects, one module per effect.

``library(kind)`` lists the effects that apply to a technology
("piezohydraulic" or "dc_motor"), in a fixed order.
"""
from __future__ import annotations

from . import (amplifier_slew_limit, backlash, coulomb_friction, current_saturation,
               fluid_compressibility, leakage, no_return, seal_stick_slip, sensor_delay,
               sensor_vibration, stack_creep, viscous_damping)
from .base import Effect, Param

PIEZO = (seal_stick_slip.EFFECT, fluid_compressibility.EFFECT, viscous_damping.EFFECT,
         leakage.EFFECT, stack_creep.EFFECT, amplifier_slew_limit.EFFECT, no_return.EFFECT,
         sensor_delay.PIEZO, sensor_vibration.PIEZO, sensor_vibration.PIEZO_SINUSOID,
         # further forms: alternatives of the families above
         seal_stick_slip.LUGRE, stack_creep.LOG, fluid_compressibility.AIR, leakage.ORIFICE,
         amplifier_slew_limit.BANDWIDTH)
DC = (current_saturation.COMMAND, current_saturation.DRIVE, coulomb_friction.COULOMB, coulomb_friction.STRIBECK,
      coulomb_friction.ASYMMETRIC,
      backlash.PLAY, backlash.COASTING,
      sensor_vibration.EFFECT, sensor_vibration.SINUSOID, sensor_delay.DC)


def library(kind: str) -> tuple[Effect, ...]:
    """Every effect of the library for a technology."""
    if kind == "piezohydraulic":
        return PIEZO
    if kind == "dc_motor":
        return DC
    raise ValueError(f"unknown technology {kind!r}")


def get(kind: str, name: str) -> Effect:
    for effect in library(kind):
        if effect.name == name:
            return effect
    raise KeyError(name)


__all__ = ["Effect", "Param", "library", "get"]
