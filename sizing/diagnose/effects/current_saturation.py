"""Current saturation below the rated limit: a drive set to a lower peak
current, a supply that sags, or a thermal fold-back, so large steps are
acceleration-limited and the loop winds up.

Model: the controller's current clipped at a lower limit. Sizes: 50 % and
25 % of the nominal limit.
"""
from __future__ import annotations

from .base import Effect, Param


EFFECT = Effect(
    name="current_saturation", technology="dc_motor",
    params=(Param("current_limit_A", 0.05, 20.0, log=True, doc="actual current limit of the drive"),),
    fields={"current_limit_A": "current_limit"}, nominal_factors=(0.5, 0.25),
    source="seed eq. 13 with a saturated input; PHYSICS-NOTES (DC motor under load)")
