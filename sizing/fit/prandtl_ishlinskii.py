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
"""
from __future__ import annotations

import warnings

import cvxpy as cp
import numpy as np

from ..errors import FitError
from ..physics import prandtl_ishlinskii as pi
from ..sim.signals import nrmse
from .common import ConvergenceWarning, HysteresisRecord, check_hysteresis_records, filter_inputs


class PrandtlIshlinskiiEstimator:
    """Fit non-negative play-operator weights.

    Parameters
    ----------
    n_operators : thresholds r_i = i R / n_operators, i = 0..n-1, with R
        half the voltage range of the training runs.
    ridge : relative Tikhonov weight on the (scaled) weights.
    cutoff_hz : low-pass of the voltage as for BoucWenEstimator.
    """

    def __init__(self, n_operators: int = 16, ridge: float = 1e-8, cutoff_hz: float | None = None):
        self.n_operators = n_operators
        self.ridge = ridge
        self.cutoff_hz = cutoff_hz

    def fit(self, records: list[HysteresisRecord]) -> "PrandtlIshlinskiiEstimator":
        self.cutoff_hz_ = dict(zip([r.name for r in records], filter_inputs(records, self.cutoff_hz)))
        check_hysteresis_records(records)
        v_all = np.concatenate([r.voltage_filtered for r in records])
        H = float(max(np.ptp(r.position) for r in records))
        V = float(np.max(np.abs(v_all))) or 1.0
        half_range = 0.5 * float(np.ptp(v_all))
        self.thresholds_ = np.arange(self.n_operators) * half_range / self.n_operators
        K, N = len(records), self.n_operators
        blocks, targets = [], []
        for k, rec in enumerate(records):
            Y = pi.play_operators(rec.voltage_filtered, self.thresholds_) / V     # scaled by V
            C = np.zeros((len(Y), K))
            C[:, k] = 1.0
            blocks.append(np.hstack([Y, C]))
            targets.append(rec.position / H)
        M = np.vstack(blocks)
        y = np.concatenate(targets)
        Q, R = np.linalg.qr(M)
        qy = Q.T @ y
        z = cp.Variable(N + K)
        objective = cp.sum_squares(R @ z - qy) + self.ridge * len(y) * cp.sum_squares(z[:N])
        problem = cp.Problem(cp.Minimize(objective), [z[:N] >= 0])
        try:
            problem.solve(solver=cp.CLARABEL)
        except cp.error.SolverError:
            problem.solve(solver=cp.OSQP, eps_abs=1e-10, eps_rel=1e-10, max_iter=200000)
        if z.value is None:
            raise FitError(f"Prandtl-Ishlinskii QP failed: {problem.status}")
        self.success_ = problem.status == cp.OPTIMAL
        self.message_ = str(problem.status)
        if not self.success_:
            warnings.warn(f"Prandtl-Ishlinskii QP ended {problem.status}", ConvergenceWarning, stacklevel=2)
        sol = np.asarray(z.value, float)
        self.weights_ = np.clip(sol[:N], 0.0, None) * H / V        # m/V, projected onto w >= 0
        self.offset_ = {r.name: float(c * H) for r, c in zip(records, sol[N:])}
        self.scales_ = (H, V)
        self.nrmse_ = {r.name: nrmse(r.position, self.predict(r)) for r in records}
        self.residual_rms_ = float(np.sqrt(np.mean(np.concatenate(
            [(r.position - self.predict(r)) ** 2 for r in records]))))
        return self

    def predict(self, record: HysteresisRecord, offset: float | None = None) -> np.ndarray:
        """Displacement (n,) m; a run not in the fit gets its offset as the
        mean residual (an initial condition, not a model parameter)."""
        if record.voltage_filtered is None:
            filter_inputs([record], self.cutoff_hz)
        x = pi.displacement(record.voltage_filtered, self.thresholds_, self.weights_)
        if offset is None:
            offset = self.offset_.get(record.name)
            if offset is None:
                offset = float(np.mean(record.position - x))
        return x + offset
