"""``sizing evaluate`` of a piezohydraulic design file: its static
figures, its force path and thermal budget, and its simulated load cases
(``Technology.evaluate``)."""
from __future__ import annotations

import math

import numpy as np

from ...engine import holding
from ...engine.evaluate import finite_or_none, lookup, worst_case
from ...engine.loads import load_cases, surface_mass
from ...errors import InputError
from ...io.catalog import Catalog
from ...physics import hydraulics, structure, thermal
from . import force_path
from .design_file import PiezoDesignFile
from .parts import (DEFAULT_PRESSURE_RATING_PA, Candidates, part_row, reference_bouc_wen, stack_bouc_wen,
                    structure_row)
from .verify import FILL_TEMPERATURE_DEGC, metrics, ramp_time, seal_friction_at, simulate_cases, static_figures

RATIO_TOLERANCE = 0.01


def evaluate_piezo(design: PiezoDesignFile, catalog: Catalog, file: str) -> dict:
    warnings: list[str] = []
    stack = lookup(catalog, catalog.stacks, design.stack, file, "stack")
    fluid = lookup(catalog, catalog.fluids, design.fluid, file, "fluid")
    seal = lookup(catalog, catalog.seals, design.seal, file, "seal")
    amplifier = lookup(catalog, catalog.amplifiers, design.amplifier, file, "amplifier")
    voltage = design.voltage or stack.max_voltage
    if voltage > stack.max_voltage * (1 + 1e-9):
        raise InputError(file, "voltage", f"expected at most the stack's rated {stack.max_voltage:g} V, got {voltage:g} V")
    ratio, wide_area = geometry(design, stack, voltage, seal, warnings)
    bw, bw_source = stack_bouc_wen(stack, reference_bouc_wen(catalog.stacks))
    if bw_source.startswith("assumed"):
        warnings.append(f"Bouc-Wen parameters of {stack.id}: {bw_source.removeprefix('assumed: ')}")
    if fluid is None:
        warnings.append("no fluid given: ISO VG 15 mineral oil, bulk modulus 1.5 GPa assumed")
    if seal is None and design.wide_friction is None:
        warnings.append("no seal given: the seed's 10 N (wide) and 0.2 N (narrow) seal friction assumed")
    overrides = design.model_dump(include={"wide_piston_mass", "narrow_piston_mass", "wide_friction",
                                           "narrow_friction", "breakaway_ratio", "loss_coefficient",
                                           "bulk_modulus", "no_return", "air_fraction", "air_pressure"})
    material, compensator, t_cap, frame_area = structure_of(design, catalog, file, stack, seal, voltage, wide_area)
    surface = surface_mass(design.load)
    struct = structure_row(material, t_cap, frame_area, spacer=force_path.spacer_material(catalog.materials),
                           spacer_length=design.spacer_length, compensator=compensator, surface_mass=surface,
                           delta_T=design.temperature - FILL_TEMPERATURE_DEGC,
                           edge_restraint=structure.edge_restraint(design.plate_edge, design.flange_restraint))
    row = part_row(stack, design.n_stacks, ratio, wide_area, voltage, bw, design.temperature,
                   design.wide_gap, fluid, seal, amplifier, design.pressure_rating, overrides, struct)
    c = Candidates.from_rows([row])
    if design.amplifier_units is not None:
        c.amp_units = np.array([float(design.amplifier_units)])
    # the ramp the drive delivers: the one asked, lengthened to what the units allow (as solve drives it)
    ramp = ramp_time(c, design.ramp_time if design.ramp_time is not None else design.rise_time)
    static = {k: float(np.asarray(v).ravel()[0])
              for k, v in static_figures(c, ramp, design.strokes_per_second).items()}
    checks = _buildable(static, design.n_stacks, warnings)
    members = force_path.members(c)
    worst_load = max((case["load_N"] for case in load_cases(design.load)), default=0.0)
    p_load = worst_load / float(c.narrow_area[0])
    seal_f = {k: float(v[0]) for k, v in seal_friction_at(c, p_load).items()}
    cases = load_cases(design.load)
    sims = simulate_cases(c, [case["load_N"] for case in cases], ramp,
                          load_stiffness=design.load.stiffness)
    simulated = holding.held_cases([dict(case, **{k: finite_or_none(v[0]) for k, v in sim.items()})
                                    for case, sim in zip(cases, sims)], static["output_stiffness_N_m"])
    return {
        "technology": "piezohydraulic",
        "design": {"stack": stack.id, "n_stacks": design.n_stacks, "ratio": ratio, "voltage_V": voltage,
                   "fluid": design.fluid, "seal": design.seal, "amplifier": design.amplifier,
                   "temperature_degC": design.temperature, "rise_time_s": design.rise_time,
                   "amplifier_units": int(c.amp_units[0]), "ramp_time_s": float(ramp[0]),
                   "bouc_wen": dict(zip(["d33", "alpha", "beta", "gamma", "delta", "n"], bw.as_array().tolist())),
                   "bouc_wen_source": bw_source},
        "static": static,
        "simulated": {"cases": simulated, "worst": worst_case(simulated)},
        "metrics": {k: float(v[0]) for k, v in metrics(c, ramp).items()},
        "force_path": force_path.as_list(members, 0, material.id, compensator.id if compensator else None,
                                         force_path.spacer_material(catalog.materials).id),
        "thermal_budget": {k: static["thermal_" + k] for k in (*thermal.TERMS, "net_m")},
        "seal_friction_N": {**seal_f, "at_pressure_Pa": p_load},
        "compensator": _compensator(compensator, members),
        "checks": checks,
        "warnings": warnings,
    }


def structure_of(design: PiezoDesignFile, catalog: Catalog, file: str, stack, seal, voltage: float,
                 wide_area: float) -> tuple:
    """(material, compensator, end cap thickness, frame area) of a design
    file: the thickness and area as given, else sized for the stacks' force."""
    material = (lookup(catalog, catalog.materials, design.material, file, "material")
                if design.material is not None else force_path.default_material(catalog.materials))
    compensator = lookup(catalog, catalog.compensators, design.compensator, file, "compensator")
    rating = design.pressure_rating or (seal.pressure_rating if seal else DEFAULT_PRESSURE_RATING_PA)
    x_free = stack.stroke * voltage / stack.max_voltage
    t_cap, frame_area = force_path.design_structure(
        design.n_stacks * stack.stiffness, design.n_stacks * stack.stiffness * x_free, wide_area, stack.length,
        design.wide_gap, rating, material, design.structure_stiffness_ratio,
        design.end_cap_thickness, design.frame_area)
    return material, compensator, t_cap, frame_area


def _buildable(static: dict, n_stacks: int, warnings: list) -> dict:
    """Can the design be built: do the stacks fit under the wide piston, does
    the wide gap exceed the stack stroke plus a clearance. A design that
    cannot be built is reported (and warned about), not an error."""
    fit = int(static["stacks_that_fit"])
    out = {"stacks_that_fit": fit, "stacks_fit": fit >= n_stacks,
           "wide_gap_ok": static["wide_gap_m"] >= static["gap_needed_m"]}
    if not out["stacks_fit"]:
        warnings.append(f"cannot be built: only {fit} of the {n_stacks} stacks fit under the "
                        f"{static['wide_diameter_m'] * 1e3:.0f} mm wide piston")
    if not out["wide_gap_ok"]:
        warnings.append(f"cannot be built: the wide gap {static['wide_gap_m'] * 1e3:.2f} mm is below the stack stroke "
                        f"plus clearance ({static['gap_needed_m'] * 1e3:.2f} mm): the wide piston bottoms out")
    out["buildable"] = out["stacks_fit"] and out["wide_gap_ok"]
    return out


def _compensator(comp, members) -> dict | None:
    if comp is None:
        return None
    k = float(members["compensator"]["stiffness"][0])
    return {"id": comp.id, "kind": comp.kind, "stiffness_N_m": k if math.isfinite(k) else None,
            "leak_m3_s_Pa": comp.leak_conductance, "mass_kg": comp.mass, "cost_usd": comp.cost_usd,
            "capacity_m3": comp.capacity}


def geometry(design: PiezoDesignFile, stack, voltage, seal, warnings) -> tuple[float, float]:
    """Ratio and wide piston area: from the diameters when given (warning if
    a stated ratio disagrees), else the wide area that keeps the blocked
    pressure at the rating (docs/models.md, "Force path")."""
    if design.wide_diameter is not None:
        ratio = float(hydraulics.area_ratio(design.wide_diameter, design.narrow_diameter))
        if design.ratio is not None and abs(design.ratio / ratio - 1) > RATIO_TOLERANCE:
            warnings.append(f"stated ratio R = {design.ratio:g} disagrees with the diameters "
                            f"({design.wide_diameter * 1e3:.2f} / {design.narrow_diameter * 1e3:.2f} mm give "
                            f"R = {ratio:.1f}); using R = {ratio:.1f}")
        return ratio, float(hydraulics.area(design.wide_diameter))
    rating = design.pressure_rating or (seal.pressure_rating if seal else DEFAULT_PRESSURE_RATING_PA)
    stack_force = design.n_stacks * stack.stiffness * stack.stroke * voltage / stack.max_voltage
    wide_area = stack_force / rating
    warnings.append(f"no diameters given: wide piston sized for a blocked pressure of {rating / 1e6:.0f} MPa "
                    f"({2 * math.sqrt(wide_area / math.pi) * 1e3:.0f} mm bore)")
    return float(design.ratio), wide_area
