"""design.toml of a piezohydraulic actuator for ``sizing evaluate`` (docs/formats.md):
the file model its ``technology`` tag selects (``io.design.load_design``)."""
from __future__ import annotations

from typing import Literal, Optional

from pydantic import Field, model_validator

from ...io.design import LoadTable
from ...io.schema import Qty, Strict


class PiezoDesignFile(Strict):
    technology: Literal["piezohydraulic"]
    stack: str
    n_stacks: int = Field(gt=0, le=1000)
    ratio: Optional[Qty("dimensionless", positive=True)] = None
    voltage: Optional[Qty("voltage", positive=True)] = None
    wide_diameter: Optional[Qty("length", positive=True)] = None
    narrow_diameter: Optional[Qty("length", positive=True)] = None
    fluid: Optional[str] = None
    seal: Optional[str] = None
    amplifier: Optional[str] = None
    wide_gap: Qty("length", positive=True) = 3e-3
    pressure_rating: Optional[Qty("pressure", positive=True)] = None
    wide_piston_mass: Optional[Qty("mass", positive=True)] = None
    narrow_piston_mass: Optional[Qty("mass", positive=True)] = None
    wide_friction: Optional[Qty("force", nonnegative=True)] = None
    narrow_friction: Optional[Qty("force", nonnegative=True)] = None
    breakaway_ratio: Optional[Qty("dimensionless", positive=True)] = None
    loss_coefficient: Optional[Qty("dimensionless", nonnegative=True)] = None
    bulk_modulus: Optional[Qty("pressure", positive=True)] = None
    rise_time: Qty("time", positive=True) = 0.1
    # the drive as ``sizing solve`` sized it: units in parallel (default 1) and
    # the ramp they drive (default: rise_time, lengthened to what the units allow)
    amplifier_units: Optional[int] = Field(None, gt=0, le=1000)
    ramp_time: Optional[Qty("time", positive=True)] = None
    temperature: Qty("temperature") = 25.0
    no_return: bool = False
    # force path, thermal budget and drive duty
    material: Optional[str] = None                     # catalogs/materials.toml id (caps, base plate, frame)
    end_cap_thickness: Optional[Qty("length", positive=True)] = None
    frame_area: Optional[Qty("area", positive=True)] = None
    structure_stiffness_ratio: Qty("dimensionless", positive=True) = 3.0
    # how the end cap and base plate are held at their edge: "simply_supported" (the
    # conservative edge), "clamped", or "flange", a bolted flange whose rotational
    # stiffness k_theta is stated as flange_restraint = k_theta a / D (physics/structure.py)
    plate_edge: Literal["simply_supported", "clamped", "flange"] = "simply_supported"
    flange_restraint: Qty("dimensionless", positive=True) = 2.0
    compensator: Optional[str] = None                  # catalogs/compensators.toml id
    spacer_length: Qty("length", nonnegative=True) = 0.0   # low-expansion spacer in the stack column (passive compensation)
    air_fraction: Qty("dimensionless", nonnegative=True) = 0.0   # entrained air by volume
    air_pressure: Qty("pressure", positive=True) = 101325.0       # absolute pressure the air fraction is stated at
    strokes_per_second: Qty("frequency", positive=True) = 1.0     # duty for the amplifier's continuous current
    load: LoadTable = Field(default_factory=LoadTable)
    notes: Optional[str] = None

    @model_validator(mode="after")
    def _geometry(self):
        if self.air_fraction >= 1.0:
            raise ValueError(f"air_fraction: expected a volume fraction below 1, got {self.air_fraction!r}")
        if (self.wide_diameter is None) != (self.narrow_diameter is None):
            raise ValueError("give both wide_diameter and narrow_diameter, or neither")
        if self.ratio is None and self.wide_diameter is None:
            raise ValueError("give ratio, or wide_diameter and narrow_diameter")
        if self.wide_diameter is not None and self.wide_diameter <= self.narrow_diameter:
            raise ValueError("wide_diameter must be larger than narrow_diameter")
        return self


DESIGN_FILE = PiezoDesignFile
