"""design.toml of a DC motor actuator (a catalog one or one from parts) for ``sizing evaluate`` (docs/formats.md):
the file model its ``technology`` tag selects (``io.design.load_design``)."""
from __future__ import annotations

from typing import Literal, Optional

from pydantic import Field, model_validator

from ...io.design import LoadTable
from ...io.schema import Qty, Strict


class DCDesignFile(Strict):
    """A catalog actuator (``actuator``), or a design from parts (``motor``,
    ``screw``, ``drive``, optional ``gear``) as ``sizing solve`` writes it:
    its controller follows from ``speed`` (the controller rule of its technology folder),
    its winding temperature from ``strokes_per_second``, its drive's
    ambient from ``amplifier_location``."""
    technology: Literal["dc_motor"]
    actuator: Optional[str] = None
    motor: Optional[str] = None
    screw: Optional[str] = None
    gear: Optional[str] = None
    drive: Optional[str] = None
    step: Qty("length", positive=True) = 0.04
    duration: Qty("time", positive=True) = 1.0
    temperature: Qty("temperature") = 25.0
    speed: Qty("speed", positive=True) = 0.1
    strokes_per_second: float = Field(1.0, gt=0.0, allow_inf_nan=False)
    # the controller and drive limits as ``sizing solve`` set them on the
    # nominal parts (kp, ki, kd, current_limit_A, voltage_limit_V); judged
    # with requirements they are kept; absent, they follow from the rule
    controller: Optional[dict[str, float]] = None
    amplifier_location: Literal["bay", "actuator"] = "bay"
    electronics_bay_temperature: Qty("temperature") = 30.0
    supply_voltage: Optional[Qty("voltage", positive=True)] = None   # design from parts: the drive's bus
    brake: bool = False                                               # design from parts: a holding brake
    load: LoadTable = Field(default_factory=LoadTable)
    notes: Optional[str] = None

    @model_validator(mode="after")
    def _one_kind(self):
        parts = [self.motor, self.screw, self.drive]
        if self.actuator is None and None in parts:
            raise ValueError("give actuator, or motor, screw and drive (and optionally gear)")
        if self.actuator is not None and any(x is not None for x in parts + [self.gear]):
            raise ValueError("give actuator or parts (motor, screw, gear, drive), not both")
        return self


DESIGN_FILE = DCDesignFile
