"""The library of candidate unmodelled effects, one module per effect.

Every effect module declares its forms in one export, ``FORMS`` (the
family's default form first). ``library(kind)`` lists the forms that apply
to a technology ("piezohydraulic" or "dc_motor"), family by family in the
fixed order of ``FAMILIES``.
"""
from __future__ import annotations

from . import (amplifier_slew_limit, backlash, coulomb_friction, current_saturation,
               fluid_compressibility, leakage, no_return, seal_stick_slip, sensor_delay,
               sensor_vibration, stack_creep, viscous_damping)
from .base import Effect, Param

# the families of each technology, in the order they are screened; each
# module declares its forms in FORMS (the family's default first)
FAMILIES = {
    "piezohydraulic": (seal_stick_slip, fluid_compressibility, viscous_damping, leakage, stack_creep,
                       amplifier_slew_limit, no_return, sensor_delay, sensor_vibration),
    "dc_motor": (current_saturation, coulomb_friction, backlash, sensor_vibration, sensor_delay),
}


def _forms(kind: str) -> tuple[Effect, ...]:
    return tuple(form for family in FAMILIES[kind] for form in family.FORMS if form.technology == kind)


PIEZO = _forms("piezohydraulic")
DC = _forms("dc_motor")


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
