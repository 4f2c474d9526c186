"""A logged command as a continuous piecewise-linear signal with free knots.

Test voltages are mostly made of holds, ramps and steps (trapezoids,
staircases of ramped steps). A symmetric low-pass rounds every corner of
such a signal: a 4-sample Gaussian moves a 1.5 V/sample ramp start by some
2 V for ten samples, and the model carries that input error into a gap that
no effect explains (on the cross-form staircases it was 2.5-4.6 x the
output error of the white voltage noise alone). When the log *is*
piecewise linear to within its noise, fitting it as such removes the
noise and keeps the corners:

1. kink candidates: peaks of the Gaussian second-derivative response at
   ``kink_scales`` samples above ``kink_sigmas`` x that response's own noise
   (sigma ||g''||), each placed by the best single hinge near it; steps
   (a sample-to-sample change ``jump_sigmas`` x the noise away from the local
   slope, so a steep ramp's noisy samples are not steps) add a knot on
   both of their samples;
2. the least-squares continuous piecewise-linear fit on those knots (hat
   basis: a tridiagonal solve);
3. backward pruning: knots whose removal raises the residual sum of squares
   by less than ``knot_penalty`` log(n) sigma^2 are removed (a BIC-like
   penalty for a knot's slope change and position);
4. accepted only when the residual rms is within ``piecewise_accept`` x the white noise
   sigma; otherwise (a sine, a chirp, a measured waveform) ``None``, and
   the caller keeps its smoother.
"""
from __future__ import annotations

import numpy as np
from scipy.linalg import solve_banded
from scipy.ndimage import gaussian_filter1d, maximum_filter1d, median_filter

from .settings import DEFAULT


def hat_fit(v: np.ndarray, knots: np.ndarray) -> np.ndarray:
    """Least-squares continuous piecewise-linear fit of v with nodes at the
    sorted sample indices ``knots`` (first 0, last len(v) - 1)."""
    t = np.arange(len(v))
    m = len(knots)
    j = np.clip(np.searchsorted(knots, t, side="right") - 1, 0, m - 2)
    w = (t - knots[j]) / (knots[j + 1] - knots[j])       # weight of the right node
    bands = np.zeros((3, m))
    off = np.bincount(j, w * (1 - w), m)[:m - 1]
    bands[0, 1:], bands[2, :-1] = off, off
    bands[1] = np.bincount(j, (1 - w) ** 2, m) + np.bincount(j + 1, w ** 2, m)
    rhs = np.bincount(j, (1 - w) * v, m) + np.bincount(j + 1, w * v, m)
    c = solve_banded((1, 1), bands, rhs)
    return c[j] * (1 - w) + c[j + 1] * w


def best_hinge(v: np.ndarray, i: int, s: int) -> int:
    """The sample within 2 s of i where a single hinge (two joined lines)
    fits v around it best."""
    lo, hi = max(i - 3 * s - 2, 0), min(i + 3 * s + 3, len(v))
    taus = np.arange(max(i - 2 * s, lo + 1), min(i + 2 * s + 1, hi - 1))
    if taus.size == 0:
        return i
    y = v[lo:hi]
    t = np.arange(lo, hi, dtype=float)
    H = np.maximum(t[None, :] - taus[:, None], 0.0)
    B = np.stack([np.ones_like(H), np.broadcast_to(t, H.shape), H], axis=2)
    G = np.einsum("tmi,tmj->tij", B, B) + 1e-12 * np.eye(3)
    c = np.linalg.solve(G, np.einsum("tmi,m->ti", B, y)[..., None])[..., 0]
    rss = np.sum((y[None, :] - np.einsum("tmi,ti->tm", B, c)) ** 2, axis=1)
    return int(taus[np.argmin(rss)])


def kink_candidates(v: np.ndarray, sigma: float) -> list[int]:
    """Sample indices of the kinks the second-derivative responses see."""
    found = set()
    for s in DEFAULT.kink_scales:
        if 8 * s > len(v):
            continue
        response = np.abs(gaussian_filter1d(v, s, order=2, mode="nearest"))
        impulse = np.zeros(8 * s + 1)
        impulse[4 * s] = 1.0
        noise = sigma * float(np.linalg.norm(gaussian_filter1d(impulse, s, order=2)))
        peaks = (response == maximum_filter1d(response, 2 * s + 1)) & (response > DEFAULT.kink_sigmas * noise)
        found.update(best_hinge(v, int(i), s) for i in np.flatnonzero(peaks))
    merged = []
    for k in sorted(found):
        if not merged or k - merged[-1] > DEFAULT.merge_samples:
            merged.append(k)
    return merged


def prune(v: np.ndarray, knots: np.ndarray, penalty: float) -> np.ndarray:
    """Remove the knots that do not pay their penalty (cheapest first, no
    two neighbours in one round, rounds until every knot pays)."""
    rss = np.sum((v - hat_fit(v, knots)) ** 2)
    while len(knots) > 2:
        cost = np.array([np.sum((v - hat_fit(v, np.delete(knots, k))) ** 2)
                         for k in range(1, len(knots) - 1)]) - rss
        weak = np.flatnonzero(cost < penalty)
        if weak.size == 0:
            break
        drop = []
        for k in weak[np.argsort(cost[weak])]:
            if all(abs(k - d) > 1 for d in drop):
                drop.append(k)
        knots = np.delete(knots, np.array(drop) + 1)
        rss = np.sum((v - hat_fit(v, knots)) ** 2)
    return knots


def steps(v: np.ndarray, sigma: float) -> np.ndarray:
    """Indices i of the steps between samples i and i + 1: a change that
    stands ``jump_sigmas`` x the noise out of the local slope (the median change
    of its neighbours), so a steep ramp's noisy samples are not steps."""
    d = np.diff(v)
    return np.flatnonzero(np.abs(d - median_filter(d, size=7, mode="nearest")) > DEFAULT.jump_sigmas * sigma)


def piecewise_linear(v: np.ndarray, sigma: float) -> np.ndarray | None:
    """The piecewise-linear fit of v (white noise ``sigma``), or None when v
    is not piecewise linear to within its noise."""
    n = len(v)
    if sigma <= 0 or n < 16:
        return None
    jumps = steps(v, sigma)
    candidates = set(kink_candidates(v, sigma)) | set(jumps.tolist()) | set((jumps + 1).tolist())
    if len(candidates) > n // 10:
        return None                              # no sparse set of corners: not this kind of signal
    knots = np.array(sorted(candidates | {0, n - 1}))
    if np.mean((v - hat_fit(v, knots)) ** 2) > (DEFAULT.piecewise_accept * sigma) ** 2:
        return None
    knots = prune(v, knots, DEFAULT.knot_penalty * np.log(n) * sigma ** 2)
    fit = hat_fit(v, knots)
    if np.sqrt(np.mean((v - fit) ** 2)) > DEFAULT.piecewise_accept * sigma:
        return None
    return fit
