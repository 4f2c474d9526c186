"""The treatment of a measured piezo voltage (sizing/diagnose/inputs.py)
against the clean signal it was made from."""
import numpy as np
import pytest

from sizing.diagnose.inputs import drive_noise_sigma, noise_sigma, treat_voltage
from sizing.diagnose.settings import DEFAULT


def _noisy(v, sigma, seed=0):
    return v + np.random.default_rng(seed).normal(0.0, sigma, v.size)


def test_a_step_stays_sharp():
    sigma = 0.3
    clean = np.r_[np.zeros(300), np.full(300, 100.0)]
    noisy = _noisy(clean, sigma, seed=1)
    assert int(np.sum(np.abs(np.diff(noisy)) > DEFAULT.jump_sigmas * sigma)) == 1
    treated = treat_voltage(noisy)
    assert abs(treated[299]) < 3 * sigma and abs(treated[300] - 100.0) < 3 * sigma



@pytest.mark.parametrize("hz", [1.0, 20.0, 50.0])
def test_drive_noise_is_not_inflated_by_a_fast_sine(hz):
    """0.3 V of white noise on a 150 V sine sampled at 1 kHz: the drive's
    noise estimate is within 10 % of 0.3 V at any of these frequencies;
    the second differences alone read 0.95 V at 20 Hz and 6 V at 50 Hz
    (150 V x (2 pi f dt)^2 of sine in each difference)."""
    rng = np.random.default_rng(3)
    t = np.arange(0.0, 2.0, 1e-3)
    v = 150.0 * np.sin(2 * np.pi * hz * t) + rng.normal(0.0, 0.3, t.size)
    assert drive_noise_sigma(v) == pytest.approx(0.3, rel=0.1)
    if hz >= 20.0:
        assert noise_sigma(v) > 0.9


def test_drive_noise_of_a_staircase_matches_its_white_noise():
    rng = np.random.default_rng(4)
    v = np.repeat(np.arange(8) * 20.0, 250) + rng.normal(0.0, 0.3, 2000)
    assert drive_noise_sigma(v) == pytest.approx(0.3, rel=0.08)
