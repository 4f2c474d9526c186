"""Where the gap is: segments of each run, frequency bands, residual tests.

Segments come from the treated input u(t): "rising" / "falling" where
|du/dt| exceeds MOVING_FRACTION of the run's input range per second,
"reversal" within REVERSAL_WINDOW_S of a sign change of
the input's motion, "hold" elsewhere; a hold that starts more than
SETTLE_S after the last motion is "steady_state". Bands: the residual
energy below and above BAND_SPLIT_HZ (the slow part the model shapes, the
fast part that is ringing, vibration or noise). Every share is a fraction
of the residual energy of all runs together: the time segments add up to
1, and so do the band entries.

Residual tests (Ljung and Box; Ljung, System Identification, ch. 16):
whiteness as the largest normalised autocorrelation of the residual at
lags 1..MAX_LAG against the 99 % band 2.58 / sqrt(N); cross-correlation of
the residual with the input and with the measured velocity, largest over
lags -MAX_LAG..MAX_LAG, with the lag.
"""
from __future__ import annotations

import numpy as np
from scipy.signal import correlate, correlation_lags

MOVING_FRACTION = 0.05      # |du/dt| above this share of the input range per second: moving
REVERSAL_WINDOW_S = 0.02
SETTLE_S = 0.3
BAND_SPLIT_HZ = 20.0
MAX_LAG = 50


def labels(t: np.ndarray, u: np.ndarray) -> np.ndarray:
    """Label of every sample from the treated input (see module docstring)."""
    span = float(np.ptp(u)) or 1.0
    du = np.gradient(u, t)
    moving = np.abs(du) > MOVING_FRACTION * span
    # input steps: a jump is a short burst of motion
    lab = np.where(du > 0, "rising", "falling").astype(object)
    lab[~moving] = "hold"
    sign = np.sign(du) * moving
    moves = np.flatnonzero(sign != 0)
    if moves.size > 1:
        s = sign[moves]
        flips = moves[1:][s[1:] != s[:-1]]
        for k in flips:
            near = np.abs(t - t[k]) <= REVERSAL_WINDOW_S
            lab[near] = "reversal"
    # holds long after the last motion are steady state
    last_move = -np.inf
    for k in range(len(t)):
        if moving[k]:
            last_move = t[k]
        elif lab[k] == "hold" and t[k] - last_move > SETTLE_S:
            lab[k] = "steady_state"
    return lab


def segments(t, lab) -> list[tuple[int, int, str]]:
    """Runs of equal labels: (start, stop (exclusive), label)."""
    out, a = [], 0
    for k in range(1, len(lab) + 1):
        if k == len(lab) or lab[k] != lab[a]:
            out.append((a, k, str(lab[a])))
            a = k
    return out


def band_energy(t, e) -> tuple[float, float]:
    """Residual energy (sum of squares) below and above BAND_SPLIT_HZ."""
    e = np.asarray(e, float)
    fs = 1.0 / float(np.median(np.diff(t)))
    E = np.fft.rfft(e)
    f = np.fft.rfftfreq(len(e), 1.0 / fs)
    power = np.abs(E) ** 2
    power[1:] *= 2.0                      # one-sided spectrum
    if len(e) % 2 == 0:
        power[-1] /= 2.0                  # the Nyquist bin is not doubled
    low = float(np.sum(power[f < BAND_SPLIT_HZ]))
    high = float(np.sum(power[f >= BAND_SPLIT_HZ]))
    total = float(np.sum(e ** 2))
    scale = total / (low + high) if low + high > 0 else 0.0
    return low * scale, high * scale


def gap_map(bench, simulated: list[np.ndarray], max_entries: int = 40) -> list[dict]:
    """The "where" list of diagnosis.json, sorted by share. ``simulated``:
    per run the position (n,) or every channel (n_ch, n); with several
    channels each entry names its ``channel`` and the shares are of the
    combined measure's energy (bench.py weights)."""
    rows = []
    for i, (r, s) in enumerate(zip(bench.runs, simulated)):
        S = np.atleast_2d(s)
        G = bench.gap(i, S)
        w = bench.weights(i)[:S.shape[0]] if S.shape[0] > 1 else np.ones(1)
        for k in range(S.shape[0]):
            rows.append((r, bench.channels[k], np.sqrt(w[k]) * G[k] / bench.spans(i)[k]))
    total = sum(float(np.sum(e ** 2)) for _, _, e in rows) or 1.0
    entries = []
    for r, channel, e in rows:
        for a, b, label in segments(r.t, labels(r.t, r.u)):
            entries.append({"run": r.name, "t_start_s": float(r.t[a]), "t_end_s": float(r.t[b - 1]),
                            "share": float(np.sum(e[a:b] ** 2)) / total, "label": label, "channel": channel})
        low, high = band_energy(r.t, e)
        for label, energy in (("low_frequency", low), ("high_frequency", high)):
            entries.append({"run": r.name, "t_start_s": float(r.t[0]), "t_end_s": float(r.t[-1]),
                            "share": energy / total, "label": label, "channel": channel,
                            "band_hz": [0.0, BAND_SPLIT_HZ] if label == "low_frequency" else [BAND_SPLIT_HZ, None]})
    entries.sort(key=lambda d: -d["share"])
    return entries[:max_entries]


def _xcorr_max(a, b, max_lag):
    """(largest normalised cross-correlation of a and b within +-max_lag
    samples, its lag): sum a[i + lag] b[i] / n, by FFT (one transform
    instead of a dot product per lag)."""
    a = (a - a.mean()) / (a.std() or 1.0)
    b = (b - b.mean()) / (b.std() or 1.0)
    n = len(a)
    c = correlate(a, b, mode="full", method="fft") / n
    lags = correlation_lags(n, n, mode="full")
    keep = np.abs(lags) <= max_lag
    c, lags = c[keep], lags[keep]
    i = int(np.argmax(np.abs(c)))
    return float(c[i]), int(lags[i])


def _autocorrelation(e0: np.ndarray, max_lag: int) -> np.ndarray:
    """Autocorrelation of the zero-mean e0 at lags 1..max_lag, by FFT."""
    n = len(e0)
    full = correlate(e0, e0, mode="full", method="fft")
    denom = float(full[n - 1]) or 1.0
    return full[n:n + max_lag] / denom


def residual_tests(bench, simulated) -> dict:
    """Per run: whiteness and cross-correlations (see module docstring)."""
    out = {}
    for r, s in zip(bench.runs, simulated):
        e = r.y - s
        n = len(e)
        acf = _autocorrelation(e - e.mean(), min(MAX_LAG, n - 1))
        band = 2.58 / np.sqrt(n)
        cu, lu = _xcorr_max(e, r.u, min(MAX_LAG, n // 4))
        cv, lv = _xcorr_max(e, np.gradient(r.y, r.t), min(MAX_LAG, n // 4))
        dt = float(np.median(np.diff(r.t)))
        out[r.name] = {
            "whiteness": {"max_autocorrelation": float(np.max(np.abs(acf))) if acf.size else 0.0,
                          "band_99": float(band), "white": bool(acf.size == 0 or np.max(np.abs(acf)) < band)},
            "cross_correlation_input": {"max": cu, "lag_s": lu * dt, "significant": bool(abs(cu) > band)},
            "cross_correlation_velocity": {"max": cv, "lag_s": lv * dt, "significant": bool(abs(cv) > band)},
        }
    return out
