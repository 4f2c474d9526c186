"""Estimator of the seed's non-symmetric Bouc-Wen model (eqs. 1-2, Table 1)
from voltage/displacement records.

Model (sizing.physics.bouc_wen, as the seed writes it):
    x = d33 v + h + offset,
    dh = {alpha - [beta sgn(v' h) + gamma] |h|^n} dv + delta v sgn(v') dt.

How the fit works
- Scaling: the raw parameters span 1e-8..1, so the solver works on the
  dimensionless groups of ``physics.bouc_wen.params_to_groups`` with the stroke
  scale H = peak-to-peak of the measured displacement and the voltage scale
  V = the largest |voltage|: [d33/d, alpha/d, beta H^n/d, gamma H^n/d,
  delta/d, n] with d = H/V. They are all of order one.
- Initial state: each run gets its own initial hysteresis state h0 (a run
  cut from a longer record starts mid-loop) and, by default, its own sensor
  offset; both are fitted with the parameters and reported. Runs may have
  different sample rates: each run's residuals are weighted by
  sqrt(dt_k / mean dt) so the cost is an integral over time.
- Input: the measured voltage is low-passed on purpose (zero phase, cut-off
  from the record's sample rate and excitation: common.fit_cutoff) before
  it drives the model, so that sensor noise cannot ratchet h.
- Solver: scipy ``least_squares`` (trust region, bounds from physics:
  d33 > 0, 0.5 <= n <= 5, the groups within +/-20..100). Many seeded random
  starts are screened in one batch simulation; the best few are refined.
  The Jacobian is a forward difference computed with the batch simulator
  (all perturbed parameter sets of a run in one call).
- Uncertainty: covariance s^2 (J^T J)^-1 from the Jacobian at the optimum,
  mapped to physical units, times (1 + rho) / (1 - rho) with rho the lag-1
  correlation of the residuals (AR(1) effective sample size: model error on
  a real record is smooth, not white); 95 % intervals +/- 1.96 sigma. A parameter that is
  at a bound, strongly correlated (|r| > 0.95) with another, or has an
  interval wider than itself gets an IdentifiabilityWarning, and so do
  residuals holding a structure the model lacks (a spectral line common to
  the runs, a trend: common.residual_structure), which the intervals
  assume absent.
- Prior (optional, ``prior=``): a second, regularised fit (fit.prior) pulls
  the groups toward catalog values where the data leave them free; it is
  stored beside the plain least-squares result, never instead of it.
"""
from __future__ import annotations

import warnings

import numpy as np
from scipy.optimize import least_squares

from ..errors import FitError
from ..physics.bouc_wen import (BoucWen, free_displacement, groups_jacobian, groups_to_params,
                                params_to_groups)  # noqa: F401  (params_to_groups: for callers of the estimator)
from ..sim.signals import nrmse
from .common import (Z95, ConvergenceWarning, HysteresisRecord, IdentifiabilityWarning, check_hysteresis_records, correlation,
                     covariance, ess_inflation, fd_columns, filter_inputs, identifiability, lag1_correlation,
                     residual_structure, run_weights)
from .prior import regularise

PARAM_NAMES = ("d33", "alpha", "beta", "gamma", "delta", "n")
# bounds of the dimensionless groups (physics: d33 > 0, n of order one)
GROUP_BOUNDS = np.array([[1e-3, 20.0], [-20.0, 20.0], [-100.0, 100.0], [-100.0, 100.0],
                         [-50.0, 50.0], [0.5, 5.0]])
# where random starting points are drawn
START_BOX = np.array([[0.5, 2.0], [-1.0, 0.5], [-2.0, 10.0], [-2.0, 10.0], [-0.5, 0.5], [0.8, 2.5]])
STATE_BOUND = 2.0   # |h0| and |offset| up to twice the stroke


class BoucWenEstimator:
    """Fit (d33, alpha, beta, gamma, delta, n) of seed eq. 1-2 to records.

    Parameters
    ----------
    n_starts : starting points refined by least squares (best of the screen).
    n_screen : seeded random starting points screened in one batch.
    random_state : seed of the starting points.
    cutoff_hz : low-pass cut-off of the voltage (Hz); None chooses it from the
        excitation, 0 disables the filter.
    fit_offset : also fit a constant sensor offset per run (default: yes;
        real sensors carry one).
    max_nfev : function evaluations per start.
    progress : optional callable(fraction done, message).
    prior : optional (6,) physical parameters to regularise toward
        (fit.prior.regularise); the result is ``regularised_``.
    prior_sigma : relative 1-sigma of the prior on each group.
    """

    def __init__(self, n_starts: int = 4, n_screen: int = 96, random_state: int = 0,
                 cutoff_hz: float | None = None, fit_offset: bool = True, max_nfev: int = 200,
                 progress=None, prior=None, prior_sigma: float = 0.5):
        self.n_starts = n_starts
        self.n_screen = n_screen
        self.random_state = random_state
        self.cutoff_hz = cutoff_hz
        self.fit_offset = fit_offset
        self.max_nfev = max_nfev
        self.progress = progress
        self.prior = prior
        self.prior_sigma = prior_sigma

    # ---- model evaluation -------------------------------------------------
    def _unpack(self, z):
        K = self._n_runs
        h0 = z[6:6 + K] * self.scales_[0]
        off = z[6 + K:6 + 2 * K] * self.scales_[0] if self.fit_offset else np.zeros(K)
        return z[:6], h0, off

    def _residual(self, z, records):
        g, h0, off = self._unpack(z)
        theta = groups_to_params(g, *self.scales_)
        parts = []
        for k, rec in enumerate(records):
            x = free_displacement(rec.time, rec.voltage_filtered, theta[None, :], np.array([h0[k]]))[0]
            parts.append((x + off[k] - rec.position) * (self._weights[k] / self.scales_[0]))
        return _finite(np.concatenate(parts))

    def _jacobian(self, z, records):
        H = self.scales_[0]
        K = self._n_runs
        g, h0, off = self._unpack(z)
        steps = 1e-6 * np.maximum(np.abs(g), 1e-2)
        Z = np.tile(g, (8, 1))
        Z[1:7] += np.diag(steps)
        P = groups_to_params(Z, *self.scales_)
        n_par = len(z)
        rows = []
        for k, rec in enumerate(records):
            dh = 1e-6
            H0 = np.full(8, h0[k])
            H0[7] += dh * H
            X = free_displacement(rec.time, rec.voltage_filtered, P, H0) / H
            J = np.zeros((len(rec.time), n_par))
            J[:, :6] = fd_columns(X[0], X[1:7], steps)
            J[:, 6 + k] = (X[7] - X[0]) / dh
            if self.fit_offset:
                J[:, 6 + K + k] = 1.0
            rows.append(J * self._weights[k])
        return _finite(np.vstack(rows))

    # ---- fitting ----------------------------------------------------------
    def fit(self, records: list[HysteresisRecord]) -> "BoucWenEstimator":
        self.cutoff_hz_ = dict(zip([r.name for r in records], filter_inputs(records, self.cutoff_hz)))
        check_hysteresis_records(records)
        self._n_runs = K = len(records)
        self._weights = run_weights(records)
        H = float(max(np.ptp(r.position) for r in records))
        V = float(max(np.max(np.abs(r.voltage_filtered)) for r in records))
        self.scales_ = (H, V)
        n_par = 6 + K * (2 if self.fit_offset else 1)
        lb = np.concatenate([GROUP_BOUNDS[:, 0], np.full(n_par - 6, -STATE_BOUND)])
        ub = np.concatenate([GROUP_BOUNDS[:, 1], np.full(n_par - 6, STATE_BOUND)])
        starts = self._starts(records, lb, ub)
        best, results = None, []
        for i, z0 in enumerate(starts):
            self._report(i / (len(starts) + 1), f"start {i + 1}/{len(starts)}")
            res = least_squares(self._residual, z0, jac=self._jacobian, bounds=(lb, ub), args=(records,),
                                method="trf", x_scale="jac", max_nfev=self.max_nfev,
                                ftol=1e-12, xtol=1e-12, gtol=1e-10)
            results.append(res)
            if best is None or res.cost < best.cost:
                best = res
        self._report(len(starts) / (len(starts) + 1), "uncertainty")
        self.start_costs_ = [float(2 * r.cost) for r in results]
        self.success_ = bool(best.success)
        self.message_ = str(best.message)
        if not best.success or best.status == 0:
            warnings.warn(f"Bouc-Wen fit did not converge: {best.message}", ConvergenceWarning, stacklevel=2)
        self._finish(best, records, lb, ub)
        if self.prior is not None:
            self._report(len(starts) / (len(starts) + 1), "prior")
            self.regularised_ = regularise(self, records, np.asarray(self.prior, float), self.prior_sigma, lb, ub)
        self._report(1.0, "done")
        return self

    def _report(self, fraction, message):
        if self.progress is not None:
            self.progress(fraction, message)

    def _starts(self, records, lb, ub):
        """Seeded random starts, screened in one batch; returns the best few."""
        H, V = self.scales_
        rng = np.random.default_rng(self.random_state)
        v_all = np.concatenate([r.voltage_filtered for r in records])
        x_all = np.concatenate([r.position - r.position.mean() for r in records])
        slope = float(np.polyfit(v_all - v_all.mean(), x_all, 1)[0])
        Z = rng.uniform(START_BOX[:, 0], START_BOX[:, 1], size=(self.n_screen, 6))
        Z[0] = [max(slope / (H / V), 0.05), 0.0, 1.0, 1.0, 0.0, 1.0]
        Z[:, 0] = np.clip(Z[:, 0], GROUP_BOUNDS[0, 0], GROUP_BOUNDS[0, 1])
        P = groups_to_params(Z, H, V)
        cost = np.zeros(len(Z))
        states = []
        for rec in records:
            x = free_displacement(rec.time, rec.voltage_filtered, P, np.zeros(len(Z)))
            # initial state such that the first sample matches (offset zero)
            h0 = rec.position[0] - x[:, 0]
            err = x + h0[:, None] - rec.position[None, :]
            cost += np.nan_to_num(np.mean(err ** 2, axis=1) / H ** 2, nan=np.inf)
            states.append(h0 / H)
        order = np.argsort(cost)[: self.n_starts]
        starts = []
        for c in order:
            z = np.concatenate([Z[c], [s[c] for s in states]])
            if self.fit_offset:
                z = np.concatenate([z, np.zeros(len(records))])
            starts.append(np.clip(z, lb + 1e-9 * (ub - lb), ub - 1e-9 * (ub - lb)))
        return starts

    def _finish(self, res, records, lb, ub):
        H, V = self.scales_
        z = res.x
        self.z_ = z.copy()
        g, h0, off = self._unpack(z)
        theta = groups_to_params(g, H, V)
        self.groups_ = g.copy()
        self.params_ = BoucWen.from_array(theta)
        self.h0_ = {r.name: float(h) for r, h in zip(records, h0)}
        self.offset_ = {r.name: float(o) for r, o in zip(records, off)}
        J = self._jacobian(z, records)
        r = self._residual(z, records)
        # residuals of a real record are coloured (model error is smooth): an
        # AR(1) effective sample size widens the intervals by (1 + rho) / (1 - rho)
        lengths = [len(rec.time) for rec in records]
        self.residual_correlation_ = lag1_correlation(r, lengths)
        self.interval_inflation_ = ess_inflation(r, lengths)
        cov_z = covariance(J, r) * self.interval_inflation_
        T = groups_jacobian(g, H, V)
        self.cov_ = T @ cov_z[:6, :6] @ T.T
        self.stderr_ = np.sqrt(np.clip(np.diag(self.cov_), 0, None))
        self.corr_ = correlation(self.cov_)
        half = Z95 * self.stderr_
        self.ci95_ = {name: (float(theta[i] - half[i]), float(theta[i] + half[i]))
                      for i, name in enumerate(PARAM_NAMES)}
        span = ub[:6] - lb[:6]
        at_bound = (np.abs(g - lb[:6]) < 1e-4 * span) | (np.abs(g - ub[:6]) < 1e-4 * span)
        self.at_bound_ = {name: bool(b) for name, b in zip(PARAM_NAMES, at_bound)}
        self.warnings_ = identifiability(list(PARAM_NAMES), theta, half, self.corr_, at_bound)
        states_at_bound = [r.name for r, h in zip(records, h0) if abs(h) > 0.999 * STATE_BOUND * H]
        if states_at_bound:
            message = (f"initial state h0 of {', '.join(states_at_bound)} is at its bound ({STATE_BOUND:g} x the "
                       "stroke): the loop lives on one side of h = 0 and the fit is a curve fit of this record")
            warnings.warn(message, IdentifiabilityWarning, stacklevel=3)
            self.warnings_.append(message)
        self.noise_ = float(np.sqrt(r @ r / max(len(r) - len(z), 1)))     # normalised residual sigma
        self.residual_rms_ = float(np.sqrt(np.mean(r ** 2)) * H)
        predicted = [self.predict(rec) for rec in records]
        self.warnings_ += residual_structure([(rec.time, y - rec.position, y) for rec, y in zip(records, predicted)])
        self.nrmse_ = {rec.name: nrmse(rec.position, y) for rec, y in zip(records, predicted)}

    # ---- use --------------------------------------------------------------
    def predict(self, record: HysteresisRecord, h0: float | None = None, offset: float | None = None) -> np.ndarray:
        """Displacement (n,) m of a record; its initial state is the fitted one
        for a training run, else estimated (``initial_state``)."""
        if record.voltage_filtered is None:
            filter_inputs([record], self.cutoff_hz)
        if h0 is None or offset is None:
            if record.name in self.h0_ and len(record.time) == len(record.position):
                h0_fit, off_fit = self.h0_[record.name], self.offset_[record.name]
            else:
                h0_fit, off_fit = self.initial_state(record)
            h0 = h0_fit if h0 is None else h0
            offset = off_fit if offset is None else offset
        x = free_displacement(record.time, record.voltage_filtered, self.params_, h0)
        return x + offset

    def initial_state(self, record: HysteresisRecord) -> tuple[float, float]:
        """(h0, offset) of a run not used in the fit, with the parameters held:
        the state is a condition of the run, not a parameter of the model."""
        if record.voltage_filtered is None:
            filter_inputs([record], self.cutoff_hz)
        H = self.scales_[0]
        theta = self.params_.as_array()[None, :]

        def resid(s):
            x = free_displacement(record.time, record.voltage_filtered, theta, np.array([s[0] * H]))[0]
            return _finite((x + (s[1] * H if self.fit_offset else 0.0) - record.position) / H)

        x0 = free_displacement(record.time, record.voltage_filtered, theta, np.zeros(1))[0]
        s0 = np.array([np.clip((record.position[0] - x0[0]) / H, -1.9, 1.9), 0.0])
        lb, ub = [-STATE_BOUND, -STATE_BOUND if self.fit_offset else -1e-12], \
                 [STATE_BOUND, STATE_BOUND if self.fit_offset else 1e-12]
        s0[1] = 0.0
        res = least_squares(resid, s0, bounds=(lb, ub), diff_step=1e-6, max_nfev=100)
        return float(res.x[0] * H), float(res.x[1] * H if self.fit_offset else 0.0)


def _finite(a: np.ndarray) -> np.ndarray:
    """Keep the solver going through diverged trial points."""
    return np.clip(np.nan_to_num(a, nan=1e3, posinf=1e3, neginf=-1e3), -1e3, 1e3)


def check_fitted(est) -> None:
    if not hasattr(est, "params_"):
        raise FitError("the estimator has not been fitted yet")
