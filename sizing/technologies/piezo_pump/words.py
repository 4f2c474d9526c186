"""How piezo pump designs are named and described: the short name (``engine.names``)
and the words (``engine.describe``) of a results.json candidate."""
from __future__ import annotations

from typing import TYPE_CHECKING

import re

from ...display import number
from ...engine.describe import mm, part_words
from ...engine.names import short_id

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def short_name(c: Candidate) -> str:
    """PP, stacks, valve (first letter and port mm), pump piston (mm) and
    pumping frequency: "PP 1xP056.90 r6 p80 50Hz"; designs that differ only
    in their accumulator add its bias (``unique``)."""
    comp, d = c.components, (c.design or {})
    stack = short_id(comp.get("stack"))
    stack = stack.upper().replace("-", "", 1) if re.match(r"^[a-z]-\d", stack) else stack
    tokens = str(comp.get("valve") or "-").split("-")
    f = float(d.get("pump_frequency", 0))
    freq = f"{f / 1e3:.3g}kHz" if f >= 1e3 else f"{f:.0f}Hz"
    return (f"PP {comp.get('n_stacks')}x{stack} {tokens[0][:1]}{tokens[-1].removesuffix('mm')} "
            f"p{d.get('pump_diameter', 0) * 1e3:.0f} {freq}")


def describe(c: Candidate, catalog) -> str:
    k, d, s = c.components, c.design or {}, c.static or {}
    return "; ".join(p for p in (
        f"{k.get('n_stacks')} x {part_words(catalog, k.get('stack'))} pumping at {number(d.get('pump_frequency'), 3)} Hz",
        f"{mm(d.get('pump_diameter'))} mm piston into a {mm(d.get('cylinder_diameter'))} mm bore cylinder",
        part_words(catalog, k.get("valve")), part_words(catalog, k.get("accumulator")),
        f"{number(s.get('output_power_W'), 3)} W out" if s.get("output_power_W") else "") if p)
