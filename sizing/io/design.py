"""design.toml: one design for ``sizing evaluate`` (docs/formats.md)."""
from __future__ import annotations

from pathlib import Path
from typing import Literal, Optional, Union, get_args

from pydantic import Field, field_validator, model_validator

from . import toml_text
from .schema import Qty, Strict, parse_tagged


class LoadTable(Strict):
    """The hinged control surface of the seed's Figure 7, or plain forces."""

    span: Qty("length", positive=True) = 15 * 0.0254
    chord: Qty("length", positive=True) = 10 * 0.0254
    thickness: Qty("length", positive=True) = 0.0625 * 0.0254
    density: Qty("density", positive=True) = 2700.0   # surface material (its inertia, reflected by R^2); assumed aluminium
    dynamic_pressure: list[Qty("pressure", nonnegative=True)] = Field(default_factory=lambda: [10e3, 25e3])
    force: Optional[list[Qty("force")]] = None      # explicit forces instead of pressures
    stiffness: Qty("stiffness", nonnegative=True) = 0.0

    @field_validator("force")
    @classmethod
    def _some_force(cls, value):
        # an empty list would run no load case: evaluate rejects it as solve does
        if value is not None and not value:
            raise ValueError("expected at least one load case, got an empty list")
        return value


def n_loads(load: LoadTable) -> int:
    """How many load cases a design file's load gives."""
    return len(load.force) if load.force is not None else len(load.dynamic_pressure)


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


DESIGN_FILES = (PiezoDesignFile, DCDesignFile, PumpDesignFile)
DesignFile = Union[DESIGN_FILES]


def load_design(path: str | Path) -> DesignFile:
    """The design file of the technology its ``technology`` field names
    (each kind's tag is its own ``technology`` literal)."""
    tags = {get_args(kind.model_fields["technology"].annotation)[0]: kind for kind in DESIGN_FILES}
    return parse_tagged(path, "technology", tags)


def design_toml(block: dict) -> str:
    """A results.json ``design`` block as a design.toml that ``sizing
    evaluate`` reads back: floats at full precision (a margin of 1e-7 must
    not flip on rounding), None left out, a dict value as a table."""
    top = [toml_text.line(k, v) for k, v in block.items() if v is not None and not isinstance(v, dict)]
    tables = [f"\n[{toml_text.key(k)}]\n" + "\n".join(toml_text.line(kk, vv) for kk, vv in v.items() if vv is not None)
              for k, v in block.items() if isinstance(v, dict)]
    return "\n".join(top) + "\n" + "".join(t + "\n" for t in tables)
