"""Estimator of c1, c2 (and optionally the PID gains) of the DC motor
lead-screw actuator from reference/position runs (seed section 3.2).

The model is the rig's closed loop, exactly the seed's eq. 14 with the
discrete PID, current limit and load of sizing.sim.dc_motor: the
reference is the input, the measured position the output, as in the seed.
The solver works on log(c1/c1_rig), log(c2/c2_rig) (and log gains), so the
parameters keep their signs (c1 < 0, c2 > 0, gains >= 0) and are of order
one. The Jacobian is a forward difference with all perturbed parameter sets
in one call of the batch simulator; several seeded starts (screened in one
batch) guard against local minima. Covariance and 95 % intervals as for the
hysteresis fit, inflated for correlated residuals (common.ess_inflation).

Sensor-mount vibration (seed sec. 3.2: "the steady-state oscillations in
Figure 15 were the result of sensor vibration"): the sensor on a lightly
damped mount reads y + z with z'' + 2 zeta w z' + w^2 z = -g y'' (the
diagnosis's sensor_vibration mount form). When the residual of the plain
fit holds a spectral line (spectrum.lines) or ``vibration=True``, the mount
(frequency, damping, gain) is fitted with c1, c2, started at the line; it
is kept when it lowers the cost. Residual structure the fitted model still
lacks (a line, a trend) is reported as a warning: the intervals assume it
is absent.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from .. import spectrum
from ..physics.sensor_mount import mount_response
from ..errors import FitError, SimulationError
from ..sim.dc_motor import DCMotorModel, simulate
from ..sim.signals import nrmse
from .common import (Z95, ConvergenceWarning, correlation, covariance, ess_inflation,
                     identifiability, require_runs, residual_structure)

GAIN_NAMES = ("kp", "ki", "kd")
MOUNT_NAMES = ("mount_frequency_Hz", "mount_damping", "mount_gain")
MOUNT_DAMPING_START = 0.05
LOG_BOUND = 6.0        # each parameter within e^{+/-6} (x 400) of the rig's value


@dataclass
class DCRecord:
    """One run: time (n,) s, reference (n,) m, measured position (n,) m."""

    name: str
    time: np.ndarray
    reference: np.ndarray
    position: np.ndarray
    source: str = ""

    @property
    def label(self) -> str:
        return self.source or self.name


class DCMotorEstimator:
    """Fit c1, c2 (1/s, rad/(s^2 A)) of seed eq. 13-14 through the closed loop.

    Parameters
    ----------
    model : DCMotorModel of the rig (one candidate); its c1, c2 (and gains)
        are the nominal values and the centre of the starts.
    fit_gains : also fit the nonzero PID gains kp, ki, kd.
    n_starts, n_screen, random_state : multi-start settings (seeded).
    vibration : fit a sensor-mount vibration with c1, c2: None (default)
        when the plain fit's residual holds a spectral line, True always,
        False never.
    """

    def __init__(self, model: DCMotorModel, fit_gains: bool = False, n_starts: int = 3,
                 n_screen: int = 24, random_state: int = 0, max_nfev: int = 100, progress=None,
                 vibration: bool | None = None):
        self.vibration = vibration
        self._n_mount = 0
        self.model = model
        self.fit_gains = fit_gains
        self.n_starts = n_starts
        self.n_screen = n_screen
        self.random_state = random_state
        self.max_nfev = max_nfev
        self.progress = progress

    def _names(self):
        names = ["c1", "c2"]
        if self.fit_gains:
            names += [g for g in GAIN_NAMES if float(getattr(self.model, g)) != 0.0]
        return names

    def _values(self, Z):
        """Physical parameters (n_cand, p) from log-ratios Z (n_cand, p)."""
        return self._nominal[None, :] * np.exp(Z)

    def _simulate(self, Z, rec):
        values = self._values(np.atleast_2d(Z))
        k = len(self.names_) - self._n_mount
        changes = {name: values[:, i] for i, name in enumerate(self.names_[:k])}
        try:
            out = simulate(self.model.replace(**changes), rec.time, rec.reference, rec.time)["position_m"]
        except SimulationError:
            out = np.full((len(values), len(rec.time)), np.nan)
        if self._n_mount:
            out = np.array([y + mount_response(rec.time, y, *v[k:]) for y, v in zip(out, values)])
        return out

    def _residual(self, z, records):
        parts = [(self._simulate(z, rec)[0] - rec.position) / self.scale_ for rec in records]
        return _finite(np.concatenate(parts))

    def _jacobian(self, z, records):
        p = len(z)
        step = 1e-6
        Z = np.tile(z, (p + 1, 1))
        Z[1:] += step * np.eye(p)
        cols = []
        for rec in records:
            X = self._simulate(Z, rec) / self.scale_
            cols.append(((X[1:] - X[0]) / step).T)
        return _finite(np.vstack(cols))

    def fit(self, records: list[DCRecord]) -> "DCMotorEstimator":
        _check(records)
        self.names_ = self._names()
        self._nominal = np.array([float(getattr(self.model, n)) for n in self.names_])
        self.scale_ = float(max(np.ptp(r.position) for r in records))
        p = len(self.names_)
        lb, ub = np.full(p, -LOG_BOUND), np.full(p, LOG_BOUND)
        rng = np.random.default_rng(self.random_state)
        Z = rng.uniform(-1.5, 1.5, size=(self.n_screen, p))
        Z[0] = 0.0
        cost = np.zeros(len(Z))
        for rec in records:
            X = self._simulate(Z, rec)
            cost += np.nan_to_num(np.mean((X - rec.position) ** 2, axis=1), nan=np.inf)
        starts = Z[np.argsort(cost)[: self.n_starts]]
        best = None
        for i, z0 in enumerate(starts):
            if self.progress is not None:
                self.progress(i / (len(starts) + 1), f"start {i + 1}/{len(starts)}")
            res = self._solve(z0, records)
            if best is None or res.cost < best.cost:
                best = res
        if self.vibration is not False:
            best = self._with_mount(best, records)
        lb, ub = np.full(len(best.x), -LOG_BOUND), np.full(len(best.x), LOG_BOUND)
        self.success_ = bool(best.success)
        self.message_ = str(best.message)
        if not best.success or best.status == 0:
            warnings.warn(f"DC motor fit did not converge: {best.message}", ConvergenceWarning, stacklevel=2)
        z = self._z = best.x
        values = self._values(z[None, :])[0]
        self.params_ = {n: float(v) for n, v in zip(self.names_, values)}
        J = self._jacobian(z, records)
        r = self._residual(z, records)
        T = np.diag(values)                      # d value / d log-ratio
        self.inflation_ = ess_inflation(r, [len(rec.time) for rec in records])
        self.cov_ = self.inflation_ * (T @ covariance(J, r) @ T.T)
        self.stderr_ = np.sqrt(np.clip(np.diag(self.cov_), 0, None))
        self.corr_ = correlation(self.cov_)
        half = Z95 * self.stderr_
        self.ci95_ = {n: (float(v - h), float(v + h)) for n, v, h in zip(self.names_, values, half)}
        at_bound = (np.abs(z - lb) < 1e-3) | (np.abs(z - ub) < 1e-3)
        self.warnings_ = identifiability(self.names_, values, half, self.corr_, at_bound)
        simulated = [self._simulate(z, rec)[0] for rec in records]
        self.warnings_ += residual_structure([(rec.time, y - rec.position, y) for rec, y in zip(records, simulated)])
        self.model_ = self.model.replace(**{n: v for n, v in self.params_.items() if n not in MOUNT_NAMES})
        self.nrmse_ = {rec.name: nrmse(rec.position, self.predict(rec)) for rec in records}
        if self.progress is not None:
            self.progress(1.0, "done")
        return self

    def _solve(self, z0, records):
        p = len(z0)
        return least_squares(self._residual, z0, jac=self._jacobian, bounds=(np.full(p, -LOG_BOUND),
                             np.full(p, LOG_BOUND)), args=(records,), method="trf", x_scale=1.0,
                             max_nfev=self.max_nfev, ftol=1e-12, xtol=1e-12)

    def _with_mount(self, best, records):
        """The fit with a sensor-mount vibration added (module docstring),
        started at the strongest line of the plain fit's residual, the
        gain solved by least squares there; ``best`` if it does not lower
        the cost (or no line is found and vibration was not asked for)."""
        sims = [self._simulate(best.x, rec)[0] for rec in records]
        found = spectrum.lines([(rec.time, rec.position - y) for rec, y in zip(records, sims)], sims)
        if not found and not self.vibration:
            return best
        if found:
            freq = found[0][0]
        else:                                   # asked for: the residual's periodogram peak
            f, P = spectrum.periodogram(records[0].time, records[0].position - sims[0])
            freq = float(f[1 + int(np.argmax(P[1:]))])
        unit = [mount_response(rec.time, y, freq, MOUNT_DAMPING_START, 1.0) for rec, y in zip(records, sims)]
        gain = sum(float(u @ (rec.position - y)) for u, rec, y in zip(unit, records, sims)) / max(
            sum(float(u @ u) for u in unit), 1e-300)
        if gain <= 0:
            return best
        names, nominal = list(self.names_), self._nominal
        self.names_ = names + list(MOUNT_NAMES)
        self._nominal = np.concatenate([nominal, [freq, MOUNT_DAMPING_START, gain]])
        self._n_mount = len(MOUNT_NAMES)
        res = self._solve(np.concatenate([best.x, np.zeros(len(MOUNT_NAMES))]), records)
        if res.cost < best.cost:
            return res
        self.names_, self._nominal, self._n_mount = names, nominal, 0
        return best

    def predict(self, record: DCRecord) -> np.ndarray:
        """Simulated position (n,) m of a run with the fitted parameters
        (with the fitted sensor-mount vibration, when there is one)."""
        return self._simulate(self._z, record)[0]


def _check(records: list[DCRecord]) -> None:
    require_runs(records)
    for rec in records:
        if np.ptp(rec.reference) == 0.0:
            raise FitError(f"{rec.label}: column reference_m: constant reference; "
                           "the fit needs a step or another change of the reference")
        if np.ptp(rec.position) == 0.0:
            raise FitError(f"{rec.label}: column position_m: the position never moves; nothing to fit")


def _finite(a: np.ndarray) -> np.ndarray:
    return np.clip(np.nan_to_num(a, nan=1e3, posinf=1e3, neginf=-1e3), -1e3, 1e3)
