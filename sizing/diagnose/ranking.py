"""The screen's ranking of candidates by their training cost: exact, with
fewer simulations.

A candidate's screening cost (``fitting.cost``) is the mean over the
training runs of its combined measure squared. Each run adds a term of at
least zero, so the runs simulated so far bound a candidate's cost from
below. The ranking simulates every candidate on the shortest training run,
completes the ``wanted`` best by that bound (as many entries as its reader
takes first), and simulates a further run only for the candidates whose
bound does not yet exceed the cost of those: the others cannot rank before
them. A reader who walks further down (the best regular point of a densely
screened effect, the spaced starts of a rugged one) has the candidates that
could come next completed as it reads.

The kernel simulates each candidate on its own (its figures do not depend
on which candidates share the batch), so every cost read is the one a
simulation of all candidates on all runs gives, to the bit, and so is the
order; what is left out is only what could not rank before the entries
read. On the independent generator's piezo campaigns the screens then
simulate about half the candidate runs (benchmarks/diagnose_speed.py).
"""
from __future__ import annotations

import numpy as np

from . import fitting

# a bound and a cost sum the same squares in other orders: a bound is
# taken to exceed a cost only beyond this relative margin (rounding is
# ~1e-16 a term)
ROUNDING = 1e-9


class Ranking:
    """The entries ``(cost, *points[k])`` of the candidates ``Z`` (rows; the
    unit coordinates ``fitting.cost`` takes) best first, as a stable sort
    of every candidate's cost on ``runs`` orders them (ties in the order
    of ``Z``); each computed when first read (``ranking[0]``, iteration)."""

    def __init__(self, bench, effects, Z, runs, points, wanted: int = 1):
        self._bench, self._effects, self._Z, self._runs = bench, list(effects), Z, list(runs)
        self._points = list(points)
        n = len(Z)
        self._squares = np.zeros((n, len(self._runs)))      # combined measure^2 of each candidate on each run
        self._done = np.zeros((n, len(self._runs)), bool)
        self._cost = np.zeros(n)
        self._known = np.zeros(n, bool)                     # the cost is computed
        self._read = np.zeros(n, bool)
        self._entries: list[int] = []
        if len(self._runs) < 2 or n < 2:
            # nothing to bound a cost with: every candidate at once
            self._cost[:] = fitting.cost(bench, self._effects, Z, self._runs) if n else []
            self._done[:] = self._known[:] = True
            return
        lengths = [float(bench.runs[i].t[-1] - bench.runs[i].t[0]) for i in self._runs]
        self._order = sorted(range(len(self._runs)), key=lambda j: (lengths[j], j))   # shortest run first
        self._simulate(np.arange(n), self._order[0])
        first = np.argsort(self._bound(), kind="stable")[:max(wanted, 1)]
        self._settle(np.inf, first)
        self._settle(float(np.max(self._cost[first])))

    def __len__(self) -> int:
        return len(self._cost)

    def __getitem__(self, k: int):
        if not isinstance(k, (int, np.integer)) or k < 0:
            raise TypeError("a ranking is read by position from its start")
        while len(self._entries) <= k:
            if not self._next():
                raise IndexError(k)
        return self._entry(self._entries[k])

    def __iter__(self):
        k = 0
        while k < len(self._entries) or self._next():
            yield self._entry(self._entries[k])
            k += 1

    def _entry(self, c: int) -> tuple:
        return (float(self._cost[c]),) + tuple(self._points[c])

    def _bound(self) -> np.ndarray:
        """(n,) each candidate's cost from the runs simulated so far (the
        others count 0): its cost once every run is simulated, a lower
        bound before."""
        return np.mean(self._squares, axis=1)

    def _simulate(self, which: np.ndarray, j: int) -> None:
        run = [self._runs[j]]
        Y = self._bench.simulate_channels(self._effects, self._Z[which], run)
        self._squares[which, j] = fitting.run_nrmse(self._bench, Y, run)[:, 0] ** 2
        self._done[which, j] = True

    def _settle(self, limit: float, which=None) -> None:
        """Simulate, run after run (shortest first), the candidates (of
        ``which``, default all) whose bound does not exceed ``limit``; then
        every candidate whose bound stays within ``limit`` has its cost."""
        chosen = np.zeros(len(self._cost), bool)
        chosen[slice(None) if which is None else which] = True
        for j in self._order:
            due = np.flatnonzero(chosen & ~self._done[:, j] & (self._bound() <= limit * (1.0 + ROUNDING)))
            if due.size:
                self._simulate(due, j)
        whole = np.flatnonzero(np.all(self._done, axis=1) & ~self._known)
        if whole.size:
            # as fitting.cost computes it: the mean over the runs, in their order
            self._cost[whole] = np.mean(self._squares[whole], axis=1)
            self._known[whole] = True

    def _next(self) -> bool:
        """Read one more entry; False when every candidate has been read."""
        while True:
            left = ~self._read
            if not left.any():
                return False
            known = left & self._known
            pending = left & ~self._known
            if known.any():
                c = int(np.flatnonzero(known)[np.argmin(self._cost[known])])     # the first of equal costs
                limit = float(self._cost[c])
                if not np.any(pending & (self._bound() <= limit * (1.0 + ROUNDING))):
                    self._read[c] = True
                    self._entries.append(c)
                    return True
            else:
                limit = float(np.min(self._bound()[pending]))
            self._settle(limit)
