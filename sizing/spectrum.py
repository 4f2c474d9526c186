"""Spectral lines of a residual (shared by the fits and the diagnosis): narrow peaks well above the residual
spectrum's local level, and a sinusoid fitted at a line.

A *line* is a bin of the Hann-windowed periodogram of a residual that
exceeds LINE_FACTOR x the running median of the periodogram over
+-LOCAL_HZ (the local level: the smooth, broadband part of the residual,
which is what a nominal of another form leaves, plus the noise). For a
noise-only periodogram (exponentially distributed about its median m) a bin
exceeds k m with probability 2^-k; with the sampling error of a 41-bin
median, the largest ratio of 1000 bins of white noise is 12 (median), 20
(99th percentile of 300 runs of 2000 samples); LINE_FACTOR = 30 leaves a
margin for 1/f noise and quantisation.
Only frequencies with at least MIN_CYCLES periods in the run are searched
(a slower "line" is a drift), and bins where the nominal's own simulated
output has a line (a periodic excitation and its harmonics, where
model-form error concentrates) are not lines of the gap.

A sinusoid at a fixed frequency f is linear in its two coefficients:
e(t) ~ a sin(2 pi f t) + b cos(2 pi f t), solved by least squares;
amplitude sqrt(a^2 + b^2), phase atan2(b, a) (of A sin(2 pi f t + phase)).
The frequency is the maximiser of the summed least-squares fit over the
runs (the periodogram peak, refined on a fine grid: the maximum-likelihood
estimate of one sinusoid in white noise).
"""
from __future__ import annotations

import numpy as np

LINE_FACTOR = 30.0     # a line: periodogram above this times its local median
LOCAL_HZ = 10.0        # half-width of the local median window
MIN_CYCLES = 4.0       # periods in the run for a frequency to be searched


def periodogram(t: np.ndarray, e: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies, Hann-windowed one-sided power) of e (evenly sampled)."""
    e = np.asarray(e, float)
    e = e - e.mean()
    dt = float(np.median(np.diff(t)))
    w = np.hanning(len(e))
    P = np.abs(np.fft.rfft(e * w)) ** 2 / max(float(np.sum(w ** 2)), 1e-30)
    return np.fft.rfftfreq(len(e), dt), P


def local_level(f: np.ndarray, P: np.ndarray, half_width: float = LOCAL_HZ) -> np.ndarray:
    """Running median of P over +-half_width Hz (the window shrinks to what
    lies inside the spectrum at its two ends).

    A rolling median (pandas' skip-list, O(n log k) time, O(n) memory): a
    window matrix of n x (2k + 1) bins grows with the square of the run's
    length and took 3 GB at 200 000 samples."""
    import pandas as pd     # deferred: the command line starts without pandas

    df = float(f[1] - f[0]) if len(f) > 1 else 1.0
    k = max(int(round(half_width / df)), 2)
    level = pd.Series(np.asarray(P, float)).rolling(2 * k + 1, center=True, min_periods=1).median()
    return np.maximum(level.to_numpy(), 1e-300)


def line_ratio(t, e, reference=None) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies, P / local level) of e; 0 below MIN_CYCLES per run and
    where ``reference`` (the simulated output) has a line itself."""
    f, P = periodogram(t, e)
    ratio = P / local_level(f, P)
    duration = float(t[-1] - t[0]) or 1.0
    ratio[f < MIN_CYCLES / duration] = 0.0
    if reference is not None:
        fr, Pr = periodogram(t, reference)
        own = Pr / local_level(fr, Pr) >= LINE_FACTOR
        own = own | np.roll(own, 1) | np.roll(own, -1)
        ratio[own] = 0.0
    return f, ratio


def sinusoid(t: np.ndarray, e: np.ndarray, freq: float) -> tuple[float, float, np.ndarray]:
    """(amplitude, phase, fitted trace) of the least-squares sinusoid
    A sin(2 pi freq t + phase) in e (after removing e's mean)."""
    t = np.asarray(t, float)
    e = np.asarray(e, float)
    w = 2 * np.pi * freq * (t - t[0])
    X = np.column_stack([np.sin(w), np.cos(w), np.ones_like(w)])
    (a, b, _c), *_ = np.linalg.lstsq(X, e, rcond=None)
    fit = a * X[:, 0] + b * X[:, 1]
    return float(np.hypot(a, b)), float(np.arctan2(b, a)), fit


def explained_power(runs, freq: float) -> float:
    """Sum over runs [(t, e)] of the energy the least-squares sinusoid at
    ``freq`` removes."""
    return float(sum(np.sum(sinusoid(t, e, freq)[2] ** 2) for t, e in runs))


def refine(runs, freq: float, span: float | None = None, n: int = 41) -> float:
    """The frequency near ``freq`` (within +-span, default half a bin of
    the shortest run) whose sinusoid removes the most energy over ``runs``."""
    if span is None:
        span = 0.5 / min(float(t[-1] - t[0]) for t, _ in runs)
    for _ in range(3):
        grid = np.linspace(max(freq - span, 1e-6), freq + span, n)
        power = [explained_power(runs, g) for g in grid]
        freq = float(grid[int(np.argmax(power))])
        span *= 4.0 / n
    return freq


def lines(runs, references=None, factor: float = LINE_FACTOR, top: int = 3) -> list[tuple[float, float]]:
    """Up to ``top`` line frequencies common to the residuals ``runs``
    [(t, e)], strongest first: [(frequency, smallest ratio over the runs)].
    A frequency counts when it is a line (within one bin) in every run."""
    ratios = []
    for k, (t, e) in enumerate(runs):
        ref = None if references is None else references[k]
        f, r = line_ratio(t, e, ref)
        ratios.append((f, r))
    f0 = ratios[0][0]
    common = None
    for f, r in ratios:
        r = np.interp(f0, f, np.maximum.reduce([r, np.roll(r, 1), np.roll(r, -1)]))
        common = r if common is None else np.minimum(common, r)
    raw = np.sum([np.interp(f0, f, r) for f, r in ratios], axis=0)
    df = float(f0[1] - f0[0])
    out = []
    order = np.argsort(common)[::-1]
    for i in order:
        if common[i] < factor or len(out) >= top:
            break
        j = i - 1 + int(np.argmax(raw[max(i - 1, 0):i + 2])) if i > 0 else int(np.argmax(raw[:2]))
        freq = float(f0[j])
        if 0 < j < len(raw) - 1:       # parabolic interpolation of the log ratio around the peak bin
            a, b, c = np.log(np.maximum(raw[j - 1:j + 2], 1e-300))
            if a - 2 * b + c < 0:
                freq += df * float(np.clip(0.5 * (a - c) / (a - 2 * b + c), -0.5, 0.5))
        if all(abs(freq - g) > 2.5 * df for g, _ in out):
            out.append((freq, float(common[i])))
    return out


def line_band(t, e, freq: float, edge: float = 4.0) -> tuple[slice, np.ndarray]:
    """(bins, local level) of the line of e at ``freq``: the contiguous bins
    around it whose periodogram exceeds ``edge`` x the local level, one bin
    more each side, at most +-LOCAL_HZ / 2."""
    f, P = periodogram(t, e)
    level = local_level(f, P)
    i = int(np.argmin(np.abs(f - freq)))
    k_max = max(int(round(0.5 * LOCAL_HZ / float(f[1] - f[0]))), 2)
    a = i
    while a > 0 and i - a < k_max and P[a - 1] > edge * level[a - 1]:
        a -= 1
    b = i
    while b < len(P) - 1 and b - i < k_max and P[b + 1] > edge * level[b + 1]:
        b += 1
    return slice(max(a - 1, 0), b + 2), level


def excess(t, e, band, level: np.ndarray) -> float:
    """Power of e's periodogram above ``level`` within ``band`` (a slice or
    a boolean mask of the bins)."""
    _f, P = periodogram(t, e)
    return float(np.sum(np.maximum(P[band] - level[band], 0.0)))


def line_removal(base: list, references: list | None, candidate: list | None) -> dict | None:
    """The lines of the residuals ``base`` [(t, e)] (their common lines,
    ``lines``; a line of the matching ``references`` trace, the simulated
    output that left e, excluded) and how much of their energy the
    residuals ``candidate`` [(t, e)] of the same runs leave. The energy of
    a line is the periodogram above the base's local level over the line's
    band (``line_band``). Returns None without a line, else
    {"frequencies_Hz", "ratio" (smallest peak / local level), "share" (of
    the base residual power in the lines), "removed" (fraction of the
    lines' energy the candidate removes)}."""
    if not base:
        return None
    found = lines(base, references)
    if not found:
        return None
    before = after = total = 0.0
    for k, (t, e) in enumerate(base):
        total += float(np.sum(periodogram(t, e)[1]))
        mask, level = None, None
        for freq, _ratio in found:          # the union of the lines' bands (bands may overlap)
            band, level = line_band(t, e, freq)
            mask = np.zeros(len(level), bool) if mask is None else mask
            mask[band] = True
        before += excess(t, e, mask, level)
        if candidate is not None:
            after += excess(*candidate[k], mask, level)
    removed = 0.0 if candidate is None or before <= 0 else float(1.0 - min(after / before, 1.0))
    return {"frequencies_Hz": [f for f, _ in found], "ratio": min(r for _, r in found),
            "share": before / max(total, 1e-300), "removed": removed}
