"""Batch simulator of the piezohydraulic actuator: closed-form limits and
stick-slip behaviour."""
import numpy as np
import pytest

from sizing.physics import hydraulics
from sizing.sim.piezohydraulic import PiezoHydraulicModel, simulate

A_W, A_N = float(hydraulics.area(3.75 * 0.0254)), float(hydraulics.area(0.375 * 0.0254))  # seed Table 3, R = 100
K = 3 * 1.96e7


def prototype(**changes):
    base = dict(k_stacks=K, d33=6.7e-7, alpha=0.0, beta=0.0, gamma=0.0, delta=0.0, n_bw=1.0,
                wide_area=A_W, narrow_area=A_N, oil_volume=A_W * 3e-3 + A_N * 0.02, bulk_modulus=1.5e9,
                narrow_mass=0.02)
    base.update(changes)
    return PiezoHydraulicModel(**base)


def slow_ramp(v_max=150.0, rise=0.5, hold=0.3):
    t = np.linspace(0, rise + hold, int((rise + hold) * 2000) + 1)
    return t, np.clip(t / rise, 0, 1) * v_max


def settled(y):
    """Mean over the last 0.1 s: the frictionless stage rings lightly."""
    return float(np.mean(y[-200:]))


def k_out(model):
    k_f = model.bulk_modulus * model.wide_area**2 / model.oil_volume
    return K * k_f / (K + k_f) / (A_W / A_N) ** 2


def test_heavy_viscous_damping_is_a_first_order_lag_of_c_over_k():
    """A frictionless output with damping c far above sqrt(k m) follows a
    voltage step as y_f (1 - exp(-t / tau)), tau = c / k_out (k_out: the
    stacks in series with the oil, seen through R^2). With tau = 20 ms,
    m / c = 0.17 ms: the inertia is negligible, and the implicit damping
    step must keep the lag at the oil mode's step (an explicit one needs
    dt < 2 m / c)."""
    model = prototype()
    tau = 0.02
    damped = prototype(viscous_damping=tau * k_out(model))
    t = np.arange(0.0, 0.15, 1e-4)
    v = np.where(t >= 0.01, 150.0, 0.0)
    y = simulate(damped, t, v, t)["position_m"][0]
    y_f = 100 * 6.7e-7 * 150
    after = t >= 0.0101
    lag = y_f * (1.0 - np.exp(-(t[after] - 0.01) / tau))
    np.testing.assert_allclose(y[after], lag, rtol=0, atol=0.01 * y_f)


def test_linear_frictionless_stroke_is_R_d33_V():
    t, v = slow_ramp()
    y = simulate(prototype(), t, v)["position_m"][0]
    assert settled(y) == pytest.approx(100 * 6.7e-7 * 150, rel=1e-3)


def test_constant_load_does_not_change_travel_from_loaded_rest():
    """The model starts at static equilibrium under the load (docs/formats.md)."""
    t, v = slow_ramp()
    out = simulate(prototype(load_force=np.array([0.0, 30.0])), t, v)
    y = out["position_m"]
    assert y[1, -1] == pytest.approx(y[0, -1], rel=1e-3)
    # Pascal at rest: pressure x narrow area carries the load exactly
    assert out["pressure_Pa"][1, 0] * A_N == pytest.approx(30.0, rel=1e-9)


def test_load_spring_closed_form_with_fluid_compliance():
    """Output spring k_L against the actuator's output stiffness k_out
    (stacks and oil in series, reflected by R^2): y = S k_out / (k_out + k_L)."""
    model = prototype(load_stiffness=5000.0)
    t, v = slow_ramp()
    y = settled(simulate(model, t, v)["position_m"][0])
    S = 100 * 6.7e-7 * 150
    assert y == pytest.approx(S * k_out(model) / (k_out(model) + 5000.0), rel=1e-3)


def test_pascal_principle_held_voltage():
    """With zero flow the stage obeys Pascal: the stack force equals p A_w
    and p A_n equals the load."""
    t = np.linspace(0, 0.5, 1001)
    v = np.full_like(t, 100.0)
    model = prototype(load_force=20.0)
    out = simulate(model, t, v)
    p = out["pressure_Pa"][0, -1]
    x = out["wide_position_m"][0, -1]
    assert K * (6.7e-7 * 100 - x) == pytest.approx(p * A_W, rel=1e-9)
    assert p * A_N == pytest.approx(20.0, rel=1e-9)


def test_coulomb_friction_leaves_a_dead_band():
    """Narrow seal friction F_c on a frictionless ramp: at the end of the
    ramp the piston stops short by at most F_c / k_out."""
    t, v = slow_ramp(rise=0.5, hold=0.5)
    model = prototype(narrow_friction=2.0)
    y = simulate(model, t, v)["position_m"][0, -1]
    S = 100 * 6.7e-7 * 150
    assert S - 2.0 / k_out(model) - 1e-6 <= y <= S + 1e-9


def test_stick_slip_moves_in_steps_without_chattering():
    """Breakaway 4x running friction on the output seal, slow drive: the
    output advances in distinct slips separated by stuck intervals, and never
    reverses (chattering would show as velocity sign flips)."""
    t, v = slow_ramp(rise=1.0, hold=0.0)
    model = prototype(narrow_friction=1.0, narrow_breakaway=4.0)
    y = simulate(model, t, v)["position_m"][0]
    dy = np.diff(y)
    stuck = np.abs(dy) < 1e-12
    assert stuck.mean() > 0.5                   # mostly stuck
    slips = np.count_nonzero(np.diff(stuck.astype(int)) == -1)
    assert 3 <= slips < 200                     # a staircase, not a buzz
    assert np.all(dy > -1e-9)                   # never moves backwards


def test_no_return_keeps_the_output_out():
    """Without a return mechanism the stacks cannot pull the piston back."""
    t = np.linspace(0, 1.0, 2001)
    v = np.interp(t, [0, 0.4, 0.8, 1.0], [0, 150, 0, 0])
    model = prototype(no_return=np.array([0.0, 1.0]), narrow_friction=0.2)
    y = simulate(model, t, v)["position_m"]
    assert abs(y[0, -1]) < 1e-4                 # with return: back at rest
    assert y[1, -1] > 0.9 * y[1].max()          # without: stays out


def test_batch_equals_single_runs():
    t, v = slow_ramp()
    frictions = np.array([0.0, 0.5, 2.0])
    batch = simulate(prototype(narrow_friction=frictions), t, v)["position_m"]
    for i, f in enumerate(frictions):
        single = simulate(prototype(narrow_friction=f), t, v)["position_m"][0]
        np.testing.assert_array_equal(batch[i], single)


def test_candidates_of_one_drive_share_it_and_mixed_batches_equal_single_runs(monkeypatch):
    """Candidates with the same amplifier, loop, step and voltage share one
    integration of the drive; a batch mixing drives, gains, creep and steps,
    cut into slices of one shared drive, or with a voltage row each, gives
    each candidate's single run to the bit."""
    from sizing.sim import piezohydraulic as ph

    t, v = slow_ramp()
    loop = dict(alpha=0.13, beta=7.5e4, gamma=-5.5e4, n_bw=1.14, slew_rate=400.0, amp_bandwidth=600.0)
    cases = [dict(narrow_friction=0.5), dict(narrow_friction=2.0, d33=7.0e-7),
             dict(creep_fraction=0.05, creep_time=0.1), dict(bulk_modulus=0.8e9),
             dict(bulk_modulus=0.8e9, narrow_friction=1.0), dict(slew_rate=200.0),
             dict(slew_rate=200.0, leak_conductance=1e-13), dict(delta=-5e-8, hold_rate=3.0)]
    rows = [loop | c for c in cases]
    batch = ph.PiezoHydraulicModel(**{k: np.array([r.get(k, getattr(prototype(**loop), k)) for r in rows])
                                      for k in set().union(*rows) | set(prototype().__dict__)})
    P = batch.matrix()
    (_, drivers, driver_of, kept), = ph._drive_groups(P, ph.stable_step(P), 0, t)
    # friction, gain and creep are not part of the drive; the stiffer oil's
    # step, the slower slew and the delta term are: four drives, three shared
    assert len(drivers) == 4 and np.count_nonzero(kept >= 0) == 3
    assert len(set(driver_of[:3])) == 1 and driver_of[3] == driver_of[4] and driver_of[5] == driver_of[6]
    monkeypatch.setattr(ph, "DRIVE_BYTES", 1)          # one shared drive a slice
    assert len(list(ph._drive_groups(P, ph.stable_step(P), 0, t))) == 3
    voltages = np.vstack([v * (1.0 + 0.1 * i) for i in range(len(rows))])
    for drive in (v, voltages):
        together = simulate(batch, t, drive)
        for i, row in enumerate(rows):
            alone = simulate(prototype(**row), t, drive if drive.ndim == 1 else drive[i])
            for name in ph.CHANNELS:
                np.testing.assert_array_equal(together[name][i], alone[name][0])


def _mixed_batch(n):
    """n candidates of several drives, steps (stiffer oil), seals (LuGre,
    Stribeck), damping, leaks, air and creep."""
    loop = dict(alpha=0.13, beta=7.5e4, gamma=-5.5e4, n_bw=1.14)
    forms = [dict(narrow_friction=0.5), dict(narrow_friction=2.0, narrow_breakaway=2.0, narrow_stribeck_velocity=2e-4),
             dict(viscous_damping=30.0), dict(bulk_modulus=0.8e9), dict(slew_rate=200.0),
             dict(narrow_presliding=2e-6, narrow_friction=1.0, narrow_breakaway=1.5),
             dict(leak_conductance=1e-13, leak_orifice_area=1e-9), dict(air_fraction=0.01),
             dict(creep_fraction=0.05, creep_time=0.1, log_creep=0.01), dict(amp_bandwidth=600.0, delta=-5e-8),
             dict(no_return=1.0, wide_friction=5.0, wide_friction_pressure=1e-6)]
    rows = [loop | forms[i % len(forms)] | {"d33": 6.7e-7 * (1.0 + 0.01 * i)} for i in range(n)]
    names = set().union(*rows) | set(prototype().__dict__)
    return rows, PiezoHydraulicModel(**{k: np.array([r.get(k, getattr(prototype(**loop), k)) for r in rows])
                                        for k in names})


def test_lanes_and_runs_together_equal_single_runs():
    """More candidates than a lane group holds (sim.piezohydraulic.LANES),
    of several drives and steps, on two runs of other lengths and rates in
    one call (``simulate_runs``): each candidate on each run is its single
    run, to the bit."""
    from sizing.sim import piezohydraulic as ph

    rows, batch = _mixed_batch(2 * ph.LANES + 3)
    t1, v1 = slow_ramp()
    t2 = np.linspace(0.0, 0.6, 301)                    # 500 Hz, a sine
    v2 = 60.0 - 60.0 * np.cos(2 * np.pi * 3.0 * t2)
    together = ph.simulate_runs(batch, [(t1, v1, None), (t2, v2, t2)])
    for i, row in enumerate(rows):
        for (t, v), out in zip([(t1, v1), (t2, v2)], together):
            alone = simulate(prototype(**row), t, v)
            for name in ph.CHANNELS:
                np.testing.assert_array_equal(out[name][i], alone[name][0])


def test_a_remembered_drive_gives_the_run_it_was_kept_from():
    """A caller's memory of drives (``simulate_runs(drives=...)``): a small
    call meeting its drives a second time keeps them, a later call reads
    them instead of integrating, and each gives the same figures to the
    bit; it keeps DRIVES_KEPT at most."""
    from sizing.sim import piezohydraulic as ph

    rows, batch = _mixed_batch(4)
    t, v = slow_ramp()
    drives = ph.DriveMemory()
    outs = [ph.simulate_runs(batch, [(t, v, None)], drives=drives, keys=["ramp"])[0]]
    assert not drives.kept and drives.met                     # met once: not kept
    outs.append(ph.simulate_runs(batch, [(t, v, None)], drives=drives, keys=["ramp"])[0])
    kept = dict(drives.kept)
    assert 0 < len(kept) <= 4
    outs.append(ph.simulate_runs(batch, [(t, v, None)], drives=drives, keys=["ramp"])[0])
    assert all(drives.kept[k] is kept[k] for k in kept)        # read, not integrated again
    for i, row in enumerate(rows):
        alone = simulate(prototype(**row), t, v)
        for out in outs:
            for name in ph.CHANNELS:
                np.testing.assert_array_equal(out[name][i], alone[name][0])
    for k in range(ph.DRIVES_KEPT + 2):
        for _ in range(2):
            ph.simulate_runs(prototype(delta=-1e-9 * (k + 1)), [(t, v, None)], drives=drives, keys=["ramp"])
    assert len(drives.kept) == ph.DRIVES_KEPT


def test_rejects_mismatched_input_rows():
    t, v = slow_ramp()
    with pytest.raises(ValueError, match="one row per candidate"):
        simulate(prototype(narrow_friction=np.array([0.0, 1.0, 2.0])), t, np.vstack([v, v]))


def test_pressure_dependent_seal_friction_closed_form():
    """The running friction of a seal grows with the chamber
    pressure, F = F_0 + c p. While the output slides outwards slowly under a
    constant load F_L, A_n p = F_L + F_0 + c p, so p = (F_L + F_0) / (A_n - c)
    (by hand: (100 + 5) / (7.126e-5 - 1e-5) = 1.714 MPa, against 1.473 MPa
    without the pressure term)."""
    t, v = slow_ramp(rise=2.0, hold=0.0)
    c = 1e-5                                   # N/Pa, pi d c_p of the narrow seal (exaggerated to show)
    model = prototype(load_force=100.0, narrow_friction=5.0, narrow_friction_pressure=c, viscous_damping=5.0)
    out = simulate(model, t, v)
    moving = (t > 0.8) & (t < 1.9)
    p = out["pressure_Pa"][0][moving]
    assert np.median(p) == pytest.approx((100.0 + 5.0) / (A_N - c), rel=0.01)
    plain = simulate(prototype(load_force=100.0, narrow_friction=5.0, viscous_damping=5.0), t, v)
    assert np.median(plain["pressure_Pa"][0][moving]) == pytest.approx(105.0 / A_N, rel=0.01)
