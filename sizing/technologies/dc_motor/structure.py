"""The structure of a DC actuator from parts, sized by the force it carries.

The force path of a screw actuator: clevis (rod end) -> output rod -> nut
-> screw -> thrust bearings -> bearing block and end cap -> housing tube
-> clevis (mount). The screw is the catalog part (its buckling, life and
static safety are ``dc_parts`` margins); the members around it are sized
here for the design force F_d = ULTIMATE_FACTOR x the largest force the
drive can push (at least the required blocked force), each by its rule,
each with its mass and its check as a margin (achieved / needed - 1):

- ``rod``: a steel tube over the screw (bore: the shaft plus a clearance),
  its wall the thinnest that carries F_d as a column (``physics/column``:
  Euler above the transition slenderness, Johnson below), free length the
  travel plus the rod end, K = 2: cantilevered from its guide, the rod end
  pinned to a surface horn that moves sideways as the actuator pivots on
  its mount (the limit of a housing much stiffer than the rod; Parker's
  stroke factor 2 for a pivot-mounted cylinder with a pivoted rod end).
  Margin ``rod_buckling``.
- ``thrust_bearing``: a back-to-back pair of 40 degree angular contact
  bearings at the fixed end, the lightest of ``BEARINGS`` whose bore fits
  the screw's journal and that meets L10 life at the duty (ISO 281) and the
  static safety (ISO 76, a factor of its own) at the peak force. Margins ``bearing_life``,
  ``bearing_static``.
- ``housing``: an aluminium tube around nut, bearings and rod guide; bore
  the largest of them, length the travel plus nut, bearing pair and guide;
  wall the thickest of: a floor (machining), the column (pinned-pinned over
  its length), the eccentric load's outer-fibre stress, and an axial
  stiffness at least the screw shaft's (so the housing adds at most as
  much compliance as the screw). Margin ``housing_stress``.
- ``end_caps``: the bearing block (a ring holding the pair, closed by a
  plate carrying F_d: ``physics/structure.plate_thickness_for_stress``,
  simply supported) and the rod-end cap carrying the guide bushing.
  Margin ``end_cap_stress``.
- ``clevises``: a pin-and-lug fitting at each end, the pin sized for shear
  and bending, the eye for bearing (``physics/clevis``).
  Margin ``clevis``.

The moving mass adds the rod and the rod-end eye to the nut.
"""
from __future__ import annotations

import numpy as np

from ...physics import bearing as bearing_phys
from ...physics import clevis as clevis_phys
from ...physics import column
from ...physics import structure as plate
from ...settings import BEARING_STATIC_SAFETY
from ...settings import REQUIRED_LIFE_H as BEARING_LIFE_H
from ...settings import ULTIMATE_FACTOR

# Materials: AISI 4340 Q&T (rod, clevises, pins) and 6061-T6 (housing, end caps),
# the values of catalogs/materials.toml (MatWeb / Aluminum Association, cited there).
STEEL = {"E": 205e9, "yield": 834e6, "density": 7850.0}
ALUMINIUM = {"E": 68.9e9, "yield": 276e6, "density": 2700.0, "poisson": 0.33}
SCREW_STEEL_DENSITY = 7850.0            # kg/m^3: the screw shaft's diameter from its mass per metre

ROD_CLEARANCE = 1.0e-3        # m radial, rod bore over the screw shaft (assumed: a ball screw's thread runs free)
ROD_MIN_WALL = 1.0e-3         # m: thinnest machined steel rod tube (assumed)
ROD_END_LENGTH = 0.02         # m: rod beyond the housing when retracted, with its thread (assumed)
ROD_K = 2.0                   # effective-length factor of the rod (see above)
GUIDE_LENGTH_OVER_DIAMETER = 1.5   # guide bushing length over the rod diameter (assumed: plain bushing L/D >= 1.5)
HOUSING_MIN_WALL = 1.5e-3     # m: thinnest machined 6061 housing wall (assumed: threads for the end caps)
HOUSING_RADIAL_CLEARANCE = 1.0e-3   # m: bore over the nut (assumed)
HOUSING_STIFFNESS_OVER_SCREW = 1.0  # housing axial stiffness at least the screw shaft's (assumed design rule)
ECCENTRICITY = 1.0e-3         # m: the load's offset from the axis (assumed: pin and bushing clearances, mount misalignment)
CAP_MIN_THICKNESS = 3.0e-3    # m: thinnest end plate (assumed)
PIN_MIN_DIAMETER = 4.0e-3     # m: smallest clevis pin (assumed: an M4 rod-end thread class)
LUG_MIN_THICKNESS = 2.0e-3    # m: thinnest lug (assumed)
JOURNAL_OVER_SHAFT = 1.05     # bearing bore at most 1.05 x the shaft's mass-equivalent diameter
# Members sized by a closed form (end plate, clevis) are sized for the force
# plus this relative part: rounding in the closed form otherwise leaves a
# member sized exactly to the force a part in 1e16 short of its own check
# (margin -2e-16), which failed every design whose plate the stress set.
SIZING_ROUNDING = 1e-9

# Back-to-back pairs of single-row 40 degree angular contact ball bearings, SKF
# 72 B / BECBP series: (designation, bore m, outer diameter m, width m, C N, C0 N, mass kg).
# assumed: the SKF general catalogue's figures for the series as tabulated in
# the rolling-bearings catalogue (publication 10000 EN), not retrieved for this
# table; checked for self-consistency (C and C0 rise with the section).
BEARINGS = (
    ("7200 BECBP", 0.010, 0.030, 0.009, 7020.0, 3350.0, 0.030),
    ("7201 BECBP", 0.012, 0.032, 0.010, 7610.0, 3800.0, 0.036),
    ("7202 BECBP", 0.015, 0.035, 0.011, 8840.0, 4650.0, 0.045),
    ("7203 BECBP", 0.017, 0.040, 0.012, 11100.0, 5850.0, 0.065),
    ("7204 BECBP", 0.020, 0.047, 0.014, 14300.0, 8300.0, 0.110),
    ("7205 BECBP", 0.025, 0.052, 0.015, 15600.0, 10000.0, 0.130),
    ("7206 BECBP", 0.030, 0.062, 0.016, 23800.0, 15600.0, 0.210),
    ("7207 BECBP", 0.035, 0.072, 0.017, 30700.0, 20800.0, 0.290),
    ("7208 BECBP", 0.040, 0.080, 0.018, 36400.0, 26000.0, 0.370),
)
MEMBERS = ("rod", "thrust_bearing", "housing", "end_caps", "clevises")
MARGINS = ("rod_buckling", "bearing_life", "bearing_static", "housing_stress", "end_cap_stress", "clevis")


def shaft_diameter(mass_per_length):
    """The screw shaft's diameter (m) from its mass per metre (solid steel)."""
    return np.sqrt(4 * np.asarray(mass_per_length) / (np.pi * SCREW_STEEL_DENSITY))


def nut_diameter(nut_mass, shaft):
    """A ball nut taken as a steel sleeve as long as its outer diameter D
    on the shaft: m = rho pi (D^2 - d^2) D / 4, solved for D (m) by bisection."""
    m = np.asarray(nut_mass, float)
    f = lambda D: SCREW_STEEL_DENSITY * np.pi / 4 * (D**2 - shaft**2) * D
    return column.smallest_outer_diameter(f, m, shaft, shaft, shaft + 0.2)


def rod(force, shaft, travel):
    """The output rod: a steel tube over the shaft sized as a column."""
    bore = shaft + 2 * ROD_CLEARANCE
    length = travel + ROD_END_LENGTH
    cap = lambda D: column.critical_load(STEEL["E"], STEEL["yield"], column.tube_area(D, bore),
                                         column.tube_radius_of_gyration(D, bore), length, ROD_K)
    outer = column.smallest_outer_diameter(cap, force, bore, bore + 2 * ROD_MIN_WALL, bore + 0.2)
    return {"outer_diameter_m": outer, "bore_m": bore, "length_m": length,
            "critical_load_N": cap(outer), "mass_kg": STEEL["density"] * column.tube_area(outer, bore) * length}


def thrust_bearing(force, holding, rev_per_s, shaft):
    """The lightest bearing pair of ``BEARINGS`` whose bore fits the journal
    and that meets life and static safety; the largest that fits where none does."""
    force, holding, rev_per_s, shaft = np.broadcast_arrays(*(np.atleast_1d(np.asarray(x, float))
                                                           for x in (force, holding, rev_per_s, shaft)))
    table = np.array([row[1:] for row in BEARINGS])
    bore, od, width, C, C0, mass = table.T
    fits = bore[None, :] <= JOURNAL_OVER_SHAFT * np.asarray(shaft)[:, None]
    life = bearing_phys.l10_hours(C[None, :], np.asarray(holding)[:, None], np.asarray(rev_per_s)[:, None])
    safe = bearing_phys.static_safety(C0[None, :], np.asarray(force)[:, None])
    good = fits & (life >= BEARING_LIFE_H) & (safe >= BEARING_STATIC_SAFETY)
    # catalog order is by rising size and mass: the first good one, else the largest that fits
    largest_fit = np.where(fits.any(axis=1), fits.shape[1] - 1 - np.argmax(fits[:, ::-1], axis=1), 0)
    pick = np.where(good.any(axis=1), np.argmax(good, axis=1), largest_fit)
    rows = np.arange(len(pick))
    return {"index": pick, "bore_m": bore[pick], "outer_diameter_m": od[pick], "width_m": width[pick],
            "life_h": life[rows, pick], "static_safety": safe[rows, pick],
            "fits": fits[rows, pick], "mass_kg": 2 * mass[pick]}


def housing(force, bore, length, screw_stiffness):
    """The housing tube: its wall from the floor, the column, the eccentric
    stress and the stiffness rule."""
    need_area = HOUSING_STIFFNESS_OVER_SCREW * screw_stiffness * length / ALUMINIUM["E"]
    stiff = np.sqrt(bore**2 + 4 * need_area / np.pi)
    cap = lambda D: np.minimum(
        column.critical_load(ALUMINIUM["E"], ALUMINIUM["yield"], column.tube_area(D, bore),
                             column.tube_radius_of_gyration(D, bore), length, column.END_FIXITY["pinned-pinned"]),
        ALUMINIUM["yield"] / np.maximum(column.eccentric_stress(1.0, ECCENTRICITY, D, bore), 1e-30))
    floor = np.maximum(bore + 2 * HOUSING_MIN_WALL, stiff)
    outer = column.smallest_outer_diameter(cap, force, bore, floor, bore + 0.3)
    return {"outer_diameter_m": outer, "bore_m": bore, "length_m": length, "capacity_N": cap(outer),
            "stiffness_N_m": ALUMINIUM["E"] * column.tube_area(outer, bore) / length,
            "mass_kg": ALUMINIUM["density"] * column.tube_area(outer, bore) * length}


def end_caps(force, housing_outer, housing_bore, bearing_od, bearing_width, rod_outer):
    """Bearing block (a ring around the pair, closed by a plate carrying the
    force) and the rod-end cap holding the guide bushing (m, kg)."""
    q = force / (np.pi * (housing_bore / 2) ** 2)
    plate_t = np.maximum(plate.plate_thickness_for_stress(q, housing_bore / 2, ALUMINIUM["yield"],
                                                         ALUMINIUM["poisson"]), CAP_MIN_THICKNESS)
    rho = ALUMINIUM["density"]
    block = rho * (np.pi / 4 * (housing_outer**2 - bearing_od**2) * 2 * bearing_width
                   + np.pi / 4 * housing_outer**2 * plate_t)
    guide = GUIDE_LENGTH_OVER_DIAMETER * rod_outer
    cap = rho * np.pi / 4 * (housing_outer**2 - rod_outer**2) * guide
    stress = plate.plate_stress(q, housing_bore / 2, plate_t, ALUMINIUM["poisson"])
    return {"plate_thickness_m": plate_t, "guide_length_m": guide, "mass_kg": block + cap,
            "plate_capacity_N": force * ALUMINIUM["yield"] / np.maximum(stress, 1e-30)}


def clevises(force):
    """A pin-and-lug fitting at each end; the rod end's eye moves with the rod."""
    Sy = STEEL["yield"]
    pin = np.maximum.reduce([clevis_phys.pin_diameter(force, Sy), clevis_phys.pin_bending_diameter(force, Sy),
                             np.full(np.shape(force), PIN_MIN_DIAMETER)])
    t = np.maximum(clevis_phys.eye_thickness(force, pin, Sy), LUG_MIN_THICKNESS)
    one = STEEL["density"] * clevis_phys.fitting_volume(pin, t)
    # the force at which shear, bearing or bending reaches yield (bending grows as F t / 4 at fixed t)
    capacity = np.minimum.reduce([np.pi * pin**2 / 2 * Sy / np.sqrt(3), pin * t * Sy,
                                  Sy * np.pi * pin**3 / (8 * t)])
    return {"pin_diameter_m": pin, "eye_thickness_m": t, "capacity_N": capacity, "mass_kg": 2 * one,
            "moving_mass_kg": one / 2}


def once_per_distinct(member, *columns, **fixed):
    """``member(*columns, **fixed)`` with each distinct row of ``columns``
    (alike to the byte) sized once and spread back to every row that has it.
    The members are elementwise, so every figure is the same to the bit;
    a catalog's combinations share few (force, screw) rows (the seed's
    39 000 screened combinations, under 5 200), and each row costs a
    60-step bisection."""
    cols = np.broadcast_arrays(*(np.asarray(c, float) for c in columns))
    if cols[0].ndim != 1 or len(cols[0]) < 2:
        return member(*columns, **fixed)
    rows = np.ascontiguousarray(np.stack(cols, axis=1))
    keys = rows.view(np.dtype((np.void, rows.itemsize * rows.shape[1]))).ravel()
    _, first, back = np.unique(keys, return_index=True, return_inverse=True)
    back = back.reshape(-1)
    out = member(*(c[first] for c in cols), **fixed)
    spread = lambda v: v[back] if np.shape(v) == (len(first),) else v      # noqa: E731
    return {k: spread(v) for k, v in out.items()} if isinstance(out, dict) else spread(out)


def size(values: dict, travel: float, peak_force, holding_force, rev_per_s, screw_length: float) -> dict:
    """Every member of each combination (``values``: ``PartArrays.values``),
    for the design force ULTIMATE_FACTOR x ``peak_force`` (N, (n,)); the
    bearings' life at ``holding_force`` and ``rev_per_s``. Returns
    {"members": {name: figures}, "margins": {name: (n,)}, "mass_kg": (n,),
    "moving_mass_kg": (n,)}."""
    F = ULTIMATE_FACTOR * np.asarray(peak_force, float)
    shaft = shaft_diameter(values["screw_mass_per_length"])
    nut = once_per_distinct(nut_diameter, values["screw_nut_mass"], shaft)
    r = once_per_distinct(rod, F, shaft, travel=travel)
    b = thrust_bearing(np.asarray(peak_force, float), holding_force, rev_per_s, shaft)
    guide = GUIDE_LENGTH_OVER_DIAMETER * r["outer_diameter_m"]
    bore = np.maximum.reduce([nut + 2 * HOUSING_RADIAL_CLEARANCE, b["outer_diameter_m"], r["outer_diameter_m"]])
    length = travel + nut + 2 * b["width_m"] + guide
    screw_k = values["screw_elastic_modulus"] * column.tube_area(values["screw_diameter"], 0.0) / screw_length
    h = once_per_distinct(housing, F, bore, length, screw_k)
    F_sized = F * (1.0 + SIZING_ROUNDING)
    caps = end_caps(F_sized, h["outer_diameter_m"], bore, b["outer_diameter_m"], b["width_m"], r["outer_diameter_m"])
    c = clevises(F_sized)
    members = {"rod": r, "thrust_bearing": b, "housing": h, "end_caps": caps, "clevises": c}
    margins = {
        "rod_buckling": r["critical_load_N"] / F - 1.0,
        "bearing_life": np.where(b["fits"], b["life_h"] / BEARING_LIFE_H - 1.0, -1.0),
        "bearing_static": np.where(b["fits"], b["static_safety"] / BEARING_STATIC_SAFETY - 1.0, -1.0),
        "housing_stress": h["capacity_N"] / F - 1.0,
        "end_cap_stress": caps["plate_capacity_N"] / F - 1.0,
        "clevis": c["capacity_N"] / F - 1.0,
    }
    mass = sum(m["mass_kg"] for m in members.values())
    return {"members": members, "margins": margins, "mass_kg": mass,
            "moving_mass_kg": r["mass_kg"] + c["moving_mass_kg"]}


def static_figures(sized: dict) -> dict:
    """Flat static figures of the members, keyed ``<member>_<figure>``
    (``rod_mass_kg``), SI."""
    out, shape = {}, np.shape(sized["mass_kg"])
    for name, figures in sized["members"].items():
        for key, val in figures.items():
            if key.endswith(("_m", "_kg", "_N", "_h", "_N_m", "_safety")) and key != "moving_mass_kg":
                out[f"{name}_{key}"] = np.broadcast_to(np.asarray(val, float), shape).copy()
    out["structure_mass_kg"] = np.asarray(sized["mass_kg"], float)
    return out


RULES = {
    "rod": ("steel tube over the screw, column of the free length (Euler/Johnson, K = 2) "
            "at the ultimate factor", "rod_buckling"),
    "thrust_bearing": ("back-to-back pair of 40 degree angular contact bearings, the lightest of the "
                       "series with L10 life (ISO 281) and static safety (ISO 76)", "bearing_life"),
    "housing": ("6061 tube around nut, bearings and guide: wall from the floor, the column, the "
                "eccentric load and an axial stiffness at least the screw's", "housing_stress"),
    "end_caps": ("bearing block (ring and plate carrying the force) and rod-end guide cap", "end_cap_stress"),
    "clevises": ("pin in double shear and bending, eye in bearing, at each end", "clevis"),
}


def structure_members(static) -> list[dict]:
    """The results.json ``structure`` list of one design from its static
    figures: each member's mass, its rule, the margin that checks it and
    its dimensions."""
    out = []
    for name in MEMBERS:
        rule, margin = RULES[name]
        dims = {key[len(name) + 1:]: static[key] for key in static if key.startswith(name + "_")}
        out.append({"member": name, "rule": rule, "margin": margin, **dims})
    return out
