"""Estimator of the Prandtl-Ishlinskii model (sizing.physics.prandtl_ishlinskii).

The model is linear in its weights, so the fit is a quadratic program:
    minimise  sum_runs ||Y_k w + c_k - x_k||^2 / H^2 + ridge ||w V / H||^2
    subject to w >= 0,
with Y_k the play-operator outputs of run k (thresholds on an even grid
from 0 to half the voltage range), c_k a free offset per run and H, V the
displacement and voltage scales. Solved with cvxpy after a QR compression
of the (large) regression matrix, so the problem has only n_r + n_runs
variables and rows. The same low-pass of the measured voltage as for the
Bouc-Wen fit drives the operators.

Initial state: a run rarely starts in the model's rest state, so each run's
operator states start at y_r(0) = clip(u, v0 - r, v0 + r), with u the
input's last turning point before the record (u = 0 and v0 = 0: the virgin
state; u = the far extreme: the periodic steady state). u is fitted per run
by a grid search with the weights held, alternating with the QP (three
passes); a run not used in the fit gets u and its offset the same way.
"""
from __future__ import annotations

import warnings

import cvxpy as cp
import numpy as np

from ..errors import FitError
from ..physics import prandtl_ishlinskii as pi
from ..sim.signals import nrmse
from .common import (ConvergenceWarning, HysteresisRecord, check_hysteresis_records, filter_inputs, residual_structure,
                     run_weights)


class PrandtlIshlinskiiEstimator:
    """Fit non-negative play-operator weights.

    Parameters
    ----------
    n_operators : thresholds r_i = i R / n_operators, i = 0..n-1, with R
        half the voltage range of the training runs.
    ridge : relative Tikhonov weight on the (scaled) weights.
    cutoff_hz : low-pass of the voltage as for BoucWenEstimator.
    fit_offset : a sensor offset per run (default); False holds it at 0.
    fit_state : fit each run's initial state u (default); False uses
        ``physics.prandtl_ishlinskii.initial_state``.
    """

    def __init__(self, n_operators: int = 16, ridge: float = 1e-8, cutoff_hz: float | None = None,
                 fit_offset: bool = True, fit_state: bool = True, passes: int = 3):
        self.n_operators = n_operators
        self.ridge = ridge
        self.cutoff_hz = cutoff_hz
        self.fit_offset = fit_offset
        self.fit_state = fit_state
        self.passes = passes

    def fit(self, records: list[HysteresisRecord]) -> "PrandtlIshlinskiiEstimator":
        self.cutoff_hz_ = dict(zip([r.name for r in records], filter_inputs(records, self.cutoff_hz)))
        check_hysteresis_records(records)
        v_all = np.concatenate([r.voltage_filtered for r in records])
        H = float(max(np.ptp(r.position) for r in records))
        V = float(np.max(np.abs(v_all))) or 1.0
        half_range = 0.5 * float(np.ptp(v_all))
        self.thresholds_ = np.arange(self.n_operators) * half_range / self.n_operators
        self.scales_ = (H, V)
        self.y0_ = {r.name: pi.initial_state(r.voltage_filtered, self.thresholds_) for r in records}
        self.memory_ = {r.name: None for r in records}
        for _ in range(self.passes if self.fit_state else 1):
            sol, problem = self._solve(records, weights=run_weights(records))
            self.weights_ = np.clip(sol[:self.n_operators], 0.0, None) * H / V        # m/V, projected onto w >= 0
            if self.fit_state:
                for rec in records:
                    self.memory_[rec.name], self.y0_[rec.name], _ = self._best_state(rec)
        sol, problem = self._solve(records, weights=run_weights(records))
        self.success_ = problem.status == cp.OPTIMAL
        self.message_ = str(problem.status)
        if not self.success_:
            warnings.warn(f"Prandtl-Ishlinskii QP ended {problem.status}", ConvergenceWarning, stacklevel=2)
        self.weights_ = np.clip(sol[:self.n_operators], 0.0, None) * H / V
        self.offset_ = {r.name: float(c * H) for r, c in zip(records, sol[self.n_operators:])}
        predicted = [self.predict(r) for r in records]
        self.nrmse_ = {r.name: nrmse(r.position, y) for r, y in zip(records, predicted)}
        self.residual_rms_ = float(np.sqrt(np.mean(np.concatenate(
            [(r.position - y) ** 2 for r, y in zip(records, predicted)]))))
        self.warnings_ = residual_structure([(r.time, y - r.position, y) for r, y in zip(records, predicted)])
        return self

    def _solve(self, records, weights):
        """The QP over weights and offsets with the current initial states."""
        H, V = self.scales_
        K, N = len(records), self.n_operators
        blocks, targets = [], []
        for k, rec in enumerate(records):
            Y = pi.play_operators(rec.voltage_filtered, self.thresholds_, self.y0_[rec.name]) / V   # scaled by V
            C = np.zeros((len(Y), K))
            C[:, k] = 1.0
            blocks.append(np.hstack([Y, C]) * weights[k])
            targets.append(rec.position / H * weights[k])
        M = np.vstack(blocks)
        y = np.concatenate(targets)
        Q, R = np.linalg.qr(M)
        qy = Q.T @ y
        z = cp.Variable(N + K)
        objective = cp.sum_squares(R @ z - qy) + self.ridge * len(y) * cp.sum_squares(z[:N])
        constraints = [z[:N] >= 0] + ([] if self.fit_offset else [z[N:] == 0])
        problem = cp.Problem(cp.Minimize(objective), constraints)
        try:
            problem.solve(solver=cp.CLARABEL)
        except cp.error.SolverError:
            problem.solve(solver=cp.OSQP, eps_abs=1e-10, eps_rel=1e-10, max_iter=200000)
        if z.value is None:
            raise FitError(f"Prandtl-Ishlinskii QP failed: {problem.status}")
        return np.asarray(z.value, float), problem

    def _best_state(self, record: HysteresisRecord):
        """(u, y0, offset) minimising the run's squared error with the weights
        held: u on a grid over the input range widened by the largest
        threshold, plus the steady-state guess."""
        v = record.voltage_filtered
        r = self.thresholds_
        reach = float(r[-1]) if len(r) else 0.0
        grid = np.concatenate([np.linspace(v.min() - reach, v.max() + reach, 81), [0.0, v.min(), v.max()]])
        candidates = [(u, np.clip(u, v[0] - r, v[0] + r)) for u in grid]
        candidates.append((None, pi.initial_state(v, r)))
        best = None
        for u, y0 in candidates:
            x = pi.play_operators(v, r, y0) @ self.weights_
            off = float(np.mean(record.position - x)) if self.fit_offset else 0.0
            cost = float(np.mean((record.position - x - off) ** 2))
            if best is None or cost < best[0]:
                best = (cost, u, y0, off)
        return best[1], best[2], best[3]

    def predict(self, record: HysteresisRecord, offset: float | None = None) -> np.ndarray:
        """Displacement (n,) m; a run not in the fit gets its initial state
        and offset fitted with the weights held (conditions of the run, not
        model parameters)."""
        if record.voltage_filtered is None:
            filter_inputs([record], self.cutoff_hz)
        if record.name in self.y0_ and len(self.y0_[record.name]) == len(self.thresholds_) \
                and record.name in getattr(self, "offset_", {}):
            y0, off = self.y0_[record.name], self.offset_[record.name]
        elif self.fit_state:
            _, y0, off = self._best_state(record)
        else:
            y0 = pi.initial_state(record.voltage_filtered, self.thresholds_)
            x = pi.displacement(record.voltage_filtered, self.thresholds_, self.weights_, y0=y0)
            off = float(np.mean(record.position - x)) if self.fit_offset else 0.0
        x = pi.displacement(record.voltage_filtered, self.thresholds_, self.weights_, y0=y0)
        return x + (off if offset is None else offset)
