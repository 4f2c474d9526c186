"""Fit the parameters of one effect (or a pair) on the training runs.

Least squares (scipy's trust-region reflective, bounds [0, 1] on the unit
search coordinates of each parameter, log-scaled where declared). The
residual of a run is (measured - simulated) / (span sqrt(n)), so the cost
is the sum over runs of NRMSE^2 (docs/formats.md; the combined measure of bench.py when
the runs log the current too). The Jacobian is a forward
difference computed as one batch of the simulator (all perturbed parameter
sets at once, only at the points whose Jacobian the solver asks for), step ``fd_step`` in unit coordinates or the effect's
``extra["fd_step"]`` (an additive sinusoid's frequency, which the cost is
sharp in). Confidence intervals: 95 % from s^2 (J'J)^-1 at the
optimum, mapped to physical units by the delta method; the residuals of a
dynamic model are correlated, so read them as optimistic.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from .settings import DEFAULT



@dataclass
class EffectFit:
    effects: tuple
    z: np.ndarray                       # unit coordinates (n_par,)
    nrmse_train: float
    nrmse_holdout: float = float("nan")
    nrmse_runs: dict = field(default_factory=dict)
    ci: dict = field(default_factory=dict)          # {param: [lo, hi]}
    success: bool = True
    message: str = ""
    nrmse_channels: dict = field(default_factory=dict)              # holdout NRMSE per channel
    residual_blocks: np.ndarray = field(default_factory=lambda: np.zeros(0))
    holdout_position: list = field(default_factory=list)     # simulated position (n,) of each holdout run
    holdout_residual: list = field(default_factory=list)     # (t, measured - simulated position) of each
    channel_blocks: dict = field(default_factory=dict)       # {channel: residual block energies} (holdout)
    discrepancy: dict | None = None     # the single plus a model discrepancy on the holdout (discrepancy.account)

    @property
    def named(self) -> tuple:
        """The effects proper (without the jointly re-fitted nominal parameters)."""
        return tuple(e for e in self.effects if not e.extra.get("nuisance"))

    @property
    def name(self) -> str:
        return "+".join(e.name for e in self.named)

    @property
    def form(self) -> str:
        """The form of each named effect, joined like ``name``."""
        return "+".join(e.form for e in self.named)

    @property
    def params(self) -> dict:
        out, col = {}, 0
        single = len(self.named) == 1
        for e in self.effects:
            for i, p in enumerate(e.params):
                key = p.name if single and not e.extra.get("nuisance") else f"{e.name}.{p.name}"
                out[key] = float(p.from_unit(self.z[col + i]))
            col += len(e.params)
        return out


def run_nrmse(bench, Yc, runs) -> np.ndarray:
    """(n_cand, n_runs) combined measure (bench.py) of each candidate on
    each run; Yc from bench.simulate_channels."""
    return bench.combined_nrmse(Yc, runs)


def cost(bench, effects, Z, runs) -> np.ndarray:
    """(n_cand,) mean combined measure^2 over ``runs`` (the screening score)."""
    return np.mean(run_nrmse(bench, bench.simulate_channels(effects, Z, runs), runs) ** 2, axis=1)


def fit(bench, effects, z0, runs, max_nfev: int = 25) -> EffectFit:
    """Least-squares fit of ``effects`` on ``runs`` from unit start ``z0``."""
    effects = tuple(effects)
    z0 = np.clip(np.asarray(z0, float), 0.0, 1.0)
    if z0.size == 0:
        Y = bench.simulate_channels(effects, np.zeros((1, 0)), runs)
        score = float(np.sqrt(np.mean(run_nrmse(bench, Y, runs) ** 2)))
        return EffectFit(effects, z0, score, message="no parameter")
    values, slopes = {}, {}
    step = np.concatenate([np.full(len(e.params), float(e.extra.get("fd_step", DEFAULT.fd_step))) for e in effects])

    def residuals(Z):
        return bench.residuals(bench.simulate_channels(effects, Z, runs), runs)

    # the residual at a point, and the perturbed points of its Jacobian only
    # when the solver asks for it: a trial step it rejects needs no
    # Jacobian (two in five trial points of the check's fits; each
    # candidate is simulated on its own, so the figures do not depend on
    # which are simulated together)
    def fun(z):
        key = z.tobytes()
        if key not in values:
            values[key] = residuals(z[None, :])[0]
        return values[key]

    def jac(z):
        key = z.tobytes()
        if key not in slopes:
            steps = np.where(z + step <= 1.0, step, -step)
            slopes[key] = (residuals(z + np.diag(steps)) - fun(z)).T / steps[None, :]
        return slopes[key]

    res = least_squares(fun, z0, jac=jac, bounds=(0.0, 1.0), x_scale=1.0, max_nfev=max_nfev,
                        diff_step=None, method="trf")
    z = res.x
    n_runs = len(runs)
    score = float(np.sqrt(2 * res.cost / n_runs))
    ci = confidence(effects, z, res.jac, res.fun)
    return EffectFit(effects, z, score, ci=ci, success=bool(res.success), message=str(res.message))


def confidence(effects, z, J, r) -> dict:
    """95 % intervals {param: [lo, hi]} (physical units) from the Jacobian."""
    params = [p for e in effects for p in e.params]
    single = sum(not e.extra.get("nuisance") for e in effects) == 1
    names = [p.name if single and not e.extra.get("nuisance") else f"{e.name}.{p.name}"
             for e in effects for p in e.params]
    n, k = J.shape
    dof = max(n - k, 1)
    s2 = float(r @ r) / dof
    try:
        cov = s2 * np.linalg.pinv(J.T @ J)
    except np.linalg.LinAlgError:
        cov = np.full((k, k), np.inf)
    out = {}
    for i, (name, p) in enumerate(zip(names, params)):
        sd = float(np.sqrt(max(cov[i, i], 0.0)))
        lo, hi = p.from_unit(max(z[i] - 1.96 * sd, 0.0)), p.from_unit(min(z[i] + 1.96 * sd, 1.0))
        out[name] = [float(lo), float(hi)]
    return out
