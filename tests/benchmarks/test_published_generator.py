"""The third generator (benchmarks/published): the published parameters,
and the paper's servo without friction against its continuous closed
loop."""
from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

from benchmarks.published import cases, servo


def test_table_i_values_are_the_published_ones():
    """Canudas de Wit et al. 1995, Table I."""
    assert servo.TABLE_I == pytest.approx(dict(sigma0=1e5, sigma1=316.2278, sigma2=0.4, fc=1.0, fs=1.5, vs=0.001),
                                          rel=1e-6)


def test_frictionless_servo_follows_the_continuous_closed_loop():
    """M x'' = -Kv x' - Kp (x - xd) - Ki int (x - xd): X/Xd = (Kp s + Ki) /
    (M s^3 + Kv s^2 + Kp s + Ki); the 1 kHz sampled loop follows it to
    within 1 % of the step."""
    t = np.arange(0.0, 8.0, 1e-3)
    xd = np.where(t >= 0.5, 1.0, 0.0)
    x, _u = servo.simulate(t, xd, None)
    loop = signal.lti([servo.PID["kp"], servo.PID["ki"]],
                      [servo.MASS, servo.PID["kv"], servo.PID["kp"], servo.PID["ki"]])
    _, expected, _ = signal.lsim(loop, xd, t)
    assert np.max(np.abs(x - expected)) < 0.01


def test_cases_have_their_truth_and_write_a_campaign():
    dev = cases.case_set("dev")
    assert {c.truth for c in dev.cases} == {"none", "coulomb_friction"}
    rig, runs, holdout = cases.generate(dev.cases[0])
    assert holdout in runs and set(runs[holdout]) == {"time_s", "reference_m", "position_m", "current_A"}
    assert 'kind = "dc_motor"' in rig
