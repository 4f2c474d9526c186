"""The records a solve passes from stage to stage.

``sizing solve`` is a pipeline: each technology enumerates its part
combinations, sizes each, builds the sized designs with their static
figures and margins, verifies them by simulation (``Simulation``), then all
are ranked. Each stage takes records and returns new ones; none is changed
after it is made, so a design's figures are what the stage that built it
computed, and a design is told apart from another by its ``origin``, not by
object identity. A technology's own records live in its folder
(``technologies/<name>/records.py``); it hands the solve an ``Outcome`` and
its records, kept by name in ``Stages``; its serialiser turns them into
results.json records, and the ranking returns a ``rank.Standing`` per
candidate beside them.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

EMPTY: Mapping = MappingProxyType({})


def frozen(mapping: Mapping | None) -> Mapping:
    """A read-only view of a fresh copy of ``mapping`` (figures, margins)."""
    return EMPTY if not mapping else MappingProxyType(dict(mapping))


@dataclass(frozen=True)
class Simulation:
    """The outcome of simulating one design under every load case."""

    success: bool
    message: str = ""
    cases: tuple = ()               # per load case: the verify.simulate_cases figures (SI floats)

    @classmethod
    def failed(cls, message: str) -> "Simulation":
        return cls(False, message, ())


@dataclass(frozen=True)
class Stages:
    """What each technology's stages of one solve produced, for the report's
    traces and for ``robust`` (which re-verifies the designs it picks by
    id): its records in order and its designs by id (``Technology.held``),
    by technology name."""

    records: Mapping = field(default_factory=lambda: EMPTY)     # name -> the technology's records
    designs: Mapping = field(default_factory=lambda: EMPTY)     # name -> {design id: design}

    @classmethod
    def of(cls, records: Mapping) -> "Stages":
        """The stages of a solve from each technology's records, by name."""
        from ..technologies.registry import held
        records = {name: tuple(rs) for name, rs in records.items()}
        return cls(MappingProxyType(records),
                   MappingProxyType({name: MappingProxyType(held(name, rs)) for name, rs in records.items()}))

    def held(self, technology: str, ident: str):
        """The design ``ident`` of ``technology`` as its stages made it (None: not held)."""
        return self.designs.get(technology, EMPTY).get(ident)


@dataclass(frozen=True)
class Outcome:
    """One technology's part of a solve: its candidate records (results.json
    ``candidates``), what it ruled out without recording, by reason, the
    one-line records of designs that are not designs (results.json
    ``ruled_out``) and its own counts."""

    technology: str
    candidates: list
    ruled_out: Counter = field(default_factory=Counter)
    records: tuple = ()
    counts: dict = field(default_factory=dict)

    @property
    def ruled_out_all(self) -> Counter:
        return self.ruled_out + Counter(r["reason"] for r in self.records)


def stages_of(records: dict) -> Stages:
    """The ``Stages`` of a solve from each technology's records (by name)."""
    return Stages.of(records)
