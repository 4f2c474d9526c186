"""``sizing catalog import-mgdb``: motors and gearheads from the makers'
datasheet tables of the Motor-Gearbox Database, and ball screws from the
makers' load-rating table, into the catalog.

The tables (MGDB, GitHub ekrimsk/MGDB at ``MGDB_COMMIT``; THK General
Catalog and HIWIN BS-08-2-EN-1704-K transcriptions) give SI values; a header
may carry a unit instead (``k_t [mN*m/A]``), converted once. Only brushless
motors are taken, with the gearheads the compatibility tables mount on them.

Provenance: every value read from a table has the status
``sourced: FILE KEY COLUMN``; a value the table derives from two of its
columns says how; a value the tables lack is stated from the maker's rule
for the family (``rule: ...``, ``FAMILY_RULES``) or, where no rule was
found, ``assumed: ...``. Each entry's ``source`` names the repository and
commit.

Every row is read and checked before anything is written: a missing column,
a non-positive resistance (or any other physical value), a compatibility row
naming a motor or gearhead the tables do not hold, raise ``InputError``
naming the file, line and column; then the three catalog files are written
atomically (``catalog_import.entry_toml``, the format of ``sizing catalog
add``) and the whole catalog is loaded back before any file is replaced.
"""
from __future__ import annotations

import csv
import datetime as dt
import fnmatch
import functools
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from ..errors import InputError
from ..units import UnitError, to_si
from .catalog import DEFAULT_CATALOG, Gear, Motor, Screw
from .catalog_import import entry_toml
from .schema import parse_model

MGDB_COMMIT = "215caccec6e05a58fdcdce14956d658853bf5128"
MGDB_SOURCE = f"Motor-Gearbox Database, GitHub ekrimsk/MGDB at commit {MGDB_COMMIT} (makers' datasheet tables as of 2020-09-22)"
SCREW_SOURCE = ("makers' ball-screw tables: THK General Catalog and HIWIN BS-08-2-EN-1704-K, transcribed in "
                "GitHub ArtemFilin1990/Mar at commit 7b871a585843d5d9236be7a5c36364a6ecb97a9d")
RETRIEVED = dt.date(2026, 11, 25)
OUT_FILES = {"motor": "motors-mgdb.toml", "gear": "gears-mgdb.toml", "screw": "screws-sourced.toml"}

# column -> (unit kind, required); units.KINDS names
MOTOR_COLUMNS = {
    "key": (None, True), "manufacturer": (None, True), "ID": (None, True), "type": (None, True),
    "V": ("voltage", True), "k_t": ("torque_constant", True), "R": ("resistance", True), "L": ("inductance", True),
    "mass": ("mass", True), "inertia": ("inertia", True), "omega_nl": ("angular_speed", True),
    "I_nl": ("current", True), "I_nom": ("current", True), "max_int_torque": ("torque", True),
    "max_int_speed": ("angular_speed", True), "Rth1": ("thermal_resistance", True),
    "Rth2": ("thermal_resistance", True),
}
GEAR_COLUMNS = {
    "key": (None, True), "manufacturer": (None, True), "ID": (None, True), "type": (None, True),
    "stages": (None, True), "ratio": ("dimensionless", True), "mass": ("mass", True), "inertia": ("inertia", True),
    "efficiency": ("dimensionless", True), "max_int_torque": ("torque", True), "max_cont_torque": ("torque", True),
}
SCREW_COLUMNS = {
    "maker": (None, True), "model": (None, True), "kind": (None, True), "diameter_mm": ("length", True),
    "lead_mm": ("length", True), "ball_centre_mm": ("length", True), "root_mm": ("length", True),
    "dynamic_load_N": ("force", True), "static_load_N": ("force", True), "nut_mass_kg": ("mass", True),
    "shaft_mass_kg_per_m": ("mass_per_length", True), "source": (None, True),
}
# screws-sourced.csv names its units in the column names
SCREW_UNITS = {"diameter_mm": "mm", "lead_mm": "mm", "ball_centre_mm": "mm", "root_mm": "mm"}
# columns that may be empty (NaN) or Inf in a row; every other number must be finite and positive
MAY_BE_MISSING = {"I_nl", "Rth1", "Rth2", "efficiency", "max_int_torque", "max_int_speed", "ball_centre_mm", "root_mm",
                  "nut_mass_kg", "shaft_mass_kg_per_m"}
MAY_BE_ZERO = {"I_nl", "inertia"}

# --- what the tables lack, per family (catalog-sources.md 2a, catalog-sources-2.md 3e) ---------
# NdFeB remanence falls 0.12 %/K (e-magnetsuk.com "Neodymium temperature ratings": -0.12 %/degC
# for N and M grades, -0.08 to -0.12 by grade; advancedmagnets.com: sintered NdFeB -0.09 to
# -0.12 %/degC, SmCo -0.03 to -0.05). k_t follows the magnet flux.
NDFEB_KT_COEFFICIENT = -0.0012
NDFEB_RULE = ("rule: NdFeB rotor magnets; remanence -0.12 %/K (e-magnetsuk.com Neodymium temperature ratings, "
              "N/M grades; advancedmagnets.com: sintered NdFeB -0.09 to -0.12 %/K)")
# an outer-rotor (flat) maxon motor carries its magnets on a wide bell: its rotor inertia over
# mass^(5/3) (size-free for similar shapes, J ~ m r^2, m ~ r^3) is above this, kg^(-2/3) m^2.
# The 338 maxon brushless rows split with a gap from 2.6e-5 to 1.2e-4 (EC 45 flat: 181 g cm^2 at
# 0.11 kg = 7.2e-4; EC-i 40: 44 g cm^2 at 0.39 kg = 2.1e-5; EC 22: 7e-6)
FLAT_INERTIA_PER_MASS = 5e-5


@dataclass(frozen=True)
class FamilyRule:
    """Winding limit, rated ambient and magnet material of a maker's family."""
    max_winding_temperature: float
    winding_status: str
    max_temperature: float
    ambient_status: str


FAMILY_RULES = {
    "maxon-flat": FamilyRule(
        125.0, "rule: maxon EC flat (outer rotor) motors, max winding +125 degC (EC 45 flat 50 W and 70 W "
               "datasheets, online.flippingbook.com/view/1042987/321 and /324); outer rotor inferred from J / m^(5/3)",
        100.0, "rule: maxon EC flat motors, ambient -40...+100 degC (same datasheets)"),
    "maxon": FamilyRule(
        155.0, "rule: maxon inner-rotor EC motors, max winding +155 degC (EC 22 datasheet, "
               "scribd 364113018 p. 214; EC-i 40 488607 in mujoco-motors); inner rotor inferred from J / m^(5/3)",
        100.0, "rule: maxon EC motors, ambient up to +100 degC (EC 22 -20...+100, EC 45 flat -40...+100 degC)"),
    "faulhaber": FamilyRule(
        125.0, "assumed: no Faulhaber winding limit found; the lower of maxon's brushless classes (125 degC)",
        100.0, "assumed: no Faulhaber ambient rating found; maxon's brushless rating (+100 degC)"),
    "allied": FamilyRule(
        125.0, "assumed: no Allied Motion winding class found; the lower of maxon's brushless classes (125 degC)",
        100.0, "assumed: no Allied Motion ambient rating found; maxon's brushless rating (+100 degC)"),
}
# ball screws: maker's permissible speed, d x n (mm rpm) or D_ball-centre x n, and efficiency
SCREW_RULES = {
    ("THK", "precision"): (70000.0, 0.90, "rule: THK permissible speed 70 000 / D (ball centre, mm) rpm for precision "
                                          "screws (General Catalog p. 723 eq. 11)",
                           "rule: THK ball screw efficiency 0.90 to 0.95 (General Catalog p. 743), lower bound"),
    ("THK", "rolled"): (50000.0, 0.90, "rule: THK permissible speed 50 000 / D (ball centre, mm) rpm for rolled "
                                       "screws (General Catalog p. 723 eq. 12)",
                        "rule: THK ball screw efficiency 0.90 to 0.95 (General Catalog p. 743), lower bound"),
    ("HIWIN", "rolled"): (70000.0, 0.85, "rule: HIWIN d x n <= 70 000 (mm rpm) for rolled screws (BS-08-2-EN-1704-K)",
                          "rule: HIWIN efficiency 0.85 to 0.95 forward (BS-08-2-EN-1704-K), lower bound"),
    ("HIWIN", "ground"): (90000.0, 0.85, "rule: HIWIN d x n <= 90 000 (mm rpm) for peeled and ground screws "
                                         "(BS-08-2-EN-1704-K)",
                          "rule: HIWIN efficiency 0.85 to 0.95 forward (BS-08-2-EN-1704-K), lower bound"),
}
STEEL_DENSITY = 7850.0   # kg/m^3
# cells of the tables that are misprinted, read as stated: (file, line, column) -> (cell, value, why)
ERRATA = {
    ("allied_motion_motors.csv", 148, "L"): ("0.85-3", 0.85e-3, "the table prints '0.85-3': read as 0.85e-3 H, "
                                                                "between its neighbours HT01001 (0.98 mH) and HT01003 (0.8 mH)"),
}


@dataclass
class Table:
    """One vendor table: rows of SI floats (None: NaN/empty) or text."""
    path: Path
    rows: list[dict] = field(default_factory=list)
    lines: list[int] = field(default_factory=list)


@dataclass
class MgdbImport:
    motors: list[dict]
    gears: list[dict]
    screws: list[dict]
    skipped: dict[str, int]


def read_table(path: str | Path, columns: dict, units: dict | None = None) -> Table:
    """Read a vendor CSV: every column of ``columns`` must be in the header
    (optionally with a unit, ``k_t [mN*m/A]``); numbers are converted to SI
    and checked (finite and positive unless the column may be missing)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise InputError(str(path), None, "file not found") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(str(path), None, f"expected a UTF-8 CSV file ({exc})") from None
    reader = list(csv.reader(text.splitlines()))
    if not reader:
        raise InputError(str(path), "line 1", "expected a header line, got an empty file")
    header = {}
    for index, cell in enumerate(reader[0]):
        match = re.match(r"^\s*([A-Za-z0-9_]+)\s*(?:[\[(]\s*([^\])]*?)\s*[\])])?\s*$", cell)
        if match:
            header[match.group(1)] = (index, match.group(2) or (units or {}).get(match.group(1)))
    for name, (kind, required) in columns.items():
        if required and name not in header:
            what = f"a column '{name}'" + (f" ({kind.replace('_', ' ')})" if kind else "")
            raise InputError(str(path), f"line 1, column {name}", f"expected {what}, missing from the header")
    table = Table(path)
    for line, cells in enumerate(reader[1:], start=2):
        if not any(c.strip() for c in cells):
            continue
        row = {}
        for name, (kind, _) in columns.items():
            index, unit = header[name]
            raw = cells[index].strip() if index < len(cells) else ""
            row[name] = raw if kind is None else _number(raw, kind, unit, name, path, line)
        row["_line"] = line
        table.rows.append(row)
        table.lines.append(line)
    return table


def _number(raw: str, kind: str, unit: str | None, name: str, path: Path, line: int):
    where = f"line {line}, column {name}"
    erratum = ERRATA.get((path.name, line, name))
    if erratum is not None and raw == erratum[0]:
        return erratum[1]
    if raw.lower() in ("", "nan"):
        if name in MAY_BE_MISSING:
            return None
        raise InputError(str(path), where, f"expected a number, got {raw or 'an empty cell'!r}")
    try:
        value = float(raw)
    except ValueError:
        raise InputError(str(path), where, f"expected a number, got {raw!r}") from None
    if math.isinf(value):
        if value > 0 and name in MAY_BE_MISSING:
            return math.inf
        raise InputError(str(path), where, f"expected a finite number, got {raw!r}")
    if not (value > 0 or (value == 0 and name in MAY_BE_ZERO)):
        raise InputError(str(path), where, f"expected a positive {kind.replace('_', ' ')}, got {raw}")
    if unit:
        try:
            value = to_si(f"{raw} {unit}", kind)
        except UnitError as exc:
            raise InputError(str(path), where, str(exc)) from None
    return value


def read_compatibility(path: str | Path, motor_keys: set, gear_keys: list) -> dict[str, set]:
    """{motor key: gear keys} of a compatibility table (one row per motor:
    the motor key, then gearhead keys or patterns such as ``FH_32A_R*``).
    A motor key the motor table lacks, or a gearhead key or pattern that
    matches no gearhead, is an InputError."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise InputError(str(path), None, f"cannot read the compatibility table ({exc.strerror or exc})") from None
    known = set(gear_keys)
    out: dict[str, set] = {}
    for line, cells in enumerate(csv.reader(text.splitlines()), start=1):
        cells = [c.strip() for c in cells if c.strip()]
        if not cells:
            continue
        motor, keys = cells[0], cells[1:]
        if motor not in motor_keys:
            raise InputError(str(path), f"line {line}, column 1", f"motor key {motor!r} matches no motor of the motor table")
        found = set()
        for col, key in enumerate(keys, start=2):
            hits = fnmatch.filter(gear_keys, key) if "*" in key else ([key] if key in known else [])
            if not hits:
                raise InputError(str(path), f"line {line}, column {col}",
                                 f"gearhead key {key!r} matches no gearhead of the gearhead table")
            found.update(hits)
        out[motor] = found
    return out


def _slug(text: str) -> str:
    return re.sub(r"-+", "-", re.sub(r"[^a-z0-9.]+", "-", text.lower())).strip("-.")


def _family(maker: str, row: dict) -> str:
    if maker == "maxon":
        return "maxon-flat" if row["inertia"] / row["mass"] ** (5 / 3) > FLAT_INERTIA_PER_MASS else "maxon"
    return maker


def motor_entry(maker: str, file_name: str, row: dict, mounts: list[str] | None) -> dict:
    """The raw catalog entry of one brushless motor row (SI)."""
    key = row["key"]
    src = lambda col: f"sourced: {file_name} {key} {col}"
    rule = FAMILY_RULES[_family(maker, row)]
    kt, V, R = row["k_t"], row["V"], row["R"]
    raw = {"id": f"{maker}-{_slug(row['ID'])}", "name": f"{row['manufacturer'].replace('_', ' ')} {row['ID']} brushless",
           "manufacturer": row["manufacturer"].replace("_", " "),
           "source": f"{MGDB_SOURCE}, {file_name}, key {key}", "retrieved": RETRIEVED}
    status = {}
    raw["torque_constant"], status["torque_constant"] = kt, src("k_t")
    raw["back_emf_constant"] = V / row["omega_nl"]
    status["back_emf_constant"] = f"sourced: {file_name} {key} V / omega_nl (no-load speed at the nominal voltage)"
    raw["winding_resistance"], status["winding_resistance"] = R, src("R")
    raw["resistance_temperature_coefficient"] = 0.00393
    status["resistance_temperature_coefficient"] = "rule: copper winding, 0.00393 1/K (the makers' terminal resistance at 25 degC)"
    raw["torque_constant_temperature_coefficient"], status["torque_constant_temperature_coefficient"] = \
        NDFEB_KT_COEFFICIENT, NDFEB_RULE
    raw["inductance"], status["inductance"] = row["L"], src("L")
    for (name, _line, col), (_cell, _value, why) in ERRATA.items():
        if name == file_name and row["_line"] == _line:
            status[{"L": "inductance"}.get(col, col)] += f" ({why})"
    raw["rotor_inertia"], status["rotor_inertia"] = row["inertia"], src("inertia")
    if row["I_nl"] is not None and row["I_nl"] > 0:
        raw["viscous_damping"] = kt * row["I_nl"] / row["omega_nl"]
        status["viscous_damping"] = f"sourced: {file_name} {key} k_t I_nl / omega_nl (no-load loss as viscous)"
    else:
        raw["viscous_damping"] = 0.02 * kt * row["I_nom"] / row["omega_nl"]
        status["viscous_damping"] = "assumed: no-load current not in the table; 2 % of the continuous torque at no-load speed"
    raw["continuous_torque"] = kt * row["I_nom"]
    status["continuous_torque"] = f"sourced: {file_name} {key} k_t x I_nom (max continuous current, 25 degC ambient)"
    if row["max_int_torque"] not in (None, math.inf):
        raw["peak_torque"], status["peak_torque"] = row["max_int_torque"], src("max_int_torque")
    else:
        raw["peak_torque"] = kt * V / R
        status["peak_torque"] = (f"rule: no peak rating in the table (Inf); the stall torque at the nominal voltage, "
                                 f"k_t V / R, as {row['manufacturer'].replace('_', ' ')} prints it")
    if row["max_int_speed"] not in (None, math.inf):
        raw["max_speed"], status["max_speed"] = row["max_int_speed"], src("max_int_speed")
    else:
        raw["max_speed"] = row["omega_nl"]
        status["max_speed"] = "rule: no speed limit in the table (Inf); the no-load speed at the nominal voltage"
    raw["rated_voltage"], status["rated_voltage"] = V, src("V")
    if row["Rth2"] is not None:
        raw["thermal_resistance"] = row["Rth1"] + row["Rth2"]
        status["thermal_resistance"] = f"sourced: {file_name} {key} Rth1 + Rth2 (winding-housing + housing-ambient)"
    else:
        raw["thermal_resistance"] = row["Rth1"]
        status["thermal_resistance"] = f"sourced: {file_name} {key} Rth1 (one lumped value, winding to ambient)"
    raw["thermal_time_constant"] = 600.0
    status["thermal_time_constant"] = "assumed: not in the table; 600 s, between EC 45 flat (127 s) and EC-i 40 (1400 s)"
    raw["max_winding_temperature"], status["max_winding_temperature"] = rule.max_winding_temperature, rule.winding_status
    raw["max_temperature"], status["max_temperature"] = rule.max_temperature, rule.ambient_status
    raw["mass"], status["mass"] = row["mass"], src("mass")
    raw["cost_usd"] = round(150.0 + 600.0 * row["mass"])
    status["cost_usd"] = "assumed: no price in the table; 150 USD + 600 USD/kg, the order of a catalog maxon EC motor"
    if mounts:
        raw["gear_mounts"] = mounts
    raw["notes"] = FAMILY_NOTES[_family(maker, row)]
    raw["status"] = status
    return raw


FAMILY_NOTES = {
    "maxon-flat": "Outer-rotor (flat) construction, inferred from the rotor inertia over mass^(5/3).",
    "maxon": "Inner-rotor construction, inferred from the rotor inertia over mass^(5/3).",
    "faulhaber": "Housed brushless motor; no thermal rating of the family was found.",
    "allied": ("Frameless (stator and rotor, built into the actuator's housing, which the mass model counts); "
               "the table gives one lumped thermal resistance, which depends on that housing."),
}


def gear_entry(maker: str, file_name: str, row: dict, mount: str) -> dict:
    """The raw catalog entry of one gearhead row (SI); torques at the output."""
    key = row["key"]
    src = lambda col: f"sourced: {file_name} {key} {col}"
    raw = {"id": f"{maker}-gh-{_slug(row['ID'])}",
           "name": f"{row['manufacturer'].replace('_', ' ')} {row['type']} gearhead {row['ID']}, "
                   f"{row['stages']} stage(s), {row['ratio']:g}:1",
           "manufacturer": row["manufacturer"].replace("_", " "),
           "source": f"{MGDB_SOURCE}, {file_name}, key {key}", "retrieved": RETRIEVED}
    status = {}
    raw["ratio"], status["ratio"] = row["ratio"], src("ratio")
    raw["efficiency"], status["efficiency"] = min(row["efficiency"], 1.0), src("efficiency")
    raw["inertia"], status["inertia"] = row["inertia"], src("inertia")
    raw["mass"], status["mass"] = row["mass"], src("mass")
    raw["max_input_speed"] = 8000.0 * 2 * math.pi / 60
    status["max_input_speed"] = "assumed: not in the table; 8000 rpm, the continuous input speed of maxon GP 32 C and GP 42 C"
    raw["max_output_torque"], status["max_output_torque"] = row["max_int_torque"], src("max_int_torque")
    raw["continuous_output_torque"], status["continuous_output_torque"] = row["max_cont_torque"], src("max_cont_torque")
    raw["max_temperature"] = 100.0
    status["max_temperature"] = "rule: maxon planetary gearheads, -40...+100 degC (GP 32 C and GP 42 C datasheets)" \
        if maker == "maxon" else "assumed: no rating found; maxon's planetary gearhead rating (+100 degC)"
    raw["cost_usd"] = round(100.0 + 400.0 * row["mass"])
    status["cost_usd"] = "assumed: no price in the table; 100 USD + 400 USD/kg"
    raw["mount"] = mount
    raw["status"] = status
    return raw


def screw_entry(row: dict, file_name: str) -> dict:
    """The raw catalog entry of one ball screw row (SI)."""
    maker, model, kind = row["maker"], row["model"], row["kind"]
    key = f"{maker} {model}"
    src = lambda col: f"sourced: {file_name} {key} {col}"
    d, lead = row["diameter_mm"], row["lead_mm"]
    dn, eta, speed_status, eta_status = SCREW_RULES[(maker, kind)]
    raw = {"id": f"{maker.lower()}-{_slug(model)}", "name": f"{maker} {model} ball screw {d * 1e3:g} x {lead * 1e3:g} mm, {kind}",
           "manufacturer": maker, "source": f"{SCREW_SOURCE}; {row['source']}", "retrieved": RETRIEVED, "type": "ball"}
    status = {}
    raw["lead"], status["lead"] = lead, src("lead_mm")
    if row["root_mm"] is not None:
        raw["diameter"], status["diameter"] = row["root_mm"], src("root_mm (thread minor diameter)")
    else:
        raw["diameter"] = 0.83 * d
        status["diameter"] = "assumed: root diameter not in the table; 0.83 x nominal, as the sourced 16 mm screws"
    raw["efficiency"], status["efficiency"] = eta, eta_status
    raw["dynamic_load_rating"], status["dynamic_load_rating"] = row["dynamic_load_N"], src("dynamic_load_N (C_a)")
    raw["static_load_rating"], status["static_load_rating"] = row["static_load_N"], src("static_load_N (C_0a)")
    if row["shaft_mass_kg_per_m"] is not None:
        m = row["shaft_mass_kg_per_m"]
        raw["mass_per_length"], status["mass_per_length"] = m, src("shaft_mass_kg_per_m")
        status["inertia_per_length"] = f"sourced: {file_name} {key} shaft mass per metre x d^2 / 8 (solid shaft, nominal d)"
    else:
        m = STEEL_DENSITY * math.pi / 4 * d**2
        raw["mass_per_length"] = m
        status["mass_per_length"] = "rule: solid steel shaft of the nominal diameter, rho pi d^2 / 4"
        status["inertia_per_length"] = "rule: solid steel shaft of the nominal diameter, rho pi d^4 / 32"
    raw["inertia_per_length"] = m * d**2 / 8
    if row["nut_mass_kg"] is not None:
        raw["nut_mass"], status["nut_mass"] = row["nut_mass_kg"], src("nut_mass_kg")
    else:
        raw["nut_mass"] = 0.25 if d >= 0.016 else 0.15
        status["nut_mass"] = "assumed: nut mass not in the table; the heaviest sourced nut of the size"
    centre = row["ball_centre_mm"] if (maker == "THK" and row["ball_centre_mm"] is not None) else d
    raw["max_speed"] = dn / (centre * 1e3) * 2 * math.pi / 60
    status["max_speed"] = speed_status
    raw["max_temperature"] = 120.0
    status["max_temperature"] = "assumed: grease and seals rated 120 degC (as the generic screws); not in the table"
    raw["cost_usd"] = 200 if d < 0.016 else 260
    status["cost_usd"] = "assumed: no price in the table; the generic screws' price of the size"
    raw["status"] = status
    return raw


def _mounts(maker: str, compat: dict[str, set], motor_keys: list[str]) -> tuple[dict[str, str], dict[str, list[str]]]:
    """Group the gearheads by the set of motors they mount on: {gear key:
    mount name}, {motor key: mount names}."""
    fits: dict[str, set] = {}
    for motor in motor_keys:
        for g in compat.get(motor, ()):
            fits.setdefault(g, set()).add(motor)
    groups = sorted({frozenset(v) for v in fits.values()}, key=lambda s: tuple(sorted(s)))
    name = {grp: f"{maker}-mount-{i + 1:03d}" for i, grp in enumerate(groups)}
    gear_mount = {g: name[frozenset(v)] for g, v in fits.items()}
    motor_mounts = {m: sorted({gear_mount[g] for g in compat.get(m, ())}) for m in motor_keys}
    return gear_mount, motor_mounts


def build(mgdb_dir: str | Path, screws_csv: str | Path | None) -> MgdbImport:
    """Read and check every table; the raw catalog entries (nothing written)."""
    folder = Path(mgdb_dir)
    motors, gears, skipped = [], [], {"brushed motors": 0, "motors without thermal resistance": 0,
                                       "gearheads that mount on no brushless motor": 0,
                                       "gearheads without efficiency": 0}
    for maker, stem, has_gears in (("maxon", "maxon", True), ("faulhaber", "faulhaber", True),
                                   ("allied", "allied_motion", False)):
        mt = read_table(folder / f"{stem}_motors.csv", MOTOR_COLUMNS)
        rows = []
        for row in mt.rows:
            if row["type"] != "BLDC":
                skipped["brushed motors"] += 1
            elif row["Rth1"] is None:
                skipped["motors without thermal resistance"] += 1
            else:
                rows.append(row)
        keys = [r["key"] for r in rows]
        gear_mount, motor_mounts, by_key = {}, {}, {}
        if has_gears:
            gt = read_table(folder / f"{stem}_gearboxes.csv", GEAR_COLUMNS)
            by_key = {r["key"]: r for r in gt.rows}
            compat = read_compatibility(folder / f"{stem}_compatibility.csv", {r["key"] for r in mt.rows},
                                        list(by_key))
            usable = {k for k, r in by_key.items() if r["efficiency"] is not None}
            skipped["gearheads without efficiency"] += len(by_key) - len(usable)
            compat = {m: gs & usable for m, gs in compat.items()}
            gear_mount, motor_mounts = _mounts(maker, compat, keys)
            skipped["gearheads that mount on no brushless motor"] += len(usable) - len(gear_mount)
        for row in rows:
            motors.append(motor_entry(maker, mt.path.name, row, motor_mounts.get(row["key"]) or None))
        for gkey, mount in sorted(gear_mount.items()):
            gears.append(gear_entry(maker, f"{stem}_gearboxes.csv", by_key[gkey], mount))
    screws = []
    if screws_csv is not None:
        st = read_table(screws_csv, SCREW_COLUMNS, SCREW_UNITS)
        for line, row in zip(st.lines, st.rows):
            if (row["maker"], row["kind"]) not in SCREW_RULES:
                raise InputError(str(st.path), f"line {line}, column kind",
                                 f"expected one of {sorted(SCREW_RULES)}, got {(row['maker'], row['kind'])}")
            screws.append(screw_entry(row, Path(screws_csv).name))
    for array, model, entries in (("motor", Motor, motors), ("gear", Gear, gears), ("screw", Screw, screws)):
        ids = set()
        for raw in entries:
            if raw["id"] in ids:
                raise InputError(OUT_FILES[array], raw["id"], "two rows give the same catalog id")
            ids.add(raw["id"])
            parse_model(model, raw, raw["source"])
    return MgdbImport(motors, gears, screws, skipped)


def _file_text(array: str, entries: list[dict], command: str) -> str:
    head = (f"# {array} entries imported by `{command}` from the makers' tables; schema: catalogs/README.md.\n"
            f"# Generated file: re-run the command instead of editing it. Status per value: 'sourced: FILE KEY\n"
            f"# COLUMN' (read from the table), 'rule: ...' (the maker's rule for the family), 'assumed: ...'.\n")
    return head + "\n".join("\n" + entry_toml(array, e) for e in entries)


def _plausible(catalog, data: MgdbImport) -> None:
    """The first implausible imported value (a unit slip, ``validate.RANGES``)
    as an InputError naming the table, the row's key and the field."""
    from .validate import problems
    origin = {raw["id"]: raw["source"].rsplit(", ", 2)[-2:] for raw in data.motors + data.gears}
    origin.update({raw["id"]: [raw["name"], ""] for raw in data.screws})
    for problem in problems(catalog):
        ident = problem.field.split("]] ", 1)[-1].split(":", 1)[0]
        if ident in origin:
            where, key = origin[ident]
            field_name = problem.field.split(": ", 1)[-1]
            raise InputError(where, f"{key.removeprefix('key ')}: {field_name}".strip(": "), problem.message)


def plan_mgdb(mgdb_dir: str | Path, screws_csv: str | Path | None = None,
              catalog_dir: str | Path | None = None) -> tuple[dict, dict[Path, str], Callable]:
    """motors-mgdb.toml, gears-mgdb.toml (and screws-sourced.toml when
    ``screws_csv`` is given) for the catalog folder: (counts, {path: text},
    ``check(catalog)``, which raises InputError when the catalog read back
    with them is implausible); ``api.catalogs`` reads back and writes."""
    data = build(mgdb_dir, screws_csv)
    folder = Path(catalog_dir) if catalog_dir is not None else DEFAULT_CATALOG
    command = "sizing catalog import-mgdb"
    texts = {OUT_FILES["motor"]: _file_text("motor", data.motors, command),
             OUT_FILES["gear"]: _file_text("gear", data.gears, command)}
    if screws_csv is not None:
        texts[OUT_FILES["screw"]] = _file_text("screw", data.screws, command)
    counts = {"motors": len(data.motors), "gears": len(data.gears), "screws": len(data.screws),
              "skipped": data.skipped, "files": sorted(texts)}
    return counts, {folder / name: text for name, text in texts.items()}, functools.partial(_plausible, data=data)
