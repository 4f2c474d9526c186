"""Piezo stack creep: after a voltage change the stack keeps extending by a
few percent over fractions of a second to seconds (first-order
approximation of the logarithmic creep of PZT).

Model: creep' = (kappa x_free - creep) / tau added to the free stroke.
Sizes: kappa = 5 % and 12 %, tau = 0.2 s and 0.5 s (datasheets quote 1-2 %
per decade of time, more for soft PZT and high fields).

Form "log" (logarithmic creep, several time constants): PZT creeps as
x(t) = x(t0) (1 + gamma log10(t / t0)) (Jung and Gweon 2000; PI, "Piezo
actuator creep": gamma of 1-2 % per decade). Written as a Prony series:
LOG_CREEP_MODES first-order modes a decade apart from the shortest time
tau_1 (tau_1, 10 tau_1, ...), each creep' = (gamma x_free - creep) / tau_k:
between tau_1 and the longest mode their sum grows by gamma per decade of
time, since the integral of (t/tau) exp(-t/tau) over ln tau is 1. Sizes:
gamma = 1 % and 2.5 % a decade, tau_1 = 10 ms and 3 ms.
"""
from __future__ import annotations

from .base import Effect, Param


class LogCreep(Effect):
    def model_changes(self, model, values):
        return {"log_creep": values["creep_per_decade"], "log_creep_time": values["creep_shortest_time_s"]}


class StackCreep(Effect):
    def model_changes(self, model, values):
        return {"creep_fraction": values["creep_fraction"], "creep_time": values["creep_time_s"]}


EXPONENTIAL = StackCreep(
    form="exponential",
    name="stack_creep", technology="piezohydraulic",
    params=(Param("creep_fraction", 0.0, 0.4, doc="final creep over the instantaneous free stroke"),
            Param("creep_time_s", 0.02, 5.0, log=True, doc="creep time constant")),
    sizes=({"creep_fraction": 0.05, "creep_time_s": 0.2}, {"creep_fraction": 0.12, "creep_time_s": 0.5}),
    source="Jung and Gweon, Rev. Sci. Instrum. 71 (2000) 3396 (creep of piezo actuators)")


LOG = LogCreep(
    name="stack_creep", technology="piezohydraulic", form="log",
    params=(Param("creep_per_decade", 0.0, 0.08, doc="creep per decade of time over the free stroke"),
            Param("creep_shortest_time_s", 1e-3, 1.0, log=True, doc="shortest of the creep modes a decade apart")),
    sizes=({"creep_per_decade": 0.01, "creep_shortest_time_s": 0.01},
           {"creep_per_decade": 0.025, "creep_shortest_time_s": 0.003}),
    source="Jung and Gweon, Rev. Sci. Instrum. 71 (2000) 3396 (logarithmic creep); Prony series of the log law")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (EXPONENTIAL, LOG)
