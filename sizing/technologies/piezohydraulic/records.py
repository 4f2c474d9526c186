"""The records the piezohydraulic stages pass from stage to stage: the
requirements in SI (``PiezoBrief``), a way to build a combination
(``Variant``), a sized design with its static figures and margins
(``PiezoDesign``) and a design verified by simulation
(``VerifiedDesign``). None is changed after it is made (``engine.records``)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Mapping

from ...engine.loads import load_cases, surface_mass
from ...engine.records import EMPTY, Simulation
from ...physics import structure

if TYPE_CHECKING:                   # the types alone: not imported when the module loads
    from ...io.catalog import Compensator, Material
    from .convex import SizingResult
    from .parts import Candidates
    from .search import Combo


@dataclass(frozen=True)
class Variant:
    """One way to build a combination: structure material and thermal
    compensation (no compensator: as built; ``passive``: a low-expansion
    spacer that cancels the thermal budget; else a catalog compensator)."""

    material: Material
    compensator: Compensator | None = None
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
    from in the list handed to ``designs.designs`` (a passive design
    shares its as-built parent's). Before it is built (the sizing gave no
    finite geometry) ``cand`` is None and the figures are empty."""

    origin: int
    id: str
    combo: Combo
    variant: Variant
    gp: SizingResult
    spacer: float = 0.0             # m, passive-compensation spacer (0: none)
    bouc_wen: tuple | None = None   # (BoucWen, source) of its stack; None: not buildable
    cand: Candidates | None = None  # one row
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
class VerifiedDesign:
    """A built design and, when it was simulated, the simulation's outcome."""

    design: PiezoDesign
    simulation: Simulation | None = None


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
