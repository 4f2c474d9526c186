"""Treatment of a measured piezo voltage before it drives the model.

The Bouc-Wen model (seed eq. 2) reacts to the sign of dv/dt at every
instant: its delta term adds delta v sgn(v') dt whatever the rate, so raw
sensor noise, which reverses the input hundreds of times a second, ratchets
the hysteresis state and creates a gap that is not in the hardware. A plain
low-pass is not enough (any wiggle left is a reversal), and a sharp one
rings at the edges of voltage steps. The treatment, stated in every report:

0. when the log is piecewise linear to within its noise (holds, ramps and
   steps: piecewise.py), its continuous piecewise-linear least-squares fit
   with free knots, which keeps the corners of ramps that any low-pass
   rounds; its significant reversals are the turning points of a zig-zag
   with a threshold of ``reversal_sigmas`` times the noise of the logged
   voltage (drive_noise_sigma) and at least 0.5 % of its range, and
   between two of them the fit is made monotone (isotonic, least-squares
   monotone regression);
1. otherwise (sines, chirps, multisines, staircases with rounded edges)
   the reversals are found on a guide: a zero-phase Gaussian low-pass
   (symmetric kernel: no delay, no overshoot at steps) of standard
   deviation ``smooth_samples`` samples, on each stretch between jumps (a
   sample-to-sample change above ``jump_sigmas`` x the noise) on its own,
   each extended past its ends by odd reflection; the zig-zag's threshold
   is ``reversal_sigmas`` x the noise (the guide's own noise is a quarter
   of the log's, so noise makes no reversal);
2. between two reversals of the guide the logged samples themselves are
   made monotone (isotonic regression): a hold's noise is pooled flat, a
   ramp keeps its samples, and the input never reverses there.

Why the logged samples and not the guide in step 2, and no range floor in
step 1: a low-pass of a few samples takes amplitude from the fast lines of
a smooth drive (a Gaussian of 4 samples keeps exp(-(2 pi f sigma / fs)^2 / 2)
of a line: 94 % of 28 Hz at 2 kHz, 37 % at 500 Hz), and a reversal
threshold at 0.5 % of the range (0.7 V on a 5-145 V multisine) flattens
the multisine's genuine small reversals, whose hysteresis the hardware
does see. On random-phase multisines with 0.015-0.03 V of noise, logged at
0.5-2 kHz, the low-passed and floored treatment erred by 0.055-0.058 V
rms from the clean command, two to four times the log's own noise, and
the nominal it drove by 3-6 x the position noise from the nominal driven
by the clean command; this treatment errs by 0.015-0.04 V and 0.7-1.5 x
(docs/diagnosis-benchmarks.md, "the voltage of smooth drives").
"""
from __future__ import annotations

from functools import lru_cache
from math import comb

import numpy as np
from scipy.ndimage import gaussian_filter1d
from scipy.optimize import isotonic_regression

from . import piecewise
from .piecewise import piecewise_linear
from .settings import DEFAULT


def noise_sigma(x: np.ndarray) -> float:
    """Robust rms of white noise on x: MAD of second differences / sqrt(6)."""
    return second_difference_sigma(np.diff(np.asarray(x, float), 2))


def drive_noise_sigma(v: np.ndarray) -> float:
    """Robust rms of the white noise on a logged drive (a voltage) that may
    move fast and smoothly: the smallest of the estimates from its second,
    third and fourth differences. White noise gives each the same value
    (the k-th difference of white noise has variance C(2k, k) sigma^2); a
    smooth drive of angular frequency w adds (w dt)^k of its amplitude,
    less at each higher k (a 20 Hz sine of 150 V sampled at 1 kHz: 2.4 V
    to the second differences, 0.04 V to the fourth); a step touches k + 1
    samples, which the clipping ignores while steps are rare. Each estimate
    is the rms of the differences within ``noise_clip`` robust sigmas of their
    median (``clipped_difference_sigma``), not their median absolute
    deviation: a log quantised on a step near its noise (0.02 V steps,
    0.015 V of noise) puts its differences on a few levels, and their MAD
    jumps with the grid (0.012 V read for 0.015 V true); too small a noise
    then reads the noise as corners (treat_voltage's piecewise-linear fit
    found more kinks than a tenth of the samples and fell back to the
    low-pass)."""
    v = np.asarray(v, float)
    estimates = [clipped_difference_sigma(np.diff(v, k), k) for k in (2, 3, 4) if v.size > k]
    return min(estimates) if estimates else 0.0


def clipped_difference_sigma(dk: np.ndarray, k: int) -> float:
    """Robust rms of the white noise whose k-th differences are ``dk``: the
    rms about the median of those within ``noise_clip`` x the MAD estimate
    (_difference_sigma), corrected for the normal tails cut off."""
    from scipy.stats import norm

    dk = np.asarray(dk, float)
    scale = _difference_sigma(dk, k) * np.sqrt(comb(2 * k, k))
    if dk.size == 0 or scale <= 0:
        return _difference_sigma(dk, k)
    centre = np.median(dk)
    clip = DEFAULT.noise_clip
    kept = dk[np.abs(dk - centre) <= clip * scale] - centre
    tails = 1.0 - 2.0 * clip * norm.pdf(clip) / (2.0 * norm.cdf(clip) - 1.0)
    return float(np.sqrt(np.mean(kept ** 2) / tails / comb(2 * k, k)))


def _difference_sigma(dk: np.ndarray, k: int) -> float:
    """Robust rms of the white noise whose k-th differences are ``dk``."""
    if dk.size == 0:
        return 0.0
    return float(1.4826 * np.median(np.abs(dk - np.median(dk))) / np.sqrt(comb(2 * k, k)))


def second_difference_sigma(d2: np.ndarray) -> float:
    """Robust rms of the white noise whose second differences are ``d2``."""
    return _difference_sigma(d2, 2)


def reversals(x: np.ndarray, threshold: float) -> list[int]:
    """Indices of the turning points of a zig-zag that ignores moves smaller
    than ``threshold``; starts with 0 and ends with len(x) - 1."""
    pivots = [0]
    i_hi = i_lo = 0
    direction = 0
    for k in range(1, len(x)):
        if direction >= 0:
            if x[k] > x[i_hi]:
                i_hi = k
            if direction == 0 and x[k] < x[i_lo]:
                i_lo = k
        if direction <= 0:
            if x[k] < x[i_lo]:
                i_lo = k
        if direction == 0:
            if x[i_hi] - x[0] > threshold:
                direction, i_lo = 1, i_hi
            elif x[0] - x[i_lo] > threshold:
                direction, i_hi = -1, i_lo
        elif direction > 0 and x[i_hi] - x[k] > threshold:
            pivots.append(i_hi)
            direction, i_lo = -1, k
        elif direction < 0 and x[k] - x[i_lo] > threshold:
            pivots.append(i_lo)
            direction, i_hi = 1, k
    if pivots[-1] != len(x) - 1:
        pivots.append(len(x) - 1)
    return pivots


def smooth_piece(x: np.ndarray) -> np.ndarray:
    """Zero-phase Gaussian low-pass of one stretch between jumps, extended
    past its ends by odd (point) reflection, so that a straight line is
    passed unchanged: a stretch that is part of a fast ramp (a commanded
    step with a finite rate, cut into short stretches where single samples
    cross the jump threshold) keeps its slope up to its ends instead of
    being flattened towards them."""
    x = np.asarray(x, float)
    if x.size < 3:
        return x.copy()
    pad = int(4 * DEFAULT.smooth_samples + 1)
    ext = np.pad(x, pad, mode="reflect", reflect_type="odd")
    return gaussian_filter1d(ext, DEFAULT.smooth_samples, mode="nearest")[pad:pad + x.size]


def treat_voltage(v: np.ndarray) -> np.ndarray:
    """The treated input (see the module docstring); a log treated before
    with the same settings is answered from memory (a copy)."""
    v = np.asarray(v, float)
    if len(v) < 8:
        return v.copy()
    return _treated(v.shape, v.tobytes(), DEFAULT, piecewise.DEFAULT).copy()


# Kept in memory for the process, where ``disk_cache`` keeps between runs the
# floats that every run asks for again (a unit's text, a plate's solve): a
# treated log is an array that only the withheld-effect check asks for again,
# within its process (each campaign's clean voltages in every case, its model
# and its synthesis: a third of its treatments, 0.05-0.15 s of CPU each).
@lru_cache(maxsize=32)
def _treated(shape: tuple, log: bytes, settings, fit_settings) -> np.ndarray:
    """_treat of the log whose float64 samples are ``log``; the treatment
    reads the settings as DEFAULT, and they are part of the key."""
    return _treat(np.frombuffer(log).reshape(shape).copy())


def _treat(v: np.ndarray) -> np.ndarray:
    sigma = drive_noise_sigma(v)
    fit = piecewise_linear(v, sigma)
    if fit is not None:
        return monotone_between(fit, fit, max(DEFAULT.reversal_sigmas * sigma, 0.005 * float(np.ptp(v)), 1e-12))
    return monotone_between(v, low_passed(v, sigma), max(DEFAULT.reversal_sigmas * sigma, 1e-12))


def low_passed(v: np.ndarray, sigma: float) -> np.ndarray:
    """The guide of step 1: each stretch between jumps (changes between
    two samples far above the noise, kept sharp) smoothed on its own."""
    jumps = np.flatnonzero(np.abs(np.diff(v)) > DEFAULT.jump_sigmas * max(sigma, 1e-12))
    smooth = np.empty_like(v)
    for a, b in zip(np.r_[0, jumps + 1], np.r_[jumps + 1, len(v)]):
        smooth[a:b] = smooth_piece(v[a:b])
    return smooth


def monotone_between(v: np.ndarray, guide: np.ndarray, threshold: float) -> np.ndarray:
    """v made monotone (isotonic regression) between each two reversals of
    ``guide`` (a zig-zag ignoring moves below ``threshold``), in the
    direction the guide moves there."""
    pivots = reversals(guide, threshold)
    out = np.array(v, float, copy=True)
    for a, b in zip(pivots[:-1], pivots[1:]):
        out[a:b + 1] = isotonic_regression(v[a:b + 1], increasing=bool(guide[b] >= guide[a])).x
    return out


def hold_rate(voltages, settings=None) -> float:
    """Deadband (V/s) of sgn(dV/dt) in the Bouc-Wen delta term for runs
    logged with these ``voltages``: the rate at which the voltage moves by
    its own noise (the median over the runs of drive_noise_sigma) in
    settings.hold_time_s. Slower than that, a run cannot tell a ramp from a
    hold, and the treated voltage of a hold keeps such a slope (the
    piecewise-linear fit's slope error, a few mV/s at 30 mV of noise), whose
    sign the delta term would integrate at the full held voltage. 0 for a
    noise-free log (the exact sign)."""
    from .settings import DEFAULT
    settings = settings or DEFAULT
    sigmas = [drive_noise_sigma(v) for v in voltages]
    return float(np.median(sigmas)) / settings.hold_time_s if sigmas else 0.0


def describe() -> str:
    return (f"voltage: piecewise-linear fit with free knots when the log is piecewise linear within its noise, "
            f"made monotone (isotonic) between reversals larger than {DEFAULT.reversal_sigmas:g} x the voltage "
            f"noise and 0.5 % of its range; else the logged samples made monotone between the reversals, larger "
            f"than {DEFAULT.reversal_sigmas:g} x the noise, of a zero-phase Gaussian low-pass "
            f"(sigma {DEFAULT.smooth_samples:g} samples)")
