"""Amplifier slew limit: the drive current i = C dV/dt of the stacks is
bounded (docs/models.md, "Piezohydraulic sizing"), so the voltage cannot follow fast
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

The bandwidth is fitted down to 2 pi 20 Hz, not lower. A linear piezo
amplifier's small-signal bandwidth into a capacitive load C is 1 / (R_o C)
with an output impedance R_o of ohms to tens of ohms: the PiezoDrive PD200
is 6.4 kHz into 10 uF, 2.4 kHz into 30 uF and 940 Hz into 110 uF (PD200
manual, table 6), against the 10-30 uF of a few stacks here. What makes an
amplifier slow on large signals is its current limit, which the slew rate
holds. A lag of a few hertz is the output's (viscous damping against the
output stiffness, a first-order lag of time constant c R^2 / (n k_s)), and
a bandwidth bound that low would let this form stand in for it.
"""
from __future__ import annotations

import numpy as np

from .base import Effect, Param


SLEW = Effect(
    form="slew",
    name="amplifier_slew_limit", technology="piezohydraulic",
    params=(Param("slew_rate_V_s", 20.0, 2e5, log=True, doc="largest dV/dt the amplifier delivers"),),
    sizes=({"slew_rate_V_s": 1000.0}, {"slew_rate_V_s": 300.0}),
    fields={"slew_rate_V_s": "slew_rate"},
    source="docs/models.md (drive current i = C dV/dt)")


BANDWIDTH = Effect(
    name="amplifier_slew_limit", technology="piezohydraulic", form="bandwidth",
    params=(Param("slew_rate_V_s", 20.0, 2e5, log=True, doc="largest dV/dt the amplifier delivers"),
            Param("bandwidth_rad_s", 2 * np.pi * 20.0, 2e4, log=True, doc="small-signal bandwidth of the amplifier")),
    sizes=({"slew_rate_V_s": 1000.0, "bandwidth_rad_s": 628.0}, {"slew_rate_V_s": 300.0, "bandwidth_rad_s": 188.0}),
    fields={"slew_rate_V_s": "slew_rate", "bandwidth_rad_s": "amp_bandwidth"},
    source="first-order amplifier with slew limit (Fleming and Leang 2014, ch. 13)")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (SLEW, BANDWIDTH)
