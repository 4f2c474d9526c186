"""How piezohydraulic designs are named and described: the short name (``engine.names``)
and the words (``engine.describe``) of a results.json candidate."""
from __future__ import annotations

from typing import TYPE_CHECKING

import re

from ...display import number
from ...engine.describe import mm, part_words
from ...engine.names import short_id, abbreviated

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def short_name(c: Candidate) -> str:
    comp = c.components
    stack = short_id(comp.get("stack"))
    stack = stack.upper().replace("-", "", 1) if re.match(r"^[a-z]-\d", stack) else stack
    parts = [f"{comp.get('n_stacks')}x{stack}", abbreviated(comp.get("fluid"), 1), abbreviated(comp.get("seal"), 3),
             abbreviated(comp.get("material"), 1)]
    variant = c.variant
    if variant == "passive":
        parts.append("sp")
    elif variant == "compensated":
        parts.append(abbreviated(comp.get("compensator"), 1))
    return " ".join(p for p in parts if p)


def describe(c: Candidate, catalog) -> str:
    k, s = c.components, c.static or {}
    parts = [f"{k.get('n_stacks')} x {part_words(catalog, k.get('stack'))}", part_words(catalog, k.get("fluid")),
             part_words(catalog, k.get("seal")), f"{part_words(catalog, k.get('material'))} structure" if k.get("material") else "",
             part_words(catalog, k.get("compensator")) if k.get("compensator") else ""]
    size = f"bores {mm(s.get('wide_diameter_m'))}/{mm(s.get('narrow_diameter_m'))} mm (R = {number(k.get('ratio'), 3)})"
    if s.get("length_m") and s.get("outer_diameter_m"):
        size += f", {mm(s['length_m'])} mm long, {mm(s['outer_diameter_m'])} mm across"
    units = s.get("amplifier_units")
    drive = f"{number(units, 3) if units else 1} x {part_words(catalog, k.get('amplifier'))}"
    return "; ".join(p for p in parts + [size, f"driven by {drive}"] if p)
