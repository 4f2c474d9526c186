"""The records the piezo pump stages pass from stage to stage: a design
(``PumpDesign``) and the pumps of one solve (``PumpOutcome``). None is
changed after it is made (``engine.records``)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Mapping

from ...engine.records import EMPTY, Simulation

if TYPE_CHECKING:                   # the types alone: not imported when the module loads
    from .screen import Group


@dataclass(frozen=True)
class PumpDesign:
    """A piezo pump design (``pump.py``): its parts, the variables the screen
    set, its static figures, margins and metrics and, when it was simulated,
    the cycle simulation (failed: it diverged). ``margins``: the static ones
    with the simulated speed in place of the cycle-averaged one."""

    group: Group                    # the parts
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
