"""The records the DC motor stages pass from stage to stage: a catalog
actuator simulated (``DCActuatorDesign``), a design from parts
(``DCParts``, ``DCDesign``) and the designs from parts of one solve
(``DCPartsOutcome``). None is changed after it is made (``engine.records``)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Mapping

from ...engine.records import EMPTY, Simulation

if TYPE_CHECKING:                   # the types alone: not imported when the module loads
    from ...io.catalog import DCActuator


@dataclass(frozen=True)
class DCActuatorDesign:
    """A catalog DC actuator simulated under every load case (``catalog_actuators``)."""

    actuator: DCActuator
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
