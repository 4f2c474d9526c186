"""``sizing solve``: enumerate, size, verify by simulation, rank.

1. ``search.enumerate_combos``: every stack x fluid x seal x amplifier x
   stack count, pruned by temperature ratings, the work bound and the
   amplifier voltage, each with the requirement that rules it out.
2. ``convex.GPSizer``: one geometric program per surviving combination
   sizes R, the wide piston area and the drive voltage.
3. The sized designs go through the same code as ``sizing evaluate``
   (``piezo.part_row``, ``verify.static_figures``, ``verify.metrics``), so
   their static figures agree with it, and are simulated under each load
   case (``verify.simulate_cases``), on and near the Pareto front first.
4. 100 degC: every design is kept as built ("uncompensated", whose oil
   drifts the output by V alpha_T dT / A_n) and, when asked, again with a
   thermal compensator (an assumed spring-loaded accumulator, with a stated
   mass and cost): both are in the results, side by side.
5. The catalog's DC actuators are simulated under the same load cases and
   ranked in the same list (``dc_candidates.py``).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace
from functools import lru_cache

import numpy as np

from .. import __version__
from ..errors import SimulationError
from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from ..physics import bouc_wen, fluid as fluid_props
from ..physics.bouc_wen import BoucWen
from ..physics import geometry, load as load_phys, stack as stack_phys, structure, thermal
from . import force_path
from .convex import GPSizer, SizingInput
from .dc_candidates import dc_candidates
from .evaluate import load_cases
from .piezo import Candidates, part_row, reference_bouc_wen, stack_bouc_wen, structure_row
from .rank import ceiling_margin, floor_margin, nondominated_levels, rank_order, verdict
from .search import Combo, enumerate_combos, temperature_margin
from .solve_summary import _assumptions, _clean, _requirements_si, _summary, _traces
from .verify import (GAP_CLEARANCE_M, STACK_SPACING_M, metrics, ramp_time,
                     seal_friction_at, simulate_cases, static_figures)

SIM_CHUNK = 32
MAX_SPACER_M = 0.5          # longest passive-compensation spacer considered
# margins the simulation order ignores: they depend on the duty or the
# compensation, not on what the simulation checks, and must not keep the
# designs that pass everything else from being simulated first
SCREEN_IGNORES = ("thermal_drift", "amplifier_continuous_current")
OBJECTIVE_KEYS = {"mass": "mass_kg", "cost": "cost_usd", "volume": "volume_m3", "power": "power_W"}


@dataclass
class SolveOutput:
    results: dict                                  # results.json
    traces: list = field(default_factory=list)     # time traces of the top designs, for the report


def _progress(callback, stage, done, total):
    if callback is not None:
        callback(stage, done, total)


def solve(req: RequirementsFile, requirements_sha256: str, catalog: Catalog, progress=None) -> SolveOutput:
    """Run the whole search. ``progress(stage, done, total)`` is called while
    candidates are sized and simulated."""
    start = time.perf_counter()
    cases = load_cases(req.load)
    loads = [c["load_N"] for c in cases]
    combos = enumerate_combos(req, catalog)
    to_size = [c for c in combos if not c.pruned]
    sized = _size(req, catalog, to_size, progress)
    designs = _designs(req, catalog, sized)
    _simulate(req, designs, loads, progress)
    candidates = [_pruned_candidate(req, c) for c in combos if c.pruned]
    for d in designs:
        candidates.extend(_design_candidates(req, d))
    dc = dc_candidates(req, catalog, loads) if req.options.dc_motors else []
    candidates.extend(dc["candidates"] if dc else [])
    _rank(req, candidates)
    candidates.sort(key=lambda c: c["rank"])
    results = {
        "tool_version": __version__,
        "requirements_sha256": requirements_sha256,
        "catalog_sha256": catalog.sha256,
        "candidates": candidates,
        "requirements": _requirements_si(req),
        "load_cases": cases,
        "objectives": list(req.objectives.minimize),
        "assumptions": _assumptions(req),
        "summary": _summary(req, candidates, catalog),
        "disagreements": _disagreements(designs),
        "hysteresis_time_scales": hysteresis_time_scales(catalog),
        "counts": {"combinations": len(combos), "pruned": len(combos) - len(to_size), "sized": len(to_size),
                   "gp_feasible": sum(1 for d in designs if d["gp_success"]),
                   "simulated": sum(1 for d in designs if d["simulated"] is not None)},
    }
    traces = _traces(req, candidates, designs, dc, loads)
    results["runtime_s"] = time.perf_counter() - start
    return SolveOutput(results=_clean(results), traces=traces)


# --- sizing ---------------------------------------------------------------
@dataclass
class Variant:
    """One way to build a combination: structure material and thermal
    compensation (None: as built; "passive": a low-expansion spacer that
    cancels the thermal budget; a catalog compensator)."""

    material: object
    compensator: object = None
    passive: bool = False

    @property
    def name(self) -> str:
        if self.compensator is not None:
            return "compensated"
        return "passive" if self.passive else "uncompensated"

    def suffix(self) -> str:
        tail = f"-{self.material.id}"
        if self.compensator is not None:
            return tail + f"-tc-{self.compensator.id}"
        return tail + ("-pc" if self.passive else "")


def effective_gap(req: RequirementsFile, stack_free_stroke: float) -> float:
    """The wide gap: the option, raised to the stack stroke plus a clearance
    (a gap below the stroke bottoms the wide piston out)."""
    return max(req.options.wide_gap, stack_free_stroke + GAP_CLEARANCE_M)


def sizing_input(req: RequirementsFile, c: Combo, material=None, compensator=None) -> SizingInput:
    T = req.requirements.max_temperature
    f, s, st = c.fluid, c.seal, c.stack
    material = material if material is not None else force_path.default_material({})
    stack_volume = st.length * st.diameter**2 * (1.0 if st.section == "square" else math.pi / 4)
    accumulator = (1.0 / compensator.volume_stiffness
                   if compensator is not None and compensator.kind == "accumulator" else 0.0)
    return SizingInput(
        n_stiffness=c.n * st.stiffness, stack_stroke=c.stack_stroke, rated_voltage=st.max_voltage,
        max_fraction=c.voltage_fraction_max, force=req.requirements.blocked_force,
        stroke=req.requirements.stroke,
        bulk_modulus=float(fluid_props.bulk_modulus_at(f.bulk_modulus, f.bulk_modulus_temperature_coefficient, T)),
        wide_gap=effective_gap(req, c.stack_stroke * c.voltage_fraction_max), pressure_rating=s.pressure_rating,
        natural_frequency=req.natural_frequency, stroke_time=req.stroke_time,
        n_capacitance=c.n * st.capacitance, max_current=c.amplifier.max_current,
        margin=req.options.design_margin,
        fixed_mass=c.n * st.mass + c.amplifier.mass + (compensator.mass if compensator else 0.0),
        fixed_cost=(c.n * st.cost_usd + c.amplifier.cost_usd + 2 * s.cost_usd + geometry.FIXED_HYDRAULIC_USD
                    + (compensator.cost_usd if compensator else 0.0)),
        fixed_volume=1.5 * c.n * stack_volume,
        oil_density=float(fluid_props.density_at(f.density, f.thermal_expansion, T)),
        oil_cost=f.cost_usd * 1000.0,
        youngs_modulus=material.youngs_modulus, poisson=material.poisson, material_density=material.density,
        material_unit_cost=material.cost_usd + geometry.MACHINING_USD_PER_KG,
        allowable_stress=material.yield_strength / force_path.STRESS_SAFETY, stack_length=st.length,
        stiffness_ratio=req.options.structure_stiffness_ratio,
        packing_area=math.pi / 4 * float(structure.packing_diameter(c.n, st.diameter, STACK_SPACING_M)) ** 2,
        accumulator_compliance=accumulator, seal_f0=s.friction_per_length, seal_cp=s.friction_pressure_coefficient,
        surface_mass=_surface_mass(req))


def _surface_mass(req: RequirementsFile) -> float:
    L = req.load
    return 0.0 if L.force is not None else float(load_phys.tip_equivalent_mass(L.span, L.chord, L.thickness))


def variants(req: RequirementsFile, catalog: Catalog) -> list[Variant]:
    """Every structure material rated to the requirement, each as built and
    with each catalog compensator rated to it (when compensation is on)."""
    T = req.requirements.max_temperature
    mats = [m for m in catalog.materials.values() if m.max_temperature >= T] or [force_path.default_material({})]
    comps = [c for c in catalog.compensators.values() if c.max_temperature >= T] if req.options.thermal_compensation else []
    return [Variant(m, comp) for m in mats for comp in [None, *comps]]


def _size(req, catalog, combos, progress):
    """One geometric program per combination, as built and with each open
    accumulator, in the default structure material; the other materials
    get the same member stiffnesses re-sized in closed form (a cheap,
    vectorisable screen: the force path is unchanged, mass and cost and
    the thermal budget follow the material). An orifice reservoir adds no
    stiffness, so it reuses the as-built sizing."""
    sizer = GPSizer(req.objectives.minimize)
    out = []
    vs = variants(req, catalog)
    base = force_path.default_material(catalog.materials)
    if base.id not in {v.material.id for v in vs}:
        base = vs[0].material
    for i, c in enumerate(combos):
        solved = {}
        for v in vs:
            key = v.compensator.id if v.compensator is not None and v.compensator.kind == "accumulator" else None
            if key not in solved:
                solved[key] = sizer.solve(sizing_input(req, c, base, v.compensator if key else None))
            res = solved[key]
            if v.material.id != base.id and math.isfinite(res.cap_thickness):
                res = _resized(req, c, res, base, v.material)
            out.append((c, v, res))
        if i % 8 == 0 or i == len(combos) - 1:
            _progress(progress, "sizing", i + 1, len(combos))
    return out


def _resized(req, c: Combo, res, old, new):
    v = min(res.voltage_fraction, c.voltage_fraction_max)
    x = c.stack_stroke * v
    t_p = float(geometry.plate_thickness(res.wide_area, c.seal.pressure_rating))
    L_f = float(force_path.frame_length(c.stack.length, t_p, effective_gap(req, x)))
    t, area = force_path.resize_for_material(res.cap_thickness, res.frame_area, res.wide_area, L_f,
                                             c.n * c.stack.stiffness * x, old, new)
    return replace(res, cap_thickness=t, frame_area=area)


def _designs(req, catalog, sized) -> list[dict]:
    """Build the sized designs with the same code as ``sizing evaluate``;
    then, for as-built designs that drift, the passive variant."""
    reference = reference_bouc_wen(catalog.stacks)
    spacer = force_path.spacer_material(catalog.materials)
    designs = []
    for combo, var, res in sized:
        d = {"combo": combo, "variant": var, "gp": res, "gp_success": res.success, "index": None, "simulated": None,
             "spacer": 0.0, "id": combo.key + var.suffix()}
        if math.isfinite(res.ratio) and math.isfinite(res.wide_area):
            d["bw"] = stack_bouc_wen(combo.stack, reference)
        designs.append(d)
    _build(req, [d for d in designs if "bw" in d], spacer)
    passive = []
    for d in designs:
        if d.get("static") is None or d["variant"].compensator is not None:
            continue
        length = _spacer_length(req, d, spacer)
        if length > 0:
            var = Variant(d["variant"].material, None, True)
            passive.append(dict(d, variant=var, spacer=length, simulated=None, static=None,
                                id=d["combo"].key + var.suffix()))
    _build(req, passive, spacer)
    return designs + passive


def _spacer_length(req, d, spacer) -> float:
    """Low-expansion spacer in the stack column (the frame longer by as
    much) that brings the as-built thermal budget to zero: net / (R
    (alpha_frame - alpha_spacer) dT). 0 when the design does not drift
    beyond the allowance, drifts the other way, or the frame material
    expands no more than the spacer."""
    st = d["static"]
    net = st["thermal_net_m"]
    allowed = req.options.max_drift_fraction * req.requirements.stroke
    dT = req.requirements.max_temperature - req.options.drift_reference_temperature
    d_alpha = d["variant"].material.thermal_expansion - spacer.thermal_expansion
    if abs(net) <= allowed or net <= 0 or d_alpha <= 0 or dT <= 0:
        return 0.0
    length = net / (st["ratio"] * d_alpha * dT)
    return length if length < MAX_SPACER_M else 0.0


def _build(req, designs, spacer) -> None:
    """Candidate rows, static figures, metrics and static margins of the designs (in place)."""
    if not designs:
        return
    T, S = req.requirements.max_temperature, req.requirements.stroke
    rows = []
    for d in designs:
        combo, res, var = d["combo"], d["gp"], d["variant"]
        v = min(res.voltage_fraction, combo.voltage_fraction_max)
        voltage = v * combo.stack.max_voltage
        free = res.ratio * combo.stack_stroke * v
        d["rise"] = 0.5 * req.stroke_time * free / S          # reach the stroke in half the time allowed
        bw, d["bouc_wen_source"] = d["bw"]
        struct = structure_row(var.material, res.cap_thickness, res.frame_area, spacer, d["spacer"],
                               var.compensator, _surface_mass(req), T - req.options.drift_reference_temperature)
        rows.append(part_row(combo.stack, combo.n, res.ratio, res.wide_area, voltage, bw, T,
                             effective_gap(req, combo.stack_stroke * v), combo.fluid, combo.seal, combo.amplifier,
                             structure=struct))
        d["index"] = len(rows) - 1
    c = Candidates.from_rows(rows)
    rise = np.array([d["rise"] for d in designs])
    ramp = ramp_time(c, rise)
    static = static_figures(c, ramp, req.duty.strokes_per_second)
    met = metrics(c, ramp)
    members = force_path.members(c)
    loads = [case["load_N"] for case in load_cases(req.load)]
    p_load = max(loads) / c.narrow_area
    seal_f = seal_friction_at(c, p_load)
    for d in designs:
        i = d["index"]
        d["cand"] = c.take([i])
        d["ramp"] = float(ramp[i])
        d["static"] = {k: float(np.asarray(v)[i]) for k, v in static.items()}
        d["metrics"] = {k: float(np.asarray(v)[i]) for k, v in met.items()}
        comp = d["variant"].compensator
        d["force_path"] = force_path.as_list(members, i, d["variant"].material.id, comp.id if comp else None,
                                             spacer.id if d["spacer"] > 0 else None)
        d["seal_friction"] = {"wide": float(seal_f["wide"][i]), "narrow": float(seal_f["narrow"][i]),
                              "at_pressure_Pa": float(p_load[i])}
        d["static_margins"] = _static_margins(req, d)


def _static_margins(req, d) -> dict:
    """Every static check of one design, from its own figures (nothing is
    copied between variants)."""
    r, o, combo, st = req.requirements, req.options, d["combo"], d["static"]
    stack, var = combo.stack, d["variant"]
    c_large = combo.n * stack.capacitance * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR
    volts_to_stroke = r.stroke * stack.max_voltage / (st["ratio"] * combo.stack_stroke)
    i_req = c_large * volts_to_stroke / req.stroke_time
    st["thermal_drift_m"] = st["thermal_net_m"]
    st["thermal_drift_oil_only_m"] = st["thermal_drift_per_K_m"] * (r.max_temperature - o.drift_reference_temperature)
    st["required_current_A"] = i_req
    st["speed_m_s"] = st["free_stroke_m"] / d["ramp"]       # the planned drive ramp, at the amplifier's limit
    st["rise_time_s"] = d["ramp"]
    temps = [combo.margins["temperature"], temperature_margin(var.material.max_temperature, r.max_temperature)]
    margins = {
        "stroke": floor_margin(st["free_stroke_m"], r.stroke),
        # the whole force path in series, less the seal friction at the blocked pressure
        "blocked_force": floor_margin(st["blocked_force_net_N"], r.blocked_force),
        "speed": floor_margin(st["speed_m_s"], r.speed),
        "temperature": min(temps),
        "amplifier_temperature": combo.margins["amplifier_temperature"],
        "pressure": floor_margin(combo.seal.pressure_rating, st["blocked_pressure_Pa"]),
        "drive_current": floor_margin(combo.amplifier.max_current, i_req),
        "amplifier_continuous_current": floor_margin(combo.amplifier.continuous_current, st["continuous_current_A"]),
        "natural_frequency": floor_margin(st["natural_frequency_Hz"], req.natural_frequency),
        "thermal_drift": ceiling_margin(abs(st["thermal_net_m"]), o.max_drift_fraction * r.stroke),
        "wide_gap": floor_margin(st["wide_gap_m"], st["gap_needed_m"]),
        "packing": floor_margin(st["stacks_that_fit"], combo.n),
    }
    comp = var.compensator
    if comp is not None:
        margins["temperature"] = min(margins["temperature"], temperature_margin(comp.max_temperature, r.max_temperature))
        margins["compensator_capacity"] = floor_margin(comp.capacity, st["thermal_compensator_volume_m3"])
        if comp.leak_conductance > 0:
            # output creep under the worst load over one duty cycle's hold
            hold = 1.0 / req.duty.strokes_per_second
            creep = comp.leak_conductance * d["seal_friction"]["at_pressure_Pa"] * hold / (st["narrow_diameter_m"] ** 2 * math.pi / 4)
            st["compensator_creep_m"] = creep
            margins["compensator_leak"] = ceiling_margin(creep, o.max_drift_fraction * r.stroke)
    return margins


# --- verification ---------------------------------------------------------
def _simulate(req, designs, loads, progress) -> None:
    """Simulate the sized designs under every load case: the statically
    feasible ones on the Pareto front first, then the next fronts, then the
    rest, up to ``options.max_simulated``."""
    pool = [d for d in designs if d["gp_success"]]
    if not pool:
        return
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    F = np.array([[d["metrics"][k] for k in keys] for d in pool])
    ok = np.array([min(v for k, v in d["static_margins"].items() if k not in SCREEN_IGNORES) >= 0 for d in pool])
    level = np.full(len(pool), 10**6)
    if ok.any():
        level[ok] = nondominated_levels(F[ok])
    order = np.lexsort((level, ~ok))[: req.options.max_simulated]
    chosen = [pool[i] for i in order]
    # designs that differ only in the structure material have the same force
    # path (the material screen keeps the members' stiffness) and so the same
    # dynamics: simulate one of each and share the result
    twins: dict[tuple, list] = {}
    for d in chosen:
        twins.setdefault(_dynamic_key(d), []).append(d)
    unique = [group[0] for group in twins.values()]
    S = req.requirements.stroke
    for start in range(0, len(unique), SIM_CHUNK):
        chunk = unique[start:start + SIM_CHUNK]
        _simulate_chunk(chunk, loads, S)
        _progress(progress, "simulating", min(start + SIM_CHUNK, len(unique)), len(unique))
    for group in twins.values():
        for d in group[1:]:
            d["simulated"] = group[0]["simulated"]


def _dynamic_key(d) -> tuple:
    """What the simulation depends on, beyond the parts: the force path's
    mechanical and hydraulic stiffness, the ramp, the masses and the leak."""
    st, c = d["static"], d["cand"]
    comp = d["variant"].compensator
    return (d["combo"].key, comp.id if comp else None, f"{st['force_path_stiffness_N_m']:.9e}",
            f"{d['ramp']:.9e}", f"{float(c.wide_mass[0]):.9e}", f"{d['spacer']:.9e}")


def _simulate_chunk(chunk, loads, S) -> None:
    c = _stack_candidates([d["cand"] for d in chunk])
    ramps = np.array([d["ramp"] for d in chunk])
    try:
        sims = simulate_cases(c, loads, ramps, target_stroke=S)
    except SimulationError:
        if len(chunk) == 1:
            chunk[0]["simulated"] = {"failed": True, "cases": []}
            return
        for d in chunk:
            _simulate_chunk([d], loads, S)
        return
    for i, d in enumerate(chunk):
        d["simulated"] = {"cases": [{k: float(np.asarray(v)[i]) for k, v in case.items()} for case in sims]}


def _stack_candidates(parts: list[Candidates]) -> Candidates:
    from dataclasses import fields
    return Candidates(**{f.name: np.concatenate([getattr(p, f.name) for p in parts]) for f in fields(Candidates)})


def _sim_margins(req, sim) -> tuple[dict, dict]:
    """Margins and the contract's ``simulated`` figures from the cases."""
    r = req.requirements
    if sim.get("failed"):
        return {"simulation": -math.inf}, {"failed": True}
    cases = sim["cases"]
    worst = max(cases, key=lambda c: c["load_N"])
    figures = {"stroke_m": worst["stroke_m"], "time_to_stroke_s": worst["time_to_stroke_s"],
               "speed_m_s": min(c["speed_m_s"] for c in cases), "overshoot": worst["overshoot"],
               "load_N": worst["load_N"], "cases": cases}
    margins = {"stroke": floor_margin(min(c["stroke_m"] for c in cases), r.stroke),
               "speed": floor_margin(min(c["speed_m_s"] for c in cases), r.speed),
               "overshoot": ceiling_margin(max(c["overshoot"] for c in cases), req.options.max_overshoot)}
    return margins, figures


# --- candidates -------------------------------------------------------------
def _components(combo: Combo, ratio) -> dict:
    return {"stack": combo.stack.id, "n_stacks": combo.n, "ratio": ratio, "fluid": combo.fluid.id,
            "seal": combo.seal.id, "amplifier": combo.amplifier.id}


def _stack_params(combo: Combo) -> dict:
    s = combo.stack
    return {"stiffness_N_m": s.stiffness, "d33_m_V": s.stroke_per_volt, "max_voltage_V": s.max_voltage}


def _temperatures(combo: Combo) -> dict:
    return {k: {"rated_degC": a, "required_degC": b} for k, (a, b) in combo.temperatures.items()}


def _pruned_candidate(req, combo: Combo) -> dict:
    s, a = combo.stack, combo.amplifier
    reasons = [k for k, v in combo.margins.items() if v < 0]
    return {
        "id": combo.key, "technology": "piezohydraulic", "variant": "uncompensated", "stage": "pruned",
        "components": _components(combo, None), "stack_params": _stack_params(combo),
        "static": {"work_J": float(stack_phys.work_capacity(combo.n, s.stiffness, combo.stack_stroke * combo.voltage_fraction_max))},
        "simulated": {}, "margins": dict(combo.margins),
        "metrics": {"mass_kg": combo.n * s.mass + a.mass,
                    "cost_usd": combo.n * s.cost_usd + a.cost_usd},
        "metrics_lower_bound": True, "temperatures": _temperatures(combo),
        "reason": "ruled out before sizing: " + ", ".join(reasons),
    }


def _design_candidates(req, d) -> list[dict]:
    combo, res, var = d["combo"], d["gp"], d["variant"]
    comp = var.compensator
    components = dict(_components(combo, res.ratio), material=var.material.id,
                      compensator=comp.id if comp else None)
    base = {
        "id": combo.key + var.suffix(), "technology": "piezohydraulic", "variant": var.name,
        "components": components, "stack_params": _stack_params(combo), "temperatures": _temperatures(combo),
    }
    if d["index"] is None:
        return [dict(base, stage="gp_failed", static={}, simulated={},
                     margins={**combo.margins, res.driver or "solver": -math.inf},
                     metrics={}, reason=f"the geometric program failed ({res.status})")]
    margins = dict(d["static_margins"])
    margins["work"] = combo.margins["work"]
    simulated = {}
    if d["simulated"] is not None:
        sim_m, simulated = _sim_margins(req, d["simulated"])
        margins.update(sim_m)
    stage = "simulated" if simulated else ("sized" if res.success else "gp_infeasible")
    T = req.requirements.max_temperature
    f = combo.fluid
    st = d["static"]
    base.update({
        "stage": stage, "static": st, "simulated": simulated,
        "static_margins": d["static_margins"],
        "force_path": d["force_path"],
        "thermal_budget": {k: st["thermal_" + k] for k in (*thermal.TERMS, "net_m")},
        "seal_friction_N": d["seal_friction"],
        "compensator": _compensator_entry(comp, d),
        "design": {"technology": "piezohydraulic", "stack": combo.stack.id, "n_stacks": combo.n,
                   "voltage": d["cand"].voltage[0], "wide_diameter": st["wide_diameter_m"],
                   "narrow_diameter": st["narrow_diameter_m"], "fluid": f.id, "seal": combo.seal.id,
                   "amplifier": combo.amplifier.id, "wide_gap": st["wide_gap_m"], "rise_time": d["ramp"],
                   "temperature": T, "material": var.material.id, "end_cap_thickness": res.cap_thickness,
                   "frame_area": res.frame_area, "compensator": comp.id if comp else None,
                   "strokes_per_second": req.duty.strokes_per_second},
        "fluid_at_temperature": {
            "kinematic_viscosity_m2_s": float(fluid_props.kinematic_viscosity(f.viscosity_40C, f.viscosity_100C, T)),
            "bulk_modulus_Pa": float(d["cand"].bulk_modulus[0]),
            "flash_point_degC": f.flash_point},
        "bouc_wen_source": d["bouc_wen_source"],
        "hysteresis": (_hysteresis(combo.stack, d["bw"][0], float(d["cand"].voltage[0]), d["ramp"])
                       if d["simulated"] is not None else None),
        "gp": {"success": res.success, "status": res.status, "binding": res.binding, "slack": res.slack},
        "reason": "" if res.success else "no design of these parts meets: " + ", ".join(res.binding),
        "metrics": dict(d["metrics"]), "margins": margins,
        "rests_on_assumed": _assumed(combo, var),
    })
    if d["spacer"] > 0:
        base["passive_compensation"] = {"spacer_length_m": d["spacer"],
                                        "spacer_material": next(r["material"] for r in d["force_path"] if r["member"] == "spacer")}
        base["design"]["spacer_length"] = d["spacer"]
    return [base]


def _assumed(combo: Combo, var: Variant) -> list[str]:
    """Catalog values marked assumed that this design rests on, as part.field."""
    parts = (combo.stack, combo.fluid, combo.seal, combo.amplifier, var.material, var.compensator)
    return [f"{p.id}.{k}" for p in parts if hasattr(p, "assumed") for k in p.assumed()]


@lru_cache(maxsize=4096)
def _ramp_stroke(stack_id, params, voltage, ramp):
    return bouc_wen.ramp_stroke(BoucWen(*params), voltage, ramp, points=1000)


def _hysteresis(stack, bw, voltage, ramp) -> dict:
    """The stroke the (transferred) Bouc-Wen model gives at this design's own
    ramp against the datasheet stroke at that voltage (issue 9, item 5)."""
    params = tuple(float(v) for v in bw.as_array())
    got = _ramp_stroke(stack.id, params, round(voltage, 3), round(ramp, 4))
    nominal = stack.stroke * voltage / stack.max_voltage
    return {"ramp_time_s": ramp, "model_stroke_m": got, "datasheet_stroke_m": nominal, "ratio": got / nominal}


def hysteresis_time_scales(catalog: Catalog) -> dict:
    """Per stack: the ramp time at which its Bouc-Wen model (own or
    transferred) gives the datasheet stroke, and the stroke at 0.01, 1 and 10 s."""
    reference = reference_bouc_wen(catalog.stacks)
    out = {}
    for st in catalog.stacks.values():
        bw, source = stack_bouc_wen(st, reference)
        out[st.id] = {"matching_ramp_time_s": bouc_wen.matching_ramp_time(bw, st.max_voltage, st.stroke),
                      "datasheet_stroke_m": st.stroke, "source": source,
                      "stroke_at_m": {str(T): bouc_wen.ramp_stroke(bw, st.max_voltage, T) for T in (0.01, 1.0, 10.0)}}
    return out


def _compensator_entry(comp, d) -> dict | None:
    if comp is None:
        return None
    k = next((r["stiffness_N_m"] for r in d["force_path"] if r["member"] == "compensator"), None)
    return {"id": comp.id, "kind": comp.kind, "stiffness_N_m": k, "leak_m3_s_Pa": comp.leak_conductance,
            "mass_kg": comp.mass, "cost_usd": comp.cost_usd, "capacity_m3": comp.capacity,
            "volume_taken_m3": d["static"]["thermal_compensator_volume_m3"]}


def _rank(req, candidates) -> None:
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    for c in candidates:
        c["feasible"], c["driver"] = verdict(c["margins"])
    feasible = np.array([c["feasible"] for c in candidates], dtype=bool)
    F = np.array([[_objective(c["metrics"].get(k)) for k in keys] for c in candidates], dtype=float)
    F = F.reshape(len(candidates), len(keys))
    worst = np.array([c["margins"][c["driver"]] if c["driver"] else -math.inf for c in candidates], dtype=float)
    rank = rank_order(feasible, F, worst)
    level = np.zeros(len(candidates), dtype=int)
    if feasible.any():
        level[feasible] = nondominated_levels(F[feasible])
    for i, c in enumerate(candidates):
        c["rank"] = int(rank[i])
        c["pareto"] = bool(feasible[i] and level[i] == 1)
        c["pareto_level"] = int(level[i]) if feasible[i] else None


def _objective(value) -> float:
    return math.inf if value is None or not math.isfinite(value) else float(value)


def _disagreements(designs) -> list[dict]:
    """Where the static screen and the simulation disagree on a requirement's
    verdict (one margin >= 0, the other < 0), or differ by more than 10 %."""
    out = []
    for d in designs:
        if not d.get("simulated") or d["simulated"].get("failed") or d["index"] is None:
            continue
        st = d["static"]
        cases = d["simulated"]["cases"]
        pairs = {"stroke": (st["free_stroke_m"], min(c["stroke_m"] for c in cases)),
                 "speed": (st["speed_m_s"], min(c["speed_m_s"] for c in cases))}
        sm = d["static_margins"]
        for key, (a, b) in pairs.items():
            req_value = a / (1 + sm[key])
            m_sim = b / req_value - 1
            flip = (sm[key] >= 0) != (m_sim >= 0)
            if flip or abs(b / a - 1) > 0.10:
                out.append({"id": d["id"], "requirement": key, "static": a, "simulated": b,
                            "static_margin": sm[key], "simulated_margin": m_sim, "verdict_changes": flip})
    return out

