"""Margins, feasibility, design driver, Pareto front and rank.

Margins follow docs/formats.md: achieved / required - 1 for a requirement that
sets a floor (stroke, force, speed, ...); for a ceiling (overshoot, thermal
drift) 1 - achieved / allowed, so that in both cases a negative margin
means the requirement is missed. The temperature margin is (rated -
required) / required, in K over the required degC value as in the
contract's example (``search.temperature_margin``).

Pareto and rank work on the arrays of pymoo: F (n_cand, n_obj), all
objectives minimised.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

# an objective named in requirements.toml -> the metric it minimises
OBJECTIVE_KEYS = {"mass": "mass_kg", "cost": "cost_usd", "volume": "volume_m3", "power": "power_W"}


def floor_margin(achieved: float, required: float) -> float:
    """achieved / required - 1 (negative: short of the requirement). Nothing
    required (e.g. no compensator volume at the filling temperature) is met
    by any non-negative amount: +inf."""
    if float(required) <= 0.0:
        return math.inf if float(achieved) >= 0.0 else -math.inf
    return float(achieved) / float(required) - 1.0


def ceiling_margin(achieved: float, allowed: float) -> float:
    """1 - achieved / allowed (negative: over the limit)."""
    return 1.0 - float(achieved) / float(allowed)


def verdict(margins: dict[str, float]) -> tuple[bool, str | None]:
    """(feasible, driver): feasible when every margin is >= 0; the driver is
    the requirement with the smallest margin. A NaN margin counts as missed."""
    if not margins:
        return False, None
    clean = {k: (-math.inf if v is None or math.isnan(v) else float(v)) for k, v in margins.items()}
    driver = min(clean, key=clean.get)
    return clean[driver] >= 0, driver


def dominates(a: np.ndarray, b: np.ndarray) -> bool:
    return bool(np.all(a <= b) and np.any(a < b))


def nondominated_levels(F: np.ndarray) -> np.ndarray:
    """Non-dominated sorting: level 1 is the Pareto front, level 2 the front
    of the rest, ... F (n_cand, n_obj), minimised. Returns (n_cand,) int."""
    F = np.asarray(F, dtype=float)
    n = F.shape[0]
    level = np.zeros(n, dtype=int)
    if n == 0:
        return level
    # dominated_by[i, j]: j dominates i
    le = np.all(F[None, :, :] <= F[:, None, :], axis=2)
    lt = np.any(F[None, :, :] < F[:, None, :], axis=2)
    dom = le & lt
    remaining = np.ones(n, dtype=bool)
    current = 1
    while remaining.any():
        front = remaining & ~np.any(dom & remaining[None, :], axis=1)
        level[front] = current
        remaining &= ~front
        current += 1
    return level


def pareto_mask(F: np.ndarray) -> np.ndarray:
    """True for the mutually non-dominated rows of F (minimised)."""
    return nondominated_levels(F) == 1


def rank_order(feasible: np.ndarray, F: np.ndarray, worst_margin: np.ndarray) -> np.ndarray:
    """1-based rank over all candidates: feasible ones first, by
    non-dominated level then by the sum of objectives normalised by their
    feasible minimum; infeasible ones after, closest to feasible first
    (largest worst margin). Ties keep the input order stable."""
    feasible = np.asarray(feasible, dtype=bool)
    F = np.asarray(F, dtype=float)
    n = len(feasible)
    level = np.full(n, np.iinfo(np.int32).max, dtype=np.int64)
    score = np.zeros(n)
    if feasible.any():
        Ff = F[feasible]
        level[feasible] = nondominated_levels(Ff)
        scale = np.where(np.min(Ff, axis=0) > 0, np.min(Ff, axis=0), 1.0)
        score[feasible] = np.sum(Ff / scale, axis=1)
    wm = np.where(np.isfinite(worst_margin), worst_margin, -np.inf)
    keys = (np.arange(n), np.where(feasible, 0.0, -wm), score, level, ~feasible)
    order = np.lexsort(keys)      # last key is primary
    rank = np.empty(n, dtype=int)
    rank[order] = np.arange(1, n + 1)
    return rank


@dataclass(frozen=True)
class Standing:
    """A candidate's place in the ranking of one solve (results.json:
    ``feasible``, ``driver``, ``rank``, ``pareto``, ``pareto_level``)."""

    feasible: bool
    driver: str | None
    rank: int
    pareto: bool
    pareto_level: int | None        # None: infeasible

    def fields(self) -> dict:
        return {"feasible": self.feasible, "driver": self.driver, "rank": self.rank, "pareto": self.pareto,
                "pareto_level": self.pareto_level}


def standings(margins: list, metrics: list, keys: list[str]) -> tuple[Standing, ...]:
    """Each candidate's standing, in order, from its margins and its metrics
    (``keys``: the metrics minimised; a missing or non-finite one is inf)."""
    verdicts = [verdict(m) for m in margins]
    feasible = np.array([f for f, _ in verdicts], dtype=bool)
    F = np.array([[_objective(m.get(k)) for k in keys] for m in metrics], dtype=float).reshape(len(metrics), len(keys))
    worst = np.array([m[d] if d else -math.inf for m, (_, d) in zip(margins, verdicts)], dtype=float)
    rank = rank_order(feasible, F, worst)
    level = np.zeros(len(metrics), dtype=int)
    if feasible.any():
        level[feasible] = nondominated_levels(F[feasible])
    return tuple(Standing(bool(ok), driver, int(rank[i]), bool(ok and level[i] == 1),
                          int(level[i]) if ok else None) for i, (ok, driver) in enumerate(verdicts))


def _objective(value) -> float:
    return math.inf if value is None or not math.isfinite(value) else float(value)
