"""A design in words, beside its short name: the parts by maker and model
and the key dimensions, as an engineer would say it ("17 x PI P-056.90 PICA
high-power piezo stack actuator; ...; bores 504/33 mm (R = 233), 554 mm
long, 546 mm across"). Read from the candidate and the catalog only."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..display import number
from ..technologies import registry

if TYPE_CHECKING:
    from .candidate import Candidate


def part_words(catalog, part_id) -> str:
    """The part's maker and model as the catalog names it, cut before its
    first comma or parenthesis; the id where the catalog does not hold it."""
    if not part_id:
        return ""
    try:
        _, entry = catalog.get(part_id)
    except (KeyError, AttributeError):
        return str(part_id)
    name = entry.name.split(",")[0].split(" (")[0].strip()
    maker = entry.manufacturer
    if maker.lower().startswith(("generic", "various", "qualified")) or name.split()[0].lower() in maker.lower():
        return name                         # the name already says who makes it
    return f"{maker.split(' (')[0].split(',')[0].strip()} {name}"


def mm(value) -> str:
    return number(value * 1e3, 3) if isinstance(value, (int, float)) else "?"


def describe(c: Candidate, catalog) -> str:
    """Candidate ``c`` in words ("" when it names no parts)."""
    if not c.components:
        return ""
    tech = registry.get(c.technology)
    return tech.describe(c, catalog) if tech is not None else ""
