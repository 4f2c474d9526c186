"""An effect whose response is a train of events, judged on the events.

A stick-slip seal moves the output in slips: it sticks while the drive
loads it, then jumps. Where each slip lands is decided by a percent of the
seal's forces (docs/diagnosis-benchmarks.md, "a field of needles"), so on
the point-by-point measure a stick-slip of the right size with its slips a
little early or late leaves more than no stick-slip at all (a sawtooth
against a sawtooth of another phase leaves sqrt(2) x the sawtooth's rms),
and the seal of another simulator is never named. What does not depend on
where the slips land is how the output moves: stuck (no increment), then
a jump of the slip's size. The measure here compares the position's
sample-to-sample increments of a run as a set (sorted, the quantile
functions of the measured increments and of the simulated ones plus the
run's white noise: a Wasserstein-2 distance), in units of the run's noise;
its floor is the distance between two draws of that noise on the nominal.

Only effects that declare it (``extra["events"]``: the Karnopp seal) are
judged this way, and only when the point-by-point verdict names nothing
while the holdout shows a gap (``judge.REVISITED``: ``unexplained``,
``undetectable``; ``judge.revisit``). The
effect is screened on a grid (``event_grid`` points per parameter, geometric
between positive bounds: a seal that only sticks, near the stated running
friction, is reached) by its distance on the training runs, and named
``partial`` when the held-out runs show an event gap (more than
``gap_factor`` x the floor) of which it removes at least ``explained`` of
the energy above the floor, on the training runs too.
"""
from __future__ import annotations

import itertools

import numpy as np

from .effects import library
from .inputs import noise_sigma
from .judge import explained
from .settings import DEFAULT, Settings
from .verdict import Verdict


def increment_distance(y: np.ndarray, sim: np.ndarray, sigma: float, seed: int = 0) -> float:
    """Wasserstein-2 distance between the sample-to-sample increments of
    ``y`` and of ``sim`` plus white noise of rms ``sigma`` (seeded), in
    units of ``sigma``: the increments compared as a set."""
    noisy = sim + np.random.default_rng(seed).normal(0.0, sigma, np.shape(sim))
    a, b = np.sort(np.diff(y)), np.sort(np.diff(noisy))
    return float(np.sqrt(np.mean((a - b) ** 2))) / sigma


class EventMeasure:
    """The increment distance of candidates on a bench's runs."""

    def __init__(self, bench, seed: int = 0):
        self.bench = bench
        self.seed = seed
        self.sigma = [max(noise_sigma(r.y), 1e-12) for r in bench.runs]
        nominal = bench.nominal()
        self.base = self.of(nominal)
        # two draws of the noise on the nominal: what the distance reads without any gap
        self.floor = np.array([increment_distance(s + np.random.default_rng(seed + 1000 + i).normal(0.0, g, s.shape),
                                                  s, g, seed + i) for i, (s, g) in enumerate(zip(nominal, self.sigma))])

    def of(self, sims) -> np.ndarray:
        """(n_runs,) distance of one candidate's simulated positions (n,) of every run."""
        return np.array([increment_distance(r.y, s, g, self.seed + i)
                         for i, (r, s, g) in enumerate(zip(self.bench.runs, sims, self.sigma))])

    def train(self, d: np.ndarray) -> float:
        return float(np.sqrt(np.mean(d[self.bench.train] ** 2)))

    def holdout(self, d: np.ndarray) -> float:
        return float(np.mean(d[self.bench.holdout]))


def grid(effect, n: int) -> np.ndarray:
    """(n^d, d) unit points: ``n`` values per parameter, geometric between
    positive bounds, evenly spaced otherwise."""
    axes = []
    for p in effect.params:
        values = np.geomspace(p.lo, p.hi, n) if p.lo > 0 else np.linspace(p.lo, p.hi, n)
        axes.append(p.to_unit(values))
    return np.array(list(itertools.product(*axes)), float).reshape(-1, len(effect.params))


def screen(bench, effect, measure: EventMeasure, n: int) -> tuple[np.ndarray, np.ndarray, list]:
    """(best unit point, its distances per run, its simulated positions) on the
    grid, best on the training runs."""
    Z = grid(effect, n)
    Y = bench.simulate([effect], Z)
    D = np.array([measure.of([y[c] for y in Y]) for c in range(len(Z))])
    k = int(np.argmin([measure.train(d) for d in D]))
    return Z[k], D[k], [y[k] for y in Y]


def event_verdict(bench, baseline_holdout: float, settings: Settings = DEFAULT, seed: int = 0):
    """(Verdict, (fitted effect, unit point)) naming an event effect
    ``partial`` by the rule of the module docstring, or None (a measure of
    ``judge.revisit``)."""
    effects = [e.for_rig(bench.rig, bench.model) for e in library(bench.kind)
               if e.extra.get("events") and e.applicable(bench.rig, bench.model)]
    if not effects:
        return None
    m = EventMeasure(bench, seed)
    base_tr, base_ho = m.train(m.base), m.holdout(m.base)
    floor_tr, floor_ho = m.train(m.floor), m.holdout(m.floor)
    if base_ho <= settings.gap_factor * floor_ho or base_tr <= settings.gap_factor * floor_tr:
        return None
    best = None
    for effect in effects:
        z, d, sims = screen(bench, effect, m, settings.event_grid)
        share_ho = explained(base_ho, m.holdout(d), floor_ho)
        share_tr = explained(base_tr, m.train(d), floor_tr)
        if share_ho >= settings.explained and share_tr >= settings.explained and (best is None or share_ho > best[0]):
            best = (share_ho, effect, z, d, sims)
    if best is None:
        return None
    share, effect, z, d, sims = best
    after = m.holdout(d)
    ho = bench.holdout
    point = float(np.mean([np.sqrt(np.mean((bench.runs[i].y - sims[i]) ** 2)) / bench.runs[i].span for i in ho]))
    reasons = (f"{effect.name} removes {100 * share:.0f} % of the held-out gap in the position's increments above "
               f"their floor (the increments compared as a set: where each slip lands is not charged; distance "
               f"{base_ho:.2f} -> {after:.2f} x the noise, floor {floor_ho:.2f})",
               f"on the point-by-point measure it leaves {point:.4f} against the nominal's {baseline_holdout:.4f}: "
               f"which instant each slip takes is not predicted")
    details = {"explained_gap_energy": share, "events": {"measure": "Wasserstein-2 distance of the position's sample-to-sample increments, "
                                     "measured against simulated plus the run's white noise, in units of that noise",
                          "baseline_holdout": base_ho, "after_holdout": after, "floor_holdout": floor_ho,
                          "baseline_train": base_tr, "after_train": m.train(d), "floor_train": floor_tr,
                          "explained": share, "params": {p.name: float(p.from_unit(zi)) for p, zi in zip(effect.params, z)},
                          "nrmse_holdout": point}}
    verdict = Verdict("partial", effect=effect.name, form=effect.form, shrink=float(1.0 - after / base_ho),
                      reasons=reasons, rule="explains_events", details=details)
    return verdict, (effect, z)
