"""requirements.toml: what ``sizing solve`` must meet (docs/formats.md).

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

from .. import settings
from .design import LoadTable
from .schema import Qty, Strict, load_toml, parse_model, read_input_bytes

OBJECTIVES = ("mass", "cost", "volume", "power")
ABSOLUTE_ZERO_DEGC = -273.15
MIN_STROKE_M = 1e-4


class RequirementsTable(Strict):
    stroke: Qty("length", positive=True)
    blocked_force: Qty("force", positive=True)
    speed: Qty("speed", positive=True)
    max_temperature: Qty("temperature")
    # the bus the DC drive and winding are chosen for (None: each drive at its rated bus)
    supply_voltage: Optional[Qty("voltage", positive=True)] = None
    # output stiffness at rest, checked for every technology (None: not required)
    min_stiffness: Optional[Qty("stiffness", positive=True)] = None
    # where the stroke is counted under a load: "loaded_rest", the seed's reading (its
    # simulation counts from where the load leaves the output at zero drive), or
    # "neutral" (a surface held to a position: the load's push-back is lost travel)
    stroke_from: Literal["neutral", "loaded_rest"] = "loaded_rest"

    @field_validator("stroke")
    @classmethod
    def _amplified_scale(cls, value: float) -> float:
        # below a tenth of a millimetre a stack drives the surface directly (PICA
        # stacks give 0.1-0.2 mm): the amplified actuators sized here have no
        # design there, and the search would size thousands of them first
        if value < MIN_STROKE_M:
            raise ValueError(f"expected a stroke of at least {MIN_STROKE_M * 1e3:g} mm (an amplified actuator; "
                             f"below it a piezo stack drives the surface directly), got {value * 1e3:g} mm")
        return value

    @field_validator("max_temperature")
    @classmethod
    def _above_absolute_zero(cls, value: float) -> float:
        if value <= ABSOLUTE_ZERO_DEGC:
            raise ValueError(f"expected a temperature above absolute zero, got {value!r} degC")
        return value


class ObjectivesTable(Strict):
    minimize: list[Literal["mass", "cost", "volume", "power"]] = Field(
        default_factory=lambda: ["mass", "cost"], min_length=1)
    # probability of compliance under [tolerances] the recommendation must
    # reach (studies/compliance.py); 0: the nominal answer
    min_compliance: Qty("dimensionless", nonnegative=True) = settings.MIN_COMPLIANCE

    @field_validator("min_compliance")
    @classmethod
    def _probability(cls, value: float) -> float:
        if value > 1.0:
            raise ValueError(f"expected a probability from 0 to 1 (or 0 % to 100 %), got {value!r}")
        return value

    @field_validator("minimize")
    @classmethod
    def _unique(cls, value: list[str]) -> list[str]:
        if len(set(value)) != len(value):
            raise ValueError(f"expected each objective once, got {value!r}")
        return value


class OptionsTable(Strict):
    """Assumptions of the search; every one is printed in the report."""

    max_stacks: int = Field(20, ge=1, le=200)             # stack counts tried: 1..max_stacks
    # smallest oil gap in the wide chamber; None: the gap is sized, the stack
    # stroke plus a clearance and a manufacturing tolerance (the stacks' technology, verify.py)
    wide_gap: Optional[Qty("length", positive=True)] = None
    design_margin: Qty("dimensionless", nonnegative=True) = settings.DESIGN_MARGIN   # static sizing margin on stroke and force
    max_overshoot: Qty("dimensionless", positive=True) = settings.MAX_OVERSHOOT      # simulated overshoot allowed
    min_natural_frequency: Optional[Qty("frequency", positive=True)] = None  # default: 10 / (stroke / speed)
    max_drift_fraction: Qty("dimensionless", positive=True) = settings.MAX_DRIFT_FRACTION  # thermal drift allowed, fraction of stroke
    drift_reference_temperature: Qty("temperature") = 20.0          # oil filled and sealed at this temperature
    thermal_compensation: bool = True                     # also evaluate every design with a compensator
    compensator_mass: Qty("mass", nonnegative=True) = 0.4            # assumed spring-loaded accumulator
    compensator_cost_usd: Qty("dimensionless", nonnegative=True) = 800.0
    amplifier_location: Literal["bay", "actuator"] = "bay"
    electronics_bay_temperature: Qty("temperature") = 30.0           # assumed conditioned bay, where the amplifier sits when "bay"
    max_simulated: int = Field(400, ge=1, le=100000)      # candidates verified by simulation
    # amplifier units a piezo drive may put in parallel (assumed: one rack)
    max_amplifier_units: int = Field(16, ge=1, le=1000)
    dc_motors: bool = True                                # rank the catalog's DC actuators too
    dc_brake: bool = False                                # a holding brake on every DC design from parts
    # end cap, base plate and frame each at least this x the stacks' stiffness; the
    # geometric program makes them stiffer where the blocked force needs it. 3 is the reviewer's
    # "frame three times stiffer than the stacks" (10-18 kg of 6061 for a 9-stack design);
    # at the floor the three members together are as compliant as the stacks (force halves)
    structure_stiffness_ratio: Qty("dimensionless", positive=True) = settings.STRUCTURE_STIFFNESS_RATIO
    # how the end cap and base plate are held at their edge: "simply_supported" (the
    # conservative edge), "clamped", or "flange", a bolted flange whose rotational
    # stiffness k_theta is stated as flange_restraint = k_theta a / D (physics/structure.py)
    plate_edge: Literal["simply_supported", "clamped", "flange"] = "simply_supported"
    # assumed: 2, a flange halfway between the two edges in edge compliance 1 / (1 + nu + beta)
    flange_restraint: Qty("dimensionless", positive=True) = 2.0


class DutyTable(Strict):
    """What the actuator does repeatedly (docs/formats.md): the
    thermal checks (winding temperature, amplifier continuous current) use
    the RMS over this cycle. One full stroke out and back counts as one."""

    strokes_per_second: float = Field(1.0, gt=0.0, allow_inf_nan=False)
    # how long a deflection is held under the steady load: the creep of a
    # leaking compensator over it is a margin. 60 s: a held trim deflection
    hold_time: Qty("time", positive=True) = 60.0
    # how long the actuator takes to heat from the fill temperature to the required one:
    # a compensator is credited only with what it takes up within the warm-up and the hold.
    # assumed: 10 min, a glide body's structure heating through its flight (no figure in the seed)
    warm_up_time: Qty("time", positive=True) = 600.0


class EnvelopeTable(Strict):
    """Where the actuator must fit; each key optional (SI after reading).
    A design outside it is ruled out, never ranked."""

    max_length: Optional[Qty("length", positive=True)] = None
    max_diameter: Optional[Qty("length", positive=True)] = None
    max_width: Optional[Qty("length", positive=True)] = None     # a square section: its side
    max_mass: Optional[Qty("mass", positive=True)] = None

    @property
    def diameter(self) -> float | None:
        """The tightest of max_diameter and max_width (a circular body in a square bay)."""
        given = [v for v in (self.max_diameter, self.max_width) if v is not None]
        return min(given) if given else None


# [tolerances] (docs/formats.md): relative 1-sigma normal spread of
# a catalog field, keyed "kind.field". Used when the table is absent (sizing
# robust); the stack, fluid and seal values are the contract's example, assumed:
# typical datasheet tolerances of PICA stacks (stroke, stiffness), oil bulk
# modulus data scatter and seal friction scatter, not measured on these parts.
# DC parts: motor datasheets state +/-10 % on their data
# (Beckhoff AM8100 technical data, "the data can have a tolerance of +/- 10%";
# HIWIN torque motors, "+/-10 % for all specification values"), taken, like
# the stack's, as the 1-sigma spread of k_t, R and R_th; the others are
# assumed (README, "Robust sizing"). A tolerance applies to the designs whose
# parts have that field: stack, fluid, seal, amplifier to designs of stacks
# and oil, motor, screw, gear, drive to motor designs sized from parts;
# operating.temperature to all.
PIEZO_DEFAULT_TOLERANCES = {"stack.stroke": 0.05, "stack.stiffness": 0.10, "fluid.bulk_modulus": 0.20,
                            "seal.friction_per_length": 0.30, "fluid.air_fraction": 0.001}
DC_DEFAULT_TOLERANCES = {"motor.torque_constant": 0.10, "motor.winding_resistance": 0.10,
                         "motor.thermal_resistance": 0.10,
                         "motor.viscous_damping": 0.30,    # assumed: itself an estimate (catalogs/motors.toml)
                         "screw.efficiency": 0.05,         # assumed: ball screws 0.85-0.95 with preload and grease
                         "gear.efficiency": 0.05,          # assumed: as the screw's
                         "drive.peak_current": 0.03,       # assumed: current-loop gain and shunt accuracy
                         "drive.bus_voltage": 0.05}        # assumed: bus regulation under load
DEFAULT_TOLERANCES = {**PIEZO_DEFAULT_TOLERANCES, **DC_DEFAULT_TOLERANCES, "operating.temperature": 1.0}
PIEZO_PARTS = ("stack", "fluid", "seal", "amplifier")
DC_PARTS = ("motor", "screw", "gear", "drive")
TOLERANCE_PSEUDO_FIELDS = {"fluid.air_fraction", "operating.temperature"}
# relative spreads of the stack's Bouc-Wen parameters (seed eq. 1-2), e.g.
# from a fit's standard errors (``sizing robust --bouc-wen-fit``)
BOUC_WEN_TOLERANCES = tuple(f"stack.bouc_wen.{p}" for p in ("d33", "alpha", "beta", "gamma", "delta", "n"))


def tolerance_fields() -> dict[str, list[str]]:
    """Catalog fields a tolerance may name, per part kind (stack and oil
    parts, motor parts): the numeric quantities, without temperatures (a
    relative spread of a degC value means nothing)."""
    from .catalog import Amplifier, Drive, Fluid, Gear, Motor, Screw, Seal, Stack
    out = {}
    for kind, model in {"stack": Stack, "fluid": Fluid, "seal": Seal, "amplifier": Amplifier,
                        "motor": Motor, "screw": Screw, "gear": Gear, "drive": Drive}.items():
        out[kind] = [f for f in model.quantity_fields()
                     if not (f.endswith("_temperature") or f == "flash_point")]
    return out


def _check_tolerance_keys(value: dict[str, float]) -> dict[str, float]:
    fields = tolerance_fields()
    for key in value:
        kind, _, name = key.partition(".")
        if key == "operating.temperature" and value[key] > 1.0:
            raise ValueError(f'"{key}": expected a fraction of the temperature range, 0 to 100 %, got {value[key]!r}')
        if key in TOLERANCE_PSEUDO_FIELDS or key in BOUC_WEN_TOLERANCES:
            continue
        if kind not in fields or name not in fields[kind]:
            known = ", ".join(f"{k}.{f}" for k in fields for f in fields[k])
            raise ValueError(f'unknown field "{key}": expected "kind.field", one of {known}, '
                             f'{", ".join(sorted(TOLERANCE_PSEUDO_FIELDS))} or stack.bouc_wen.PARAM')
    return value


class RequirementsFile(Strict):
    requirements: RequirementsTable
    load: LoadTable
    objectives: ObjectivesTable = Field(default_factory=ObjectivesTable)
    options: OptionsTable = Field(default_factory=OptionsTable)
    duty: DutyTable = Field(default_factory=DutyTable)
    envelope: EnvelopeTable = Field(default_factory=EnvelopeTable)
    tolerances: Optional[dict[str, Qty("dimensionless", nonnegative=True)]] = None   # None: DEFAULT_TOLERANCES
    notes: Optional[str] = None

    @field_validator("tolerances")
    @classmethod
    def _tolerance_keys(cls, value):
        return value if value is None else _check_tolerance_keys(value)

    @property
    def tolerance_spreads(self) -> dict[str, float]:
        """[tolerances] as given, or DEFAULT_TOLERANCES when the table is absent."""
        return dict(DEFAULT_TOLERANCES if self.tolerances is None else self.tolerances)

    @property
    def stroke_time(self) -> float:
        """Time allowed for the stroke, s: stroke / speed."""
        return self.requirements.stroke / self.requirements.speed

    @property
    def natural_frequency(self) -> float:
        """Lowest natural frequency accepted, Hz (default ten cycles per stroke time)."""
        f = self.options.min_natural_frequency
        return f if f is not None else 10.0 / self.stroke_time


# A bare number is SI (docs/formats.md), so stroke = 40 is 40 m, which its
# author meant as 40 mm. Bare numbers beyond what a control-surface actuator
# could ask are refused with the unit to write: (SI unit, largest plausible, example)
BARE_LIMITS = {"requirements": {"stroke": ("m", 1.0, '"40 mm"'), "speed": ("m/s", 10.0, '"100 mm/s"'),
                                "blocked_force": ("N", 1e7, '"2.5 kN"')},
               "envelope": {"max_length": ("m", 10.0, '"300 mm"'), "max_diameter": ("m", 5.0, '"120 mm"'),
                            "max_width": ("m", 5.0, '"120 mm"')}}


def _check_bare_numbers(data: dict, path: Path) -> None:
    """Refuse a bare (SI) number far beyond its field's scale: most likely
    written in another unit (exit 2, naming the unit to write)."""
    from ..errors import InputError
    for table, fields in BARE_LIMITS.items():
        section = data.get(table)
        if not isinstance(section, dict):
            continue
        for key, (unit, largest, example) in fields.items():
            value = section.get(key)
            if isinstance(value, (int, float)) and not isinstance(value, bool) and abs(value) > largest:
                raise InputError(str(path), f"[{table}].{key}",
                                 f"a bare number is SI: {value!r} means {value!r} {unit}; write the unit, "
                                 f"e.g. {example}")


def load_requirements(path: str | Path) -> tuple[RequirementsFile, str]:
    """Read and validate requirements.toml; returns the model and the
    file's sha256. Raises InputError naming the file and the field."""
    path = Path(path)
    data = load_toml(path)
    req = parse_requirements(data, path)
    _check_bare_numbers(data, path)
    return req, hashlib.sha256(read_input_bytes(path)).hexdigest()


def parse_requirements(data: dict, path: str | Path) -> RequirementsFile:
    """Validate requirements already read as a dict (``sizing sweep`` edits
    one field per grid point); errors name ``path``."""
    req = parse_model(RequirementsFile, data, path)
    if req.load.force is None and not req.load.dynamic_pressure:
        from ..errors import InputError
        raise InputError(str(path), "[load].dynamic_pressure", "expected at least one load case")
    return req


def design_requirements(design, loads: list[float]) -> RequirementsFile:
    """The requirements a DC design file from parts implies for ``sizing
    evaluate``: its step, speed (the controller rule), temperature, duty and
    drive location; blocked force 1 N (evaluate reports figures, not that
    margin)."""
    supply = {} if design.supply_voltage is None else {"supply_voltage": design.supply_voltage}
    return RequirementsFile.model_validate({
        "requirements": {"stroke": design.step, "blocked_force": 1.0, "speed": design.speed,
                         "max_temperature": design.temperature, **supply},
        "load": {"force": list(loads)}, "duty": {"strokes_per_second": design.strokes_per_second},
        "options": {"amplifier_location": design.amplifier_location,
                    "electronics_bay_temperature": design.electronics_bay_temperature,
                    "dc_brake": design.brake}})
