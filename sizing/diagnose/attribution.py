"""Which effect explains the gap, and how far it shrinks.

1. Noise floor of each run, from the data: the white part of the position
   measurement (second differences, robust) plus the logged input's noise
   carried through the run's gain (position span / input span).
2. Screen: every effect of the library at its two realistic sizes and a
   seeded Latin-hypercube of parameter sets, one simulator batch per
   effect, scored on the training runs.
3. Fit the promising effects (least squares on the training runs, from the
   best screened point); judge every effect on the holdout runs only.
4. Pairs: when no single effect explains the gap, the best pairs of the
   top singles are fitted together.
5. Verdict: "no significant gap" when the baseline holdout NRMSE is within
   GAP_FACTOR times the noise floor; an effect when it removes at least
   EXPLAINED of the gap energy above the noise floor on the holdout runs
   and leaves at most RESIDUAL_FACTOR times the noise floor (what it leaves
   must look like noise, not like a smaller gap); otherwise "unexplained". Both null verdicts name no effect.
"""
from __future__ import annotations

import itertools

import numpy as np

from . import fitting
from .effects import library
from .inputs import noise_sigma

GAP_FACTOR = 1.5
EXPLAINED = 0.8
RESIDUAL_FACTOR = 2.0  # an explaining effect leaves at most this times the noise floor
N_SCREEN = 10          # screened parameter sets per effect parameter
TOP_FIT = 4            # effects fitted at least
TOP_PAIRS = 3          # singles combined into pairs


def noise_floor(bench, replicas: int = 3, seed: int = 0) -> np.ndarray:
    """(n_runs,) NRMSE expected from measurement noise alone: the position
    noise (robust, from second differences of the baseline residual) and, for a piezo rig, the
    spread of the simulated output when the logged voltage is logged again
    with the same noise and treated the same way (one simulator batch)."""
    from ..sim import piezohydraulic as ph_sim
    from .inputs import treat_voltage

    rng = np.random.default_rng(seed)
    out = []
    for i, r in enumerate(bench.runs):
        sy = noise_sigma(r.y - bench.nominal()[i])     # high-frequency residual
        su = 0.0
        if bench.kind == "piezohydraulic":
            sigma_v = noise_sigma(r.u_raw)
            if sigma_v > 0:
                V = np.vstack([treat_voltage(r.u_raw + rng.normal(0.0, sigma_v, len(r.t))) for _ in range(replicas)])
                Y = ph_sim.simulate(bench.model.replace(h0=np.zeros(replicas)), r.t, V, r.t)["position_m"]
                su = float(np.sqrt(np.mean((Y - bench.nominal()[i][None, :]) ** 2)))
        out.append(float(np.hypot(sy, su)) / r.span)
    return np.array(out)


def _lhs(n: int, d: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    Z = (np.argsort(rng.random((d, n)), axis=1).T + rng.random((n, d))) / n
    return Z


def screen(bench, effect, seed: int = 0) -> tuple[np.ndarray, float]:
    """(best unit point, its training score) over sizes + a Latin hypercube."""
    train = bench.train
    d = len(effect.params)
    if d == 0:
        return np.zeros(0), float(np.sqrt(fitting.cost(bench, [effect], np.zeros((1, 0)), train)[0]))
    sizes = [effect.unit(s) for s in effect.sizes_for(bench.rig, bench.model) if s]
    n = N_SCREEN * d * (4 if effect.post else 1)
    Z = np.vstack(sizes + [_lhs(n, d, seed)]) if sizes else _lhs(n, d, seed)
    Z = np.clip(Z, 0.0, 1.0)
    scores = fitting.cost(bench, [effect], Z, train)
    k = int(np.argmin(scores))
    return Z[k], float(np.sqrt(scores[k]))


def holdout_score(bench, fit: fitting.EffectFit) -> None:
    runs = bench.holdout
    Y = bench.simulate(fit.effects, fit.z[None, :], runs)
    per_run = fitting.run_nrmse(bench, Y, runs)[0]
    fit.nrmse_runs = {bench.runs[i].name: float(v) for i, v in zip(runs, per_run)}
    fit.nrmse_holdout = float(np.mean(per_run))


def explained(base: float, after: float, floor: float) -> float:
    """Fraction of the gap energy above the noise floor that an effect removes."""
    excess = base ** 2 - floor ** 2
    if excess <= 0:
        return 0.0
    return float(1.0 - max(after ** 2 - floor ** 2, 0.0) / excess)


def attribute(bench, baseline_holdout: float, floor_holdout: float, seed: int = 0, pairs: bool = True):
    """Screen, fit and rank every effect. Returns (fits sorted best first,
    verdict dict)."""
    effects = [e for e in library(bench.kind) if e.applicable(bench.rig, bench.model)]
    base_train = float(np.sqrt(np.mean(fitting.run_nrmse(
        bench, [y[None, :] for y in (bench.nominal()[i] for i in bench.train)], bench.train) ** 2)))
    screened = [(e, *screen(bench, e, seed)) for e in effects]
    screened.sort(key=lambda s: s[2])
    fits = []
    for rank, (effect, z0, score) in enumerate(screened):
        promising = rank < TOP_FIT or score < 0.9 * base_train
        if promising:
            f = fitting.fit(bench, [effect], z0, bench.train)
        else:
            f = fitting.EffectFit((effect,), z0, score, message="screened only")
        holdout_score(bench, f)
        fits.append(f)
    fits.sort(key=lambda f: f.nrmse_holdout)
    best = fits[0]
    if pairs and explained(baseline_holdout, best.nrmse_holdout, floor_holdout) < EXPLAINED:
        tops = [f for f in fits[:TOP_PAIRS]]
        for a, b in itertools.combinations(tops, 2):
            if a.effects[0].post and b.effects[0].post is False:
                a, b = b, a          # model effects first, measurement effects after
            f = fitting.fit(bench, a.effects + b.effects, np.concatenate([a.z, b.z]), bench.train)
            holdout_score(bench, f)
            fits.append(f)
        fits.sort(key=lambda f: f.nrmse_holdout)
    return fits


def verdict(baseline_holdout: float, floor_holdout: float, fits) -> dict:
    if baseline_holdout <= GAP_FACTOR * floor_holdout:
        return {"effect": None, "shrink_holdout": 0.0, "status": "no_significant_gap",
                "reason": f"baseline holdout NRMSE {baseline_holdout:.4f} is within {GAP_FACTOR:g} x "
                          f"the noise floor {floor_holdout:.4f}"}
    best = fits[0] if fits else None
    if best is not None:
        shrink = 1.0 - best.nrmse_holdout / baseline_holdout
        share = explained(baseline_holdout, best.nrmse_holdout, floor_holdout)
        if shrink > 0 and share >= EXPLAINED and best.nrmse_holdout <= RESIDUAL_FACTOR * floor_holdout:
            return {"effect": best.name, "shrink_holdout": float(shrink), "status": "explained",
                    "explained_gap_energy": share,
                    "reason": f"{best.name} removes {100 * share:.0f} % of the holdout gap energy above the noise floor"}
    share = explained(baseline_holdout, best.nrmse_holdout, floor_holdout) if best else 0.0
    return {"effect": None, "shrink_holdout": 0.0, "status": "unexplained",
            "explained_gap_energy": share,
            "reason": f"no effect of the library removes {100 * EXPLAINED:.0f} % of the holdout gap energy "
                      f"above the noise floor and leaves a gap within {RESIDUAL_FACTOR:g} x the noise floor "
                      f"(best: {best.name if best else 'none'}, {100 * share:.0f} %, holdout NRMSE "
                      f"{best.nrmse_holdout if best else float('nan'):.4f})"}
