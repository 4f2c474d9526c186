"""The treatment of a measured piezo voltage (sizing/diagnose/inputs.py)
against the clean signal it was made from."""
import numpy as np

from sizing.diagnose.inputs import JUMP_SIGMAS, treat_voltage


def _noisy(v, sigma, seed=0):
    return v + np.random.default_rng(seed).normal(0.0, sigma, v.size)


def test_a_step_stays_sharp():
    sigma = 0.3
    clean = np.r_[np.zeros(300), np.full(300, 100.0)]
    noisy = _noisy(clean, sigma, seed=1)
    assert int(np.sum(np.abs(np.diff(noisy)) > JUMP_SIGMAS * sigma)) == 1
    treated = treat_voltage(noisy)
    assert abs(treated[299]) < 3 * sigma and abs(treated[300] - 100.0) < 3 * sigma

