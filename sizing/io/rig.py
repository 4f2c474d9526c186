"""rig.toml: the nominal model of the hardware under test (docs/formats.md)."""
from __future__ import annotations

from pathlib import Path
from typing import Literal, Optional, Union

from pydantic import Field, model_validator

from .schema import BW_EXPONENT, BW_LINEAR, BW_SHAPE, GAIN, Qty, Strict, parse_tagged


class BoucWenRig(Strict):
    alpha: BW_LINEAR
    beta: BW_SHAPE
    gamma: BW_SHAPE
    delta: BW_LINEAR
    n: BW_EXPONENT


class StackRig(Strict):
    count: int = Field(gt=0)
    stiffness: Qty("stiffness", positive=True)
    d33: Qty("strain_per_volt", positive=True)
    bouc_wen: BoucWenRig


class HydraulicsRig(Strict):
    wide_diameter: Qty("length", positive=True)
    narrow_diameter: Qty("length", positive=True)
    wide_piston_mass: Qty("mass", positive=True)
    narrow_piston_mass: Qty("mass", positive=True)
    fluid_density: Qty("density", positive=True)
    loss_coefficient: Qty("dimensionless", nonnegative=True)
    # additions (optional): oil spring and geometry
    bulk_modulus: Qty("pressure", positive=True) = 1.5e9
    wide_gap: Qty("length", positive=True) = 3e-3
    narrow_length: Qty("length", positive=True) = 0.02
    expansion_loss_coefficient: Optional[Qty("dimensionless", nonnegative=True)] = None

    @model_validator(mode="after")
    def _order(self):
        if self.wide_diameter <= self.narrow_diameter:
            raise ValueError("wide_diameter must be larger than narrow_diameter")
        return self


class SealsRig(Strict):
    wide_friction: Qty("force", nonnegative=True)
    narrow_friction: Qty("force", nonnegative=True)
    breakaway_ratio: Qty("dimensionless", positive=True) = 1.0


class LoadRig(Strict):
    force: Qty("force") = 0.0
    stiffness: Qty("stiffness", nonnegative=True) = 0.0


class PiezoRig(Strict):
    kind: Literal["piezohydraulic"]
    stack: StackRig
    hydraulics: HydraulicsRig
    seals: SealsRig
    load: LoadRig = Field(default_factory=LoadRig)
    no_return: bool = False
    notes: Optional[str] = None


class MotorRig(Strict):
    c1: float = Field(ge=-1e6, allow_inf_nan=False)
    c2: float = Field(gt=0, le=1e9, allow_inf_nan=False)
    screw_lead: Qty("length", positive=True)
    screw_efficiency: Qty("dimensionless", positive=True) = 0.9
    torque_constant: Qty("torque_constant", positive=True) = 0.1

    @model_validator(mode="after")
    def _stable(self):
        if not self.c1 < 0:
            raise ValueError(f"c1: expected a negative rate (-lambda/J), got {self.c1!r}")
        return self


class ControllerRig(Strict):
    rate: Qty("frequency", positive=True)
    kp: GAIN
    ki: GAIN
    kd: GAIN
    derivative_on: Literal["error", "measurement"] = "error"
    current_limit: Qty("current", positive=True)


class DCRig(Strict):
    kind: Literal["dc_motor"]
    motor: MotorRig
    controller: ControllerRig
    load: LoadRig = Field(default_factory=LoadRig)
    notes: Optional[str] = None


Rig = Union[PiezoRig, DCRig]


# the rig kinds (a rig.toml's ``kind``, and the columns of its run CSVs, ``runs.read_runs``)
STACK_KIND = "piezohydraulic"       # a piezo stack driving oil
DC_KIND = "dc_motor"                # a DC motor driving a lead screw


def load_rig(path: str | Path) -> Rig:
    return parse_tagged(path, "kind", {STACK_KIND: PiezoRig, DC_KIND: DCRig})
