"""The force path of piezohydraulic candidates: every member between the
stacks and the output as a spring in series, referred to the wide piston
(docs/formats.md, ``force_path``), with its mass and cost.

Order from the stack base: stacks, (thermal spacer), base plate, frame (tie
rods), wide piston, oil column, (accumulator), end cap, narrow piston. The
mechanical members (stacks to wide piston) make the simulator's stack-side
stiffness; the hydraulic ones (oil, accumulator, end cap, narrow piston)
are folded into the simulator's effective bulk modulus, so the simulated
blocked force equals the static one.

Plates: simply supported by default (the conservative edge), clamped or a
flange with a stated rotational restraint (``[options] plate_edge``; see
physics/structure.py), with bending and shear (Reissner-Mindlin), the
clamped value reported beside it; each states its model and its thickness
over radius, which must stay within the model's validity
(``structure.plate_in_range``). Thicker than ``plate_fe.FE_CHECK_RATIO`` the
plate model is checked against an axisymmetric finite-element solid
(``fe_stiffness_ratio``) and the solid's stiffness is used when they differ
by more than ``plate_fe.FE_TOLERANCE``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...physics import geometry, plate_fe, structure
from ...settings import STRESS_SAFETY

MECHANICAL = ("stacks", "spacer", "base_plate", "frame", "wide_piston")
HYDRAULIC = ("oil_column", "compensator", "end_cap", "narrow_piston")
ALUMINIUM_E = 68.9e9          # Pa, 6061-T6 pistons (physics/geometry.py); catalogs/materials.toml al-6061-t6
ALUMINIUM_NU = 0.33           # catalogs/materials.toml al-6061-t6
STACK_SPACING_M = 1e-3        # assumed: clearance between neighbouring stacks under the wide piston
FRAME_MARGIN_M = 0.0          # frame spans stacks + wide piston + gap exactly


@dataclass(frozen=True)
class FallbackMaterial:
    """6061-T6 (the catalog's al-6061-t6 values) for catalogs without materials.toml."""

    id: str = "al-6061-t6 (built in)"
    youngs_modulus: float = 68.9e9
    poisson: float = 0.33
    density: float = 2700.0
    thermal_expansion: float = 23.6e-6
    yield_strength: float = 276e6
    max_temperature: float = 150.0
    cost_usd: float = 10.0


DEFAULT_MATERIAL = "al-6061-t6"


def default_material(materials: dict):
    """The catalog's 6061-T6, else its first material, else the built-in one."""
    if DEFAULT_MATERIAL in materials:
        return materials[DEFAULT_MATERIAL]
    return next(iter(materials.values()), FallbackMaterial())


def spacer_material(materials: dict):
    """The lowest-expansion material: what a passive-compensation spacer is made of."""
    return min(materials.values(), key=lambda m: m.thermal_expansion) if materials else FallbackMaterial()


def frame_length(stack_length, wide_piston_thickness, wide_gap, spacer_length=0.0):
    """Length of the tie rods between base plate and end cap (m)."""
    return (np.asarray(stack_length) + np.asarray(wide_piston_thickness) + np.asarray(wide_gap)
            + np.asarray(spacer_length) + FRAME_MARGIN_M)


def size_structure(stack_stiffness_total, stack_force, wide_area, frame_len, E, nu, yield_strength,
                   stiffness_ratio):
    """Closed-form sizing of the end cap / base plate thickness and the frame
    section: each at least ``stiffness_ratio`` x the stacks' stiffness and
    within yield / STRESS_SAFETY at the stack force (blocked pressure).
    Returns (cap_thickness m, frame_area m^2)."""
    a = np.sqrt(np.asarray(wide_area) / math.pi)
    allow = np.asarray(yield_strength) / STRESS_SAFETY
    q = np.asarray(stack_force) / np.asarray(wide_area)
    k_target = np.asarray(stiffness_ratio) * np.asarray(stack_stiffness_total)
    t = np.maximum(structure.plate_thickness_for_stiffness(k_target, a, E, nu),
                   structure.plate_thickness_for_stress(q, a, allow, nu))
    area = np.maximum(k_target * np.asarray(frame_len) / np.asarray(E), np.asarray(stack_force) / allow)
    return t, area


def members(c) -> dict[str, dict[str, np.ndarray]]:
    """Every member of ``c`` (piezo.Candidates): stiffness (N/m, referred to
    the wide piston; inf when absent), mass (kg) and cost (USD)."""
    n = len(c)
    inf = np.full(n, np.inf)
    zero = np.zeros(n)
    a = np.sqrt(c.wide_area / math.pi)
    t_p = geometry.plate_thickness(c.wide_area, c.pressure_rating)
    L_f = frame_length(c.stack_length, t_p, c.wide_gap, c.spacer_length)
    model = structure.plate_stiffness(a, c.cap_thickness, c.mat_E, c.mat_nu, edge="flange", restraint=c.edge_restraint)
    fe_ratio = fe_ratios(structure.thickness_ratio(c.cap_thickness, a), c.mat_nu, c.edge_restraint)
    plate = plate_fe.checked_stiffness(model, fe_ratio)
    plate_clamped = structure.plate_stiffness(a, c.cap_thickness, c.mat_E, c.mat_nu, edge="clamped")
    plate_mass = c.mat_density * c.wide_area * c.cap_thickness
    unit = c.mat_cost + geometry.MACHINING_USD_PER_KG
    footprint = c.n_stacks * math.pi * c.stack_diameter**2 / 4
    spacer = np.where(c.spacer_length > 0, c.spacer_E * footprint / np.maximum(c.spacer_length, 1e-12), inf)
    spacer_mass = c.spacer_density * footprint * c.spacer_length
    L_n = c.free_stroke + geometry.ROD_EXTRA_LENGTH
    out = {
        "stacks": {"stiffness": c.n_stacks * c.stiffness, "mass": c.n_stacks * c.stack_mass,
                   "cost": c.n_stacks * c.stack_cost},
        "spacer": {"stiffness": spacer, "mass": spacer_mass, "cost": spacer_mass * (c.spacer_cost + geometry.MACHINING_USD_PER_KG)},
        "base_plate": {"stiffness": plate, "stiffness_clamped": plate_clamped, "mass": plate_mass,
                       "cost": plate_mass * unit, "thickness": c.cap_thickness, "radius": a,
                       "edge": c.edge_restraint, "fe_ratio": fe_ratio},
        "frame": {"stiffness": structure.rod_stiffness(c.mat_E, c.frame_area, L_f),
                  "mass": c.mat_density * c.frame_area * L_f, "cost": c.mat_density * c.frame_area * L_f * unit,
                  "length": L_f, "area": c.frame_area},
        "wide_piston": {"stiffness": wide_piston_stiffness(c, t_p), "mass": c.wide_mass,
                        "cost": zero},
        "oil_column": {"stiffness": c.bulk_modulus * c.wide_area**2 / c.oil_volume,
                       "mass": c.density * c.oil_volume, "cost": zero},
        "compensator": {"stiffness": np.where(c.comp_kind == 1, c.comp_volume_stiffness * c.wide_area**2, inf),
                        "mass": c.comp_mass, "cost": c.comp_cost},
        "end_cap": {"stiffness": plate, "stiffness_clamped": plate_clamped, "mass": plate_mass,
                    "cost": plate_mass * unit, "thickness": c.cap_thickness, "radius": a,
                    "edge": c.edge_restraint, "fe_ratio": fe_ratio},
        "narrow_piston": {"stiffness": c.ratio**2 * structure.rod_stiffness(ALUMINIUM_E, c.narrow_area, L_n),
                          "mass": c.narrow_mass, "cost": zero},
    }
    return out


def wide_piston_stiffness(c, thickness) -> np.ndarray:
    """The wide piston: its compression E A / t in series with the bending
    of the ring that overhangs the stacks' packing circle
    (``structure.overhang_volume``, referred to the wide piston: 1/k = V/q / A^2)."""
    a = np.sqrt(c.wide_area / math.pi)
    b = structure.packing_diameter(c.n_stacks.astype(int), c.stack_diameter, STACK_SPACING_M) / 2
    overhang = structure.overhang_volume(a, b, thickness, ALUMINIUM_E, ALUMINIUM_NU) / c.wide_area**2
    return 1.0 / (1.0 / structure.rod_stiffness(ALUMINIUM_E, c.wide_area, thickness) + overhang)


def fe_ratios(thickness_ratio, nu, restraint) -> np.ndarray:
    """Plate model over finite-element stiffness of each plate thicker than
    ``plate_fe.FE_CHECK_RATIO`` with a simply supported or clamped edge
    (``plate_fe.model_ratio``); NaN where not checked."""
    ratio = np.broadcast_to(np.asarray(thickness_ratio, float), np.shape(restraint))
    nu = np.broadcast_to(np.asarray(nu, float), ratio.shape)
    beta = np.broadcast_to(np.asarray(restraint, float), ratio.shape)
    out = np.full(ratio.shape, np.nan)
    for i in np.flatnonzero((ratio > plate_fe.FE_CHECK_RATIO) & ((beta == 0) | np.isinf(beta))):
        out[i] = plate_fe.model_ratio(ratio[i], nu[i], structure.edge_name(float(beta[i])))
    return out


def totals(m: dict) -> dict[str, np.ndarray]:
    """Series stiffness of the whole path and of its two sides (N/m)."""
    mech = structure.series(*(m[k]["stiffness"] for k in MECHANICAL))
    hyd = structure.series(*(m[k]["stiffness"] for k in HYDRAULIC))
    return {"total": structure.series(mech, hyd), "mechanical": mech, "hydraulic": hyd,
            "compliance_sum": sum(1.0 / np.asarray(m[k]["stiffness"], float) for k in MECHANICAL + HYDRAULIC)}


def simulator_bulk_modulus(c, m: dict) -> np.ndarray:
    """Effective bulk modulus of the simulator's oil spring that gives the
    hydraulic side's stiffness: beta_eff A_w^2 / V = k_hydraulic."""
    k_h = structure.series(*(m[k]["stiffness"] for k in HYDRAULIC))
    return k_h * c.oil_volume / c.wide_area**2


def columns(figures: dict) -> dict[str, list[float]]:
    """Each figure's array as a list of floats, one per candidate: read a
    candidate at a time without a numpy lookup apiece."""
    return {k: np.asarray(v, dtype=float).tolist() for k, v in figures.items()}


def listed(m: dict) -> dict[str, dict[str, list]]:
    """``members(c)`` with every array a list of floats (``columns``), as
    ``as_list`` reads it."""
    return {name: columns(member) for name, member in m.items()}


def _at(values, i: int) -> float:
    return float(values[i]) if isinstance(values, list) else float(np.asarray(values)[i])


def as_list(m: dict, i: int, material_id: str, compensator_id: str | None,
            spacer_id: str | None = None) -> list[dict]:
    """The contract's ``force_path`` list for candidate i (absent members
    left out); ``m``: ``members(c)`` or ``listed(members(c))``."""
    out = []
    for name in MECHANICAL + HYDRAULIC:
        k = _at(m[name]["stiffness"], i)
        if name == "spacer" and not math.isfinite(k):
            continue
        if name == "compensator" and compensator_id is None:
            continue
        row = {"member": name, "stiffness_N_m": k if math.isfinite(k) else None,
               "mass_kg": _at(m[name]["mass"], i), "cost_usd": _at(m[name]["cost"], i)}
        if name in ("base_plate", "end_cap", "frame"):
            row["material"] = material_id
        if name == "spacer":
            row["material"] = spacer_id
        if name in ("base_plate", "end_cap"):
            row["stiffness_clamped_N_m"] = _at(m[name]["stiffness_clamped"], i)
            row["thickness_m"] = _at(m[name]["thickness"], i)
            beta = _at(m[name]["edge"], i)
            row["edge"] = structure.edge_name(beta)
            if row["edge"] == "flange":
                row["edge_restraint"] = beta
            ratio = _at(m[name]["fe_ratio"], i)
            if math.isfinite(ratio):
                row["fe_stiffness_ratio"] = ratio
            row["model"] = structure.PLATE_MODEL
            row["thickness_to_radius"] = float(structure.thickness_ratio(row["thickness_m"], _at(m[name]["radius"], i)))
            row["model_valid_to_thickness_to_radius"] = structure.MINDLIN_MAX_THICKNESS_RATIO
        if name == "frame":
            row["length_m"] = _at(m[name]["length"], i)
            row["area_m2"] = _at(m[name]["area"], i)
        if name == "compensator":
            row["id"] = compensator_id
        out.append(row)
    total = sum(1.0 / r["stiffness_N_m"] for r in out if r["stiffness_N_m"])
    for r in out:
        r["compliance_share"] = (1.0 / r["stiffness_N_m"] / total) if r["stiffness_N_m"] else 0.0
    return out


def design_structure(n_stiffness, stack_force, wide_area, stack_length, wide_gap, pressure_rating,
                     material, stiffness_ratio, cap_thickness=None, frame_area=None):
    """Cap thickness and frame section of one design: the given values, or
    the closed-form rule of ``size_structure`` (SI floats)."""
    t_p = float(geometry.plate_thickness(wide_area, pressure_rating))
    L_f = float(frame_length(stack_length, t_p, wide_gap))
    t, area = size_structure(n_stiffness, stack_force, wide_area, L_f, material.youngs_modulus,
                             material.poisson, material.yield_strength, stiffness_ratio)
    return (float(t) if cap_thickness is None else cap_thickness,
            float(area) if frame_area is None else frame_area)
