"""How the report shows one technology's designs (``Technology.report``):
its markers in objective space, its line styles, its words for a design's
parts and its own sections. Every field has a default, so a technology
that says nothing of its looks is still drawn, tabled and counted."""
from __future__ import annotations

from typing import TYPE_CHECKING

import html
from collections.abc import Callable
from dataclasses import dataclass, field

if TYPE_CHECKING:
    from ..engine.candidate import Candidate


def _nothing(*_args, **_kwargs) -> str:
    return ""


# the stages the objective-space figure draws of a technology that sizes
# (or screens) before it simulates: its ruled-out combinations are counted, not drawn
SIZED_STAGES = ("simulated", "sized", "gp_infeasible")


def escaped(x) -> str:
    return html.escape(str(x))


def shown(v, scale=1.0, fmt="{:.4g}") -> str:
    """A figure of a table cell: ``v * scale`` in ``fmt``, "n/a" when unknown."""
    return "n/a" if v is None else fmt.format(v * scale)


def ruled_out_by_part(pruned: list[Candidate], part: str) -> str:
    """The table rows of ``pruned`` candidates counted by their ``part``
    (a components key) and the requirement that rules them out."""
    from collections import Counter
    by = Counter((c.components[part], c.driver) for c in pruned)
    return "".join(f"<tr><td class='l'>{escaped(p)}</td><td class='l'>{escaped(d)}</td><td>{n}</td></tr>"
                   for (p, d), n in sorted(by.items()))


@dataclass(frozen=True)
class Marker:
    """One legend entry of the objective-space figure: the technology's
    candidates whose ``variant`` is ``variant`` (None: every one), drawn
    only at ``stages`` (None: at every stage)."""

    variant: str | None
    legend: str                             # "DC motor from parts" (", feasible" or ", infeasible" follows)
    symbol: str                             # plotly marker symbol of the feasible ones (infeasible: ``open_symbol``)
    open_symbol: str
    color: str
    size: int = 8
    stages: tuple[str, ...] | None = None
    open_color: str | None = None           # the infeasible ones' colour (None: ``color``)

    def takes(self, candidate: Candidate) -> bool:
        return self.variant is None or candidate.variant == self.variant


@dataclass(frozen=True)
class Presentation:
    """What the report (``sizing.report``) needs of a technology beyond its
    name, label and words (``registry.Technology``)."""

    markers: tuple[Marker, ...] = ()        # none: one brown hexagon per verdict
    front_color: str = "black"              # its Pareto front's dotted line
    trace_dash: str = "solid"               # its designs' time traces
    hover: Callable | None = None           # (candidate) -> the hover's first lines (None: label and short name)
    parts: Callable | None = None           # (candidate) -> its parts in the design table (None: label, parts by kind)
    # (candidates in rank order) -> its designs in the comparison figure and table (None: its best one)
    comparison_picks: Callable | None = None
    counts_words: Callable | None = None    # (results) -> its counts in the requirements paragraph (None: not stated)
    checks_table: bool = False              # its designs fill the table of checks beyond the seed
    section: Callable = field(default=_nothing)   # (candidates, figure -> html) -> a section of its own, after the margins
    pruned_words: Callable = field(default=_nothing)   # (results) -> what its screen ruled out before sizing
    # (heading, figure title) of the comparison section when it is the technology the others are compared against
    comparison_titles: tuple[str, str] | None = None


PLAIN = Presentation()
