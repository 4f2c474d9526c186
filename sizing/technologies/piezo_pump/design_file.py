"""design.toml of a piezo pump for ``sizing evaluate`` (docs/formats.md):
the file model its ``technology`` tag selects (``io.design.load_design``)."""
from __future__ import annotations

from typing import ClassVar, Literal, Optional

from pydantic import Field

from ...io.design import LoadTable
from ...io.schema import Qty, Strict


class PumpDesignFile(Strict):
    """A pump design, the ``design`` block ``sizing solve`` writes
    for one (CONTRACTS: pump_frequency, pump_diameter, cylinder_diameter,
    bias_pressure, valve, stack, n_stacks, voltage, fluid, seal, amplifier,
    accumulator, temperature), with the requirements its margins are judged
    against (``stroke``, ``speed``, ``blocked_force``) and, optionally, the
    line from pump to cylinder. ``pump_frequency`` may be set anywhere
    below the valve's wetted resonance: above its rating it is a warning."""
    technology: Literal["piezo_pump"]
    stack: str
    n_stacks: int = Field(gt=0, le=100)
    voltage: Optional[Qty("voltage", positive=True)] = None
    pump_frequency: Qty("frequency", positive=True)
    pump_diameter: Qty("length", positive=True)
    cylinder_diameter: Qty("length", positive=True)
    bias_pressure: Optional[Qty("pressure", nonnegative=True)] = None   # default: the accumulator's
    valve: str
    accumulator: str
    fluid: str
    seal: str
    amplifier: str
    temperature: Qty("temperature") = 25.0
    line_length: Optional[Qty("length", positive=True)] = None
    line_diameter: Optional[Qty("length", positive=True)] = None
    stroke: Qty("length", positive=True) = 0.04
    speed: Qty("speed", positive=True) = 0.1
    blocked_force: Qty("force", positive=True) = 2500.0
    strokes_per_second: float = Field(1.0, gt=0.0, allow_inf_nan=False)
    load: LoadTable = Field(default_factory=LoadTable)
    notes: Optional[str] = None

    # robust judges it at the required maximum temperature, moving its piezo parts only
    sampled_temperature: ClassVar[bool] = False

    @property
    def tolerated_parts(self) -> tuple[str, ...]:
        """The parts robust's tolerances move (``studies.tolerances.applicable``)."""
        from ...io.requirements import PIEZO_PARTS
        return PIEZO_PARTS


DESIGN_FILE = PumpDesignFile
