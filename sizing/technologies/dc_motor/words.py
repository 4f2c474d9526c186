"""How DC motor designs are named and described: the short name (``engine.names``)
and the words (``engine.describe``) of a results.json candidate."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ...display import number
from ...engine.describe import mm, part_words
from ...engine.names import short_id, id_tokens

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def short_name(c: Candidate) -> str:
    comp = c.components
    if "actuator" in comp:
        return "DC " + short_id(comp["actuator"], 28)
    gear = comp.get("gear")
    return " ".join(x for x in ("DC", id_tokens(comp.get("motor"), 1).upper(), id_tokens(comp.get("screw"), 2).upper(),
                                id_tokens(gear, 2) if gear else "") if x)


def describe(c: Candidate, catalog) -> str:
    k, s = c.components, c.static or {}
    if "actuator" in k:
        return f"{part_words(catalog, k['actuator'])}, stroke {mm(s.get('stroke_m'))} mm"
    parts = [part_words(catalog, k.get("motor")), part_words(catalog, k.get("screw")),
             part_words(catalog, k.get("gear")) if k.get("gear") else "no gear (direct drive)", part_words(catalog, k.get("drive"))]
    lead = s.get("effective_lead_m")
    if lead:
        parts.append(f"{number(lead * 1e3, 3)} mm of travel per motor turn")
    return "; ".join(p for p in parts if p)
