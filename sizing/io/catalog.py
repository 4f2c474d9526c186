"""The parts catalog: one TOML file per part kind (catalogs/README.md).

Entries are validated with pydantic into frozen models whose quantity
fields are SI floats (temperatures in degC). Each entry keeps its provenance:
``source``, ``retrieved`` and a status per value (datasheet, seed, measured,
or "assumed: reason").
"""
from __future__ import annotations

import datetime as dt
import hashlib
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Literal, Optional

from pydantic import AfterValidator, Field, ValidationInfo, field_validator, model_validator

from ..errors import InputError
from .schema import BW_LINEAR, BW_SHAPE, GAIN, Qty, Strict, load_toml, parse_model, read_input_bytes

DEFAULT_CATALOG = Path(__file__).resolve().parents[2] / "catalogs"
ID_PATTERN = re.compile(r"^[a-z0-9][a-z0-9.\-]*$")
# "sourced: <file, key, column>" is a value read from a maker's table with its
# provenance; "rule: <text>" a value the table lacks, stated from the maker's
# rule for the family (catalogs/README.md)
STATUS_PATTERN = re.compile(r"^((datasheet|seed|measured|sourced)(: .+)?|(assumed|rule): .+)$")


class Entry(Strict):
    id: str
    name: str
    manufacturer: str
    source: str
    retrieved: dt.date
    status: dict[str, str]
    notes: Optional[str] = None

    @field_validator("id")
    @classmethod
    def _id(cls, value: str) -> str:
        if not ID_PATTERN.match(value):
            raise ValueError(f"expected lower case letters, digits, '.' and '-', got {value!r}")
        return value

    @field_validator("status")
    @classmethod
    def _status(cls, value: dict[str, str]) -> dict[str, str]:
        for key, text in value.items():
            if not STATUS_PATTERN.match(text):
                raise ValueError(f'status of {key}: expected "datasheet", "seed", "measured", "sourced" (each optionally followed by ": note"), "rule: <text>" or "assumed: <reason>", got {text!r}')
        return value

    @model_validator(mode="after")
    def _every_value_has_a_status(self):
        missing = [name for name in self.quantity_fields() if name in self.model_fields_set and name not in self.status]
        if missing:
            raise ValueError(f"status: no status for {', '.join(missing)}")
        unknown = [name for name in self.status if name not in self.quantity_fields() and name != "bouc_wen"]
        if unknown:
            raise ValueError(f"status: unknown field {', '.join(unknown)}")
        return self

    @classmethod
    def quantity_fields(cls) -> list[str]:
        skip = set(Entry.model_fields) | {"bouc_wen", "pid", "material", "type", "section", "kind", "gear_mounts", "mount"}
        return [name for name in cls.model_fields if name not in skip]

    def assumed(self) -> dict[str, str]:
        """Fields whose value is assumed, with the reason."""
        return {k: v.removeprefix("assumed: ") for k, v in self.status.items() if v.startswith("assumed")}


class BoucWenTable(Strict):
    d33: Qty("strain_per_volt", positive=True)
    alpha: BW_LINEAR
    beta: BW_SHAPE
    gamma: BW_SHAPE
    delta: BW_LINEAR
    n: float = Field(le=10.0, allow_inf_nan=False)   # assumed bound, as schema.BW_EXPONENT

    @field_validator("n")
    @classmethod
    def _n(cls, value: float) -> float:
        if not value > 0:
            raise ValueError(f"expected a positive exponent, got {value!r}")
        return value


class Stack(Entry):
    stiffness: Qty("stiffness", positive=True)
    stroke_per_volt: Qty("strain_per_volt", positive=True)
    max_voltage: Qty("voltage", positive=True)
    min_voltage: Qty("voltage") = 0.0
    stroke: Qty("length", positive=True)
    blocked_force: Qty("force", positive=True)
    capacitance: Qty("capacitance", positive=True)
    mass: Qty("mass", positive=True)
    length: Qty("length", positive=True)
    diameter: Qty("length", positive=True)
    section: Literal["round", "square"] = "round"
    max_temperature: Qty("temperature")
    curie_temperature: Optional[Qty("temperature")] = None
    stroke_temperature_coefficient: Qty("per_kelvin") = 0.0
    cost_usd: Qty("dimensionless", positive=True)
    thermal_expansion: Optional[Qty("per_kelvin")] = None   # linear, along the stroke
    loss_factor: Optional[Qty("dimensionless", positive=True)] = None   # small-signal tan(delta)
    bouc_wen: Optional[BoucWenTable] = None


class Fluid(Entry):
    density: Qty("density", positive=True)
    viscosity_40C: Qty("kinematic_viscosity", positive=True)
    viscosity_100C: Qty("kinematic_viscosity", positive=True)
    bulk_modulus: Qty("pressure", positive=True)
    bulk_modulus_temperature_coefficient: Qty("per_kelvin") = 0.0
    # absolute pressure at which the entrained air has all dissolved (the
    # pump's eq. P8 of docs/models.md); None: the free air does not dissolve
    air_dissolution_pressure: Optional[Qty("pressure", positive=True)] = None
    thermal_expansion: Qty("per_kelvin", positive=True)
    min_temperature: Qty("temperature")
    max_temperature: Qty("temperature")
    flash_point: Qty("temperature")
    cost_usd: Qty("dimensionless", nonnegative=True)


class Seal(Entry):
    material: str
    type: str
    friction_per_length: Qty("friction_per_length", nonnegative=True)
    friction_pressure_coefficient: Qty("friction_per_length_pressure", nonnegative=True) = 0.0
    breakaway_ratio: Qty("dimensionless", positive=True)
    min_temperature: Qty("temperature")
    max_temperature: Qty("temperature")
    pressure_rating: Qty("pressure", positive=True)
    cost_usd: Qty("dimensionless", nonnegative=True)


class Amplifier(Entry):
    max_voltage: Qty("voltage", positive=True)
    min_voltage: Qty("voltage") = 0.0
    max_current: Qty("current", positive=True)
    continuous_current: Qty("current", positive=True)
    peak_duration: Qty("time", positive=True)                 # how long max_current may be drawn
    energy_recovery: Qty("dimensionless", nonnegative=True) = 0.0   # fraction of C V^2 returned per cycle
    max_power: Optional[Qty("power", positive=True)] = None
    slew_rate: Optional[Qty("slew", positive=True)] = None
    mass: Qty("mass", positive=True)
    max_temperature: Qty("temperature")
    cost_usd: Qty("dimensionless", nonnegative=True)


class PIDTable(Strict):
    rate: Qty("frequency", positive=True)
    kp: GAIN
    ki: GAIN
    kd: GAIN
    derivative_on: Literal["error", "measurement"] = "error"


class DCActuator(Entry):
    max_force: Qty("force", positive=True)
    continuous_force: Qty("force", positive=True)
    max_speed: Qty("speed", positive=True)
    stroke: Qty("length", positive=True)
    mass: Qty("mass", positive=True)
    length: Qty("length", positive=True)
    diameter: Qty("length", positive=True)
    min_temperature: Qty("temperature")
    max_temperature: Qty("temperature")
    screw_lead: Qty("length", positive=True)
    screw_efficiency: Qty("dimensionless", positive=True)
    torque_constant: Qty("torque_constant", positive=True)
    c1: float
    c2: float
    current_limit: Qty("current", positive=True)
    supply_voltage: Qty("voltage", positive=True)
    cost_usd: Qty("dimensionless", nonnegative=True)
    pid: PIDTable
    # the voltage ceiling (docs/models.md, the motor actuator): bus-referred back-EMF
    # constant and winding resistance; absent = no voltage limit
    back_emf_constant: Optional[Qty("back_emf_constant", positive=True)] = None
    winding_resistance: Optional[Qty("resistance", positive=True)] = None


# --- parts of a DC actuator sized from parts ---------------------
def _at_most_one(value: float) -> float:
    if not 0 < value <= 1:
        raise ValueError(f"expected an efficiency in (0, 1], got {value!r}")
    return value


Efficiency = Annotated[Qty("dimensionless", positive=True), AfterValidator(_at_most_one)]


class Motor(Entry):
    """Brushless motor. k_e is bus-referred (V s/rad: no-load speed = bus
    voltage / k_e); resistance and inductance terminal to terminal at 25 degC."""
    torque_constant: Qty("torque_constant", positive=True)
    back_emf_constant: Qty("back_emf_constant", positive=True)
    winding_resistance: Qty("resistance", positive=True)
    resistance_temperature_coefficient: Qty("per_kelvin", nonnegative=True) = 0.00393   # copper
    torque_constant_temperature_coefficient: Qty("per_kelvin") = 0.0
    inductance: Qty("inductance", positive=True)
    rotor_inertia: Qty("inertia", positive=True)
    viscous_damping: Qty("rotational_damping", nonnegative=True)
    continuous_torque: Qty("torque", positive=True)
    peak_torque: Qty("torque", positive=True)
    max_speed: Qty("angular_speed", positive=True)
    rated_voltage: Qty("voltage", positive=True)
    thermal_resistance: Qty("thermal_resistance", positive=True)
    thermal_time_constant: Qty("time", positive=True)
    max_winding_temperature: Qty("temperature")
    magnet_max_temperature: Optional[Qty("temperature")] = None
    max_temperature: Qty("temperature")            # ambient
    mass: Qty("mass", positive=True)
    cost_usd: Qty("dimensionless", nonnegative=True)
    # the gearhead mounts this motor takes (gears.mount); absent: the
    # gearheads without a mount (the generic ones)
    gear_mounts: Optional[list[str]] = None


class Screw(Entry):
    """Ball, lead or roller screw with its nut; diameter is the root
    diameter used for buckling."""
    type: Literal["ball", "lead", "roller"]
    lead: Qty("length", positive=True)
    diameter: Qty("length", positive=True)
    efficiency: Efficiency
    dynamic_load_rating: Qty("force", positive=True)
    inertia_per_length: Qty("inertia_per_length", positive=True)
    mass_per_length: Qty("mass_per_length", positive=True)
    nut_mass: Qty("mass", nonnegative=True)
    max_speed: Qty("angular_speed", positive=True)
    elastic_modulus: Qty("pressure", positive=True) = 2.0e11     # steel
    max_temperature: Qty("temperature")
    cost_usd: Qty("dimensionless", nonnegative=True)
    static_load_rating: Optional[Qty("force", positive=True)] = None   # C0 (ISO 3408-5)


class Gear(Entry):
    ratio: Qty("dimensionless", positive=True)
    efficiency: Efficiency
    inertia: Qty("inertia", nonnegative=True)          # referred to the input shaft
    mass: Qty("mass", positive=True)
    max_input_speed: Qty("angular_speed", positive=True)
    max_output_torque: Qty("torque", positive=True)                # intermittent (peak)
    max_temperature: Qty("temperature")
    cost_usd: Qty("dimensionless", nonnegative=True)
    continuous_output_torque: Optional[Qty("torque", positive=True)] = None
    mount: Optional[str] = None      # fits the motors whose gear_mounts list it


class Drive(Entry):
    bus_voltage: Qty("voltage", positive=True)
    continuous_current: Qty("current", positive=True)
    peak_current: Qty("current", positive=True)
    rate: Qty("frequency", positive=True) = 1250.0     # position loop rate
    max_temperature: Qty("temperature")                # rated ambient
    mass: Qty("mass", positive=True)
    cost_usd: Qty("dimensionless", nonnegative=True)


class Material(Entry):
    """A structural material of the force path (caps, frame, casing, pistons)."""

    youngs_modulus: Qty("pressure", positive=True)
    poisson: Qty("dimensionless", nonnegative=True)
    density: Qty("density", positive=True)
    thermal_expansion: Qty("per_kelvin", positive=True)
    yield_strength: Qty("pressure", positive=True)
    max_temperature: Qty("temperature")
    cost_usd: Qty("dimensionless", nonnegative=True)          # per kg

    @field_validator("poisson")
    @classmethod
    def _poisson(cls, value: float) -> float:
        if not value < 0.5:
            raise ValueError(f"expected a Poisson ratio below 0.5, got {value!r}")
        return value


class Compensator(Entry):
    """An active thermal compensator of the oil (catalogs/compensators.toml)."""

    kind: Literal["accumulator", "orifice_reservoir"]
    volume_stiffness: Qty("volume_stiffness", positive=True)
    leak_conductance: Qty("conductance", nonnegative=True) = 0.0
    capacity: Qty("volume", positive=True)
    mass: Qty("mass", nonnegative=True)
    max_temperature: Qty("temperature")
    cost_usd: Qty("dimensionless", nonnegative=True)


class Valve(Entry):
    """A reed check valve of a pump (catalogs/valves.toml): a reed
    over a circular port, preloaded to its cracking pressure. With its
    wetted geometry (``reed_shape``, ``reed_width``, ``reed_length``,
    ``modal_factor``) the reed carries the oil it moves (physics/pump.py,
    P5), and its rated frequency must lie below its resonance in the
    reference oil (REFERENCE_OIL_DENSITY), not only in air."""

    reed_stiffness: Qty("stiffness", positive=True)
    reed_mass: Qty("mass", positive=True)
    cracking_pressure: Qty("pressure", nonnegative=True)
    port_area: Qty("area", positive=True)
    max_lift: Qty("length", positive=True)
    discharge_coefficient: Qty("dimensionless", positive=True)
    reed_shape: Literal["cantilever", "disc"] = "cantilever"
    reed_width: Optional[Qty("length", positive=True)] = None     # a disc's diameter
    reed_length: Optional[Qty("length", positive=True)] = None
    modal_factor: Qty("dimensionless", positive=True) = 0.24
    seat_width: Qty("length", nonnegative=True) = 0.0     # the land under the reed (laminar loss, P9)
    seat_gap: Qty("length", nonnegative=True) = 0.0       # the gap a seated reed leaves (leakage, P7)
    max_frequency: Qty("frequency", positive=True)           # highest pumping frequency it is rated for
    max_temperature: Qty("temperature")
    mass: Qty("mass", positive=True)
    cost_usd: Qty("dimensionless", nonnegative=True)

    @field_validator("max_frequency")
    @classmethod
    def _below_resonance(cls, value: float, info: ValidationInfo) -> float:
        k, m = info.data.get("reed_stiffness"), info.data.get("reed_mass")
        if k and m:
            from ..physics.pump import reed_added_mass
            added = reed_added_mass(info.data.get("reed_shape", "cantilever"), REFERENCE_OIL_DENSITY,
                                    info.data.get("reed_width"), info.data.get("reed_length"),
                                    info.data.get("modal_factor", 0.24))
            resonance = (k / (m + added)) ** 0.5 / (2 * 3.141592653589793)
            if value >= resonance:
                where = "in oil, with its added mass" if added > 0 else "sqrt(reed_stiffness / reed_mass) / 2 pi"
                raise ValueError(f"expected a pumping frequency below the reed's resonance ({where}) "
                                 f"= {resonance:.4g} Hz, got {value:.4g} Hz")
        return value


# kg/m^3: the oil a valve's rating is checked in (ISO VG 15-32 mineral oils, 850-870)
REFERENCE_OIL_DENSITY = 850.0


class Accumulator(Entry):
    """A pump's bias-pressure accumulator (catalogs/accumulators.toml):
    it holds the low side at ``bias_pressure`` (gauge) and takes the oil's
    thermal expansion up to its capacity."""

    bias_pressure: Qty("pressure", nonnegative=True)
    capacity: Qty("volume", positive=True)
    max_temperature: Qty("temperature")
    mass: Qty("mass", positive=True)
    cost_usd: Qty("dimensionless", nonnegative=True)


# file name -> (TOML array name, model)
KINDS: dict[str, tuple[str, type[Entry]]] = {
    "stacks.toml": ("stack", Stack),
    "fluids.toml": ("fluid", Fluid),
    "seals.toml": ("seal", Seal),
    "amplifiers.toml": ("amplifier", Amplifier),
    "dc_actuators.toml": ("dc_actuator", DCActuator),
    "materials.toml": ("material", Material),
    "compensators.toml": ("compensator", Compensator),
    "motors.toml": ("motor", Motor),
    "screws.toml": ("screw", Screw),
    "gears.toml": ("gear", Gear),
    "drives.toml": ("drive", Drive),
    "valves.toml": ("valve", Valve),
    "accumulators.toml": ("accumulator", Accumulator),
    # parts imported from makers' tables (``sizing catalog import-mgdb``)
    "motors-mgdb.toml": ("motor", Motor),
    "gears-mgdb.toml": ("gear", Gear),
    "screws-sourced.toml": ("screw", Screw),
}


@dataclass
class Catalog:
    folder: Path
    stacks: dict[str, Stack] = field(default_factory=dict)
    fluids: dict[str, Fluid] = field(default_factory=dict)
    seals: dict[str, Seal] = field(default_factory=dict)
    amplifiers: dict[str, Amplifier] = field(default_factory=dict)
    dc_actuators: dict[str, DCActuator] = field(default_factory=dict)
    materials: dict[str, Material] = field(default_factory=dict)
    compensators: dict[str, Compensator] = field(default_factory=dict)
    motors: dict[str, Motor] = field(default_factory=dict)
    screws: dict[str, Screw] = field(default_factory=dict)
    gears: dict[str, Gear] = field(default_factory=dict)
    drives: dict[str, Drive] = field(default_factory=dict)
    valves: dict[str, Valve] = field(default_factory=dict)
    accumulators: dict[str, Accumulator] = field(default_factory=dict)
    files: dict[str, str] = field(default_factory=dict)   # file name -> sha256
    origin: dict[str, str] = field(default_factory=dict)  # entry id -> file name

    def groups(self) -> dict[str, dict[str, Entry]]:
        return {"stack": self.stacks, "fluid": self.fluids, "seal": self.seals,
                "amplifier": self.amplifiers, "dc_actuator": self.dc_actuators,
                "material": self.materials, "compensator": self.compensators,
                "motor": self.motors, "screw": self.screws, "gear": self.gears, "drive": self.drives,
                "valve": self.valves, "accumulator": self.accumulators}

    def entries(self) -> list[tuple[str, Entry]]:
        return [(kind, e) for kind, group in self.groups().items() for e in group.values()]

    def get(self, entry_id: str) -> tuple[str, Entry]:
        for kind, group in self.groups().items():
            if entry_id in group:
                return kind, group[entry_id]
        raise KeyError(entry_id)

    @property
    def sha256(self) -> str:
        digest = hashlib.sha256()
        for name in sorted(self.files):
            digest.update(f"{name}:{self.files[name]}\n".encode())
        return digest.hexdigest()


def load_catalog(folder: str | Path | None = None) -> Catalog:
    """Read and validate every catalog file in ``folder`` (default: the
    repository's catalogs/). Raises InputError naming file, entry and field."""
    folder = Path(folder) if folder is not None else DEFAULT_CATALOG
    if not folder.is_dir():
        raise InputError(str(folder), None, "expected a catalog folder")
    catalog = Catalog(folder=folder)
    defined_in: dict[str, str] = {}
    found = False
    for file_name, (array_name, model) in KINDS.items():
        path = folder / file_name
        if not os.path.lexists(path):     # a symlink loop or a dangling link is an error, not an absent file
            continue
        found = True
        catalog.files[file_name] = hashlib.sha256(read_input_bytes(path, "a TOML file")).hexdigest()
        group = catalog.groups()[array_name]
        parsed = _cached(catalog.files[file_name])
        if parsed is None:
            parsed = _parse_file(path, array_name, model)
            _store(catalog.files[file_name], parsed)
        for label, entry in parsed:
            if entry.id in defined_in:
                raise InputError(str(path), f"{label}: id", f"duplicate id, already defined in {defined_in[entry.id]}")
            defined_in[entry.id] = file_name
            catalog.origin[entry.id] = file_name
            group[entry.id] = entry
    if not found:
        raise InputError(str(folder), None, f"no catalog files ({', '.join(KINDS)})")
    _check_drives(catalog)
    return catalog


def _parse_file(path: Path, array_name: str, model: type[Entry]) -> list[tuple[str, Entry]]:
    """(label, validated entry) of every entry of one catalog file."""
    data = load_toml(path)
    unknown = [k for k in data if k != array_name]
    if unknown:
        raise InputError(str(path), unknown[0], f"unknown table; expected [[{array_name}]] entries")
    entries = data.get(array_name, [])
    if not isinstance(entries, list):
        raise InputError(str(path), array_name, f"expected [[{array_name}]] entries (an array of tables), "
                                                f"got {type(entries).__name__} {entries!r:.40}")
    out = []
    for index, raw in enumerate(entries):
        label = f"[[{array_name}]] {raw.get('id', '#' + str(index + 1))}" if isinstance(raw, dict) else f"[[{array_name}]] #{index + 1}"
        out.append((label, _parse_entry(model, raw, path, label)))
    return out


# Parsed catalog files are kept by content hash (and the schema's own hash):
# a TOML file of a thousand datasheet entries parses in about a second and
# the unit strings of the small files in a third of one; the validated
# entries unpickle in a few hundredths, in the project's cache folder
# (disk_cache.root); an unreadable or stale cache entry is parsed again.
# the models, their quantity parsing and the units: a change to any of them re-parses
_SCHEMA_HASH = hashlib.sha256(b"".join(p.read_bytes() for p in (
    Path(__file__), Path(__file__).with_name("schema.py"), Path(__file__).parents[1] / "units.py"))).hexdigest()[:16]


CACHE_KEEP = 200               # cached files kept, the most recently written


def _cache_path(digest: str) -> Path:
    from ..disk_cache import root        # the project's cache folder (SIZING_CACHE_DIR moves it)
    return root() / "catalog" / f"{digest}-{_SCHEMA_HASH}.pickle"


def _cached(digest: str):
    import pickle
    try:
        with open(_cache_path(digest), "rb") as handle:
            return pickle.load(handle)
    except Exception:           # absent, unreadable, or written by another schema
        return None


def _store(digest: str, parsed: list) -> None:
    import pickle

    from .atomic import store_cache
    store_cache(_cache_path(digest), pickle.dumps(parsed, protocol=pickle.HIGHEST_PROTOCOL), CACHE_KEEP)


def _check_drives(catalog: Catalog) -> None:
    """A drive whose bus is below the rated voltage of every motor can run
    none of them at its rating: a catalog error, not a design to rank."""
    if not catalog.motors:
        return
    lowest = min(m.rated_voltage for m in catalog.motors.values())
    for d in catalog.drives.values():
        if d.bus_voltage < lowest * (1 - 1e-9):
            raise InputError(str(catalog.folder / "drives.toml"), f"[[drive]] {d.id}: bus_voltage",
                             f"expected at least the lowest motor rated_voltage in motors.toml "
                             f"({lowest:g} V), got {d.bus_voltage:g} V")


def _parse_entry(model: type[Entry], raw: object, path: Path, label: str) -> Entry:
    try:
        return parse_model(model, raw, path)
    except InputError as exc:
        raise InputError(str(path), f"{label}: {exc.field}" if exc.field else label, exc.message) from None
