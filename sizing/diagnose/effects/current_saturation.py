"""Current saturation below the rated limit: a drive set to a lower peak
current, a supply that sags, or a thermal fold-back, so large steps are
acceleration-limited and the loop winds up.

Model: the controller's current clipped at a lower limit. Sizes: 50 % and
25 % of the nominal limit.
"""
from __future__ import annotations

import numpy as np

from .base import Effect, Param


class CurrentSaturation(Effect):
    def sizes_for(self, rig, model):
        i_max = float(np.min(model.current_limit))
        return ({"current_limit_A": 0.5 * i_max}, {"current_limit_A": 0.25 * i_max})

    def model_changes(self, model, values):
        return {"current_limit": values["current_limit_A"]}


EFFECT = CurrentSaturation(
    name="current_saturation", technology="dc_motor",
    params=(Param("current_limit_A", 0.05, 20.0, log=True, doc="actual current limit of the drive"),),
    source="seed eq. 13 with a saturated input; PHYSICS-NOTES (DC motor under load)")
