"""Amplifier slew limit: the drive current i = C dV/dt of the stacks is
bounded (PHYSICS-NOTES, "Drive current"), so the voltage cannot follow fast
commands; the run's voltage column is the command.

Model: the voltage ramps at most at the slew rate. Sizes: 1000 and
300 V/s, a 20 mA and a 6 mA amplifier on about 20 uF of large-signal
capacitance (three PK4GA7P1 stacks).

Form "bandwidth" (amplifier bandwidth and slew limit): a linear amplifier
driving a capacitive load is a first-order low-pass of bandwidth w_a
(V' = w_a (V_cmd - V)) whose rate is clipped at the slew rate (PI,
"Piezo amplifier bandwidth and slew rate"; Fleming and Leang, Design,
Modeling and Control of Nanopositioning Systems (2014) ch. 13). Sizes:
w_a = 2 pi 100 Hz with 1000 V/s and 2 pi 30 Hz with 300 V/s.
"""
from __future__ import annotations

from .base import Effect, Param


EFFECT = Effect(
    form="slew",
    name="amplifier_slew_limit", technology="piezohydraulic",
    params=(Param("slew_rate_V_s", 20.0, 2e5, log=True, doc="largest dV/dt the amplifier delivers"),),
    sizes=({"slew_rate_V_s": 1000.0}, {"slew_rate_V_s": 300.0}),
    fields={"slew_rate_V_s": "slew_rate"},
    source="PHYSICS-NOTES (drive current i = C dV/dt)")


BANDWIDTH = Effect(
    name="amplifier_slew_limit", technology="piezohydraulic", form="bandwidth",
    params=(Param("slew_rate_V_s", 20.0, 2e5, log=True, doc="largest dV/dt the amplifier delivers"),
            Param("bandwidth_rad_s", 10.0, 2e4, log=True, doc="small-signal bandwidth of the amplifier")),
    sizes=({"slew_rate_V_s": 1000.0, "bandwidth_rad_s": 628.0}, {"slew_rate_V_s": 300.0, "bandwidth_rad_s": 188.0}),
    fields={"slew_rate_V_s": "slew_rate", "bandwidth_rad_s": "amp_bandwidth"},
    source="first-order amplifier with slew limit (Fleming and Leang 2014, ch. 13)")
