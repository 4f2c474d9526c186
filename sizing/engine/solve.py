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
from dataclasses import dataclass, field

import numpy as np

from .. import __version__
from ..errors import SimulationError
from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from ..physics import fluid as fluid_props
from ..physics import geometry, stack as stack_phys
from .convex import GPSizer, SizingInput
from .dc_candidates import dc_candidates
from .evaluate import load_cases
from .piezo import Candidates, part_row, reference_bouc_wen, stack_bouc_wen
from .rank import ceiling_margin, floor_margin, nondominated_levels, rank_order, verdict
from .search import Combo, enumerate_combos
from .solve_summary import _assumptions, _clean, _requirements_si, _summary, _traces
from .verify import metrics, ramp_time, simulate_cases, static_figures

SIM_CHUNK = 32
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
    sized = _size(req, to_size, progress)
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
        "counts": {"combinations": len(combos), "pruned": len(combos) - len(to_size), "sized": len(to_size),
                   "gp_feasible": sum(1 for d in designs if d["gp_success"]),
                   "simulated": sum(1 for d in designs if d["simulated"] is not None)},
    }
    traces = _traces(req, candidates, designs, dc, loads)
    results["runtime_s"] = time.perf_counter() - start
    return SolveOutput(results=_clean(results), traces=traces)


# --- sizing ---------------------------------------------------------------
def sizing_input(req: RequirementsFile, c: Combo) -> SizingInput:
    T = req.requirements.max_temperature
    f, s, st = c.fluid, c.seal, c.stack
    stack_volume = st.length * st.diameter**2 * (1.0 if st.section == "square" else math.pi / 4)
    return SizingInput(
        n_stiffness=c.n * st.stiffness, stack_stroke=c.stack_stroke, rated_voltage=st.max_voltage,
        max_fraction=c.voltage_fraction_max, force=req.requirements.blocked_force,
        stroke=req.requirements.stroke,
        bulk_modulus=float(fluid_props.bulk_modulus_at(f.bulk_modulus, f.bulk_modulus_temperature_coefficient, T)),
        wide_gap=req.options.wide_gap, pressure_rating=s.pressure_rating,
        natural_frequency=req.natural_frequency, stroke_time=req.stroke_time,
        n_capacitance=c.n * st.capacitance, max_current=c.amplifier.max_current,
        margin=req.options.design_margin,
        fixed_mass=c.n * st.mass * (1 + geometry.FRAME_FRACTION) + c.amplifier.mass,
        fixed_cost=c.n * st.cost_usd + c.amplifier.cost_usd + 2 * s.cost_usd + geometry.FIXED_HYDRAULIC_USD,
        fixed_volume=1.5 * c.n * stack_volume,
        oil_density=float(fluid_props.density_at(f.density, f.thermal_expansion, T)),
        oil_cost=f.cost_usd * 1000.0)


def _size(req, combos, progress):
    sizer = GPSizer(req.objectives.minimize)
    out = []
    for i, c in enumerate(combos):
        out.append((c, sizer.solve(sizing_input(req, c))))
        if i % 8 == 0 or i == len(combos) - 1:
            _progress(progress, "sizing", i + 1, len(combos))
    return out


def _designs(req, catalog, sized) -> list[dict]:
    """Build the sized designs with the same code as ``sizing evaluate``."""
    reference = reference_bouc_wen(catalog.stacks)
    T, S = req.requirements.max_temperature, req.requirements.stroke
    rows, designs = [], []
    for combo, res in sized:
        if not (math.isfinite(res.ratio) and math.isfinite(res.wide_area)):
            designs.append({"combo": combo, "gp": res, "gp_success": False, "index": None, "simulated": None})
            continue
        v = min(res.voltage_fraction, combo.voltage_fraction_max)
        voltage = v * combo.stack.max_voltage
        free = res.ratio * combo.stack_stroke * v
        rise = 0.5 * req.stroke_time * free / S          # reach the stroke in half the time allowed
        bw, bw_source = stack_bouc_wen(combo.stack, reference)
        rows.append(part_row(combo.stack, combo.n, res.ratio, res.wide_area, voltage, bw, T,
                             req.options.wide_gap, combo.fluid, combo.seal, combo.amplifier))
        designs.append({"combo": combo, "gp": res, "gp_success": res.success, "index": len(rows) - 1,
                        "rise": rise, "bouc_wen_source": bw_source, "simulated": None})
    if not rows:
        return designs
    c = Candidates.from_rows(rows)
    rise = np.array([d["rise"] for d in designs if d["index"] is not None])
    ramp = ramp_time(c, rise)
    static = static_figures(c, ramp)
    met = metrics(c, ramp)
    for d in designs:
        i = d["index"]
        if i is None:
            continue
        d["cand"] = c.take([i])
        d["ramp"] = float(ramp[i])
        d["static"] = {k: float(np.asarray(v)[i]) for k, v in static.items()}
        d["metrics"] = {k: float(np.asarray(v)[i]) for k, v in met.items()}
        d["static_margins"] = _static_margins(req, d)
    return designs


def _static_margins(req, d) -> dict:
    r, o, combo, st = req.requirements, req.options, d["combo"], d["static"]
    stack = combo.stack
    c_large = combo.n * stack.capacitance * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR
    volts_to_stroke = r.stroke * stack.max_voltage / (st["ratio"] * combo.stack_stroke)
    i_req = c_large * volts_to_stroke / req.stroke_time
    drift = st["thermal_drift_per_K_m"] * (r.max_temperature - o.drift_reference_temperature)
    st["thermal_drift_m"] = drift
    st["required_current_A"] = i_req
    st["speed_m_s"] = st["free_stroke_m"] / d["ramp"]       # the planned drive ramp, at the amplifier's limit
    st["rise_time_s"] = d["ramp"]
    return {
        "stroke": floor_margin(st["free_stroke_m"], r.stroke),
        "blocked_force": floor_margin(st["blocked_force_compliant_N"], r.blocked_force),
        "speed": floor_margin(st["speed_m_s"], r.speed),
        "temperature": combo.margins["temperature"],
        "amplifier_temperature": combo.margins["amplifier_temperature"],
        "pressure": floor_margin(combo.seal.pressure_rating, st["blocked_pressure_Pa"]),
        "drive_current": floor_margin(combo.amplifier.max_current, i_req),
        "natural_frequency": floor_margin(st["natural_frequency_Hz"], req.natural_frequency),
        "thermal_drift": ceiling_margin(abs(drift), o.max_drift_fraction * r.stroke),
    }


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
    ok = np.array([min(v for k, v in d["static_margins"].items() if k != "thermal_drift") >= 0 for d in pool])
    level = np.full(len(pool), 10**6)
    if ok.any():
        level[ok] = nondominated_levels(F[ok])
    order = np.lexsort((level, ~ok))[: req.options.max_simulated]
    chosen = [pool[i] for i in order]
    S = req.requirements.stroke
    for start in range(0, len(chosen), SIM_CHUNK):
        chunk = chosen[start:start + SIM_CHUNK]
        _simulate_chunk(chunk, loads, S)
        _progress(progress, "simulating", min(start + SIM_CHUNK, len(chosen)), len(chosen))


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
        "metrics": {"mass_kg": combo.n * s.mass * (1 + geometry.FRAME_FRACTION) + a.mass,
                    "cost_usd": combo.n * s.cost_usd + a.cost_usd},
        "metrics_lower_bound": True, "temperatures": _temperatures(combo),
        "reason": "ruled out before sizing: " + ", ".join(reasons),
    }


def _design_candidates(req, d) -> list[dict]:
    combo, res = d["combo"], d["gp"]
    o = req.options
    base = {
        "technology": "piezohydraulic", "components": _components(combo, res.ratio),
        "stack_params": _stack_params(combo), "temperatures": _temperatures(combo),
    }
    if d["index"] is None:
        return [dict(base, id=combo.key, variant="uncompensated", stage="gp_failed", static={}, simulated={},
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
    base.update({
        "stage": stage, "static": d["static"], "simulated": simulated,
        "static_margins": d["static_margins"],
        "design": {"technology": "piezohydraulic", "stack": combo.stack.id, "n_stacks": combo.n,
                   "voltage": d["cand"].voltage[0], "wide_diameter": d["static"]["wide_diameter_m"],
                   "narrow_diameter": d["static"]["narrow_diameter_m"], "fluid": f.id, "seal": combo.seal.id,
                   "amplifier": combo.amplifier.id, "wide_gap": o.wide_gap, "rise_time": d["ramp"],
                   "temperature": T},
        "fluid_at_temperature": {
            "kinematic_viscosity_m2_s": float(fluid_props.kinematic_viscosity(f.viscosity_40C, f.viscosity_100C, T)),
            "bulk_modulus_Pa": float(d["cand"].bulk_modulus[0]),
            "flash_point_degC": f.flash_point},
        "bouc_wen_source": d["bouc_wen_source"],
        "gp": {"success": res.success, "status": res.status, "binding": res.binding, "slack": res.slack},
        "reason": "" if res.success else "no design of these parts meets: " + ", ".join(res.binding),
    })
    plain = dict(base, id=combo.key, variant="uncompensated", margins=margins, metrics=dict(d["metrics"]))
    out = [plain]
    if o.thermal_compensation:
        m = {k: v for k, v in margins.items() if k != "thermal_drift"}
        met = dict(d["metrics"])
        met["mass_kg"] += o.compensator_mass
        met["cost_usd"] += o.compensator_cost_usd
        expansion = d["static"]["oil_volume_m3"] * f.thermal_expansion * abs(T - o.drift_reference_temperature)
        out.append(dict(base, id=combo.key + "-tc", variant="compensated", margins=m, metrics=met,
                        compensator={"mass_kg": o.compensator_mass, "cost_usd": o.compensator_cost_usd,
                                     "expansion_volume_m3": expansion}))
    return out


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
                out.append({"id": d["combo"].key, "requirement": key, "static": a, "simulated": b,
                            "static_margin": sm[key], "simulated_margin": m_sim, "verdict_changes": flip})
    return out



# --- hook for sizing robust (issue 13): re-verify fixed designs ------------
def verify_sized(req, catalog: Catalog, sized: list, loads: list[float], chunk: int = SIM_CHUNK,
                 temperatures=None) -> list[list[dict]]:
    """Re-verify designs whose geometry is fixed, through the very steps of
    ``solve`` (static figures, margins, simulation under every load case,
    verdict). ``sized``: (Combo, SizingResult) pairs, e.g. one design whose
    parts were perturbed. ``temperatures``: optional, per pair, the
    temperature its parts work at instead of the required maximum (ratings
    are still judged at the maximum, by the combo's margins). Returns, per
    pair, its candidates (uncompensated, and compensated when the options
    ask) with ``feasible`` and ``driver``."""
    temps = [None] * len(sized) if temperatures is None else [float(t) for t in temperatures]
    designs, reqs = [None] * len(sized), {}
    for t in dict.fromkeys(temps):
        idx = [i for i, x in enumerate(temps) if x == t]
        reqs[t] = req if t is None else req.model_copy(update={
            "requirements": req.requirements.model_copy(update={"max_temperature": t})})
        for i, d in zip(idx, _designs(reqs[t], catalog, [sized[i] for i in idx])):
            designs[i] = d
    built = [d for d in designs if d["index"] is not None]
    for start in range(0, len(built), chunk):
        _simulate_chunk(built[start:start + chunk], loads, req.requirements.stroke)
    out = []
    for d, t in zip(designs, temps):
        cands = _design_candidates(reqs[t], d)
        for c in cands:
            c["feasible"], c["driver"] = verdict(c["margins"])
        out.append(cands)
    return out
