"""The records a solve passes from stage to stage.

``sizing solve`` is a pipeline: enumerate the part combinations
(``search.Combo``), size each (``convex.SizingResult``), build the sized
designs with their static figures and margins (``PiezoDesign``), verify
them by simulation (``Simulation``, ``VerifiedDesign``), then rank. Each
stage takes records and returns new ones; none is changed after it is made,
so a design's figures are what the stage that built it computed, and a
design is told apart from another by its ``origin``, not by object identity.
The DC motor (``DCActuatorDesign``, ``DCDesign``) and the piezo pump
(``PumpDesign``) stages return records of the same kind. One serialiser per
technology turns them into results.json records (``candidate.py``,
``dc_candidate.py``, ``pump_candidate.py``); the ranking returns a
``rank.Standing`` per candidate beside them.
"""
from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

from ..physics import structure
from .loads import load_cases, surface_mass

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
    ramp: float = math.nan          # s, the drive's voltage ramp (sized with the units)
    amplifier_units: float = math.nan   # amplifier units in parallel (sized against the speed and the duty)
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
    def ramp_time(self) -> float:
        """s, the voltage ramp the drive is sized for (``ramp``)."""
        return self.ramp

    @property
    def sized(self) -> tuple:
        """What ``piezohydraulic.stage.verify_sized`` re-verifies: (Combo, Variant, SizingResult),
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


# --- DC motor -----------------------------------------------------------------
@dataclass(frozen=True)
class DCActuatorDesign:
    """A catalog DC actuator simulated under every load case (``dc_candidates``)."""

    actuator: object                # io.catalog.DCActuator
    static: Mapping                 # dc.static_figures at the largest load, and free_stroke_m
    simulation: Simulation          # the step of the required stroke under every load case
    margins: Mapping
    metrics: Mapping                # mass_kg, cost_usd, volume_m3, power_W

    @property
    def id(self) -> str:
        return f"dc-{self.actuator.id}"


@dataclass(frozen=True)
class DCParts:
    """The catalog ids of a DC design from parts (gear None: direct drive)."""

    motor: str
    screw: str
    gear: str | None
    drive: str

    @property
    def id(self) -> str:
        return f"dc-{self.motor}-{self.screw}-{self.gear or 'direct'}-{self.drive}"

    def components(self) -> dict:
        return {"motor": self.motor, "screw": self.screw, "gear": self.gear, "drive": self.drive}


@dataclass(frozen=True)
class DCDesign:
    """A DC design from parts (``dc_sizing``): the parts, what the sizing
    set (the controller and the drive's limits), the static figures and,
    when it was simulated, the simulation with its figures. ``margins``:
    the static screen's, replaced by the simulation's where it ran, those
    with no limit to check (inf) left out."""

    parts: DCParts
    controller: Mapping             # gains, rate, pole, bandwidth, current and voltage limits
    static: Mapping                 # the screen's figures, SI
    metrics: Mapping
    rated_ambient: float            # degC, the lowest of the motor's, screw's and gear's ratings
    duration: float                 # s, the simulated step
    margins: Mapping
    simulation: Simulation | None = None
    simulated: Mapping = field(default_factory=lambda: EMPTY)   # the simulation's figures
    model: Mapping = field(default_factory=lambda: EMPTY)       # its model's parameters (the report's traces)

    @property
    def id(self) -> str:
        return self.parts.id

    @property
    def missed(self) -> list[str]:
        return [k for k, v in self.margins.items() if not v >= 0]

    @property
    def stage(self) -> str:
        if self.simulation is not None:
            return "simulated"
        return "pruned" if self.missed else "sized"


@dataclass(frozen=True)
class DCPartsOutcome:
    """The DC designs from parts of one solve: those recorded, the others
    counted by reason, and how many combinations the catalog makes."""

    designs: tuple = ()             # DCDesign
    ruled_out: Mapping = field(default_factory=lambda: EMPTY)
    combinations: int = 0


# --- piezo pump ---------------------------------------------------------------
@dataclass(frozen=True)
class PumpDesign:
    """A piezo pump design (``pump.py``): its parts, the variables the screen
    set, its static figures, margins and metrics and, when it was simulated,
    the cycle simulation (failed: it diverged). ``margins``: the static ones
    with the simulated speed in place of the cycle-averaged one."""

    group: object                   # pump_screen.Group, the parts
    voltage: float                  # V, the drive's peak
    frequency: float                # Hz, pumping
    pump_diameter: float            # m
    cylinder_diameter: float        # m
    bias_pressure: float            # Pa, the accumulator's
    static: Mapping                 # SI, the cycle-averaged model's and the derived ones
    static_margins: Mapping
    metrics: Mapping
    margins: Mapping
    simulation: Simulation | None = None

    @property
    def id(self) -> str:
        g, f = self.group, self.frequency
        return (f"pp-{g.n}x{g.stack.id}-{g.valve.id}-{g.accumulator.id}-p{self.pump_diameter * 1e3:.0f}"
                f"-c{self.cylinder_diameter * 1e3:.0f}-{f:.0f}hz")


@dataclass(frozen=True)
class PumpOutcome:
    """The piezo pumps of one solve: the designs recorded, the rows counted
    by reason, the one-line records of bodies outside the envelope, counts."""

    designs: tuple = ()             # PumpDesign
    ruled_out: Mapping = field(default_factory=lambda: EMPTY)
    records: tuple = ()
    counts: Mapping = field(default_factory=lambda: EMPTY)


@dataclass(frozen=True)
class Stages:
    """What each stage of one solve produced, for the report's traces and
    for ``robust`` (which re-verifies the designs it picks by id)."""

    verified: tuple = ()            # VerifiedDesign, piezohydraulic
    by_id: Mapping = field(default_factory=dict)
    dc: Mapping = field(default_factory=lambda: EMPTY)      # id -> DCActuatorDesign or DCDesign
    pumps: tuple = ()               # PumpDesign

    @classmethod
    def of(cls, verified, dc=(), pumps=()) -> "Stages":
        verified = tuple(verified)
        return cls(verified, MappingProxyType({v.design.id: v.design for v in verified}),
                   MappingProxyType({d.id: d for d in dc}), tuple(pumps))


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
    warm_up_time: float             # s, heating from the fill temperature to the required one
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
    min_stiffness: float = 0.0      # N/m, output stiffness at rest the requirements ask (0: none)
    stroke_from: str = "loaded_rest"    # where the stroke is counted under the load (engine/holding.py)
    edge_restraint: float = 0.0     # end cap and base plate edge, k_theta a / D (0 simply supported, inf clamped)

    @classmethod
    def of(cls, req) -> "PiezoBrief":
        r, o, L, env = req.requirements, req.options, req.load, req.envelope
        return cls(stroke=r.stroke, blocked_force=r.blocked_force, speed=r.speed, temperature=r.max_temperature,
                   delta_T=r.max_temperature - o.drift_reference_temperature, stroke_time=req.stroke_time,
                   natural_frequency=req.natural_frequency, strokes_per_second=req.duty.strokes_per_second,
                   hold_time=req.duty.hold_time, warm_up_time=req.duty.warm_up_time, allowed_drift=o.max_drift_fraction * r.stroke,
                   max_amplifier_units=o.max_amplifier_units, wide_gap_floor=o.wide_gap or 0.0,
                   design_margin=o.design_margin, stiffness_ratio=o.structure_stiffness_ratio,
                   max_length=env.max_length, max_diameter=env.diameter, max_mass=env.max_mass,
                   surface_mass=surface_mass(L), max_load=max(c["load_N"] for c in load_cases(L)),
                   objectives=tuple(req.objectives.minimize), thermal_compensation=bool(o.thermal_compensation),
                   min_stiffness=r.min_stiffness or 0.0, stroke_from=r.stroke_from,
                   edge_restraint=float(structure.edge_restraint(o.plate_edge, o.flange_restraint)))


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
    return Stages.of(records.get("piezohydraulic", ()), records.get("dc_motor", ()), records.get("piezo_pump", ()))
