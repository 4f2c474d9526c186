"""The widened DC effect forms (command/drive current limit,
Coulomb/Stribeck friction, play/coasting backlash): hand-computed numbers,
and the library holds them as alternatives of one family."""
import numpy as np
import pytest

from sizing.diagnose.effects import backlash, coulomb_friction, current_saturation, library
from sizing.sim.dc_motor import DCMotorModel


def _ramp_and_stop(v=0.01, t_stop=0.2):
    t = np.arange(0.0, 0.5, 1e-3)
    y = np.clip(t - 0.1, 0.0, t_stop - 0.1) * v
    return t, y


def test_play_dead_band_output():
    """A ramp of 1 mm through a 0.4 mm play: the output is y - 0.2 mm once
    the play is taken up, and stays there."""
    t, y = _ramp_and_stop()
    out = backlash.play(y, 4e-4)
    assert out[-1] == pytest.approx(1e-3 - 2e-4, abs=1e-15)
    assert np.all(out[t < 0.12] == 0.0)                          # inside the first half-gap (0.2 mm at 10 mm/s)


def test_coasting_load_runs_on_by_v_tau():
    """The motor stops dead at 10 mm/s; the free load coasts v tau = 0.1 mm
    further (geometric sum of the exact exponential steps), inside the 1 mm gap."""
    t, y = _ramp_and_stop()
    out = backlash.coasting(t, y, 1e-3, 0.01)
    assert out[-1] == pytest.approx(1e-3 - 5e-4 + 0.01 * 0.01, rel=1e-6)


def test_coasting_stops_at_the_far_flank():
    """A coast longer than the gap ends on the other flank: y + b/2."""
    t, y = _ramp_and_stop()
    out = backlash.coasting(t, y, 1e-4, 0.05)                   # v tau = 0.5 mm > 0.1 mm gap
    assert out[-1] == pytest.approx(1e-3 + 5e-5, abs=1e-12)


def test_coasting_without_inertia_is_the_play_operator():
    t, y = _ramp_and_stop()
    y = y - 0.5 * np.clip(t - 0.3, 0, 0.1) * 0.01
    np.testing.assert_array_equal(backlash.coasting(t, y, 3e-4, 0.0), backlash.play(y, 3e-4))


def test_forms_map_to_the_simulator_fields():
    model = DCMotorModel(c1=-25.0, c2=3000.0, lead=2e-3, current_limit=8.0)
    drive = current_saturation.DRIVE
    assert drive.sizes_for(None, model) == ({"current_limit_A": 4.0}, {"current_limit_A": 2.0})
    assert drive.model_changes(model, {"current_limit_A": np.array([3.0])}) == {"drive_current_limit": np.array([3.0])}
    assert current_saturation.COMMAND.model_changes(model, {"current_limit_A": 3.0}) == {"current_limit": 3.0}
    ch = coulomb_friction.STRIBECK.model_changes(model, {"coulomb_friction_N": np.array([20.0]), "static_ratio": np.array([1.5]),
                                                        "stribeck_velocity_m_s": np.array([1e-3])})
    assert ch["coulomb_friction"][0] == 20.0 and ch["static_friction"][0] == 30.0 and ch["stribeck_velocity"][0] == 1e-3


def test_dc_library_forms_are_alternatives_of_one_family():
    forms = {}
    for e in library("dc_motor"):
        forms.setdefault(e.name, set()).add(e.form)
    assert forms["current_saturation"] == {"command", "drive"}
    assert forms["coulomb_friction"] == {"coulomb", "stribeck", "asymmetric"}
    assert forms["backlash"] == {"play", "coasting", "in_loop"}
    for e in library("dc_motor"):
        assert e.source and len(e.sizes_for(None, DCMotorModel(c1=-25.0, c2=3000.0, lead=2e-3, current_limit=8.0))) == 2


def test_asymmetric_friction_in_the_closed_loop_by_hand():
    """A slow ramp out and back on the seed's servo: at constant speed w the
    held current is i = F to_i - c1 w / c2 (eq. 13 at rest acceleration), so
    the currents moving out (F+) and in (F-) at one speed sum to (F+ - F-) to_i
    and differ by (F+ + F-) to_i - 2 c1 |w| / c2 (to_i = lead / (2 pi eta k_t))."""
    from sizing.io.rig import load_rig
    from sizing.sim import dc_motor
    from sizing.sim.rigs import dc_model

    model = dc_model(load_rig("studies/campaigns/dc-motor/rig.toml"))
    up, down = 40.0, 15.0
    changed = model.replace(**coulomb_friction.ASYMMETRIC.model_changes(
        model, {"extend_friction_N": np.array([up]), "retract_friction_N": np.array([down])}))
    t = np.arange(0.0, 2.0, 1e-3)
    speed = 0.01                                              # m/s, both ways
    y = np.where(t < 1.0, speed * t, speed * (2.0 - t))
    current = dc_motor.simulate(changed, t, y)["current_A"][0]
    i_out, i_in = np.median(current[(t > 0.6) & (t < 0.95)]), np.median(current[(t > 1.6) & (t < 1.95)])
    lead = float(np.atleast_1d(model.lead)[0])
    to_i = lead / (2 * np.pi * float(np.atleast_1d(model.efficiency)[0]) * float(np.atleast_1d(model.torque_constant)[0]))
    w = speed * 2 * np.pi / lead
    c1, c2 = float(np.atleast_1d(model.c1)[0]), float(np.atleast_1d(model.c2)[0])
    assert i_out + i_in == pytest.approx((up - down) * to_i, rel=0.02)
    assert i_out - i_in == pytest.approx((up + down) * to_i - 2 * c1 * w / c2, rel=0.02)
    # and the symmetric Coulomb form at the mean force gives equal and opposite currents
    mean = model.replace(coulomb_friction=np.array([0.5 * (up + down)]))
    current = dc_motor.simulate(mean, t, y)["current_A"][0]
    assert np.median(current[(t > 0.6) & (t < 0.95)]) + np.median(current[(t > 1.6) & (t < 1.95)]) == pytest.approx(
        0.0, abs=0.02 * (up - down) * to_i)
