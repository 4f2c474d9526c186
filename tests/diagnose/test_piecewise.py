"""The piecewise-linear reading of a logged command (sizing/diagnose/piecewise.py)
against the clean signals it was made from."""
import numpy as np
import pytest

from sizing.diagnose.inputs import noise_sigma, treat_voltage
from sizing.diagnose.piecewise import hat_fit, kink_candidates, piecewise_linear
from .excitations import ramp_and_hold_500hz

T = np.arange(0.0, 2.0, 1e-3)


def _staircase():
    """Levels held 0.25 s, each step commanded as a 40 ms ramp (up to 2.25 V a sample)."""
    levels = np.array([0, 0.4, 0.9, 0.6, 0.1, 0.75, 0.3, 0.0]) * 150.0
    edges = np.arange(1, 8) * 0.25
    knots_t = np.ravel([[e, e + 0.04] for e in edges])
    knots_v = np.ravel([[a, b] for a, b in zip(levels[:-1], levels[1:])])
    return np.interp(T, np.r_[0.0, knots_t], np.r_[0.0, knots_v]), np.round(knots_t * 1000).astype(int)


def test_hat_fit_is_exact_on_its_own_knots():
    # a piecewise-linear signal with corners at 300 and 700 is reproduced exactly
    v = np.interp(np.arange(1000), [0, 300, 700, 999], [1.0, 4.0, -2.0, -2.5])
    fit = hat_fit(v, np.array([0, 300, 700, 999]))
    assert np.max(np.abs(fit - v)) < 1e-9
    # and a line through one knot fewer is the least-squares line: residual orthogonal to 1 and t
    fit = hat_fit(v, np.array([0, 999]))
    r = v - fit
    assert abs(r.sum()) < 1e-6 * len(v) and abs((r * np.arange(1000)).sum()) < 1e-3 * len(v) ** 2


def test_corners_of_a_ramped_staircase_are_found_to_two_samples():
    clean, corners = _staircase()
    noisy = clean + np.random.default_rng(1).normal(0.0, 0.3, T.size)
    found = np.array(kink_candidates(noisy, noise_sigma(noisy)))
    nearest = np.abs(found[:, None] - corners[None, :]).min(axis=0)
    assert np.all(nearest <= 2), nearest


def test_staircase_error_is_ten_times_below_the_noise():
    """A 4-sample Gaussian rounds each ramp corner by up to 2 V; the
    piecewise-linear fit leaves less than a tenth of the 0.3 V noise."""
    clean, _ = _staircase()
    noisy = clean + np.random.default_rng(2).normal(0.0, 0.3, T.size)
    fit = piecewise_linear(noisy, noise_sigma(noisy))
    assert fit is not None
    assert np.sqrt(np.mean((fit - clean) ** 2)) < 0.03
    assert np.sqrt(np.mean((treat_voltage(noisy) - clean) ** 2)) < 0.03


def test_a_sine_is_not_read_as_piecewise_linear():
    v = 75.0 + 75.0 * np.sin(2 * np.pi * 3 * T) + np.random.default_rng(3).normal(0.0, 0.3, T.size)
    assert piecewise_linear(v, noise_sigma(v)) is None
    # and the treatment still follows it (the Gaussian path) within the noise
    assert np.sqrt(np.mean((treat_voltage(v) - (75.0 + 75.0 * np.sin(2 * np.pi * 3 * T))) ** 2)) < 0.3


def test_noise_alone_gives_a_line():
    v = 5.0 + np.random.default_rng(4).normal(0.0, 0.3, T.size)
    fit = piecewise_linear(v, noise_sigma(v))
    assert fit is not None
    assert np.allclose(np.diff(fit, 2), 0.0, atol=1e-9)       # one straight line: no knot paid its penalty


def _ramp_and_hold_500hz(seed: int, sigma: float, step: float = 0.02):
    """Levels 40-150 V held 0.45 s, joined by 220 V/s ramps (0.44 V a
    sample at 500 Hz), so that the corners fall between samples; logged
    with white noise ``sigma`` and quantised on ``step``."""
    t, clean = ramp_and_hold_500hz()
    noisy = np.round((clean + np.random.default_rng(seed).normal(0.0, sigma, t.size)) / step) * step
    return clean, noisy


def test_a_high_hold_is_no_kink():
    """The curvature kernel sums to zero: a hold at 150 V with 0.03 V of
    noise shows no kink (the truncated Gaussian kernel answered the level
    itself, 0.013 V at 2 samples against a threshold of 0.012 V, and at
    every sample of the hold)."""
    v = 150.0 + np.random.default_rng(6).normal(0.0, 0.03, 2000)
    assert kink_candidates(v, 0.03) == []


def test_quantised_voltage_noise_is_read_whole():
    """0.015 V of noise quantised on 0.02 V: the log's noise is the rms of
    the two, 0.0153 V; the median absolute deviation of its differences
    sits on the grid (0.012 V)."""
    from sizing.diagnose.inputs import drive_noise_sigma

    clean, noisy = _ramp_and_hold_500hz(7, 0.015)
    assert drive_noise_sigma(noisy) == pytest.approx(np.std(noisy - clean), rel=0.05)


@pytest.mark.parametrize("sigma", [0.015, 0.03])
def test_ramp_and_hold_at_500_hz_with_corners_between_samples(sigma):
    """Each corner is found between its two samples: the treated voltage
    errs by less than a fifth of the noise (knots held to samples left
    0.018 V at 0.03 V of noise, and at 0.015 V the log was not read as
    piecewise linear at all)."""
    clean, noisy = _ramp_and_hold_500hz(8, sigma)
    from sizing.diagnose.inputs import drive_noise_sigma

    assert piecewise_linear(noisy, drive_noise_sigma(noisy)) is not None
    assert np.sqrt(np.mean((treat_voltage(noisy) - clean) ** 2)) < 0.2 * sigma


def _hat_fit_numpy(v, knots):
    """hat_fit as numpy and scipy compute it: np.bincount's sums, solve_banded."""
    from scipy.linalg import solve_banded

    t = np.arange(len(v))
    m = len(knots)
    j = np.clip(np.searchsorted(knots, t, side="right") - 1, 0, m - 2)
    w = (t - knots[j]) / (knots[j + 1] - knots[j])
    bands = np.zeros((3, m))
    off = np.bincount(j, w * (1 - w), m)[:m - 1]
    bands[0, 1:], bands[2, :-1] = off, off
    bands[1] = np.bincount(j, (1 - w) ** 2, m) + np.bincount(j + 1, w ** 2, m)
    rhs = np.bincount(j, (1 - w) * v, m) + np.bincount(j + 1, w * v, m)
    c = solve_banded((1, 1), bands, rhs)
    return c[j] * (1 - w) + c[j + 1] * w


def test_compiled_hat_fit_is_numpy_and_lapack_to_the_last_bit():
    # the knot search depends on the fit's last bits (its minimiser's path):
    # the compiled fit sums and solves in the same order as np.bincount and LAPACK's dgtsv
    rng = np.random.default_rng(4)
    for trial in range(300):
        n = int(rng.integers(8, 2500))
        m = int(rng.integers(2, min(n // 4, 40) + 2))
        knots = np.r_[0.0, np.sort(rng.choice(np.arange(2, n - 2), m - 2, replace=False)
                                   + rng.uniform(-0.4, 0.4, m - 2)), n - 1.0]
        v = np.cumsum(rng.normal(size=n)) * rng.uniform(0.01, 50.0) + rng.uniform(-150.0, 150.0)
        assert hat_fit(v, knots).tobytes() == _hat_fit_numpy(v, knots).tobytes()


def test_compiled_tridiagonal_solve_is_lapack_with_row_interchanges():
    # the kernel's call into LAPACK passes each band where dgtsv reads it:
    # random systems pivot, so a sub- and super-diagonal swapped would show
    from scipy.linalg import solve_banded

    from sizing.diagnose.piecewise import _gtsv, _link_dgtsv

    _link_dgtsv()
    rng = np.random.default_rng(5)
    for trial in range(500):
        n = int(rng.integers(2, 30))
        dl, d, du, b = rng.normal(size=n - 1), rng.normal(size=n), rng.normal(size=n - 1), rng.normal(size=n)
        ab = np.zeros((3, n))
        ab[0, 1:], ab[1], ab[2, :-1] = du, d, dl
        x = b.copy()
        assert _gtsv(dl.copy(), d.copy(), du.copy(), x) == 0
        assert x.tobytes() == solve_banded((1, 1), ab, b).tobytes()


# A fresh process: importing the module leaves LLVM's symbol table alone;
# the first fit gives dgtsv its name and runs the kernel numba cached
FRESH = """
import numpy as np, llvmlite.binding as llvm
from sizing.diagnose import piecewise
before = llvm.address_of_symbol(piecewise._DGTSV_SYMBOL)
fit = piecewise.hat_fit(np.cos(np.arange(400.0) / 37.0), np.array([0.0, 50.5, 120.0, 399.0]))
print(before, llvm.address_of_symbol(piecewise._DGTSV_SYMBOL) is not None,
      sum(piecewise._hat_fit.stats.cache_hits.values()), fit.tobytes().hex())
"""


def test_import_registers_nothing_and_a_second_process_loads_the_cached_kernel():
    import subprocess
    import sys

    runs = [subprocess.run([sys.executable, "-c", FRESH], capture_output=True, text=True, check=True).stdout.split()
            for _ in range(2)]                  # the first may compile and cache; the second loads
    fit = hat_fit(np.cos(np.arange(400.0) / 37.0), np.array([0.0, 50.5, 120.0, 399.0]))
    for before, linked, _, fit_hex in runs:
        assert before == "None" and linked == "True"
        assert fit_hex == fit.tobytes().hex()
    assert int(runs[1][2]) >= 1


def test_a_singular_system_names_its_pivot():
    from scipy.linalg import LinAlgError

    from sizing.diagnose.piecewise import _gtsv, _link_dgtsv

    _link_dgtsv()
    # the second row is zero: LAPACK's info names pivot 2
    assert _gtsv(np.zeros(2), np.array([1.0, 0.0, 1.0]), np.zeros(2), np.ones(3)) == 2
    with pytest.raises(LinAlgError):
        hat_fit(np.ones(10), np.array([0.0, 0.3, 0.6, 9.0]))        # the hat at 0.3 covers no sample


def test_hinge_by_projections_is_the_normal_equations_hinge():
    from sizing.diagnose import piecewise

    rng = np.random.default_rng(6)
    for trial in range(300):
        s = int(rng.choice([2, 5, 12, 30]))
        n = 8 * s + 40
        offset = int(rng.choice([0, 1000, 3000]))
        corner = n // 2 + rng.uniform(-s, s)
        v = np.interp(np.arange(n), [0, corner, n - 1], rng.uniform(-150, 150, 3)) + rng.normal(0, 0.03, n)
        v = np.r_[np.full(offset, v[0]), v]
        i = offset + n // 2
        lo, hi = max(i - 3 * s - 2, 0), min(i + 3 * s + 3, len(v))
        taus = np.arange(max(i - 2 * s, lo + 1), min(i + 2 * s + 1, hi - 1))
        t = np.arange(lo, hi, dtype=float)
        H = np.maximum(t[None, :] - taus[:, None], 0.0)
        normal = int(taus[np.argmin(piecewise._hinge_rss_normal(v[lo:hi], t, H))])
        assert piecewise.best_hinge(v, i, s) == normal


def test_a_treated_log_is_answered_from_memory_as_a_copy():
    rng = np.random.default_rng(7)
    v = _staircase()[0] + rng.normal(0, 0.03, len(T))
    first = treat_voltage(v)
    first[:] = 0.0                                    # the caller's copy, not the one kept
    again = treat_voltage(v.copy())
    assert np.array_equal(again, treat_voltage(v + 0.0)) and np.ptp(again) > 100.0


def test_a_treated_log_is_kept_by_log_and_settings(monkeypatch):
    from dataclasses import replace

    from sizing.diagnose import inputs

    v = _staircase()[0] + np.random.default_rng(8).normal(0, 0.03, len(T))
    inputs._treated.cache_clear()
    first = treat_voltage(v)
    assert np.array_equal(treat_voltage(v), first) and inputs._treated.cache_info().hits == 1
    treat_voltage(v + 1e-9)                           # another log: treated
    monkeypatch.setattr(inputs, "DEFAULT", replace(inputs.DEFAULT, smooth_samples=9.0))
    treat_voltage(v)                                  # other settings: treated again
    assert inputs._treated.cache_info().misses == 3
