"""Pieces shared by the estimators: measured records, input checks and
treatment, and the statistics of a least-squares fit (covariance from the
Jacobian, 95 % intervals, identifiability warnings).

Pure numerics: nothing here opens files or prints. Records arrive as arrays
(SI) with the name and path of the run they came from, so that a FitError
can name the file.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from ..errors import FitError
from ..sim.signals import lowpass_zero_phase, sample_rate

MIN_FIT_SAMPLES = 20          # per run
MIN_REVERSALS = 1             # per run: a loop needs the input to turn
Z95 = 1.959963984540054
# default input filter (fit_cutoff): 20 x the dominant frequency of the
# excitation, 3 x the band that holds 99 % of its energy above the noise
# floor, at least 5 Hz, and never above a quarter of the Nyquist frequency
CUTOFF_HARMONICS, CUTOFF_BAND_FACTOR, CUTOFF_FLOOR_HZ, CUTOFF_MAX_NYQUIST = 20.0, 3.0, 5.0, 0.25


class ConvergenceWarning(UserWarning):
    """The solver stopped before it converged (STYLE.md: scikit-learn)."""


class IdentifiabilityWarning(UserWarning):
    """A parameter is poorly determined by the data: strongly correlated with
    another, at a bound, or with a confidence interval wider than its value."""


@dataclass
class HysteresisRecord:
    """One run for a hysteresis fit: time (n,) s, voltage (n,) V, measured
    displacement (n,) m. ``source`` names the file in messages."""

    name: str
    time: np.ndarray
    voltage: np.ndarray
    position: np.ndarray
    source: str = ""
    voltage_filtered: np.ndarray | None = field(default=None, repr=False)

    @property
    def label(self) -> str:
        return self.source or self.name


def count_reversals(v: np.ndarray, tol: float) -> int:
    """Turns of the input by more than ``tol`` (a hysteresis loop needs one)."""
    turns, direction = 0, 0
    hi = lo = ext = float(v[0])
    for value in np.asarray(v, float)[1:]:
        if direction == 0:
            hi, lo = max(hi, value), min(lo, value)
            if hi - lo > tol:
                direction, ext = (1 if value == hi else -1), value
        elif direction == 1:
            if value > ext:
                ext = value
            elif ext - value > tol:
                turns, direction, ext = turns + 1, -1, value
        else:
            if value < ext:
                ext = value
            elif value - ext > tol:
                turns, direction, ext = turns + 1, 1, value
    return turns


def require_runs(records) -> None:
    """Raise FitError unless there is a run and each is long enough to fit."""
    if not records:
        raise FitError("no run to fit")
    for rec in records:
        if len(rec.time) < MIN_FIT_SAMPLES:
            raise FitError(f"{rec.label}: too short for a fit: {len(rec.time)} samples, "
                           f"expected at least {MIN_FIT_SAMPLES}")


def check_hysteresis_records(records: list[HysteresisRecord]) -> None:
    """Raise FitError when the records cannot support a hysteresis fit."""
    require_runs(records)
    for rec in records:
        span_v = float(np.ptp(rec.voltage))
        if span_v <= 1e-9 * max(1.0, float(np.max(np.abs(rec.voltage)))):
            raise FitError(f"{rec.label}: column voltage_V: constant input "
                           f"({rec.voltage[0]:g} V throughout); a hysteresis fit needs a varying voltage")
        if float(np.ptp(rec.position)) == 0.0:
            raise FitError(f"{rec.label}: column position_m: constant displacement; nothing to fit")
    v_scale = max(float(np.ptp(r.voltage)) for r in records)
    for rec in records:
        v = rec.voltage_filtered if rec.voltage_filtered is not None else rec.voltage
        if count_reversals(v, 0.05 * v_scale) < MIN_REVERSALS:
            duration = float(rec.time[-1] - rec.time[0])
            raise FitError(f"{rec.label}: column voltage_V: no reversal: the record is shorter than one reversal "
                           f"of the input (over {duration:.3g} s it only rises or only falls); a hysteresis loop "
                           "needs the voltage to turn at least once in every run")


def fit_cutoff(t: np.ndarray, v: np.ndarray) -> float:
    """Default cut-off (Hz) of the input filter for one record, from its
    sample rate and its excitation: the largest of 20 x the dominant
    frequency, 3 x the band holding 99 % of the excitation's energy above
    the noise floor (minor loops, triangles, steps), and 5 Hz; never above
    a quarter of the Nyquist frequency fs / 2."""
    fs = sample_rate(t)
    ceiling = CUTOFF_MAX_NYQUIST * fs / 2
    x = np.asarray(v, float) - np.mean(v)
    if len(x) < 8 or not np.any(x):
        return ceiling
    power = np.abs(np.fft.rfft(x * np.hanning(len(x)))) ** 2
    freqs = np.fft.rfftfreq(len(x), 1.0 / fs)
    dominant = float(freqs[1:][np.argmax(power[1:])])
    clean = np.clip(power - 4.0 * np.median(power), 0.0, None)   # white-noise floor removed
    cumulative = np.cumsum(clean)
    band = float(freqs[np.searchsorted(cumulative, 0.99 * cumulative[-1])]) if cumulative[-1] > 0 else dominant
    return float(min(max(CUTOFF_HARMONICS * dominant, CUTOFF_BAND_FACTOR * band, CUTOFF_FLOOR_HZ), ceiling))


def run_weights(records: list[HysteresisRecord]) -> np.ndarray:
    """Weight of each run's residuals in a joint fit: sqrt(dt_k / mean dt),
    so the cost is an integral over time and a run sampled ten times faster
    does not count ten times more (runs may have different sample rates)."""
    dt = np.array([1.0 / sample_rate(r.time) for r in records])
    return np.sqrt(dt / dt.mean())


def filter_inputs(records: list[HysteresisRecord], cutoff_hz: float | None) -> list[float]:
    """Low-pass each record's voltage on purpose (zero phase, no delay) so that
    sensor noise cannot ratchet the hysteresis state. Returns the cut-off used
    per record (Hz); ``cutoff_hz=None`` picks it per record with
    ``fit_cutoff`` (sample rate and excitation); ``0`` disables filtering."""
    used = []
    for rec in records:
        if cutoff_hz == 0:
            rec.voltage_filtered = np.asarray(rec.voltage, float).copy()
            used.append(0.0)
            continue
        fc = fit_cutoff(rec.time, rec.voltage) if cutoff_hz is None else float(cutoff_hz)
        rec.voltage_filtered = padded_lowpass(rec.time, rec.voltage, fc)
        used.append(fc)
    return used


def padded_lowpass(t: np.ndarray, v: np.ndarray, cutoff_hz: float) -> np.ndarray:
    """``lowpass_zero_phase`` with long, smooth extensions at both ends, so
    that the filter's start-up transient stays outside the record: a mirror
    image (even extension) where the record ends at a turning point of the
    input, a point reflection (odd extension, value and slope kept) where it
    ends mid-stroke. The filter's own short padding would otherwise bend the
    first and last tenths of a second by up to 0.3 % of the range."""
    v = np.asarray(v, float)
    n = len(v)
    fs = 1.0 / float(np.median(np.diff(t)))
    if cutoff_hz <= 0 or cutoff_hz >= 0.45 * fs or n < 8:
        return lowpass_zero_phase(t, v, cutoff_hz)
    n_pad = min(int(3 * fs / cutoff_hz) + 1, n - 1)
    window = max(3, min(int(fs / cutoff_hz), n // 4))

    w_c = 2 * np.pi * cutoff_hz / fs   # rad per sample

    def extension(seg, edge):          # seg runs away from the edge
        # the mirror breaks the slope (error ~ 2|s|/w_c), the point
        # reflection the curvature (~ 2|c|/w_c^2): take the smaller
        curv2, slope, _ = np.polyfit(np.arange(window), seg[:window], 2)
        turning = abs(slope) * w_c < abs(2 * curv2)
        mirrored = seg[1:n_pad + 1][::-1]
        return mirrored if turning else 2 * edge - mirrored

    head = extension(v, v[0])
    tail = extension(v[::-1], v[-1])[::-1]
    padded = np.concatenate([head, v, tail])
    dt = 1.0 / fs
    tp = np.concatenate([t[0] - dt * np.arange(len(head), 0, -1), t, t[-1] + dt * np.arange(1, len(tail) + 1)])
    return lowpass_zero_phase(tp, padded, cutoff_hz)[len(head):len(head) + n]


def covariance(jac: np.ndarray, residual: np.ndarray, n_free: int | None = None) -> np.ndarray:
    """Gauss-Newton covariance s^2 (J^T J)^+ of the parameters of a
    least-squares fit, with s^2 the residual variance (m - p dof)."""
    m, p = jac.shape
    dof = max(m - (n_free if n_free is not None else p), 1)
    s2 = float(residual @ residual) / dof
    _, sv, vt = np.linalg.svd(jac, full_matrices=False)
    keep = sv > sv[0] * 1e-12 if sv.size and sv[0] > 0 else np.zeros_like(sv, bool)
    inv = (vt[keep].T / sv[keep] ** 2) @ vt[keep]
    return s2 * inv


def lag1_correlation(residual: np.ndarray, lengths: list[int]) -> float:
    """Pooled lag-1 autocorrelation of residuals stacked run after run
    (pairs that straddle two runs are left out)."""
    r = np.asarray(residual, float)
    keep = np.ones(len(r) - 1, bool)
    ends = np.cumsum(lengths)[:-1] - 1
    keep[ends[ends < len(keep)]] = False
    denominator = float(r @ r)
    return float(np.sum(r[:-1][keep] * r[1:][keep]) / denominator) if denominator > 0 else 0.0


def ess_inflation(residual: np.ndarray, lengths: list[int]) -> float:
    """Factor on a least-squares covariance for residuals correlated in
    time: n / n_eff = (1 + rho) / (1 - rho) for an AR(1) residual of lag-1
    autocorrelation rho (``lag1_correlation``), the effective-sample-size
    correction; 1 for rho <= 0. The Gauss-Newton covariance treats the n
    residuals as independent; a dynamic model's residuals are not, and
    its intervals shrink as if they were."""
    rho = min(lag1_correlation(residual, lengths), 0.999)
    return float((1 + rho) / (1 - rho)) if rho > 0 else 1.0


TREND_SHARE = 0.5     # a trend: a straight line holds this share of the residual's variance in every run


def residual_structure(runs) -> list[str]:
    """Messages for structure in fit residuals that the model lacks, over
    runs [(t, residual, simulated output)]: a spectral line common to the
    runs (sizing.spectrum.lines: in every run above LINE_FACTOR x
    the periodogram's local median, not a line of the simulated output),
    and a trend (a straight line in time holding TREND_SHARE of the
    residual's variance in every run). Confidence intervals assume the
    residual has neither. Each message is also issued as an
    IdentifiabilityWarning."""
    from .. import spectrum

    out = []
    for freq, ratio in spectrum.lines([(t, r) for t, r, _ in runs], [y for _, _, y in runs]):
        order, fundamental = _harmonic(freq, runs[0][0], runs[0][2])
        cause = (f"the {order}th harmonic of the {fundamental:.2f} Hz motion: a loop or waveform shape"
                 if order else "a sensor-mount vibration or another resonance")
        out.append(f"the residuals hold a spectral line at {freq:.1f} Hz ({ratio:.0f} x the local level) that "
                   f"the model lacks ({cause}); the 95% intervals assume residuals without it")
    shares = []
    for t, r, _ in runs:
        r = np.asarray(r, float) - np.mean(r)
        slope = np.polyfit(t, r, 1)[0]
        fitted = slope * (np.asarray(t) - np.mean(t))
        shares.append(float(fitted @ fitted / max(float(r @ r), 1e-300)))
    if shares and min(shares) >= TREND_SHARE:
        out.append(f"the residuals drift: a straight line in time holds {100 * min(shares):.0f}% or more of their "
                   "variance in every run (a thermal drift or an offset the model lacks); the 95% intervals "
                   "assume residuals without it")
    for message in out:
        warnings.warn(message, IdentifiabilityWarning, stacklevel=3)
    return out


def _harmonic(freq: float, t: np.ndarray, y: np.ndarray) -> tuple[int, float]:
    """(n, f0) when ``freq`` is the n-th harmonic (n >= 2, within 1.5
    periodogram bins) of the fundamental f0 of the simulated output y(t):
    its strongest spectral peak; (0, f0) otherwise. A hysteresis model that
    misses the loop's shape leaves lines at the drive's harmonics, not a
    resonance."""
    from ..spectrum import periodogram

    f, P = periodogram(t, np.asarray(y, float) - np.mean(y))
    f0 = float(f[1 + int(np.argmax(P[1:]))]) if len(f) > 2 else 0.0
    if f0 <= 0.0:
        return 0, f0
    n = int(round(freq / f0))
    return (n if n >= 2 and abs(freq - n * f0) <= 1.5 * float(f[1] - f[0]) else 0), f0


def correlation(cov: np.ndarray) -> np.ndarray:
    sd = np.sqrt(np.clip(np.diag(cov), 0, None))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(sd, sd)
    return np.nan_to_num(corr, nan=0.0)


def identifiability(names: list[str], values: np.ndarray, half_width: np.ndarray, corr: np.ndarray,
                    at_bound: np.ndarray, max_corr: float = 0.95) -> list[str]:
    """Messages for parameters the data do not pin down; also issued as
    IdentifiabilityWarning."""
    out = []
    for i, name in enumerate(names):
        if at_bound[i]:
            out.append(f"{name} = {values[i]:.4g} is at a bound of its physical range; "
                       "the data push it outside, or do not determine it")
        if not np.isfinite(half_width[i]) or half_width[i] > abs(values[i]):
            out.append(f"{name}: the 95% confidence interval (+/- {half_width[i]:.3g}) is wider "
                       f"than the value ({values[i]:.4g}); not identifiable from these runs")
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            if abs(corr[i, j]) > max_corr:
                out.append(f"{names[i]} and {names[j]} are strongly correlated (r = {corr[i, j]:+.3f}); "
                           "the data determine a combination of them better than each one")
    for message in out:
        warnings.warn(message, IdentifiabilityWarning, stacklevel=3)
    return out


def fd_columns(base: np.ndarray, perturbed: np.ndarray, steps: np.ndarray) -> np.ndarray:
    """Forward-difference Jacobian columns: (perturbed - base) / step."""
    return ((perturbed - base[None, :]) / steps[:, None]).T
