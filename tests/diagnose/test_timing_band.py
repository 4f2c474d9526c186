"""The current's one-sample timing tolerance (bench.timing_band)."""
import numpy as np

from sizing.diagnose.bench import timing_band


def test_a_jump_one_sample_late_or_early_leaves_no_gap():
    simulated = np.array([0.0, 0.0, 0.0, -10.0, -10.0, -10.0])
    late = np.array([0.0, 0.0, 0.0, 0.0, -10.0, -10.0])
    early = np.array([0.0, 0.0, -10.0, -10.0, -10.0, -10.0])
    midway = np.array([0.0, 0.0, 0.0, -6.0, -10.0, -10.0])   # a held command sampled mid-jump
    for measured in (late, early, midway):
        assert np.allclose(timing_band(measured, simulated), 0.0)


def test_a_jump_two_samples_late_is_a_gap():
    simulated = np.array([0.0, 0.0, -10.0, -10.0, -10.0, -10.0])
    measured = np.array([0.0, 0.0, 0.0, 0.0, -10.0, -10.0])
    gap = timing_band(measured, simulated)
    assert gap[3] == 10.0 and np.count_nonzero(gap) == 1     # hand: sample 3's band is [-10, -10]


def test_a_level_offset_is_measured_in_full():
    # friction shows as a level: 1.5 A more everywhere on a slowly varying current
    simulated = np.linspace(0.0, 0.1, 50)
    gap = timing_band(simulated + 1.5, simulated)
    step = 0.1 / 49
    assert np.allclose(gap[1:-1], 1.5 - step)             # less by the band's half-width: one sample's change
    assert np.allclose(np.sqrt(np.mean(gap ** 2)), 1.5, rtol=0.01)


def test_batches_of_candidates_are_handled_row_by_row():
    simulated = np.array([[0.0, 1.0, 2.0], [5.0, 5.0, 5.0]])
    measured = np.array([1.0, 1.0, 1.0])
    gap = timing_band(measured, simulated)
    assert np.allclose(gap[0], 0.0) and np.allclose(gap[1], -4.0)
