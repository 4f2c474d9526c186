"""Amplifier slew limit: the drive current i = C dV/dt of the stacks is
bounded (PHYSICS-NOTES, "Drive current"), so the voltage cannot follow fast
commands; the run's voltage column is the command.

Model: the voltage ramps at most at the slew rate. Sizes: 1000 and
300 V/s, a 20 mA and a 6 mA amplifier on about 20 uF of large-signal
capacitance (three PK4GA7P1 stacks).
"""
from __future__ import annotations

from .base import Effect, Param


EFFECT = Effect(
    name="amplifier_slew_limit", technology="piezohydraulic",
    params=(Param("slew_rate_V_s", 20.0, 2e5, log=True, doc="largest dV/dt the amplifier delivers"),),
    sizes=({"slew_rate_V_s": 1000.0}, {"slew_rate_V_s": 300.0}),
    fields={"slew_rate_V_s": "slew_rate"},
    source="PHYSICS-NOTES (drive current i = C dV/dt)")
