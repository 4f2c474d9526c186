"""Seal stick-slip: spring-energised PTFE seals whose breakaway (static)
friction exceeds the running friction, so the output sticks, loads up the
oil column and jumps ("stepped" motion, seed sec. 4, first prototype).

Model: Karnopp friction on the output (narrow) seal with running force F_run
and breakaway F_run * ratio; the wide seal keeps its nominal running force
and takes the same breakaway ratio. Size: the seed's 7 mm measured against
7.5 mm simulated means about 0.5 mm lost against the output stiffness of the
stacks (n k_s / R^2, about 5.9 kN/m for Table 3): some 3 N of extra
running friction; spring-energised seals break away at 1.5-2.5 times it.
"""
from __future__ import annotations

from .base import Effect, Param


class SealStickSlip(Effect):
    def model_changes(self, model, values):
        ratio = values["breakaway_ratio"]
        return {"narrow_friction": values["narrow_friction_N"],
                "narrow_breakaway": ratio, "wide_breakaway": ratio}


EFFECT = SealStickSlip(
    name="seal_stick_slip", technology="piezohydraulic",
    params=(Param("narrow_friction_N", 0.0, 20.0, doc="running friction of the output seal"),
            Param("breakaway_ratio", 1.0, 4.0, doc="breakaway / running friction of both seals")),
    sizes=({"narrow_friction_N": 1.5, "breakaway_ratio": 1.8},
           {"narrow_friction_N": 3.0, "breakaway_ratio": 2.0}),
    source="seed sec. 4 (stepped response of the first prototype); Karnopp (1985) friction")
