"""The frequency-rectified piezohydraulic pump (technology "piezo_pump"),
ranked beside the single-stroke actuator and the DC motor.

1. ``pump_screen``: every part combination x pump piston x pumping
   frequency, the bore sized for the blocked force, screened by the
   cycle-averaged model (physics/pump.py).
2. The designs that pass every static check, the best first (nondominated
   levels in the objectives, one per stack x count x valve x accumulator x
   piston), then the closest of those that do not, are verified by the
   cycle-resolved simulation (sim/pump.py) under every load case: thousands
   of pumping cycles a stroke at the higher frequencies.
3. Each simulated design as a ``records.PumpDesign`` (``record.py``
   writes its results.json candidate, CONTRACTS.md, "The piezo pump"); the
   rows not simulated are counted by the check they miss most (or as not
   simulated).
"""
from __future__ import annotations

import math
from collections import Counter
from typing import NamedTuple

import numpy as np

from ...physics.stack import derated_stroke
from ...sim.pump import PumpModel, simulate
from . import screen
from ..piezohydraulic.parts import reference_bouc_wen, stack_bouc_wen
from ...engine.rank import OBJECTIVE_KEYS, floor_margin, nondominated_levels
from ...engine.records import Simulation, frozen
from .records import PumpDesign, PumpOutcome
from ...settings import DIVERGED_FACTOR
from ...settings import PUMP_CLOSEST_SIMULATED as MIN_CLOSEST_SIMULATED
from ...settings import PUMP_FEASIBLE_SIMULATED as MAX_FEASIBLE_SIMULATED
from ...settings import PUMP_SIMULATED as SIMULATED

# the simulated mean speed over the cycle-averaged one, less 1, lies in this
# band on the simulated designs (tests/engine/test_pump_engine.py; docs/models.md):
# the averaged model is conservative, for it omits the load and the line's
# oil ringing on the high-side oil at each valve opening, whose momentum
# draws oil from the accumulator through both valves; below it by what leaks
# back through the seated reeds' gaps, which the averaged model omits too
# (with a light load and tight reeds they agree within 5 %,
# tests/physics/test_pump_physics.py)
AGREEMENT_TOLERANCE = (-0.10, 0.50)
NOT_SIMULATED = "not simulated: passes the pump screen, dominated by the simulated designs"
BEST_DEMONSTRATED_POWER_W = 46.0
BEST_DEMONSTRATED_SOURCE = ("46 W at 1 kHz, 1 kV, 500 psi bias (Kinetic Ceramics / Lynch group, "
                            "'Characterization of a piezohydraulic actuator')")


def _progress(callback, stage, done, total):
    if callback is not None:
        callback(stage, done, total)


def pump_designs(req, catalog, loads: list[float], progress=None, step_factor: float = 1.0) -> PumpOutcome:
    """Screen and simulate the pump designs: those simulated as records, the
    other rows counted by reason, the bodies outside the envelope as
    one-line records. ``step_factor`` scales the simulation's step (a
    convergence check halves it)."""
    if not (catalog.valves and catalog.accumulators and catalog.stacks):
        return _nothing({})
    gs, ruled = screen.groups(req, catalog)
    if not gs:
        return _nothing(ruled)
    R, st, M, met, valid, outside = _screened(req, catalog, gs, loads)
    records = _envelope_records(gs, R, outside)
    valid &= outside == ""
    worst, violation, chosen = _chosen(req, R, M, met, valid)
    _progress(progress, "simulating pumps", 0, len(chosen))
    sims = _simulate(req, reference_bouc_wen(catalog.stacks), gs, R, st, chosen, loads, step_factor)
    _progress(progress, "simulating pumps", len(chosen), len(chosen))
    screened = _Screen(gs, R, st, M, met)
    designs = tuple(_design(req, screened, i, _sim_cases(sims, k, loads, st["speeds"], i))
                    for k, i in enumerate(chosen))
    out = Counter()
    no_bore = ~np.isfinite(st["cylinder_diameter_m"])
    if no_bore.any():
        out["no bore gives the blocked force"] = int(no_bore.sum())
    names = list(M)
    rest = np.setdiff1d(np.flatnonzero(valid), chosen)
    out[NOT_SIMULATED] += int((worst[rest] >= 0).sum())
    missing = rest[worst[rest] < 0]
    if missing.size:                       # each counted by the check it misses most (the first of equals)
        G_rest = np.vstack([np.where(np.isfinite(M[k][missing]), M[k][missing], -np.inf) for k in names])
        out.update(Counter(names[j] for j in np.argmin(G_rest, axis=0)))
    if not out[NOT_SIMULATED]:
        del out[NOT_SIMULATED]
    return PumpOutcome(designs, frozen(out), tuple(records), frozen(
        {"combinations": int(len(R["group"])), "groups": len(gs), "simulated": len(chosen),
         "screen_feasible": int((worst >= 0).sum()), "parts_not_rated": ruled,
         "outside_envelope": int((outside != "").sum())}))


def _chosen(req, R, M, met, valid) -> tuple:
    """Each row's worst margin and summed violation, and the rows chosen
    for simulation (``_choose``)."""
    G = np.vstack([np.where(np.isfinite(v), v, -np.inf) for v in M.values()])
    worst = np.min(G, axis=0)
    violation = np.sum(np.maximum(-G, 0.0), axis=0)       # pymoo's CV over the margins
    # the simulation verifies designs inside the quasi-static validity of
    # both models: the valves return their drop within the cycle, the
    # output is far below its resonance (docs/models.md, "Piezo pump")
    inside = valid & (M["valve_flow"] >= 0) & (M["output_resonance"] >= 0)
    return worst, violation, _choose(req, R, met, worst, violation, inside)


def complying_designs(req, catalog, loads: list[float]) -> tuple:
    """The designs ``pump_designs`` would find complying, and only those
    simulated: of the rows it chooses for simulation, those that pass every
    check the simulation does not replace (the others miss a check whatever
    the simulation gives). What the flips' re-solves ask of the pump: the
    same verdict and lightest design, without simulating rows that cannot
    comply."""
    if not (catalog.valves and catalog.accumulators and catalog.stacks):
        return ()
    gs, _ = screen.groups(req, catalog)
    if not gs:
        return ()
    R, st, M, met, valid, outside = _screened(req, catalog, gs, loads)
    valid &= outside == ""
    _, _, chosen = _chosen(req, R, M, met, valid)
    static_ok = np.ones(len(valid), dtype=bool)
    for k, v in M.items():
        if k not in SIMULATED_MARGINS:
            static_ok &= np.nan_to_num(v, nan=-1.0) >= 0
    kept = [i for i in chosen if static_ok[i]]
    sims = _simulate(req, reference_bouc_wen(catalog.stacks), gs, R, st, kept, loads)
    screened = _Screen(gs, R, st, M, met)
    return tuple(_design(req, screened, i, _sim_cases(sims, k, loads, st["speeds"], i)) for k, i in enumerate(kept))


def _screened(req, catalog, gs, loads) -> tuple:
    """The static screen over every row: rows, figures, margins, metrics,
    which rows have a bore and why a row leaves the envelope ("" inside)."""
    R = screen.rows(req, catalog, gs)
    st = screen.figures(req, R, loads)
    st.update(screen.drive(req, gs, R, st))
    M = screen.margins(req, gs, R, st, loads)
    met = screen.metrics(req, gs, R, st)
    valid = np.isfinite(st["cylinder_diameter_m"])
    outside = screen.envelope(req, R, st, met) if valid.any() else np.full(len(valid), "", dtype=object)
    return R, st, M, met, valid, outside


# the margin the cycle simulation replaces (``_design``): the others are final after the screen
SIMULATED_MARGINS = ("speed",)


def could_comply(req, catalog, loads: list[float]) -> bool:
    """Whether some pump row inside the envelope passes every static check
    the simulation does not replace: when none does, no simulated pump can
    comply, and a re-solve (``resolve.py``) need not simulate."""
    if not (catalog.valves and catalog.accumulators and catalog.stacks):
        return False
    gs, _ = screen.groups(req, catalog)
    if not gs:
        return False
    R, st, M, met, valid, outside = _screened(req, catalog, gs, loads)
    ok = valid & (outside == "")
    for k, v in M.items():
        if k not in SIMULATED_MARGINS:
            ok &= np.nan_to_num(v, nan=-1.0) >= 0
    return bool(ok.any())


def _nothing(ruled: dict) -> PumpOutcome:
    """No pump to size: the catalog has no valves or accumulators, or no
    part combination is rated for the requirements."""
    return PumpOutcome(counts=frozen({"combinations": 0, "simulated": 0, "parts_not_rated": ruled}))


def _envelope_records(gs, R, outside) -> list[dict]:
    """One line per part combination and pump piston outside the envelope
    (results.json ``ruled_out``): its pumping frequencies share the body."""
    records: dict[tuple, dict] = {}
    for i in np.flatnonzero(outside != ""):
        g, Dp = gs[R["group"][i]], float(R["pump_diameter"][i])
        key = (int(R["group"][i]), Dp)
        if key not in records:
            records[key] = {"id": f"pp-{g.n}x{g.stack.id}-{g.valve.id}-{g.accumulator.id}-p{Dp * 1e3:.0f}",
                            "technology": "piezo_pump", "variant": "pump", "reason": "envelope",
                            "detail": str(outside[i]), "designs": 0}
        records[key]["designs"] += 1
    return list(records.values())


def _choose(req, R, met, worst, violation, valid) -> list[int]:
    """Row indices to simulate: feasible rows by nondominated level then the
    first objective, one per stack x count x valve x accumulator x piston;
    then the closest infeasible rows (smallest sum of missed margins), likewise."""
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    F = np.column_stack([met[k] for k in keys])
    ok = valid & (worst >= 0) & np.all(np.isfinite(F), axis=1)
    level = np.full(len(worst), 10**6)
    if ok.any():
        level[ok] = nondominated_levels(F[ok])
    feasible_order = np.lexsort((F[:, 0], level))
    near_order = np.lexsort((F[:, 0], np.where(valid & ~ok, violation, np.inf)))
    chosen, taken_keys = [], set()
    limits = (MAX_FEASIBLE_SIMULATED, None)
    for order, limit, pool in zip((feasible_order, near_order), limits, (ok, valid & ~ok)):
        limit = limit if limit is not None else max(MIN_CLOSEST_SIMULATED, SIMULATED - len(chosen))
        taken = 0
        for i in order:
            if taken >= limit:
                break
            if not pool[i]:
                continue
            key = (int(R["group"][i]), float(R["pump_diameter"][i]))
            if key in taken_keys:
                continue
            taken_keys.add(key)
            chosen.append(int(i))
            taken += 1
    return chosen


def _simulate(req, ref, gs, R, st, chosen, loads, step_factor=1.0) -> list[dict]:
    """Simulate the chosen rows under each load case: a list per case of
    {output: ndarray (n_chosen,)}."""
    if not chosen:
        return []
    model = simulation_model(req, ref, gs, R, st, np.asarray(chosen))
    return [simulate(model.replace(load_force=F), step_factor) for F in loads]


def simulation_model(req, ref, gs, R, st, idx) -> PumpModel:
    """The cycle-resolved model of the screen's rows ``idx`` (no load force
    yet). ``ref``: the catalog's reference Bouc-Wen stack, the one the
    screen's strokes transfer (``screen.rows``), so both models drive
    the same free stroke."""
    r = req.requirements
    bws = [stack_bouc_wen(gs[R["group"][i]].stack, ref)[0] for i in idx]
    # the kernel runs the Bouc-Wen model and scales its output by the
    # temperature derating, as bouc_wen_stroke does for the screen
    derate = np.array([_derating(gs[R["group"][i]].stack, r.max_temperature) for i in idx])
    return PumpModel(
        k_stacks=st["stack_stiffness_N_m"][idx], d33=np.array([b.d33 for b in bws]),
        alpha=np.array([b.alpha for b in bws]), beta=np.array([b.beta for b in bws]),
        gamma=np.array([b.gamma for b in bws]), delta=np.array([b.delta for b in bws]),
        n_bw=np.array([b.n for b in bws]), stroke_scale=derate,
        voltage=R["voltage"][idx], frequency=R["frequency"][idx], pump_area=st["pump_area_m2"][idx],
        chamber_volume=st["chamber_volume_m3"][idx], bulk_modulus=R["bulk_modulus"][idx],
        air_fraction=screen.AIR_FRACTION, air_dissolution_pressure=R["air_dissolution_pressure"][idx],
        wall_compliance=st["wall_compliance_1_Pa"][idx], density=R["density"][idx],
        bias_pressure=R["bias_pressure"][idx], cylinder_area=st["cylinder_area_m2"][idx],
        dead_length=screen.DEAD_LENGTH, load_mass=st["output_mass_kg"][idx], load_force=0.0,
        line_mass=st["line_mass_kg"][idx], line_damping=st["line_damping_N_s_m"][idx],
        line_volume=st["line_volume_m3"][idx], reed_mass=R["reed_wetted_mass"][idx],
        reed_damping_ratio=screen.REED_DAMPING_RATIO, seat_width=R["seat_width"][idx], seat_gap=R["seat_gap"][idx],
        viscosity=R["kinematic_viscosity"][idx] * R["density"][idx],
        friction=R["f0"][idx], friction_pressure=R["cp"][idx], target_stroke=r.stroke,
        t_end=2.0 * r.stroke / r.speed, **{k: R[k][idx] for k in screen.valve_of(R)})


def _derating(stack, temperature) -> float:
    return float(derated_stroke(1.0, stack.stroke_temperature_coefficient, temperature))


def _sim_cases(sims, k, loads, static_speeds, i) -> list[dict]:
    """The ``k``-th simulated design's (row ``i``) figures per load case."""
    cases = []
    for j, (s, F) in enumerate(zip(sims, loads)):
        v = float(s["mean_speed_m_s"][k])
        cases.append({"load_N": float(F), "stroke_m": float(s["stroke_m"][k]),
                      "time_to_stroke_s": float(s["time_to_stroke_s"][k]), "speed_m_s": v, "mean_speed_m_s": v,
                      "cycles": float(s["cycles"][k]), "pumped_volume_m3": float(s["pumped_volume_m3"][k]),
                      "delivered_volume_m3": float(s["delivered_volume_m3"][k]),
                      "peak_chamber_pressure_Pa": float(s["peak_chamber_pressure_Pa"][k]),
                      "peak_cylinder_pressure_Pa": float(s["peak_cylinder_pressure_Pa"][k]),
                      "reached": bool(s["reached"][k] > 0), "overshoot": 0.0,
                      "backflow_volume_m3": float(s["backflow_volume_m3"][k]),
                      "stack_work_J": float(s["stack_work_J"][k]), "output_work_J": float(s["output_work_J"][k]),
                      "quasi_static_bound_J": float(s["quasi_static_bound_J"][k]),
                      "cycle_averaged_speed_m_s": float(static_speeds[j][i]),
                      "agreement": v / float(static_speeds[j][i]) - 1.0 if static_speeds[j][i] > 0 else None})
    return cases


def diverged(cases: list[dict], swept_speed: float) -> str:
    """Why the cycle simulation of a design cannot be trusted ("" if it can):
    a non-finite figure, or a speed more than ``DIVERGED_FACTOR`` times what
    the pump sweeps (swept volume x frequency / bore: a numerical
    divergence, not physics)."""
    for c in cases:
        figures = (c["stroke_m"], c["mean_speed_m_s"], c["delivered_volume_m3"], c["peak_cylinder_pressure_Pa"])
        if not all(math.isfinite(x) for x in figures):
            return f"the cycle simulation diverged under {c['load_N']:.0f} N (a non-finite figure)"
        if abs(c["mean_speed_m_s"]) > DIVERGED_FACTOR * swept_speed:
            return (f"the cycle simulation diverged under {c['load_N']:.0f} N: {c['mean_speed_m_s']:.3g} m/s against "
                    f"{swept_speed:.3g} m/s swept")
    return ""


class _Screen(NamedTuple):
    """The pump screen: the part groups and the arrays over rows."""
    groups: list
    rows: dict
    static: dict
    margins: dict
    metrics: dict


def _design(req, screened: _Screen, i: int, cases: list[dict]) -> PumpDesign:
    """Row ``i`` of the screen with its cycle simulation (``cases``, [] when
    there is no load case to simulate)."""
    R, st, r = screened.rows, screened.static, req.requirements
    f = float(R["frequency"][i])
    static_margins = {k: float(v[i]) for k, v in screened.margins.items()}
    static = {k: float(v[i]) for k, v in st.items() if k != "speeds"}
    static["speed_m_s"] = static["mean_speed_m_s"]
    static["free_stroke_m"] = r.stroke * (1.0 + req.options.design_margin)
    static["stack_stroke_m"] = float(R["stroke"][i])
    static["max_flow_m3_s"] = static["swept_volume_m3"] * f
    sim = _simulation(cases, static["swept_volume_m3"] * f / static["cylinder_area_m2"])
    margins = dict(static_margins)
    if sim is not None and not sim.success:
        margins["simulation"] = -math.inf
    elif sim is not None:
        margins["speed"] = floor_margin(min(c["speed_m_s"] for c in cases), r.speed)
    return PumpDesign(screened.groups[R["group"][i]], float(R["voltage"][i]), f, float(R["pump_diameter"][i]),
                      static["cylinder_diameter_m"], float(R["bias_pressure"][i]), frozen(static),
                      frozen(static_margins), frozen({k: float(v[i]) for k, v in screened.metrics.items()}),
                      frozen(margins), sim)


def _simulation(cases: list[dict], swept_speed: float) -> Simulation | None:
    """The cycle simulation's outcome: failed where it diverged."""
    if not cases:
        return None
    return Simulation(not (why := diverged(cases, swept_speed)), why, tuple(cases))
