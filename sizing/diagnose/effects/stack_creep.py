"""Piezo stack creep: after a voltage change the stack keeps extending by a
few percent over fractions of a second to seconds (first-order
approximation of the logarithmic creep of PZT).

Model: creep' = (kappa x_free - creep) / tau added to the free stroke.
Sizes: kappa = 5 % and 12 %, tau = 0.2 s and 0.5 s (datasheets quote 1-2 %
per decade of time, more for soft PZT and high fields).
"""
from __future__ import annotations

from .base import Effect, Param


class StackCreep(Effect):
    def model_changes(self, model, values):
        return {"creep_fraction": values["creep_fraction"], "creep_time": values["creep_time_s"]}


EFFECT = StackCreep(
    name="stack_creep", technology="piezohydraulic",
    params=(Param("creep_fraction", 0.0, 0.4, doc="final creep over the instantaneous free stroke"),
            Param("creep_time_s", 0.02, 5.0, log=True, doc="creep time constant")),
    sizes=({"creep_fraction": 0.05, "creep_time_s": 0.2}, {"creep_fraction": 0.12, "creep_time_s": 0.5}),
    source="Jung and Gweon, Rev. Sci. Instrum. 71 (2000) 3396 (creep of piezo actuators)")
