"""The catalog prior of a Bouc-Wen fit, and what the data determine.

A single record often leaves some Bouc-Wen parameters free (d33 and alpha
enter a one-amplitude loop almost only through d33 + alpha, beta and gamma
trade against each other). The plain least-squares values then wander along
that valley and are no material constants. The rig-ready values therefore
come from a second, regularised fit (maximum a posteriori with a Gaussian
prior on the dimensionless groups of ``physics.bouc_wen.params_to_groups``):

    minimise  sum r_i^2 + s^2 sum_j ((g_j - g_prior_j) / sd_j)^2,
    sd_j = sigma_rel max(|g_prior_j|, 0.1)

with r the weighted, normalised residuals of the plain fit and s^2 their
variance at its optimum (so the data term is the white-noise chi^2).
Where the data determine a group, its posterior sd is far below sd_j and
the prior does not move it; along a flat direction the prior fixes it.
``prior_share`` (posterior variance / prior variance, Laplace
approximation) says which it is: near 0 from the data, near 1 from the
prior. The posterior (intervals, shares) counts the data with the plain
fit's AR(1) interval inflation, (1 + rho) / (1 - rho), as its intervals do;
the point itself weighs the prior against the white chi^2.

Where the prior comes from (pure numbers; the workflow reads the catalog):
- ``transfer_prior``: a catalog stack's Bouc-Wen parameters carried to
  other scales in normalised form (docs/models.md, corrections to the seed, item 4), e.g. the seed's
  Table 1 (thorlabs-pk4ga7p1, 100 um at 150 V) onto the measured record's
  displacement and voltage ranges when no stack is named.
"""
from __future__ import annotations

import copy
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from ..physics.bouc_wen import BoucWen, groups_jacobian, groups_to_params, params_to_groups, transfer
from ..sim.signals import nrmse
from .common import Z95

PRIOR_FLOOR = 0.1   # groups are of order one; a prior value near 0 still gets sd = sigma_rel x 0.1


@dataclass
class Regularised:
    """The MAP fit: parameters, states and how much of each came from the prior."""

    params: BoucWen
    h0: dict
    offset: dict
    prior: np.ndarray          # (6,) physical prior values
    prior_share: np.ndarray    # (6,) posterior / prior variance, 0 = data, 1 = prior
    nrmse: dict                # per training run
    cov: np.ndarray            # (6, 6) posterior covariance of the physical parameters (Laplace)
    estimator: object = field(default=None, repr=False)   # a BoucWenEstimator holding these values (predict)


def transfer_prior(params: BoucWen, source_stroke: float, source_voltage: float,
                   target_stroke: float, target_voltage: float) -> np.ndarray:
    """Physical prior (6,) for a stack of stroke ``target_stroke`` over the
    voltage range ``target_voltage``: the same dimensionless loop."""
    return transfer(params, source_stroke, source_voltage, target_stroke, target_voltage).as_array()


def regularise(est, records, prior: np.ndarray, sigma_rel: float, lb: np.ndarray, ub: np.ndarray) -> Regularised:
    """MAP refit of a fitted BoucWenEstimator ``est`` toward ``prior``."""
    H, V = est.scales_
    g_prior = params_to_groups(prior, H, V)
    sd = sigma_rel * np.maximum(np.abs(g_prior), PRIOR_FLOOR)
    s = max(est.noise_, 1e-12)
    n_z = len(est.z_)
    rows = np.zeros((6, n_z))
    rows[:, :6] = np.diag(s / sd)

    def residual(z):
        return np.concatenate([est._residual(z, records), s * (z[:6] - g_prior) / sd])

    def jacobian(z):
        return np.vstack([est._jacobian(z, records), rows])

    inner = lb + 1e-9 * (ub - lb), ub - 1e-9 * (ub - lb)
    from_prior = est.z_.copy()
    from_prior[:6] = g_prior
    best = None
    for z0 in (est.z_, np.clip(from_prior, *inner)):
        res = least_squares(residual, z0, jac=jacobian, bounds=(lb, ub), method="trf", x_scale="jac",
                            max_nfev=est.max_nfev, ftol=1e-12, xtol=1e-12, gtol=1e-10)
        if best is None or res.cost < best.cost:
            best = res
    z = best.x
    J = est._jacobian(z, records)
    precision = J.T @ J / (s ** 2 * est.interval_inflation_)     # coloured residuals: see BoucWenEstimator
    precision[:6, :6] += np.diag(1.0 / sd ** 2)
    posterior = np.linalg.pinv(precision)
    share = np.clip(np.diag(posterior)[:6] * (1.0 / sd ** 2), 0.0, 1.0)
    g, h0, off = est._unpack(z)
    fitted = copy.copy(est)
    fitted.params_ = BoucWen.from_array(groups_to_params(g, H, V))
    fitted.h0_ = {r.name: float(h) for r, h in zip(records, h0)}
    fitted.offset_ = {r.name: float(o) for r, o in zip(records, off)}
    fitted.regularised_ = None
    result = Regularised(params=fitted.params_, h0=fitted.h0_, offset=fitted.offset_, prior=np.asarray(prior, float),
                         prior_share=share, nrmse={r.name: nrmse(r.position, fitted.predict(r)) for r in records},
                         cov=(T := groups_jacobian(g, H, V)) @ posterior[:6, :6] @ T.T, estimator=fitted)
    return result


def combinations(theta: np.ndarray, cov: np.ndarray) -> dict:
    """What one record determines even when the raw parameters are not:
    value, 95 % interval (linearised, from the plain fit's covariance) and
    relative half-width of
    - small_signal_slope_m_V = d33 + alpha (dx/dv at h = 0, eq. 1-2),
    - beta_plus_gamma and gamma_minus_beta: the |h|^n coefficients of the
      branch where v' and h share their sign and of the other branch,
    - beta_over_gamma: the loop's asymmetry."""
    d33, alpha, beta, gamma = theta[:4]
    grads = {
        "small_signal_slope_m_V": (d33 + alpha, np.array([1.0, 1.0, 0, 0, 0, 0])),
        "beta_plus_gamma": (beta + gamma, np.array([0, 0, 1.0, 1.0, 0, 0])),
        "gamma_minus_beta": (gamma - beta, np.array([0, 0, -1.0, 1.0, 0, 0])),
        "beta_over_gamma": (beta / gamma if gamma != 0 else float("inf"),
                            np.array([0, 0, 1.0 / gamma, -beta / gamma ** 2, 0, 0]) if gamma != 0 else np.full(6, np.inf)),
    }
    out = {}
    for name, (value, grad) in grads.items():
        with np.errstate(invalid="ignore"):
            half = Z95 * float(np.sqrt(max(grad @ cov @ grad, 0.0))) if np.all(np.isfinite(grad)) else float("inf")
        out[name] = {"value": float(value), "ci95": [float(value - half), float(value + half)],
                     "relative_half_width": float(half / abs(value)) if value else float("inf")}
    return out
