"""The treatment of a measured piezo voltage (sizing/diagnose/inputs.py)
against the clean signal it was made from."""
import numpy as np

from sizing.diagnose.inputs import JUMP_SIGMAS, step_edges, treat_voltage


def _noisy(v, sigma, seed=0):
    return v + np.random.default_rng(seed).normal(0.0, sigma, v.size)


def test_a_fast_ramp_at_the_jump_threshold_is_not_cut_into_pieces():
    # a 40-sample ramp whose per-sample change equals the jump threshold:
    # noise pushes half its samples over it; none of them is a jump
    sigma = 0.3
    slope = JUMP_SIGMAS * sigma
    clean = np.concatenate([np.zeros(200), slope * np.arange(1, 41), np.full(200, 40 * slope)])
    noisy = _noisy(clean, sigma)
    assert step_edges(noisy, sigma).size == 0
    treated = treat_voltage(noisy)
    ramp = slice(205, 235)                     # away from the corners the low-pass rounds
    assert np.sqrt(np.mean((treated[ramp] - clean[ramp]) ** 2)) < 1.5 * sigma   # no worse than the log


def test_a_step_stays_sharp():
    sigma = 0.3
    clean = np.r_[np.zeros(300), np.full(300, 100.0)]
    noisy = _noisy(clean, sigma, seed=1)
    assert list(step_edges(noisy, sigma)) == [300]
    treated = treat_voltage(noisy)
    assert abs(treated[299]) < 3 * sigma and abs(treated[300] - 100.0) < 3 * sigma


def test_treated_voltage_is_closer_to_the_clean_one_than_the_log():
    """The second generator's own excitations (a slow trapezoid, staircases
    of 40 ms ramps) logged with its own sensor model (0.3 V white, 1/f,
    10 mV steps): the treated voltage is nearer the clean voltage than the
    log is, on every run and seed."""
    import sys
    from pathlib import Path
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    from benchmarks.crossform import piezo
    from benchmarks.crossform.common import measure

    refs, _ = piezo.excitations(150.0)
    for seed in range(3):
        rng = np.random.default_rng(seed)
        for name, clean in refs.items():
            logged = measure(clean, rng, 0.3, 0.05, 0.01)
            raw = np.sqrt(np.mean((logged - clean) ** 2))
            treated = np.sqrt(np.mean((treat_voltage(logged) - clean) ** 2))
            assert treated < 0.75 * raw, (name, seed, treated, raw)
