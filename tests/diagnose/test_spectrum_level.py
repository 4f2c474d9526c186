"""The periodogram's local level (a running median) against a plain loop,
and its cost: linear in the run's length, not a window matrix."""
import tracemalloc

import numpy as np
import pytest

from sizing.spectrum import local_level


def loop_median(P: np.ndarray, k: int) -> np.ndarray:
    """Median of P[i-k : i+k+1], the window cut at the spectrum's ends."""
    return np.array([np.median(P[max(i - k, 0):i + k + 1]) for i in range(len(P))])


@pytest.mark.parametrize("n, half_width", [(3, 10.0), (9, 2.0), (501, 10.0), (2000, 37.0)])
def test_local_level_is_the_running_median_of_a_loop(n, half_width):
    rng = np.random.default_rng(n)
    f = np.arange(n) * 0.5                      # 0.5 Hz bins
    P = rng.exponential(size=n) * (1 + f)       # a sloping noise spectrum
    k = max(int(round(half_width / 0.5)), 2)
    np.testing.assert_allclose(local_level(f, P, half_width), loop_median(P, k), rtol=1e-12)


def test_local_level_memory_is_linear_in_the_run():
    """A 100 000-bin spectrum (a 200 000-sample run of 100 s) with a 20 Hz
    window at 0.01 Hz bins: a window matrix would be 100 000 x 2001 doubles
    (1.6 GB); the running median stays within a few copies of the input."""
    n = 100_000
    f = np.arange(n) * 1e-2
    P = np.random.default_rng(1).exponential(size=n)
    tracemalloc.start()
    level = local_level(f, P, half_width=10.0)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert level.shape == P.shape
    assert peak < 20 * P.nbytes, f"{peak / 1e6:.0f} MB for a {P.nbytes / 1e6:.0f} MB spectrum"
