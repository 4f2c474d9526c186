"""Many combinations sized at once: ``convex.GPSizer.solve``'s three
programs (the optimum; when no design meets every requirement, phase 1's
slacks and the closest bounded design) solved for all rows together by
``batch_gp``, with Clarabel through ``GPSizer`` for every row the batch
does not certify.

A row is answered by the batch only when the answer cannot depend on
which solver gave it: the optimum certified (``batch_gp``); or the parts
certainly infeasible (phase 1 certified with a requirement missed by more
than ``SURELY_MISSED``), no slack so near ``FEASIBLE_SLACK`` that the
binding set would hang on the solvers' last digits, and the closest design
certified. Everything else, and any row the batch finds feasible but not
optimal, goes to ``GPSizer``: the same program, solved by the reference.
tests/engine/test_batch_sizer.py compares both on every combination the
seed and low-duty solves size.
"""
from __future__ import annotations

import math

import numpy as np

from . import batch_gp
from .convex import (CONSTRAINTS, FEASIBLE_SLACK, PARAMETERS, POINT, VARIABLES, GPSizer, Program, SizingInput,
                     SizingResult, allowed_misses, binding_of, parameter_values)
from .posynomial import Layout, Posynomial

# the optimum's Newton steps: the seed's and low-duty's feasible rows are all
# certified within 52; the rest are infeasible parts, for phase 1 to show
OPTIMUM_ITERATIONS = 60
SURELY_MISSED = 1e-4      # phase 1's largest slack beyond 1: infeasible whichever solver says so
SLACK_DOUBT = 10.0        # a slack within this factor (in log) of FEASIBLE_SLACK's edge is left to the reference
INFEASIBLE = "infeasible"     # the status the reference gives infeasible parts (cvxpy's word)
SLACKS = tuple(f"s_{k}" for k in CONSTRAINTS)
ALLOWED = tuple(f"allow_{k}" for k in CONSTRAINTS)


def _program(objective: list, constraints: list, variables: tuple, parameters: tuple) -> batch_gp.Program:
    return batch_gp.Program(Layout.of(objective, list(variables), list(parameters)),
                            Layout.of(constraints, list(variables), list(parameters)), variables, parameters)


class BatchSizer:
    """``GPSizer``'s programs laid out for ``batch_gp``, for a set of objectives."""

    def __init__(self, objectives=("mass", "cost")):
        self.objectives = tuple(objectives)
        p = Program(self.objectives, Posynomial.symbol, Posynomial.symbol)
        terms, bounds = p._constraint_terms(), p._bounds()
        slack = {k: Posynomial.symbol(n) for k, n in zip(CONSTRAINTS, SLACKS)}
        allow = {k: Posynomial.symbol(n) for k, n in zip(CONSTRAINTS, ALLOWED)}
        self.problem = _program(p._objective_factors(), [t <= 1 for t in terms.values()] + bounds,
                                VARIABLES, PARAMETERS)
        self.phase1 = _program([slack[k] for k in CONSTRAINTS],
                               [terms[k] <= slack[k] for k in CONSTRAINTS] + [1 / s <= 1 for s in slack.values()]
                               + bounds, VARIABLES + SLACKS, PARAMETERS)
        self.relaxed = _program(p._objective_factors(), [terms[k] / allow[k] <= 1 for k in CONSTRAINTS] + bounds,
                                VARIABLES, PARAMETERS + ALLOWED)
        self._reference: GPSizer | None = None

    @property
    def reference(self) -> GPSizer:
        """Clarabel through cvxpy, built on the first row the batch leaves to it."""
        if self._reference is None:
            self._reference = GPSizer(self.objectives)
        return self._reference

    def solve(self, inputs: list[SizingInput]) -> list[SizingResult]:
        """``GPSizer.solve`` of every input, in order."""
        if not inputs:
            return []
        values = np.array([[p[k] for k in PARAMETERS] for p in map(parameter_values, inputs)])
        theta, vmax = np.log(values), values[:, PARAMETERS.index("vmax")]
        out: list[SizingResult | None] = [None] * len(inputs)
        best = batch_gp.solve(self.problem, theta, np.zeros((len(inputs), len(VARIABLES))), OPTIMUM_ITERATIONS)
        for i in np.flatnonzero(best.certified):
            out[i] = SizingResult(True, *_point(best.y[i], vmax[i]), status="optimal")
        rest = np.flatnonzero(~best.certified)
        if len(rest):
            for i, res in zip(rest, self._infeasible(theta[rest], vmax[rest])):
                out[i] = res
        return [res if res is not None else self.reference.solve(s) for res, s in zip(out, inputs)]

    def _infeasible(self, theta: np.ndarray, vmax: np.ndarray) -> list[SizingResult | None]:
        """Phase 1 and the closest design of rows without a certified
        optimum; None for a row left to the reference."""
        one = batch_gp.solve(self.phase1, theta, np.zeros((len(theta), len(VARIABLES) + len(SLACKS))))
        slacks = np.exp(one.y[:, len(VARIABLES):])
        doubt = np.abs(np.log(slacks) - math.log(FEASIBLE_SLACK)) < SLACK_DOUBT * batch_gp.FEASIBILITY
        sure = one.certified & (slacks.max(axis=1) > 1 + SURELY_MISSED) & ~doubt.any(axis=1)
        rows = np.flatnonzero(sure)
        out: list[SizingResult | None] = [None] * len(theta)
        if not len(rows):
            return out
        found = []
        for i in rows:
            slack = {k: float(v) for k, v in zip(CONSTRAINTS, slacks[i])}
            found.append((slack, binding_of(slack)))
        allowed = np.log([[allowed_misses(slack, binding)[k] for k in CONSTRAINTS] for slack, binding in found])
        closest = batch_gp.solve(self.relaxed, np.hstack([theta[rows], allowed]),
                                 np.zeros((len(rows), len(VARIABLES))))
        for j, i in enumerate(rows):
            if closest.certified[j]:
                slack, binding = found[j]
                out[i] = SizingResult(False, *_point(closest.y[j], vmax[i]), slack=slack, binding=binding,
                                      status=INFEASIBLE)
        return out


def _point(y: np.ndarray, vmax: float) -> tuple:
    """The design's variables from their logarithms, v <= v_max as ``GPSizer`` returns them."""
    point = [float(math.exp(v)) for v in y[:len(POINT)]]
    point[2] = min(point[2], vmax)
    return tuple(point)
