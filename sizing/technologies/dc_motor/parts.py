"""DC actuators sized from parts: every motor x screw x gear (or none) x
drive of the catalog, screened statically, vectorised over combinations.

Each check is a margin (rank.py conventions) named after what it protects;
a combination is ruled out by every margin below zero, and keeps them:
- blocked_force: peak motor torque (the lower of the motor's peak torque and
  the drive's peak current times k_t at temperature) through gear and screw,
  F = 2 pi eta_s eta_g N T / l (physics/screw.py), capped by the gear's
  output torque;
- speed: the output speed the bus allows under the worst load,
  (U - R_hot i_load) / k_e (physics/motor.py), capped by the motor's, the
  gear's and the screw's speed limits: static.max_speed_m_s;
- winding_temperature: the steady winding temperature at the required
  ambient with the RMS current of the duty cycle (static: the holding
  current of the worst load, held all the time; the simulation then gives
  the cycle's own RMS) against the insulation's max_winding_temperature;
- magnet_temperature: the rotor taken at the winding temperature against
  the magnet's limit (where the catalog gives one);
- temperature: motor, screw and gear rated ambient against the requirement;
  drive_temperature: the drive where it sits (options.amplifier_location);
- drive_current: the drive's continuous current against the duty's RMS;
- buckling: Euler load of the screw (fixed-pinned) against the peak force
  the drive can push (at least the required blocked force);
- screw_life: L10 life at the duty against REQUIRED_LIFE_H;
- static_safety: the screw's C0 over that peak force against THK's 2.0;
- continuous_torque: the motor's continuous rating derated to the ambient
  (physics/motor.py) against the duty's torque;
- gear_torque: the gear's continuous output torque against the holding load;
- holding: the winding after holding the steady load on the back-driven
  screw for the hold time (no brake; with ``[options] dc_brake`` the brake
  holds and the winding carries no current, the brake's mass is counted);
- rod_buckling, bearing_life, bearing_static, housing_stress, clevis: the
  structure around the screw, sized for the force the drive can push
  (``dc_structure``), each member's check.
k_t is taken with the magnets at the holding duty's winding temperature.
Continuous choices are catalog values (lead, ratio): the feasible ratios of
a motor-screw pair form an interval (force needs N >= N_min, speed N <=
N_max; ``ratio_interval``, reported as static.ratio_low / ratio_high), and
the enumeration covers it at the catalog's ratios (1 = direct).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...physics import motor as motor_phys
from ...physics import screw as screw_phys
from . import structure as dc_structure
from ...settings import REQUIRED_LIFE_H
from ...settings import TRAVEL_FACTOR

# Assumed construction (README, DC sizing): stated here, used everywhere.
SCREW_EXTRA_LENGTH = 0.05     # m: nut, bearings and end stop beyond the travel (assumed)
ASSEMBLY_USD = 600.0          # assumed: machining and assembly of housing and bearing block
STATIC_SAFETY_REQUIRED = screw_phys.STATIC_SAFETY_WITH_VIBRATION   # C0 / F_peak (THK, with vibration)
SCREW_BACK_EFFICIENCY = 0.75  # reverse efficiency of a ball screw, the low end of HIWIN's 0.75-0.85


@dataclass
class PartArrays:
    """One row per combination; ids for the results, SI floats for physics."""
    motor: np.ndarray
    screw: np.ndarray
    gear: np.ndarray          # object array, None for a direct drive
    drive: np.ndarray
    values: dict              # name -> (n,) float array

    def __len__(self):
        return len(self.motor)

    def take(self, idx) -> "PartArrays":
        return PartArrays(self.motor[idx], self.screw[idx], self.gear[idx], self.drive[idx],
                          {k: v[idx] for k, v in self.values.items()})


def _col(entries, name, default=np.nan):
    return np.array([getattr(e, name) if getattr(e, name, None) is not None else default for e in entries], float)


def enumerate_parts(catalog) -> PartArrays:
    """Every motor x (gear that mounts on it, or none) x screw x drive."""
    lists = part_lists(catalog)
    M, S, G, D = lists
    if not (M and S and D):
        return PartArrays(*(np.array([], dtype=object) for _ in range(4)), values={})
    pm, pg = [], []
    for i, gears in enumerate(mountable(catalog)):
        pm += [i] * (len(gears) + 1)
        pg += [0] + [int(g) + 1 for g in gears]
    pair, isc, idr = (a.ravel() for a in np.meshgrid(np.arange(len(pm)), np.arange(len(S)), np.arange(len(D)),
                                                      indexing="ij"))
    return parts_at(lists, np.asarray(pm)[pair], isc, np.asarray(pg)[pair], idr)


# A drive runs from a supply between this fraction of its rated bus and the
# rated bus (assumed: compact servo drives accept about 4:1, e.g. maxon EPOS4
# 50/8, 10-50 V; TGdrives TGZ-D-48, 0-48 V).
DRIVE_SUPPLY_RANGE = 0.25


def drives_for_supply(catalog, supply_voltage):
    """The catalog with only the drives that run from ``supply_voltage``
    (V; None: the catalog as it is), each at that bus: the speed ceiling,
    the drive's voltage limit and the controller then follow the supply, so
    the windings whose back-EMF suits it are the ones that meet the speed."""
    if supply_voltage is None:
        return catalog
    from dataclasses import replace
    drives = {k: d.model_copy(update={"bus_voltage": float(supply_voltage)}) for k, d in catalog.drives.items()
              if DRIVE_SUPPLY_RANGE * d.bus_voltage <= supply_voltage <= d.bus_voltage * (1 + 1e-9)}
    return replace(catalog, drives=drives)


def part_lists(catalog) -> tuple[list, list, list, list]:
    """(motors, screws, [None] + gears, drives) in catalog order."""
    return (list(catalog.motors.values()), list(catalog.screws.values()),
            [None] + list(catalog.gears.values()), list(catalog.drives.values()))


def mountable(catalog) -> list[np.ndarray]:
    """Per motor (catalog order), the indices into catalog.gears of the
    gearheads that mount on it, by rising ratio: a gear with a ``mount``
    (a maker's gearhead) fits the motors whose ``gear_mounts`` name it; a
    gear without one (a generic reduction, assumed adaptable) fits every motor."""
    gears = list(catalog.gears.values())
    by_mount: dict = {}
    for j, g in enumerate(gears):
        by_mount.setdefault(g.mount, []).append(j)
    # most motors name the same mounts: each distinct set of mounts sorted once
    # (the motors that share it share its read-only array)
    fits: dict = {}
    out = []
    for m in catalog.motors.values():
        keys = tuple(m.gear_mounts or ())
        if keys not in fits:
            idx = sorted({j for k in (None,) + keys for j in by_mount.get(k, ())}, key=lambda j: (gears[j].ratio, j))
            fits[keys] = np.asarray(idx, dtype=int)
            fits[keys].flags.writeable = False
        out.append(fits[keys])
    return out


_COLUMNS: dict = {}


def _columns(lists) -> dict:
    """Per part list, its SI columns (cached per list identity for one search)."""
    key = tuple(id(x) for x in lists)
    if _COLUMNS.get("key") != key:
        M, S, G, D = lists
        gears = [g for g in G if g is not None]
        cols = {}
        for name in MOTOR_FIELDS:
            cols["motor_" + name] = _col(M, name)
        cols["motor_magnet_max_temperature"] = _col(M, "magnet_max_temperature", np.inf)
        cols["motor_frameless"] = np.array([float(is_frameless(m)) for m in M])
        for name in SCREW_FIELDS:
            cols["screw_" + name] = _col(S, name)
        cols["screw_static_load_rating"] = _col(S, "static_load_rating", np.inf)
        for name, none_value in GEAR_FIELDS.items():
            cols["gear_" + name] = np.concatenate([[none_value], _col(gears, name, none_value)])
        for name in DRIVE_FIELDS:
            cols["drive_" + name] = _col(D, name)
        ids = lambda entries: np.array([e.id if e is not None else None for e in entries], dtype=object)
        cols["ids"] = (ids(M), ids(S), ids(G), ids(D))
        _COLUMNS.clear()
        _COLUMNS.update(key=key, cols=cols, lists=lists)
    return _COLUMNS["cols"]


MOTOR_FIELDS = ("torque_constant", "back_emf_constant", "winding_resistance", "resistance_temperature_coefficient",
                "torque_constant_temperature_coefficient", "inductance", "rotor_inertia", "viscous_damping",
                "continuous_torque", "peak_torque", "max_speed", "rated_voltage", "thermal_resistance",
                "thermal_time_constant", "max_winding_temperature", "max_temperature", "mass", "cost_usd")
SCREW_FIELDS = ("lead", "diameter", "efficiency", "dynamic_load_rating", "inertia_per_length", "mass_per_length",
                "nut_mass", "max_speed", "elastic_modulus", "max_temperature", "cost_usd")
# gear columns and their value for a direct drive (no gear)
GEAR_FIELDS = {"ratio": 1.0, "efficiency": 1.0, "inertia": 0.0, "mass": 0.0, "max_input_speed": np.inf,
               "max_output_torque": np.inf, "continuous_output_torque": np.inf, "max_temperature": np.inf,
               "cost_usd": 0.0}
DRIVE_FIELDS = ("bus_voltage", "continuous_current", "peak_current", "rate", "max_temperature", "mass", "cost_usd")


def parts_at(lists, im, isc, ig, idr) -> PartArrays:
    """The combinations (motor im, screw isc, gear ig (0: none, else
    catalog gear ig - 1), drive idr) of the part lists (``part_lists``)."""
    cols = _columns(lists)
    index = {"motor": im, "screw": isc, "gear": ig, "drive": idr}
    v = {name: col[index[name.split("_", 1)[0]]] for name, col in cols.items() if name != "ids"}
    iM, iS, iG, iD = cols["ids"]
    return PartArrays(iM[im], iS[isc], iG[ig], iD[idr], v)


def plant(p: PartArrays, stroke: float, temperature: float, moving_structure=0.0) -> dict[str, np.ndarray]:
    """Seed eq. 13 of each combination, referred to the motor shaft:
    J = J_motor + J_gear + J_screw / N^2 + m_moving (l / 2 pi N)^2,
    c1 = -b / J, c2 = k_t(T) / J, effective lead l / N (m per motor turn).
    The moving mass is the nut and ``moving_structure`` (kg: the rod and
    its rod-end eye, ``dc_structure``)."""
    v = p.values
    N = v["gear_ratio"]
    lead_eff = v["screw_lead"] / N
    screw_len = TRAVEL_FACTOR * stroke + SCREW_EXTRA_LENGTH
    moving = v["screw_nut_mass"] + moving_structure
    J = (v["motor_rotor_inertia"] + v["gear_inertia"] + v["screw_inertia_per_length"] * screw_len / N**2
         + moving * (lead_eff / (2 * np.pi)) ** 2)
    kt = motor_phys.torque_constant_at(v["motor_torque_constant"], v["motor_torque_constant_temperature_coefficient"],
                                       temperature)
    return {"inertia": J, "c1": -v["motor_viscous_damping"] / J, "c2": kt / J, "lead": lead_eff,
            "efficiency": v["screw_efficiency"] * v["gear_efficiency"], "torque_constant": kt,
            "screw_length": np.full(len(p), screw_len)}


def drive_voltage(p: PartArrays, w_mech) -> np.ndarray:
    """The drive's output voltage limit: the bus, or lower where the bus
    would spin the motor past its (or the gear's, or the screw's) speed
    rating at no load, U_lim = min(U_bus, k_e w_mech): a drive setting
    that keeps every design within its mechanical ratings."""
    return np.minimum(p.values["drive_bus_voltage"], p.values["motor_back_emf_constant"] * w_mech)


def current_limit(p: PartArrays, kt) -> np.ndarray:
    """Peak current: the drive's, or what gives the motor's peak torque."""
    return np.minimum(p.values["drive_peak_current"], p.values["motor_peak_torque"] / kt)


def winding(p: PartArrays, ambient, i_rms) -> dict[str, np.ndarray]:
    """Winding rise and temperature at the RMS current; resistance hot."""
    v = p.values
    rise = motor_phys.winding_rise(v["motor_thermal_resistance"], v["motor_winding_resistance"],
                                   v["motor_resistance_temperature_coefficient"], ambient, i_rms)
    return {"rise_K": rise, "temperature_degC": ambient + rise}


def temperature_margin(rated, required):
    """search.temperature_margin, vectorised. A winding that runs away
    (required temperature unbounded) gets the margin's limit, -1 ((rated -
    T) / T as T grows): a finite number that fails, as results.json needs."""
    required = np.asarray(required, float)
    with np.errstate(invalid="ignore"):
        return np.where(np.isfinite(required), (np.asarray(rated) - required) / np.maximum(np.abs(required), 1.0), -1.0)


def static_screen(p: PartArrays, req, loads, ambient=None, settings=None) -> tuple[dict, dict, dict]:
    """(plant, static figures, margins): dicts of (n,) arrays.
    ``ambient`` (sizing robust): per row, the temperature the parts work at
    instead of the required maximum (k_t and the hot resistance follow it;
    ratings are still judged at the maximum). ``settings``: the drive's
    current limit and voltage limit as designed (``current_limit_A``,
    ``voltage_limit_V``, (n,) arrays), which the drive keeps whatever the
    parts: the hardware can only lower them (its peak current, its bus)."""
    r, o, v = req.requirements, req.options, p.values
    T = r.max_temperature
    T_op = T if ambient is None else np.asarray(ambient, float)
    F_load = max(loads) if loads else 0.0
    pl = plant(p, r.stroke, T_op)
    lead, eta = pl["lead"], pl["efficiency"]
    # k_t with the magnets at the winding temperature of the holding duty (physics/motor.py)
    t_load = screw_phys.torque_for_force(F_load, lead, eta)
    hold = derated(p, T_op, t_load)
    kt = hold["torque_constant"]
    pl["torque_constant"], pl["c2"] = kt, kt / pl["inertia"]
    i_max = current_limit(p, kt) if settings is None else np.minimum(settings["current_limit_A"], v["drive_peak_current"])
    F_peak = np.minimum(screw_phys.force_from_torque(kt * i_max, lead, eta),
                        screw_phys.force_from_torque(v["gear_max_output_torque"], v["screw_lead"], v["screw_efficiency"]))
    i_load = hold["current_A"]
    r_hot = motor_phys.resistance_at(v["motor_winding_resistance"], v["motor_resistance_temperature_coefficient"],
                                     np.minimum(hold["temperature_degC"], 1e3))
    rated = hold if ambient is None else derated(p, T, t_load)      # the ratings' check, at the maximum
    # holding the steady load on the back-driven screw for the hold time, no brake
    t_hold = screw_phys.holding_torque(F_load, v["screw_lead"], SCREW_BACK_EFFICIENCY, v["gear_ratio"],
                                       v["gear_efficiency"])
    brake = brake_mass(t_hold) if o.dc_brake else np.zeros(len(p))
    if o.dc_brake:          # the brake holds: the winding carries no current while holding
        t_hold = np.zeros(len(p))
    held = derated(p, T_op, t_hold)
    hold_power = r_hot * held["current_A"] ** 2
    end_of_hold = motor_phys.holding_temperature(rated["temperature_degC"], held["temperature_degC"],
                                                 req.duty.hold_time, v["motor_thermal_time_constant"])
    w_mech = np.minimum.reduce([v["motor_max_speed"], v["gear_max_input_speed"], v["screw_max_speed"] * v["gear_ratio"]])
    u_drive = drive_voltage(p, w_mech) if settings is None else np.minimum(v["drive_bus_voltage"], settings["voltage_limit_V"])
    w_volt = motor_phys.speed_ceiling(u_drive, v["motor_back_emf_constant"], r_hot, i_load)
    w_max = np.minimum(w_volt, w_mech)
    v_max = screw_phys.output_speed(w_max, lead)
    P_cr = screw_phys.buckling_load(v["screw_elastic_modulus"], v["screw_diameter"], pl["screw_length"])
    rev_per_s = 2 * r.stroke / v["screw_lead"] * req.duty.strokes_per_second
    # the structure around the screw, sized for what the drive can push; its moving part joins the plant
    built = dc_structure.size(v, TRAVEL_FACTOR * r.stroke, np.maximum(F_peak, r.blocked_force), F_load,
                              rev_per_s, float(pl["screw_length"][0]) if len(p) else 0.0)
    moved = plant(p, r.stroke, T_op, built["moving_mass_kg"])
    for key in ("inertia", "c1"):
        pl[key] = moved[key]
    pl["c2"] = kt / pl["inertia"]
    life_h = screw_phys.l10_revolutions(v["screw_dynamic_load_rating"], F_load) / rev_per_s / 3600.0
    n_low, n_high = ratio_interval(kt, v["motor_back_emf_constant"], r_hot, i_max, v["screw_lead"], eta,
                                   v["drive_bus_voltage"], v["motor_max_speed"], r.blocked_force, F_load, r.speed)
    drive_ambient = o.electronics_bay_temperature if o.amplifier_location == "bay" else T
    static = {
        "blocked_force_N": F_peak, "max_speed_m_s": v_max, "voltage_speed_limit_m_s": screw_phys.output_speed(w_volt, lead),
        "mechanical_speed_limit_m_s": screw_phys.output_speed(w_mech, lead), "current_limit_A": i_max,
        "load_current_A": i_load, "holding_winding_temperature_degC": hold["temperature_degC"],
        "buckling_load_N": P_cr, "screw_life_h": life_h, "inertia_kg_m2": pl["inertia"],
        "effective_lead_m": lead, "efficiency": eta, "torque_constant_at_temperature": kt,
        "drive_voltage_V": u_drive, "hot_resistance_ohm": r_hot, "ratio_low": n_low, "ratio_high": n_high, "stroke_m": np.full(len(p), TRAVEL_FACTOR * r.stroke),
        "magnet_temperature_degC": hold["temperature_degC"], "holding_power_W": hold_power,
        "holding_power_with_brake_W": np.zeros(len(p)), "static_safety": screw_phys.static_safety(v["screw_static_load_rating"], F_peak),
        "continuous_torque_rated_N_m": motor_phys.continuous_torque_at(v["motor_continuous_torque"],
                                                                       v["motor_max_winding_temperature"], T),
        "moving_mass_kg": v["screw_nut_mass"] + built["moving_mass_kg"], "brake_mass_kg": brake,
        **dc_structure.static_figures(built),
        # the servo holds the motor angle; the shaft, nut and bearing give under the load
        "output_stiffness_N_m": screw_phys.axial_stiffness(v["screw_elastic_modulus"], v["screw_diameter"],
                                                           pl["screw_length"]),
        "back_drives": np.full(len(p), float(screw_phys.back_drives(SCREW_BACK_EFFICIENCY))),
    }
    static.update({f"mass_{name}_kg": m for name, m in mass_breakdown(p, req, static).items()})
    margins = {
        "blocked_force": F_peak / r.blocked_force - 1.0,
        "speed": v_max / r.speed - 1.0,
        "winding_temperature": temperature_margin(v["motor_max_winding_temperature"], rated["temperature_degC"]),
        "magnet_temperature": temperature_margin(v["motor_magnet_max_temperature"], rated["temperature_degC"]),
        "temperature": temperature_margin(np.minimum.reduce([v["motor_max_temperature"], v["screw_max_temperature"],
                                                             v["gear_max_temperature"]]), T),
        "drive_temperature": temperature_margin(v["drive_max_temperature"], drive_ambient),
        "drive_current": v["drive_continuous_current"] / np.maximum(i_load, 1e-12) - 1.0,
        "buckling": P_cr / np.maximum(F_peak, r.blocked_force) - 1.0,   # the screw carries what the drive can push
        "screw_life": life_h / REQUIRED_LIFE_H - 1.0,
        "static_safety": static["static_safety"] / STATIC_SAFETY_REQUIRED - 1.0,
        "gear_torque": v["gear_continuous_output_torque"] / np.maximum(screw_phys.torque_for_force(
            F_load, v["screw_lead"], v["screw_efficiency"]), 1e-12) - 1.0,
        "continuous_torque": static["continuous_torque_rated_N_m"] / np.maximum(kt * rated["current_A"], 1e-12) - 1.0,
        "holding": temperature_margin(v["motor_max_winding_temperature"], end_of_hold),
        **built["margins"],
    }
    if r.min_stiffness is not None:
        margins["stiffness"] = static["output_stiffness_N_m"] / r.min_stiffness - 1.0
    return pl, static, margins


def derated(p: PartArrays, ambient, torque) -> dict[str, np.ndarray]:
    """Winding temperature, k_t and current of each motor delivering
    ``torque`` (RMS, N m) at ``ambient`` with its magnets at the winding
    temperature (``motor.derated_winding``)."""
    v = p.values
    Tw, kt, i = motor_phys.derated_winding(v["motor_thermal_resistance"], v["motor_winding_resistance"],
                                           v["motor_resistance_temperature_coefficient"], v["motor_torque_constant"],
                                           v["motor_torque_constant_temperature_coefficient"], ambient, torque)
    return {"temperature_degC": Tw, "torque_constant": kt, "current_A": i}


def ratio_interval(kt, ke, r_hot, i_max, lead, eta, u_bus, w_mech_motor, force, load, speed):
    """The continuous reduction ratios N (motor turns per screw turn) with
    which a motor and screw meet the force and the speed: a 1-D convex
    program solved in closed form, against which the catalog's ratios are
    snapped. With a = l / 2 pi and eta the whole train's efficiency:
      force:  2 pi eta k_t i_max N / l >= F          -> N >= F a / (eta k_t i_max)
      speed:  (U - R F a / (eta k_t N)) / k_e >= v N / a
              -> (k_e v / a) N^2 - U N + R F a / (eta k_t) <= 0, between its roots
      rating: v N / a <= w_mech.
    Returns (N_low, N_high); N_low > N_high where no ratio works."""
    a = np.asarray(lead) / (2 * np.pi)
    n_force = force * a / (eta * kt * i_max)
    A, B, C = ke * speed / a, -u_bus, r_hot * load * a / (eta * kt)
    disc = B**2 - 4 * A * C
    root = np.sqrt(np.maximum(disc, 0.0))
    lo = np.where(disc >= 0, (-B - root) / (2 * A), np.inf)
    hi = np.where(disc >= 0, (-B + root) / (2 * A), -np.inf)
    hi = np.minimum(hi, w_mech_motor * a / speed)
    return np.maximum(n_force, lo), hi


MASS_PARTS = ("motor", "motor_housing", "brake", "gear", "screw", "nut", "drive") + dc_structure.MEMBERS
# Holding brake on the motor shaft ([options] dc_brake): a spring-applied
# brake rated for the holding torque. assumed: 0.05 kg + 0.5 kg per N m of
# rated torque, the order of small servo-motor holding brakes (0.1-0.2 kg
# for 0.1-0.4 N m); no brake datasheet was retrieved.
BRAKE_FIXED_MASS = 0.05
BRAKE_MASS_PER_TORQUE = 0.5


def brake_mass(holding_torque):
    """Mass (kg) of a holding brake for ``holding_torque`` (N m, motor shaft)."""
    return BRAKE_FIXED_MASS + BRAKE_MASS_PER_TORQUE * np.abs(np.asarray(holding_torque, float))
# A frameless kit (stator and rotor) needs the housing, shaft, bearings and
# feedback a housed motor carries. Rule from the motor database: the mass of
# housed motors of the closest form (maxon's outer-rotor flat EC motors, 26,
# large diameter and short like the kits) against the frameless kits (Allied
# HT and Megaflux, 148), each fitted as m = a T_c^b over continuous torque
# (least squares in logs, catalogs/motors-mgdb.toml; tests/engine/
# test_dc_structure.py refits them): housed 0.842 T^0.720, frameless
# 0.543 T^0.771 (kg, N m). The kit carries the difference at its own torque.
HOUSED_FIT = (0.842, 0.720)
FRAMELESS_FIT = (0.543, 0.771)


def frameless_housing_mass(continuous_torque):
    """Housing, bearings and feedback of a frameless kit (kg): the housed
    fit minus the frameless fit at its continuous torque (N m), at least 0."""
    T = np.maximum(np.asarray(continuous_torque, float), 1e-6)
    return np.maximum(HOUSED_FIT[0] * T ** HOUSED_FIT[1] - FRAMELESS_FIT[0] * T ** FRAMELESS_FIT[1], 0.0)


def is_frameless(motor) -> bool:
    """A catalog motor that is a frameless kit (its notes say so)."""
    return (getattr(motor, "notes", None) or "").lower().startswith("frameless")


def mass_breakdown(p: PartArrays, req, static: dict) -> dict[str, np.ndarray]:
    """Mass of each part and member (kg), (n,) arrays: the catalog parts,
    the screw shaft over its length, and the structure (``dc_structure``)."""
    v = p.values
    L = TRAVEL_FACTOR * req.requirements.stroke + SCREW_EXTRA_LENGTH
    out = {"motor": v["motor_mass"],
           "motor_housing": np.where(v["motor_frameless"] > 0, frameless_housing_mass(v["motor_continuous_torque"]), 0.0),
           "brake": static["brake_mass_kg"],
           "gear": v["gear_mass"], "screw": v["screw_mass_per_length"] * L,
           "nut": v["screw_nut_mass"], "drive": v["drive_mass"]}
    out.update({name: static[f"{name}_mass_kg"] for name in dc_structure.MEMBERS})
    return out


def metrics(p: PartArrays, req, static: dict) -> dict[str, np.ndarray]:
    """Mass, cost, volume and peak electrical power of each combination."""
    v = p.values
    L = TRAVEL_FACTOR * req.requirements.stroke + SCREW_EXTRA_LENGTH
    mass = sum(static[f"mass_{name}_kg"] for name in MASS_PARTS)
    cost = v["motor_cost_usd"] + v["gear_cost_usd"] + v["screw_cost_usd"] + v["drive_cost_usd"] + ASSEMBLY_USD
    # volume: the housing tube over its length plus motor and gear at 3000 kg/m^3 (assumed)
    volume = (np.pi / 4 * static["housing_outer_diameter_m"] ** 2 * np.maximum(static["housing_length_m"], L)
              + (v["motor_mass"] + v["gear_mass"]) / 3000.0)
    return {"mass_kg": mass, "cost_usd": cost, "volume_m3": volume,
            "power_W": v["drive_bus_voltage"] * static["current_limit_A"]}
