"""DC motor estimator: c1, c2 of seed eq. 13-14 through the closed loop
(ARL-TR-10251 section 3.2: c1 = -25.5552 1/s, c2 = 2987.02)."""
import warnings

import numpy as np
import pytest

from sizing.errors import FitError
from sizing.fit.dc_motor import DCMotorEstimator, DCRecord
from sizing.sim.dc_motor import DCMotorModel, simulate

C1, C2 = -25.5552, 2987.02     # seed section 3.2


def rig_model(**changes):
    # catalog ultramotion-amcx8b-b0m1: 2 mm lead, 1.25 kHz PID, 10 A limit
    model = DCMotorModel(c1=C1, c2=C2, lead=0.002, rate=1250.0, kp=4000.0, ki=8000.0, kd=0.0,
                         derivative_on_measurement=1.0, current_limit=10.0, torque_constant=0.05)
    return model.replace(**changes) if changes else model


def step_run(noise=0.001, seed=0):
    t = np.arange(0.0, 0.8, 1e-3)
    ref = np.where(t >= 0.05, 0.010, 0.0)                      # 10 mm step
    out = simulate(rig_model(), t, ref)
    x = out["position_m"][0]
    assert np.mean(np.abs(out["current_A"][0]) >= 10.0 - 1e-9) > 0.03   # the current limit is active
    x = x + noise * np.ptp(x) * np.random.default_rng(seed).standard_normal(len(t))
    return DCRecord("step", t, ref, x, source="step.csv")


def test_step_response_gives_c1_c2_back_within_1_percent():
    start = rig_model(c1=-12.0, c2=1500.0)       # the rig file's guess, a factor 2 off
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        est = DCMotorEstimator(start, random_state=0).fit([step_run()])
    assert est.params_["c1"] == pytest.approx(C1, rel=0.01)
    assert est.params_["c2"] == pytest.approx(C2, rel=0.01)
    lo, hi = est.ci95_["c1"]
    assert lo < est.params_["c1"] < hi
    assert est.nrmse_["step"] < 0.002


def test_gains_can_be_fitted_too():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        est = DCMotorEstimator(rig_model(c1=-20.0, c2=2500.0, kp=3000.0), fit_gains=True,
                               random_state=0).fit([step_run(noise=0.0005)])
    assert set(est.params_) == {"c1", "c2", "kp", "ki"}       # kd = 0 stays out
    assert est.params_["c1"] == pytest.approx(C1, rel=0.02)
    assert est.params_["kp"] == pytest.approx(4000.0, rel=0.05)


def test_constant_reference_is_rejected():
    t = np.arange(0.0, 0.2, 1e-3)
    rec = DCRecord("flat", t, np.zeros_like(t), 1e-6 * np.sin(t), source="flat.csv")
    with pytest.raises(FitError, match="flat.csv: column reference_m: constant reference"):
        DCMotorEstimator(rig_model()).fit([rec])
