"""Holding the surface, for every technology: where the output sits under
a load at zero drive, the travel it reaches from neutral, and the
requirements' optional output stiffness (``min_stiffness``) and stroke
reference (``stroke_from``).

A load F on an output of stiffness k at rest pushes it back by F / k (the
rest offset). A simulation that starts from that loaded rest (the stacks
and oil one; the DC servo holds its motor angle, so its chain's
compliance offsets the output the same way) counts its stroke from there,
so from neutral the output reaches the stroke less F / k. Which of the two
a requirement means is ``stroke_from``: "loaded_rest" (the default, the
seed's reading: its simulation counts from the loaded rest) or "neutral"
(a surface held to a position, as flight-control actuators are specified,
with a stiffness)."""
from __future__ import annotations

import math

from .rank import floor_margin


def rest_offset(load, stiffness) -> float:
    """F / k, m (0 without a load; inf on an output that does not hold)."""
    if load == 0:
        return 0.0
    return load / stiffness if stiffness > 0 else math.inf


def held_cases(cases, stiffness) -> list[dict]:
    """The simulated cases with ``rest_offset_m`` and ``travel_from_neutral_m``
    (the stroke from the loaded rest less the rest offset)."""
    out = []
    for case in cases:
        offset = rest_offset(case["load_N"], stiffness)
        stroke = case.get("stroke_m")
        travel = stroke - offset if stroke is not None and math.isfinite(offset) else None
        out.append(dict(case, rest_offset_m=offset if math.isfinite(offset) else None, travel_from_neutral_m=travel))
    return out


def travel(req, stroke, stiffness, load) -> float:
    """The stroke the requirement counts: from the loaded rest, or from
    neutral (less the rest offset under ``load``)."""
    if req.requirements.stroke_from == "neutral":
        return stroke - rest_offset(load, stiffness)
    return stroke


def margins(req, stiffness, cases=None) -> dict:
    """The ``stiffness`` margin when the requirements ask for one, and, for
    a stroke counted from neutral, the simulated ``stroke`` margin on the
    least travel from neutral over the cases (``held_cases``)."""
    r = req.requirements
    out = {}
    if r.min_stiffness is not None:
        out["stiffness"] = floor_margin(stiffness, r.min_stiffness)
    if r.stroke_from == "neutral" and cases:
        reached = [c["travel_from_neutral_m"] for c in cases]
        out["stroke"] = (floor_margin(min(reached), r.stroke) if all(x is not None for x in reached)
                         else -math.inf)
    return out
