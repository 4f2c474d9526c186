"""The solve summary's thermal statement (results.json ``summary.thermal``):
how far the enclosed oil, casing, stacks, pistons and frame drift the output
between the reference and the required temperature, and whether that rules
out every as-built design."""
from __future__ import annotations

from typing import TYPE_CHECKING

import math

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def _label(c: Candidate) -> str:
    return c.name or c.id


def thermal_statement(req, candidates: list[Candidate]) -> str:
    """The smallest net drift of the sized as-built designs, its oil term,
    and how many of them the drift rules out."""
    T = req.requirements.max_temperature
    plain = [c for c in candidates if c.technology == "piezohydraulic" and c.variant == "uncompensated"
             and "thermal_drift" in c.margins]
    if not plain:
        return "No piezohydraulic design got as far as the thermal drift check."
    drifting = [c for c in plain if c.margins["thermal_drift"] < 0]
    smallest = min(plain, key=lambda c: abs(c.static.get("thermal_drift_m", math.inf)))
    drift = abs(smallest.static["thermal_drift_m"])
    text = (f"Thermal budget from {req.options.drift_reference_temperature:g} to {T:g} degC (oil, casing, stacks, "
            f"pistons, frame; net against {req.options.max_drift_fraction:.0%} of the "
            f"{req.requirements.stroke * 1e3:g} mm stroke): the smallest net drift of any sized as-built design is "
            f"{drift * 1e3:.1f} mm ({_label(smallest)}); its oil term alone is "
            f"{smallest.own.get('thermal_budget', {}).get('oil_m', math.nan) * 1e3:.1f} mm. ")
    if len(drifting) == len(plain):
        text += ("The drift makes EVERY uncompensated piezohydraulic design infeasible. "
                 "Passively compensated designs (a low-expansion spacer and a longer frame) and designs with a "
                 "catalog compensator are shown separately.")
    else:
        text += f"{len(drifting)} of {len(plain)} sized uncompensated designs fail it."
    return text
