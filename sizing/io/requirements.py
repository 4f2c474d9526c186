"""requirements.toml: what ``sizing solve`` must meet (CONTRACTS.md).

``[requirements]``, ``[load]`` and ``[objectives]`` are the contract's
tables. ``[options]`` is an extension with defaults: the assumptions of the
search (stack counts, margins, the wide-chamber gap) and of the 100 degC
mitigations (thermal compensator, amplifier location), each stated in the
report. Values are converted to SI once, here.
"""
from __future__ import annotations

import hashlib
from pathlib import Path
from typing import Literal, Optional

from pydantic import Field, field_validator

from .design import LoadTable
from .schema import Qty, Strict, load_toml, parse_model, read_input_bytes

OBJECTIVES = ("mass", "cost", "volume", "power")
ABSOLUTE_ZERO_DEGC = -273.15


class RequirementsTable(Strict):
    stroke: Qty("length", positive=True)
    blocked_force: Qty("force", positive=True)
    speed: Qty("speed", positive=True)
    max_temperature: Qty("temperature")

    @field_validator("max_temperature")
    @classmethod
    def _above_absolute_zero(cls, value: float) -> float:
        if value <= ABSOLUTE_ZERO_DEGC:
            raise ValueError(f"expected a temperature above absolute zero, got {value!r} degC")
        return value


class ObjectivesTable(Strict):
    minimize: list[Literal["mass", "cost", "volume", "power"]] = Field(
        default_factory=lambda: ["mass", "cost"], min_length=1)

    @field_validator("minimize")
    @classmethod
    def _unique(cls, value: list[str]) -> list[str]:
        if len(set(value)) != len(value):
            raise ValueError(f"expected each objective once, got {value!r}")
        return value


class OptionsTable(Strict):
    """Assumptions of the search; every one is printed in the report."""

    max_stacks: int = Field(20, ge=1, le=200)             # stack counts tried: 1..max_stacks
    wide_gap: Qty("length", positive=True) = 3e-3         # oil gap in the wide chamber
    design_margin: Qty("dimensionless", nonnegative=True) = 0.05   # static sizing margin on stroke and force
    max_overshoot: Qty("dimensionless", positive=True) = 0.10      # simulated overshoot allowed
    min_natural_frequency: Optional[Qty("frequency", positive=True)] = None  # default: 10 / (stroke / speed)
    max_drift_fraction: Qty("dimensionless", positive=True) = 0.10  # thermal drift allowed, fraction of stroke
    drift_reference_temperature: Qty("temperature") = 20.0          # oil filled and sealed at this temperature
    thermal_compensation: bool = True                     # also evaluate every design with a compensator
    compensator_mass: Qty("mass", nonnegative=True) = 0.4            # assumed spring-loaded accumulator
    compensator_cost_usd: Qty("dimensionless", nonnegative=True) = 800.0
    amplifier_location: Literal["bay", "actuator"] = "bay"
    electronics_bay_temperature: Qty("temperature") = 30.0           # assumed conditioned bay, where the amplifier sits when "bay"
    max_simulated: int = Field(400, ge=1, le=100000)      # candidates verified by simulation
    dc_motors: bool = True                                # rank the catalog's DC actuators too


class DutyTable(Strict):
    """What the actuator does repeatedly (CONTRACTS.md, second round): the
    thermal checks (winding temperature, amplifier continuous current) use
    the RMS over this cycle. One full stroke out and back counts as one."""

    strokes_per_second: float = Field(1.0, gt=0.0, allow_inf_nan=False)


class RequirementsFile(Strict):
    requirements: RequirementsTable
    load: LoadTable
    objectives: ObjectivesTable = Field(default_factory=ObjectivesTable)
    options: OptionsTable = Field(default_factory=OptionsTable)
    duty: DutyTable = Field(default_factory=DutyTable)
    notes: Optional[str] = None

    @property
    def stroke_time(self) -> float:
        """Time allowed for the stroke, s: stroke / speed."""
        return self.requirements.stroke / self.requirements.speed

    @property
    def natural_frequency(self) -> float:
        """Lowest natural frequency accepted, Hz (default ten cycles per stroke time)."""
        f = self.options.min_natural_frequency
        return f if f is not None else 10.0 / self.stroke_time


def load_requirements(path: str | Path) -> tuple[RequirementsFile, str]:
    """Read and validate requirements.toml; returns the model and the
    file's sha256. Raises InputError naming the file and the field."""
    path = Path(path)
    data = load_toml(path)
    req = parse_model(RequirementsFile, data, path)
    if req.load.force is None and not req.load.dynamic_pressure:
        from ..errors import InputError
        raise InputError(str(path), "[load].dynamic_pressure", "expected at least one load case")
    return req, hashlib.sha256(read_input_bytes(path)).hexdigest()
