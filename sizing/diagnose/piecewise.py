"""A logged command as a continuous piecewise-linear signal with free knots.

Test voltages are mostly made of holds, ramps and steps (trapezoids,
staircases of ramped steps). A symmetric low-pass rounds every corner of
such a signal: a 4-sample Gaussian moves a 1.5 V/sample ramp start by some
2 V for ten samples, and the model carries that input error into a gap that
no effect explains (on the cross-form staircases it is 2.5-4.6 x the
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
4. each knot moved to its best position between samples (``refine``)
   before the pruning and after each of its two passes: a commanded corner falls between
   two log samples, and on a fast ramp against the log rate (220 V/s
   logged at 500 Hz: 0.44 V a sample) a knot held to a sample misplaces
   it by up to half a sample, 0.2 V, seven times a 0.03 V noise; the
   pruning then keeps spurious knots next to it that bend the holds
   either side (on such a ramp-and-hold log, 28 knots for 16 corners and
   0.021 V rms from the clean command; with the knots between samples,
   18 knots and 0.004 V);
5. accepted only when the residual rms is within ``piecewise_accept`` x the white noise
   sigma (and, before the knots are moved, within ``piecewise_screen`` x that:
   a quick refusal of a sine or a chirp); otherwise (a sine, a chirp, a measured waveform) ``None``, and
   the caller keeps its smoother.
"""
from __future__ import annotations

import numba
import numpy as np
from scipy.linalg import LinAlgError
from scipy.ndimage import convolve1d, gaussian_filter1d, maximum_filter1d, median_filter

from .settings import DEFAULT

# LAPACK's dgtsv, the routine scipy's solve_banded calls for one band either
# side, called by its name from compiled code: a kernel that held a ctypes
# function would hold its address, which numba does not cache (1 s to
# compile again in every process), and one given it as an argument pays
# 1.2 us a call to type it (a short fit takes 1.5 us), 15-20 % of the
# voltage treatment
_DGTSV_SYMBOL = "sizing_scipy_lapack_dgtsv"
_INT, _DOUBLE = numba.types.CPointer(numba.int32), numba.types.CPointer(numba.float64)
_DGTSV = numba.types.ExternalFunction(_DGTSV_SYMBOL, numba.void(_INT, _INT, *[_DOUBLE] * 4, _INT, _INT))
_dgtsv_linked = False


def _link_dgtsv() -> None:
    """Give LLVM dgtsv's address under ``_DGTSV_SYMBOL``, once a process,
    before the first call of a kernel that reaches it (``_gtsv``, through
    ``_hat_fit``): numba resolves the name at that call, whether it compiles
    the kernel or loads it from its cache. Not at import: LLVM's symbol
    table is the whole process's, shared by every numba kernel and
    llvmlite user, and importing a module should not change it."""
    global _dgtsv_linked
    import llvmlite.binding as llvm
    from numba.extending import get_cython_function_address

    llvm.add_symbol(_DGTSV_SYMBOL, get_cython_function_address("scipy.linalg.cython_lapack", "dgtsv"))
    _dgtsv_linked = True


def hat_fit(v: np.ndarray, knots: np.ndarray) -> np.ndarray:
    """Least-squares continuous piecewise-linear fit of v with nodes at the
    sorted positions ``knots`` in samples (first 0, last len(v) - 1; the
    others may fall between samples)."""
    if not _dgtsv_linked:             # a flag, not functools.cache: hat_fit runs hundreds of times a log
        _link_dgtsv()
    fit, info = _hat_fit(np.ascontiguousarray(v, dtype=float), np.ascontiguousarray(knots, dtype=float))
    if info > 0:
        raise LinAlgError("singular matrix")
    return fit


@numba.njit(cache=True)
def _hat_fit(v, knots):
    """hat_fit compiled (the knot search, refine, fits hundreds of short
    stretches a log, where numpy's call overheads cost more than the
    arithmetic): the normal equations summed sample by sample in order,
    as np.bincount does, and solved by LAPACK's dgtsv as scipy's
    solve_banded with one band either side solves them, so the fit is the
    same to the last bit as with numpy and scipy. (fit, LAPACK's info)."""
    n, m = v.shape[0], knots.shape[0]
    j = np.empty(n, np.int64)
    w = np.empty(n)
    k = 0
    for t in range(n):
        while k < m - 2 and knots[k + 1] <= t:        # searchsorted(side="right") - 1, clipped to [0, m - 2]
            k += 1
        j[t] = k
        w[t] = (t - knots[k]) / (knots[k + 1] - knots[k])
    off = np.zeros(m)
    left, right = np.zeros(m), np.zeros(m)
    rhs_left, rhs_right = np.zeros(m), np.zeros(m)
    for t in range(n):
        a, b, r = 1.0 - w[t], w[t], j[t]
        off[r] += b * a
        left[r] += a * a
        right[r + 1] += b * b
        rhs_left[r] += a * v[t]
        rhs_right[r + 1] += b * v[t]
    diagonal = left + right
    c = rhs_left + rhs_right
    info = _gtsv(off[:m - 1].copy(), diagonal, off[:m - 1].copy(), c)
    fit = np.empty(n)
    for t in range(n):
        fit[t] = c[j[t]] * (1.0 - w[t]) + c[j[t] + 1] * w[t]
    return fit, info


@numba.njit(cache=True)
def _gtsv(dl, d, du, b):
    """LAPACK's dgtsv for one right-hand side (contiguous arrays, changed
    in place as LAPACK changes them): b becomes the solution; returns
    LAPACK's info (0, or the singular pivot's number). Called from Python,
    ``_link_dgtsv()`` first."""
    ints = np.empty(4, np.int32)                      # n, nrhs, ldb, info
    ints[0], ints[1], ints[2], ints[3] = d.shape[0], 1, d.shape[0], 0
    _DGTSV(ints[0:].ctypes, ints[1:].ctypes, dl.ctypes, d.ctypes, du.ctypes, b.ctypes, ints[2:].ctypes,
           ints[3:].ctypes)
    return ints[3]


def best_hinge(v: np.ndarray, i: int, s: int) -> int:
    """The sample within 2 s of i where a single hinge (two joined lines)
    fits v around it best.

    Each hinge's residual is found first by projections (the window's time
    centred: one matrix product for every hinge); only when the best two
    hinges are closer than ``_tie`` of the residual energy is the choice
    made as the normal equations of each hinge make it (the time
    uncentred, whose rounding error, about 1e-9 of that energy in windows
    ending before sample 4000 and growing as the fourth power of the
    position, may reorder near ties): the hinge found is the same either way."""
    lo, hi = max(i - 3 * s - 2, 0), min(i + 3 * s + 3, len(v))
    taus = np.arange(max(i - 2 * s, lo + 1), min(i + 2 * s + 1, hi - 1))
    if taus.size == 0:
        return i
    y = v[lo:hi]
    t = np.arange(lo, hi, dtype=float)
    H = np.maximum(t[None, :] - taus[:, None], 0.0)
    if taus.size > 1:
        rss, energy = _hinge_rss(y, t, H)
        best, second = np.partition(rss, 1)[:2]
        if second - best > _tie(hi) * energy:
            return int(taus[np.argmin(rss)])
    return int(taus[np.argmin(_hinge_rss_normal(y, t, H))])


def _tie(end: int) -> float:
    """Residual-energy share below which two hinges ending a window at
    sample ``end`` are a near tie for _hinge_rss: 1e-6, a thousand times
    the normal equations' rounding up to sample 4000 (measured: 8e-10 at
    4000, 8e-8 at 16000, 4e-5 at 64000), raised as the fifth power of the
    position beyond it."""
    return 1e-6 * max(1.0, end / 4000.0) ** 5


def _hinge_rss(y: np.ndarray, t: np.ndarray, H: np.ndarray) -> tuple[np.ndarray, float]:
    """(residual sum of squares of the line plus each hinge column of H,
    that of the line alone): the hinges projected off the centred line."""
    tc = t - t.mean()
    r0 = y - y.mean()
    r0 = r0 - (tc @ r0) / (tc @ tc) * tc
    Hc = H - H.mean(axis=1, keepdims=True)
    Hc -= np.outer(Hc @ tc / (tc @ tc), tc)
    hh = np.einsum("tm,tm->t", Hc, Hc)
    hr = Hc @ r0
    energy = float(r0 @ r0)
    return energy - np.where(hh > 0, hr * hr / np.where(hh > 0, hh, 1.0), 0.0), energy


def _hinge_rss_normal(y: np.ndarray, t: np.ndarray, H: np.ndarray) -> np.ndarray:
    """Residual sum of squares of each hinge from its normal equations."""
    B = np.stack([np.ones_like(H), np.broadcast_to(t, H.shape), H], axis=2)
    G = np.einsum("tmi,tmj->tij", B, B) + 1e-12 * np.eye(3)
    c = np.linalg.solve(G, np.einsum("tmi,m->ti", B, y)[..., None])[..., 0]
    return np.sum((y[None, :] - np.einsum("tmi,ti->tm", B, c)) ** 2, axis=1)


def curvature_kernel(scale: int) -> np.ndarray:
    """The Gaussian second-derivative kernel of standard deviation ``scale``
    samples (truncated at 4 of them), less its mean: truncated, the kernel
    sums to -8.7e-5 at 2 samples, so a hold at 150 V answered -0.013 V, as
    much as five times a 0.03 V noise's response, and a flat response is its
    own local maximum at every sample: every sample of a high hold was a
    kink. Zero-sum and symmetric, it answers neither a level nor a slope."""
    impulse = np.zeros(8 * scale + 1)
    impulse[4 * scale] = 1.0
    kernel = gaussian_filter1d(impulse, scale, order=2)
    return kernel - kernel.mean()


def kink_candidates(v: np.ndarray, sigma: float) -> list[int]:
    """Sample indices of the kinks the second-derivative responses see."""
    found = set()
    for s in DEFAULT.kink_scales:
        if 8 * s > len(v):
            continue
        kernel = curvature_kernel(s)
        response = np.abs(convolve1d(v, kernel, mode="nearest"))
        noise = sigma * float(np.linalg.norm(kernel))
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


def refine(v: np.ndarray, knots: np.ndarray, sigma: float, reach: float = 1.5, sweeps: int = 3) -> np.ndarray:
    """The knots, each moved (in turn, the others held) to the position
    within ``reach`` samples, between its neighbours, where the fit is best:
    a search on the fit of the stretch from the third knot before it to the
    third after it (the fit's dependence on one knot's position is local;
    the stretch's two end knots are rounded to samples). The best position
    of one knot depends on where its neighbours are: up to ``sweeps``
    passes, until no knot moves by 0.05 sample. Only the knots whose slope
    change d (per sample) exceeds the noise ``sigma`` are moved: a knot
    misplaced by half a sample errs by up to d / 2 on its nearest samples,
    less than half the noise below that (the many gentle knots of a
    signal that is not piecewise linear, a sine, are left where they
    are), and a knot moves only when that lowers the squared error by more
    than log(n) sigma^2, the BIC price of one parameter: a corner on a
    sample stays there rather than follow the noise (on a staircase logged
    at 1 kHz, moved by the noise alone, the fit erred by 0.038 V for 0.028 V
    on the samples)."""
    knots = np.asarray(knots, float).copy()
    for _ in range(sweeps):
        before = knots.copy()
        knots = _refine_sweep(v, knots, sigma, reach)
        if np.max(np.abs(knots - before), initial=0.0) < 0.05:
            break
    return knots


def _refine_sweep(v: np.ndarray, knots: np.ndarray, sigma: float, reach: float) -> np.ndarray:
    from scipy.optimize import minimize_scalar

    knots = knots.copy()
    last = len(knots) - 1
    fit = hat_fit(v, knots)
    nodes = np.interp(knots, np.arange(len(v)), fit)
    bends = np.abs(np.diff(np.diff(nodes) / np.diff(knots)))      # slope change at knots 1..last-1
    for i in range(1, last):
        if bends[i - 1] <= sigma:
            continue
        # a sample at least between two knots, so that every node is determined
        lo, hi = max(knots[i - 1] + 1.0, knots[i] - reach), min(knots[i + 1] - 1.0, knots[i] + reach)
        if hi <= lo:
            continue
        first, end = max(i - 3, 0), min(i + 3, last)
        a, b = int(np.floor(knots[first])), int(np.ceil(knots[end]))
        local = knots[first:end + 1] - a
        local[0], local[-1] = 0.0, float(b - a)
        j = i - first
        piece = v[a:b + 1]

        def rss(x):
            k = local.copy()
            k[j] = x - a
            return float(np.sum((piece - hat_fit(piece, k)) ** 2))

        # the fit's error is not convex in a knot's position (it bends at
        # each sample): a grid of tenths of a sample, then the bracket
        grid = np.linspace(lo, hi, max(int(np.ceil((hi - lo) / 0.1)) + 1, 2))
        start = grid[int(np.argmin([rss(x) for x in grid]))]
        best = minimize_scalar(rss, bounds=(max(start - 0.1, lo), min(start + 0.1, hi)), method="bounded",
                               options={"xatol": 0.005})
        if best.fun < rss(knots[i]) - np.log(len(v)) * sigma ** 2:
            knots[i] = best.x
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
    if np.mean((v - hat_fit(v, knots)) ** 2) > (DEFAULT.piecewise_screen * DEFAULT.piecewise_accept * sigma) ** 2:
        return None                              # far from any line through these corners: not worth refining
    knots = refine(v, knots, sigma)
    if np.mean((v - hat_fit(v, knots)) ** 2) > (DEFAULT.piecewise_accept * sigma) ** 2:
        return None
    penalty = DEFAULT.knot_penalty * np.log(n) * sigma ** 2
    knots = refine(v, prune(v, knots, penalty), sigma)
    knots = refine(v, prune(v, knots, penalty), sigma)
    fit = hat_fit(v, knots)
    if np.sqrt(np.mean((v - fit) ** 2)) > DEFAULT.piecewise_accept * sigma:
        return None
    return fit
