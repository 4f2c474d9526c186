"""Input treatment for measured signals.

Hysteresis models react to every reversal of their input, so raw sensor
noise on a measured voltage ratchets the hysteresis state and creates a gap
that is not in the hardware. Measured inputs therefore pass a zero-phase
low-pass (4th-order Butterworth run forwards and backwards, so no delay is
added) before they drive a model. The cut-off is chosen well above the
excitation's content and well below the noise.
"""
from __future__ import annotations

import numpy as np
from scipy import signal

DEFAULT_ORDER = 4


def sample_rate(t: np.ndarray) -> float:
    """Median sample rate of a (possibly unevenly sampled) time vector, Hz."""
    return 1.0 / float(np.median(np.diff(t)))


def lowpass_zero_phase(t: np.ndarray, x: np.ndarray, cutoff_hz: float, order: int = DEFAULT_ORDER) -> np.ndarray:
    """Zero-phase Butterworth low-pass of x(t). Uneven samples are filtered
    on the median spacing (adequate for logger jitter, not for gaps)."""
    fs = sample_rate(t)
    if cutoff_hz >= 0.45 * fs or len(x) < 3 * (2 * order + 1):
        return np.asarray(x, dtype=float).copy()
    sos = signal.butter(order, cutoff_hz, fs=fs, output="sos")
    return signal.sosfiltfilt(sos, np.asarray(x, dtype=float))


def excitation_cutoff(t: np.ndarray, x: np.ndarray, harmonics: float = 20.0, floor_hz: float = 5.0) -> float:
    """A cut-off that keeps the excitation: ``harmonics`` times the dominant
    frequency of x, at least ``floor_hz``, at most 0.4 fs."""
    fs = sample_rate(t)
    x = np.asarray(x, float) - np.mean(x)
    if len(x) < 8 or not np.any(x):
        return 0.4 * fs
    spectrum = np.abs(np.fft.rfft(x * np.hanning(len(x))))
    freqs = np.fft.rfftfreq(len(x), 1.0 / fs)
    dominant = freqs[1:][np.argmax(spectrum[1:])] if len(freqs) > 1 else floor_hz
    return float(min(max(harmonics * dominant, floor_hz), 0.4 * fs))


def nrmse(measured: np.ndarray, simulated: np.ndarray) -> float:
    """RMS(measured - simulated) / (max - min of measured) (docs/formats.md)."""
    measured = np.asarray(measured, float)
    span = float(np.max(measured) - np.min(measured))
    rms = float(np.sqrt(np.mean((measured - np.asarray(simulated, float)) ** 2)))
    return rms / span if span > 0 else float("inf")
