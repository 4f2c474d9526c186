"""The records a solve passes from stage to stage.

``sizing solve`` is a pipeline: enumerate the part combinations
(``search.Combo``), size each (``convex.SizingResult``), build the sized
designs with their static figures and margins (``PiezoDesign``), verify
them by simulation (``Simulation``, ``VerifiedDesign``), then rank. Each
stage takes records and returns new ones; none is changed after it is made,
so a design's figures are what the stage that built it computed, and a
design is told apart from another by its ``origin``, not by object identity.
``candidate.py`` turns a verified design into its results.json record.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

EMPTY: Mapping = MappingProxyType({})


def frozen(mapping: Mapping | None) -> Mapping:
    """A read-only view of a fresh copy of ``mapping`` (figures, margins)."""
    return EMPTY if not mapping else MappingProxyType(dict(mapping))


@dataclass(frozen=True)
class Variant:
    """One way to build a combination: structure material and thermal
    compensation (no compensator: as built; ``passive``: a low-expansion
    spacer that cancels the thermal budget; else a catalog compensator)."""

    material: object
    compensator: object = None
    passive: bool = False

    @property
    def name(self) -> str:
        if self.compensator is not None:
            return "compensated"
        return "passive" if self.passive else "uncompensated"

    def suffix(self) -> str:
        tail = f"-{self.material.id}"
        if self.compensator is not None:
            return tail + f"-tc-{self.compensator.id}"
        return tail + ("-pc" if self.passive else "")

    def as_built(self) -> "Variant":
        """The same material and compensator without the passive spacer."""
        return Variant(self.material, self.compensator, False)


@dataclass(frozen=True)
class PiezoDesign:
    """A sized piezohydraulic design with its static figures and margins.

    ``origin``: the index of the (combination, variant, sizing) it was built
    from in the list handed to ``piezo_designs.designs`` (a passive design
    shares its as-built parent's). Before it is built (the sizing gave no
    finite geometry) ``cand`` is None and the figures are empty."""

    origin: int
    id: str
    combo: object                   # search.Combo
    variant: Variant
    gp: object                      # convex.SizingResult
    spacer: float = 0.0             # m, passive-compensation spacer (0: none)
    bouc_wen: tuple | None = None   # (BoucWen, source) of its stack; None: not buildable
    cand: object = None             # piezo.Candidates, one row
    ramp: float = math.nan          # s, the planned drive ramp
    static: Mapping = field(default_factory=lambda: EMPTY)  # static figures, SI (verify.static_figures and the derived ones)
    metrics: Mapping = field(default_factory=lambda: EMPTY)  # mass_kg, cost_usd, volume_m3, power_W
    force_path: tuple = ()          # members in series (force_path.as_list rows)
    seal_friction: Mapping = field(default_factory=lambda: EMPTY)  # N at the largest load's pressure: wide, narrow, at_pressure_Pa
    static_margins: Mapping = field(default_factory=lambda: EMPTY)
    ruled_out: Mapping | None = None    # reason and detail when it is not a design at all

    @property
    def built(self) -> bool:
        return self.cand is not None

    @property
    def sized(self) -> tuple:
        """What ``solve.verify_sized`` re-verifies: (Combo, Variant, SizingResult),
        the variant as built (``designs`` derives the spacer again)."""
        return self.combo, self.variant.as_built(), self.gp


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
class VerifiedDesign:
    """A built design and, when it was simulated, the simulation's outcome."""

    design: PiezoDesign
    simulation: Simulation | None = None


@dataclass(frozen=True)
class Stages:
    """What each stage of one solve produced, for the report's traces and
    for ``robust`` (which re-verifies the designs it picks by id)."""

    verified: tuple = ()            # VerifiedDesign, piezohydraulic
    by_id: Mapping = field(default_factory=dict)

    @classmethod
    def of(cls, verified) -> "Stages":
        verified = tuple(verified)
        return cls(verified, MappingProxyType({v.design.id: v.design for v in verified}))
