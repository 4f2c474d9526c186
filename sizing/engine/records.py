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


@dataclass(frozen=True)
class PiezoBrief:
    """What the piezohydraulic stages need from the requirements, in SI,
    computed once per solve (``of``): the sizing, the builder and the margins
    read these figures, never the requirements file itself."""

    stroke: float                   # m
    blocked_force: float            # N
    speed: float                    # m/s
    temperature: float              # degC, the required maximum
    delta_T: float                  # K, from the drift reference (fill) temperature to ``temperature``
    stroke_time: float              # s, stroke over speed
    natural_frequency: float        # Hz, the least the output may have
    strokes_per_second: float       # 1/s, the duty
    hold_time: float                # s, a deflection held under the steady load
    allowed_drift: float            # m, the thermal drift allowed
    max_amplifier_units: int
    wide_gap_floor: float           # m, the options' least oil gap (0: none)
    design_margin: float
    stiffness_ratio: float          # structure over stack stiffness, the least
    max_length: float | None        # m, envelope (None: no limit)
    max_diameter: float | None      # m
    max_mass: float | None          # kg
    surface_mass: float             # kg, tip-equivalent mass of the driven surface
    max_load: float                 # N, the largest load case
    objectives: tuple               # what the sizing minimises
    thermal_compensation: bool      # size compensated variants too

    @classmethod
    def of(cls, req) -> "PiezoBrief":
        from .evaluate import load_cases, surface_mass
        r, o, L, env = req.requirements, req.options, req.load, req.envelope
        return cls(stroke=r.stroke, blocked_force=r.blocked_force, speed=r.speed, temperature=r.max_temperature,
                   delta_T=r.max_temperature - o.drift_reference_temperature, stroke_time=req.stroke_time,
                   natural_frequency=req.natural_frequency, strokes_per_second=req.duty.strokes_per_second,
                   hold_time=req.duty.hold_time, allowed_drift=o.max_drift_fraction * r.stroke,
                   max_amplifier_units=o.max_amplifier_units, wide_gap_floor=o.wide_gap or 0.0,
                   design_margin=o.design_margin, stiffness_ratio=o.structure_stiffness_ratio,
                   max_length=env.max_length, max_diameter=env.diameter, max_mass=env.max_mass,
                   surface_mass=surface_mass(L), max_load=max(c["load_N"] for c in load_cases(L)),
                   objectives=tuple(req.objectives.minimize), thermal_compensation=bool(o.thermal_compensation))


def brief_of(req_or_brief) -> PiezoBrief:
    """The brief itself, or the brief of a requirements file."""
    return req_or_brief if isinstance(req_or_brief, PiezoBrief) else PiezoBrief.of(req_or_brief)
