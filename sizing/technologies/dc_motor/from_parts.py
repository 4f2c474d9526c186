"""The DC option sized from parts: screen every motor x screw x
gear x drive (``search``, ``parts``), give each design its controller
(``controller``), simulate the best under every load case with the
back-EMF, current and voltage limits and the load term (``sim/dc_motor``,
batched over designs and cases), and return each as a ``records.DCDesign``
(``record.py`` writes its results.json candidate, docs/formats.md).

Simulation-based margins replace the static ones where the simulation says
more: stroke and speed (98 % of the step, as for the catalog actuators),
overshoot, winding and magnet temperature and drive current from the RMS
current of the simulated duty cycle, and ``mechanical_speed`` (the peak
speed against the motor's, gear's and screw's speed ratings, which the
drive does not enforce).
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ...physics import motor as motor_phys
from ...physics import screw as screw_phys
from ...sim.dc_motor import HEAT, DCMotorModel, simulate
from ...sim.metrics import step_metrics
from . import controller as ctl
from .actuator import SETTLED, output_times
from ...engine import holding
from . import search as dc_search
from . import verdict as dc_verdict
from .parts import drives_for_supply, enumerate_parts, metrics, mountable, static_screen, temperature_margin
from .catalog_actuators import dc_duration
from ...engine.rank import OBJECTIVE_KEYS, nondominated_levels, verdict
from ...engine.records import Simulation, frozen
from .records import DCDesign, DCParts, DCPartsOutcome
from ...settings import DC_MAX_SIMULATED as MAX_SIMULATED
from ...settings import DC_MIN_SIMULATED as MIN_SIMULATED
from ...settings import DC_REAL_SHARE as REAL_SHARE

NOT_SIMULATED = "not simulated (feasible, later Pareto level)"   # statically feasible, beyond the simulation budget
SIM_CHUNK = 64          # rows (design x load case) per batched simulation


def duty_rms(t, heat, current, period) -> np.ndarray:
    """RMS current over one duty period from step responses (n, n_t):
    ``heat``, the integral of the square of the current flowing from t[0]
    (``simulate(heat=True)``, accumulated over every control period),
    read at the period, then the final (holding) ``current`` for the rest
    when the period outlasts the run. Read from the integral rather than
    from samples of the current, the RMS does not depend on how the output
    grid falls on the controller's held current."""
    heat = np.atleast_2d(heat)
    if period >= t[-1]:
        energy = heat[:, -1] + (period - t[-1]) * current[:, -1] ** 2
    else:
        k = int(np.clip(np.searchsorted(t, period), 1, len(t) - 1))
        w = (period - t[k - 1]) / (t[k] - t[k - 1])
        energy = (1.0 - w) * heat[:, k - 1] + w * heat[:, k]
    return np.sqrt(energy / period)


def crossing_time(t, y, target, first) -> np.ndarray:
    """The time each row of y (n, n_t) reaches ``target`` (n,), between the
    samples ``first`` - 1 and ``first`` (the first at or past the target),
    by linear interpolation: the time to stroke then moves continuously
    with the design instead of by output samples."""
    rows = np.arange(len(y))
    k = np.clip(first, 1, y.shape[1] - 1)
    y0, y1 = y[rows, k - 1], y[rows, k]
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.where(y1 > y0, (target - y0) / (y1 - y0), 1.0)
    return t[k - 1] + np.clip(w, 0.0, 1.0) * (t[k] - t[k - 1]) - t[0]


def models(pl, static, gains, p, idx, loads, hot_resistance) -> DCMotorModel:
    """One row per (design, load case), designs outer."""
    n_l = len(loads)
    rep = lambda a: np.repeat(np.asarray(a)[idx], n_l)
    return DCMotorModel(
        c1=rep(pl["c1"]), c2=rep(pl["c2"]), lead=rep(pl["lead"]), rate=rep(p.values["drive_rate"]),
        kp=rep(gains["kp"]), ki=rep(gains["ki"]), kd=rep(gains["kd"]), derivative_on_measurement=1.0,
        proportional_on_measurement=1.0, current_limit=rep(static["current_limit_A"]),
        load_force=np.tile(np.asarray(loads, float), len(idx)), efficiency=rep(pl["efficiency"]),
        torque_constant=rep(pl["torque_constant"]), bus_voltage=rep(static["drive_voltage_V"]),
        back_emf_constant=rep(p.values["motor_back_emf_constant"]), winding_resistance=rep(hot_resistance),
        integrate_to_limit=1.0)


def _choose(margins, met, req, real=None) -> np.ndarray:
    """Statically feasible designs by Pareto level, then the closest to
    feasible, up to MAX_SIMULATED (at least MIN_SIMULATED when there are).
    ``real`` (bool per row, designs whose parts all exist): up to
    REAL_SHARE of the budget goes first to them, chosen the same way, so
    that the verdict on real parts does not depend on generic parts
    crowding them out."""
    if real is not None and real.any() and not real.all():
        idx = np.flatnonzero(real)
        first = idx[_choose({k: v[idx] for k, v in margins.items()}, {k: v[idx] for k, v in met.items()}, req)]
        first = first[: int(MAX_SIMULATED * REAL_SHARE)]
        rest = [i for i in _choose(margins, met, req) if i not in set(first)]
        return np.concatenate([first, rest])[:max(MAX_SIMULATED, len(first))].astype(int)
    M = np.vstack(list(margins.values()))
    worst = np.nan_to_num(M.min(axis=0), nan=-np.inf, neginf=-1e9)
    ok = worst >= 0
    F = np.column_stack([met[OBJECTIVE_KEYS[k]] for k in req.objectives.minimize])
    level = np.full(len(worst), 10**6)
    if ok.any():
        level[ok] = pareto_levels(F[ok])
    score = F.sum(axis=1) / np.maximum(F.min(axis=0), 1e-12).sum()
    order = np.lexsort((score, -worst, level, ~ok))
    n = min(len(order), MAX_SIMULATED, max(int(ok.sum()), MIN_SIMULATED))
    return order[:n]


def dc_parts_designs(req, catalog, loads, progress=None, duration=None, exhaustive=False,
                     rows=None) -> DCPartsOutcome:
    """The DC designs from parts. The catalog-scale search (``dc_search``)
    screens what no bound rules out and simulates the best; only simulated
    designs are recorded, the rest are counted by reason in ``ruled_out``.
    ``exhaustive`` (a catalog of one design, ``sizing evaluate``), or a
    catalog of at most MIN_SIMULATED combinations: every combination, each
    recorded. ``rows``: the (motor, screw, gear, drive) ids of the only
    designs to size, each simulated and recorded (the flips' re-solves)."""
    duration = dc_duration(req) if duration is None else duration
    catalog = drives_for_supply(catalog, req.requirements.supply_voltage)
    ruled_out, combinations = {}, None
    small = sum(1 + len(g) for g in mountable(catalog)) * len(catalog.screws) * len(catalog.drives)
    if rows is not None:
        exhaustive = True
        p = enumerate_parts(catalog)
        p = p.take(np.flatnonzero([r in rows for r in zip(p.motor, p.screw, p.gear, p.drive)]).astype(int))
    elif exhaustive or small <= MIN_SIMULATED:      # a few parts (evaluate, robust): every one simulated
        exhaustive = True
        p = enumerate_parts(catalog)
    else:
        found = dc_search.search(catalog, req, loads)
        p, ruled_out, combinations = found.parts, dict(found.ruled_out), found.combinations
    if len(p) == 0:
        return DCPartsOutcome((), frozen(ruled_out), combinations or 0)
    pl, static, margins = static_screen(p, req, loads)
    screen = _Screen(p, pl, static, margins, metrics(p, req, static),
                     ctl.pole_target(req.stroke_time, p.values["drive_rate"]))
    gains = ctl.ipd_gains(pl["c1"], pl["c2"], pl["lead"], screen.pole)
    real_ids = {e.id for _, e in catalog.entries() if dc_verdict.is_real(e)}
    real = np.array([all(x is None or x in real_ids for x in row) for row in zip(p.motor, p.screw, p.gear, p.drive)])
    chosen = np.arange(len(p)) if rows is not None else _choose(margins, screen.metrics, req, real)
    sims = _simulate(req, pl, static, gains, p, chosen, loads, duration, progress)
    if not exhaustive:
        sims.update(_beyond_budget(req, screen, gains, chosen, sims, loads, duration))
        _count_unsimulated(ruled_out, margins, np.setdiff1d(np.arange(len(p)), np.fromiter(sims, int, len(sims))))
    rows = range(len(p)) if exhaustive else (i for i in range(len(p)) if i in sims)
    designs = tuple(_design(req, screen, gains, i, sims.get(i), duration) for i in rows)
    return DCPartsOutcome(designs, frozen(ruled_out), combinations if combinations is not None else len(p))


def _beyond_budget(req, screen: _Screen, gains: dict, chosen, sims: dict, loads, duration) -> dict:
    """When no simulated design complies but designs that pass the static
    screen were left beyond the simulation budget, those too, a budget at a
    time in the same order, until one complies or none is left: the verdict
    must not depend on which designs the budget reached (at a 160 mm stroke
    the seed's first 300 held none of the five that comply, while both 158
    and 161.6 mm found some). Returns their simulations."""
    p = screen.parts

    def complies(i) -> bool:
        st = {k: float(v[i]) for k, v in screen.static.items()}
        return verdict(_row_margins(req, p, i, st, screen.margins, sims.get(i, more.get(i)))[1])[0]
    more: dict = {}
    if any(complies(i) for i in sims):
        return more
    worst = np.nan_to_num(np.vstack(list(screen.margins.values())).min(axis=0), nan=-np.inf)
    left = np.setdiff1d(np.flatnonzero(worst >= 0), np.asarray(chosen, int))
    while left.size:
        part = {k: np.asarray(v)[left] for k, v in screen.margins.items()}
        nxt = left[_choose(part, {k: np.asarray(v)[left] for k, v in screen.metrics.items()}, req)]
        more.update(_simulate(req, screen.plant, screen.static, gains, p, nxt, loads, duration, None))
        if any(complies(i) for i in nxt):
            break
        left = np.setdiff1d(left, nxt)
    return more


def row_parts(p, i: int) -> DCParts:
    """The catalog ids of row ``i`` of ``p`` (PartArrays)."""
    return DCParts(p.motor[i], p.screw[i], p.gear[i], p.drive[i])


class _Screen(NamedTuple):
    """The static screen of the combinations, arrays over rows."""
    parts: object           # PartArrays
    plant: dict
    static: dict
    margins: dict
    metrics: dict
    pole: np.ndarray        # rad/s, the controller's triple pole


def _design(req, screen: _Screen, gains: dict, i: int, sim: dict | None, duration: float) -> DCDesign:
    """Row ``i`` of the screen, with its simulation when it ran."""
    p, pl, v = screen.parts, screen.plant, screen.parts.values
    st = {k: float(x[i]) for k, x in screen.static.items()}
    st["no_load_max_speed_m_s"] = float(st["drive_voltage_V"] / v["motor_back_emf_constant"][i]
                                        * pl["lead"][i] / (2 * math.pi))
    simulated, m = _row_margins(req, p, i, st, screen.margins, sim)
    w0 = screen.pole[i]
    controller = {"kp": float(gains["kp"][i]), "ki": float(gains["ki"][i]), "kd": float(gains["kd"][i]),
                  "rate_Hz": float(v["drive_rate"][i]), "rule": "I-PD, triple closed-loop pole",
                  "pole_rad_per_second": float(w0), "bandwidth_Hz": float(ctl.bandwidth(w0) / (2 * math.pi)),
                  "current_limit_A": st["current_limit_A"], "bus_voltage_V": float(v["drive_bus_voltage"][i]),
                  "voltage_limit_V": st["drive_voltage_V"]}
    rated = float(min(v["motor_max_temperature"][i], v["screw_max_temperature"][i], v["gear_max_temperature"][i]))
    return DCDesign(row_parts(p, i), frozen(controller), frozen(st),
                    frozen({k: float(x[i]) for k, x in screen.metrics.items()}), rated, duration, frozen(m),
                    None if sim is None else Simulation(True, "", tuple(sim["cases"])),
                    frozen(simulated), frozen(sim["model"] if sim is not None else None))


def _count_unsimulated(counts: dict, margins: dict, rows) -> None:
    """Screened combinations the simulation budget left out: each counted
    under the margin it misses most, or as not simulated (feasible but
    beyond the simulation budget, on a later Pareto level of mass and cost)."""
    if len(rows) == 0:
        return
    names = list(margins)
    M = np.nan_to_num(np.vstack([np.asarray(margins[k], float)[rows] for k in names]), nan=-np.inf)
    worst = M.argmin(axis=0)
    missed = M[worst, np.arange(len(rows))] < 0
    for k, name in enumerate(names):
        n = int(np.sum(missed & (worst == k)))
        if n:
            counts[name] = counts.get(name, 0) + n
    if (~missed).any():
        counts[NOT_SIMULATED] = counts.get(NOT_SIMULATED, 0) + int((~missed).sum())


def pareto_levels(F: np.ndarray) -> np.ndarray:
    """Non-dominated sorting (level 1 = the Pareto front), as
    ``rank.nondominated_levels``; for two objectives in O(n log n): by
    rising first objective, each point joins the first level whose latest
    member (the lowest second objective so far) does not dominate it."""
    F = np.asarray(F, float)
    if F.ndim != 2 or F.shape[1] != 2 or not np.isfinite(F).all():
        return nondominated_levels(F)
    import bisect
    order = np.lexsort((F[:, 1], F[:, 0]))
    keys: list = []
    level = np.zeros(len(F), dtype=int)
    for i in order:
        key = (F[i, 1], F[i, 0])
        L = bisect.bisect_left(keys, key)
        if L == len(keys):
            keys.append(key)
        else:
            keys[L] = key
        level[i] = L + 1
    return level


def _row_margins(req, p, i, st, margins, sim) -> tuple[dict, dict]:
    """(simulated figures, margins) of row i: the static margins, replaced by
    the simulation's where it ran; a margin with no limit to check (inf,
    e.g. no magnet rating) is dropped."""
    m = {k: float(v[i]) for k, v in margins.items()}
    simulated = {}
    if sim is not None:
        simulated, sim_margins = _sim_figures(req, p, i, st, sim)
        m.update(sim_margins)
    return simulated, {k: val for k, val in m.items() if val != math.inf}


def verify_parts(req, p, loads, settings: dict, ambient=None, duration=None) -> list[dict]:
    """Re-verify DC designs whose parts and settings are fixed (``sizing
    robust``: one design, its parts perturbed per row) through the steps of
    ``dc_parts_designs``: static screen, simulation of every row under
    every load case, margins, verdict. ``settings``: (n,) arrays of the
    design's controller gains (kp, ki, kd: tuned on the nominal parts and
    kept) and drive limits (current_limit_A, voltage_limit_V);
    ``ambient``: optional per-row operating temperature (``static_screen``).
    Returns per row {"margins", "feasible", "driver", "simulated"}."""
    duration = dc_duration(req) if duration is None else duration
    pl, static, margins = static_screen(p, req, loads, ambient=ambient, settings=settings)
    gains = {k: np.asarray(settings[k], float) for k in ("kp", "ki", "kd")}
    sims = _simulate(req, pl, static, gains, p, np.arange(len(p)), loads, duration, None)
    out = []
    for i in range(len(p)):
        st = {k: float(v[i]) for k, v in static.items()}
        simulated, m = _row_margins(req, p, i, st, margins, sims.get(i))
        feasible, driver = verdict(m)
        out.append({"margins": m, "feasible": feasible, "driver": driver, "simulated": simulated})
    return out


def _simulate(req, pl, static, gains, p, chosen, loads, duration, progress) -> dict:
    """Simulate the chosen designs under every load case, batched."""
    if len(chosen) == 0 or not loads:
        return {}
    S = req.requirements.stroke
    t = output_times(duration)
    ref = np.full_like(t, S)
    ref[0] = 0.0
    n_l = len(loads)
    per_chunk = max(1, SIM_CHUNK // n_l)
    period = 1.0 / req.duty.strokes_per_second
    result = {}
    for start in range(0, len(chosen), per_chunk):
        idx = chosen[start:start + per_chunk]
        model = models(pl, static, gains, p, idx, loads, static["hot_resistance_ohm"])
        out = simulate(model, t, ref, heat=True)
        y, v, i_trace = out["position_m"], out["velocity_m_s"], out["current_A"]
        fig = _step_figures(t, y, SETTLED * S)
        rms = duty_rms(t, out[HEAT], i_trace, period)
        P = model.matrix()
        for k, design in enumerate(idx):
            rows = slice(k * n_l, (k + 1) * n_l)
            cases = []
            for j, row in enumerate(range(rows.start, rows.stop)):
                case = {name: float(val[row]) for name, val in fig.items()}
                case.update({"load_N": float(loads[j]), "peak_current_A": float(np.max(np.abs(i_trace[row]))),
                             "peak_speed_m_s": float(np.max(np.abs(v[row]))), "rms_current_A": float(rms[row]),
                             "max_speed_m_s": float(_case_ceiling(p, pl, static, design, loads[j]))})
                cases.append(case)
            result[int(design)] = {"cases": cases, "model": _row_params(P[k * n_l])}
        if progress is not None:
            progress("simulating DC", min(start + per_chunk, len(chosen)), len(chosen))
    return result


def _step_figures(t, y, target) -> dict:
    """``step_metrics`` with the time to stroke (and the speed from it)
    interpolated between output samples."""
    fig = step_metrics(t, y, np.full(len(y), target))
    hit = np.isfinite(fig["time_to_stroke_s"])
    if hit.any():
        first = np.argmax(y >= target, axis=1)
        time = crossing_time(t, y, np.full(len(y), target), first)
        fig["time_to_stroke_s"] = np.where(hit, time, fig["time_to_stroke_s"])
        with np.errstate(divide="ignore"):
            fig["speed_m_s"] = np.where(hit, np.where(time > 0, target / time, np.inf), fig["speed_m_s"])
    return fig


def _row_params(row) -> dict:
    """The scalar parameters of one row of the model matrix (load_force
    excluded: set per case)."""
    return {name: float(row[j]) for j, name in enumerate(DCMotorModel.PARAMS) if name != "load_force"}


def _case_ceiling(p, pl, static, i, load) -> float:
    """Output speed the drive's voltage allows under ``load`` (m/s)."""
    i_load = screw_phys.torque_for_force(load, pl["lead"][i], pl["efficiency"][i]) / pl["torque_constant"][i]
    w = motor_phys.speed_ceiling(static["drive_voltage_V"][i], p.values["motor_back_emf_constant"][i],
                                 static["hot_resistance_ohm"][i], i_load)
    return float(screw_phys.output_speed(w, pl["lead"][i]))


def _sim_figures(req, p, i, st, sim) -> tuple[dict, dict]:
    r = req.requirements
    k_out = float(st["output_stiffness_N_m"])
    cases = holding.held_cases(sim["cases"], k_out)
    worst = max(cases, key=lambda c: c["load_N"])
    S = r.stroke
    reached = all(c["stroke_m"] >= SETTLED * S for c in cases)
    v = p.values
    # the simulated RMS current at the screen's k_t, re-derated at the winding it heats (physics/motor.py)
    torque_rms = st["torque_constant_at_temperature"] * max(c["rms_current_A"] for c in cases)
    Tw, _, i_rms = (float(x) for x in motor_phys.derated_winding(
        v["motor_thermal_resistance"][i], v["motor_winding_resistance"][i],
        v["motor_resistance_temperature_coefficient"][i], v["motor_torque_constant"][i],
        v["motor_torque_constant_temperature_coefficient"][i], r.max_temperature, torque_rms))
    peak = max(c["peak_speed_m_s"] for c in cases)
    figures = {"stroke_m": worst["stroke_m"], "time_to_stroke_s": worst["time_to_stroke_s"],
               "speed_m_s": min(c["speed_m_s"] for c in cases), "overshoot": max(c["overshoot"] for c in cases),
               "load_N": worst["load_N"], "peak_speed_m_s": peak, "rms_current_A": i_rms,
               "rms_torque_N_m": torque_rms, "winding_temperature_degC": Tw, "cases": cases}
    margins = {
        # a servo settles on its reference: the stroke is the designed travel once the
        # simulation shows the step reached (to 98 %) under every load (as for catalog actuators)
        # (from neutral, less the rest offset under the largest load: engine/holding.py)
        "stroke": (holding.travel(req, st["stroke_m"], k_out, worst["load_N"]) / S - 1.0 if reached
                   else min(holding.travel(req, c["stroke_m"], k_out, c["load_N"]) for c in cases) / S - 1.0),
        "speed": figures["speed_m_s"] / r.speed - 1.0,
        "overshoot": 1.0 - figures["overshoot"] / req.options.max_overshoot,
        "winding_temperature": float(temperature_margin(p.values["motor_max_winding_temperature"][i], Tw)),
        "magnet_temperature": float(temperature_margin(p.values["motor_magnet_max_temperature"][i], Tw)),
        "drive_current": float(p.values["drive_continuous_current"][i] / max(i_rms, 1e-12) - 1.0),
        "continuous_torque": float(st["continuous_torque_rated_N_m"] / max(torque_rms, 1e-12) - 1.0),
        "mechanical_speed": st["mechanical_speed_limit_m_s"] / max(peak, 1e-12) - 1.0,
    }
    return figures, margins


def evaluate_parts(design, catalog, parts: dict, cases: list[dict]) -> dict:
    """``sizing evaluate`` of one design from parts: the same screen,
    controller and simulation as ``sizing solve`` (a one-design catalog)."""
    from dataclasses import replace
    from ...io.requirements import design_requirements
    one = replace(catalog, motors={parts["motor"].id: parts["motor"]}, screws={parts["screw"].id: parts["screw"]},
                  gears={parts["gear"].id: parts["gear"]} if parts["gear"] is not None else {},
                  drives={parts["drive"].id: parts["drive"]})
    loads = [c["load_N"] for c in cases]
    req = design_requirements(design, loads)
    found = dc_parts_designs(req, one, loads, duration=design.duration, exhaustive=True).designs
    d = next(x for x in found if x.parts.gear == (parts["gear"].id if parts["gear"] is not None else None))
    sim = dict(d.simulated) or {"cases": []}
    simulated = [dict(case, **s) for case, s in zip(cases, sim["cases"])]
    worst = max(simulated, key=lambda x: x["load_N"]) if simulated else {}
    margins = {k: v for k, v in d.margins.items() if k != "blocked_force"}
    warnings = [f"{k}: margin {v:+.1%}" for k, v in margins.items() if not v >= 0]
    return {"technology": "dc_motor", "design": dict(d.parts.components(), step_m=design.step),
            "controller": dict(d.controller), "static": dict(d.static),
            "simulated": {"cases": simulated, "worst": worst, **{k: v for k, v in sim.items() if k != "cases"}},
            "margins": margins, "metrics": dict(d.metrics), "warnings": warnings}
