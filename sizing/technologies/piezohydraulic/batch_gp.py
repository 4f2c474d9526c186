"""The sizing program (``convex.Program``) solved for many combinations at
once: a primal-dual interior-point method in numpy over every row.

In the logarithms y of its variables a geometric program is convex:
minimise sum_j lse(a_jk . y + b_jk) subject to lse(a_ik . y + b_ik) <= 0,
with lse the log-sum-exp of a posynomial's terms and b the logarithms of
each term's coefficient and parameters (``posynomial.Layout``). Every
combination has the same exponents a and only its own b, so one Newton
system per row, ten unknowns, is assembled and solved for all rows with a
handful of array operations per iteration (Boyd and Vandenberghe, Convex
Optimization, sections 4.5 and 11.7: the primal-dual method, here with
slacks s = -g(y) so that the start need not be feasible).

A row is *certified* when its point meets every constraint within
``FEASIBILITY`` (log terms), its Lagrangian's gradient is below
``STATIONARITY`` and the duality gap sum_i z_i s_i below ``GAP``: its
objective is then within GAP of the optimum (relative, the objective
being a logarithm). Rows not certified (infeasible parts, or a row the
method did not finish) are left to Clarabel, one at a time
(``convex.GPSizer``), which stays the reference.

Which rows an iteration's products hold together is part of the answer:
a BLAS product's last bit depends on the rows it holds (one row's
gradient changes between batches of 128 and 129 rows), so rows leave the
batch only when certified or given up, and grouping them otherwise would
change the answers' bits. The rows left after the last certifiable one
keep iterating until given up: there is no cheap proof that a row cannot
certify (its multipliers leave the objective's gradient uncancelled).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .posynomial import Layout

FEASIBILITY = 1e-9       # largest log-constraint value accepted (1e-9 relative on a posynomial <= 1)
STATIONARITY = 1e-8      # largest gradient of the Lagrangian accepted
GAP = 1e-10              # largest duality gap accepted (the log objective's distance to the optimum)
MAX_ITERATIONS = 100
STEP_TO_BOUNDARY = 0.99  # of the largest step that keeps s and z positive
BACKTRACK = 0.5
BACKTRACKS = 12          # halvings of a step before the row counts it as stalled
STALLS = 3               # stalled steps before a row is given up
CENTRING = 0.1           # sigma of a plain Newton step (after a stalled one)
REGULARISATION = 1e-12   # on the Newton matrix's diagonal: the epigraph variables leave it singular at the optimum
SUFFICIENT = 0.01        # the residual falls by at least this fraction of the step


@dataclass(frozen=True)
class Program:
    """A geometric program's exponents: the objective's factors and the
    constraints (each posynomial <= 1), over ``variables`` and ``parameters``."""

    objective: Layout
    constraints: Layout
    variables: tuple
    parameters: tuple

    def offsets(self, log_parameters: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """b: each term's log coefficient for every row (rows x terms)."""
        return (log_parameters @ self.objective.parameter_powers.T + self.objective.log_coefficient,
                log_parameters @ self.constraints.parameter_powers.T + self.constraints.log_coefficient)


@dataclass
class Solution:
    y: np.ndarray             # (rows, variables): the logarithms of the variables
    z: np.ndarray             # (rows, constraints): the multipliers
    certified: np.ndarray     # (rows,) bool
    iterations: int
    at: np.ndarray = None     # (rows,) the iteration each row was certified at


class _Posynomials:
    """lse of each posynomial of a layout at y: value, gradient and, weighted
    by w per posynomial, the sum of their Hessians."""

    def __init__(self, layout: Layout):
        self.layout = layout
        a = layout.variable_powers
        terms, n, m = a.shape[0], a.shape[1], layout.size
        self.outer = (a[:, :, None] * a[:, None, :]).reshape(terms, -1)      # a_k a_k^T, flattened
        self.member = np.zeros((terms, m))                                   # term k -> its posynomial
        self.member[np.arange(terms), layout.group] = 1.0
        spread = np.zeros((terms, m, n))                                     # a_k in its posynomial's row
        spread[np.arange(terms), layout.group] = a
        self.spread = spread.reshape(terms, m * n)

    def evaluate(self, y: np.ndarray, b: np.ndarray, value: bool = True):
        """lse of each posynomial (None when not ``value``), its gradient and
        each term's share of its posynomial. ``take`` and the in-place
        operations compute what fancy indexing and fresh arrays would, bit for
        bit, with fewer allocations: the backtracking calls this thousands of
        times on a few rows."""
        L = self.layout
        e = y @ L.variable_powers.T + b                               # (rows, terms)
        top = np.maximum.reduceat(e, L.starts, axis=1)
        e -= top.take(L.group, axis=1)
        w = np.exp(e, out=e)
        total = w @ self.member
        w /= total.take(L.group, axis=1)                              # each term's share of its posynomial
        grad = (w @ self.spread).reshape(len(y), L.size, -1)          # (rows, m, n)
        return (top + np.log(total) if value else None), grad, w

    def hessian(self, w: np.ndarray, grad: np.ndarray, weight: np.ndarray) -> np.ndarray:
        """sum_i weight_i (sum_k w_k a_k a_k^T - grad_i grad_i^T)."""
        n = grad.shape[2]
        first = ((weight[:, self.layout.group] * w) @ self.outer).reshape(-1, n, n)
        return first - np.matmul((grad * weight[:, :, None]).transpose(0, 2, 1), grad)


def solve(program: Program, log_parameters: np.ndarray, y0: np.ndarray,
          max_iterations: int = MAX_ITERATIONS) -> Solution:
    """The optimum of ``program`` for every row of ``log_parameters`` (rows x
    parameters), from the start y0 (rows x variables, need not be feasible).
    Each step is Mehrotra's predictor-corrector on the Newton system of the
    perturbed KKT conditions, damped until the residual falls; a row whose
    residual stops falling (infeasible parts) is given up, uncertified."""
    obj, con = _Posynomials(program.objective), _Posynomials(program.constraints)
    b_obj, b_con = program.offsets(log_parameters)
    rows = len(log_parameters)
    y = np.array(y0, dtype=float, copy=True)
    g, _, _ = con.evaluate(y, b_con)
    s = np.maximum(-g, 1.0)
    z = 1.0 / s
    certified = np.zeros(rows, dtype=bool)
    at = np.zeros(rows, dtype=int)
    stalled = np.zeros(rows, dtype=int)
    active = np.arange(rows)
    it = 0
    for it in range(1, max_iterations + 1):
        ya, sa, za, bo, bc = y[active], s[active], z[active], b_obj[active], b_con[active]
        _, G0, w0 = obj.evaluate(ya, bo, value=False)
        g, J, w = con.evaluate(ya, bc)
        r_d = G0.sum(axis=1) + np.einsum("rm,rmn->rn", za, J)
        r_p = g + sa
        done = ((g.max(axis=1) <= FEASIBILITY) & (np.abs(r_d).max(axis=1) <= STATIONARITY)
                & ((sa * za).sum(axis=1) <= GAP))
        certified[active[done]] = True
        at[active[done]] = it
        keep = ~done & (stalled[active] < STALLS)
        if not keep.any():
            break
        active, ya, sa, za, bo, bc = active[keep], ya[keep], sa[keep], za[keep], bo[keep], bc[keep]
        G0, w0, g, J, w, r_d, r_p = G0[keep], w0[keep], g[keep], J[keep], w[keep], r_d[keep], r_p[keep]
        H = (obj.hessian(w0, G0, np.ones(G0.shape[:2])) + con.hessian(w, J, za)
             + np.matmul((J * (za / sa)[:, :, None]).transpose(0, 2, 1), J))
        H += REGULARISATION * np.eye(H.shape[1])

        def newton(r_c):
            rhs = -r_d - np.einsum("rmn,rm->rn", J, (za * r_p - r_c) / sa)
            dy = np.linalg.solve(H, rhs[:, :, None])[:, :, 0]
            ds = -r_p - np.einsum("rmn,rn->rm", J, dy)
            return dy, ds, (-r_c - za * ds) / sa

        mu = (sa * za).mean(axis=1)
        _, ds, dz = newton(sa * za)                                   # predictor: the affine step
        a = np.minimum(1.0, np.minimum(_to_boundary(sa, ds), _to_boundary(za, dz)))
        sigma = np.clip((((sa + a[:, None] * ds) * (za + a[:, None] * dz)).mean(axis=1) / mu) ** 3, 0.0, 1.0)
        # the corrector; a row whose last step stalled takes the plain
        # Newton step to a fixed centring instead, a descent direction of
        # the residual the step is damped on
        plain = stalled[active] > 0
        sigma[plain] = CENTRING
        target = sigma * mu
        r_c = sa * za + np.where(plain[:, None], 0.0, ds * dz) - target[:, None]
        dy, ds, dz = newton(r_c)
        alpha = np.minimum(1.0, STEP_TO_BOUNDARY * np.minimum(_to_boundary(sa, ds), _to_boundary(za, dz)))
        before = _residual(r_d, r_p, sa * za - target[:, None])
        y_new, s_new, z_new = ya + alpha[:, None] * dy, sa + alpha[:, None] * ds, za + alpha[:, None] * dz
        bad = _backtrack(obj, con, (ya, sa, za), (dy, ds, dz), (y_new, s_new, z_new), alpha, (bo, bc),
                         target, before)
        stalled[active[bad]] += 1
        y[active], s[active], z[active] = y_new, s_new, z_new
    return Solution(y, z, certified, it, at)


def _backtrack(obj, con, start, step, new, alpha, offsets, target, before) -> np.ndarray:
    """Damp the steps of the rows whose residual does not fall, halving
    ``alpha`` up to BACKTRACKS times; ``new`` (y, s, z) and ``alpha`` are
    updated in place. Returns the rows still not falling (stalled). The
    rows in doubt are carried as compact arrays, cut down after each trial:
    the same figures as indexing the whole arrays each time, with fewer
    copies."""
    (ya, sa, za), (dy, ds, dz), (y_new, s_new, z_new), (bo, bc) = start, step, new, offsets
    bad = np.arange(len(alpha))
    yb, sb, zb, ab, tb, fb = y_new, s_new, z_new, alpha[bad], target, before
    for _ in range(BACKTRACKS):
        _, G0n, _ = obj.evaluate(yb, bo, value=False)
        gn, Jn, _ = con.evaluate(yb, bc)
        after = _residual(G0n.sum(axis=1) + np.einsum("rm,rmn->rn", zb, Jn), gn + sb, sb * zb - tb[:, None])
        fails = ~(after <= (1 - SUFFICIENT * ab) * fb)
        bad = bad[fails]
        if not len(bad):
            break
        ya, sa, za, dy, ds, dz, bo, bc, tb, fb = (x[fails] for x in (ya, sa, za, dy, ds, dz, bo, bc, tb, fb))
        ab = ab[fails] * BACKTRACK
        yb, sb, zb = ya + ab[:, None] * dy, sa + ab[:, None] * ds, za + ab[:, None] * dz
        alpha[bad], y_new[bad], s_new[bad], z_new[bad] = ab, yb, sb, zb
    return bad


def _to_boundary(x: np.ndarray, dx: np.ndarray) -> np.ndarray:
    """The largest step t with x + t dx >= 0, per row (inf when dx >= 0).
    Only negative dx divide (the others by -1, then dropped): no division by
    zero to silence."""
    return np.where(dx < 0, -x / np.where(dx < 0, dx, -1.0), np.inf).min(axis=1)


def _residual(r_d, r_p, r_c) -> np.ndarray:
    return np.sqrt((r_d**2).sum(axis=1) + (r_p**2).sum(axis=1) + (r_c**2).sum(axis=1))
