"""Step-response figures by hand, and a candidate's figures read over its
own run only: the same whatever longer runs it was simulated beside."""
import numpy as np
import pytest

from sizing.sim.metrics import final_value, step_metrics

T = np.arange(0.0, 2.0001, 0.01)


def ramp(rate, t=T):
    return np.minimum(rate * t, 0.03)


def test_figures_by_hand():
    m = step_metrics(T, ramp(0.05)[None, :], np.array([0.02]))
    assert m["time_to_stroke_s"][0] == pytest.approx(0.4)          # 0.02 m at 0.05 m/s
    assert m["speed_m_s"][0] == pytest.approx(0.05)
    assert m["stroke_m"][0] == pytest.approx(0.03) and m["overshoot"][0] == 0.0


def test_a_missed_target_over_the_candidates_own_run():
    """0.01 m/s never reaches 0.04 m: over a 1 s run it travels 0.01 m, so
    its speed is 0.01 m/s whether the batch's run lasts 1 s or 2 s."""
    y = np.vstack([ramp(0.01), ramp(0.1)])
    alone = step_metrics(T[T <= 1.0], y[:1, T <= 1.0], np.array([0.04]))
    beside = step_metrics(T, y, np.array([0.04, 0.02]), horizon=np.array([1.0, 2.0]))
    for key in ("stroke_m", "peak_m", "speed_m_s", "time_to_stroke_s"):
        assert beside[key][0] == pytest.approx(alone[key][0]), key
    assert beside["speed_m_s"][0] == pytest.approx(0.01)
    assert final_value(T, y, np.array([1.0, 2.0])) == pytest.approx([0.01, 0.03])
    # without a horizon the whole run is read (a single candidate's own run)
    assert step_metrics(T, y[:1], np.array([0.04]))["stroke_m"][0] == pytest.approx(0.02)
