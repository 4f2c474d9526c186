"""The widened effect forms of the piezohydraulic
simulator, each against a hand-computed or closed-form number, and the
nominal path unchanged (bit for bit) when their fields are at default."""
import numpy as np
import pytest

from sizing.diagnose.effects import library
from sizing.diagnose.inputs import treat_voltage
from sizing.sim import piezohydraulic as ph
from sizing.sim.piezohydraulic import PiezoHydraulicModel, simulate

from ..sim.test_sim_piezohydraulic import A_N, A_W, K, prototype   # the seed's Table 3 prototype


def test_nominal_path_is_bit_identical_at_default_fields():
    """Values recorded with the simulator before the widened forms were
    added (commit 4a0d8d2), Karnopp seals, creep, slew, leak, load and
    pressure-dependent friction on: the new fields at their defaults must
    reproduce them exactly."""
    m = PiezoHydraulicModel(
        k_stacks=K, d33=8.15e-7, alpha=-2.23e-7, beta=0.134, gamma=0.0755, delta=-5.46e-8, n_bw=1.14,
        wide_area=A_W, narrow_area=A_N, oil_volume=A_W * 3e-3 + A_N * 0.02, bulk_modulus=1.5e9, narrow_mass=0.02,
        wide_friction=10.0, narrow_friction=np.array([0.2, 3.0]), narrow_breakaway=np.array([1.0, 2.0]),
        wide_breakaway=1.5, load_force=5.0, load_stiffness=2000.0, viscous_damping=np.array([0.0, 300.0]),
        leak_conductance=np.array([0.0, 2e-13]), creep_fraction=np.array([0.0, 0.05]),
        creep_time=np.array([0.0, 0.2]), slew_rate=np.array([0.0, 800.0]),
        narrow_friction_pressure=np.array([0.0, 1e-5]))
    t = np.arange(0.0, 0.6, 1e-3)
    v = 150.0 * np.interp(t, [0, 0.05, 0.25, 0.35, 0.5, 0.6], [0, 0, 1, 1, 0.3, 0.3])
    out = simulate(m, t, v, t)
    idx = [100, 200, 300, 400, 500, 599]
    y = [[0.0017589243950275222, 0.0057732168196900965, 0.007924932418573078, 0.007024454911712406,
          0.003585089026736314, 0.0035422465451716207],
         [0.000243357446066216, 0.0033874870990410755, 0.006535795917456486, 0.00696769220363573,
          0.005284158844689143, 0.004130387225078469]]
    p = [[99578.90398595283, 211288.26112145762, 273323.6858733898, 247585.43104813428, 151405.65970548135,
          153667.41744379277],
         [221370.822773698, 404273.8099825097, 385398.4574636173, 251999.5785527022, 13135.525672264004,
          101297.90845022861]]
    # the first candidate (no damping) bit for bit; the second carries viscous
    # damping, since integrated implicitly (unconditionally stable): within
    # 3e-4 of its stroke of the explicit step's values (both steps are
    # within 2e-4 of the span of a 100 x finer one)
    assert out["position_m"][0, idx].tolist() == y[0]
    assert out["pressure_Pa"][0, idx].tolist() == p[0]
    np.testing.assert_allclose(out["position_m"][1, idx], y[1], rtol=0, atol=3e-4 * max(y[1]))
    np.testing.assert_allclose(out["pressure_Pa"][1, idx], p[1], rtol=0, atol=3e-4 * max(p[1]))


def test_stribeck_friction_by_hand():
    # F_c = 1 N, F_s = 2 N, v_s = 1 mm/s, at u = v_s: friction 1 + e^-1 = 1.367879 N;
    # a = (5 - 1.367879) / 0.02 = 181.6060 m/s^2
    a = ph._narrow_accel_stribeck(5.0, 1e-3, 1.0, 2.0, 1 / 0.02, 1e3)
    assert a == pytest.approx(181.6060, rel=1e-5)
    assert ph._narrow_accel_stribeck(1.5, 0.0, 1.0, 2.0, 1 / 0.02, 1e3) == 0.0       # below breakaway: stuck
    assert ph._narrow_accel_stribeck(2.5, 0.0, 1.0, 2.0, 1 / 0.02, 1e3) == pytest.approx(25.0)  # (2.5 - 2) / 0.02


def lugre_step(F, u, z, F_c, F_s, inv_vs, z_pre, m, dt):
    """One LuGre step from the seal's forces, presliding, mass and step."""
    s0, s1, den = ph._lugre_constants(F_s, z_pre, m, dt)
    u, z, _ = ph._lugre_step(F, u, z, ph._lugre_g(u, F_c, F_s, inv_vs), s0, s1, den, F_c, F_s, inv_vs, m, dt)
    return u, z


def test_lugre_presliding_is_a_spring_of_breakaway_over_deflection():
    """Below the running friction a LuGre seal is a spring sigma0 = F_s /
    z_pre: a constant 0.5 N on a seal of F_c = 1 N, F_s = 2 N and 10 um
    presliding comes to rest with the bristle at 0.5 / 2e5 = 2.5 um."""
    u, z, y, dt = 0.0, 0.0, 0.0, 1e-5
    for _ in range(30000):
        u, z = lugre_step(0.5, u, z, 1.0, 2.0, 1e3, 1e-5, 0.02, dt)
        y += u * dt
    assert z == pytest.approx(2.5e-6, rel=1e-6)
    assert abs(u) < 1e-9
    assert 2.5e-6 <= y < 5e-6            # the output moved by the deflection (and a little slip)


def test_lugre_steady_sliding_friction_is_the_stribeck_curve():
    """At a steady speed the bristle settles at g(u) / sigma0, so the
    friction is the Stribeck curve: F_c = 1, F_s = 2, v_s = 1 mm/s at
    u = 1 mm/s gives 1 + e^-1 = 1.367879 N (speed held by a huge mass)."""
    u, z = 1e-3, 0.0
    for _ in range(20000):
        u, z = lugre_step(0.0, u, z, 1.0, 2.0, 1e3, 1e-5, 1e12, 1e-5)
    assert u == pytest.approx(1e-3, rel=1e-4)
    assert z * 2.0 / 1e-5 == pytest.approx(1.367879, rel=1e-4)


def test_log_creep_grows_by_the_prony_sum():
    """A 100 V step, no hysteresis, no load, the output damped near critically
    (20 N s/m): the output follows R x_free, and
    four creep modes of 10, 100, 1000, 10000 ms at 2 % each give
    1 + 0.02 (1 + (1 - e^-5) + (1 - e^-0.5) + (1 - e^-0.05)) = 1.048710
    of the instantaneous stroke 0.5 s after the step."""
    t = np.arange(0.0, 0.8, 5e-4)
    v = np.where(t >= 0.3, 100.0, 0.0)
    v[(t > 0.2995) & (t < 0.3)] = 0.0
    y = simulate(prototype(log_creep=0.02, log_creep_time=0.01, viscous_damping=20.0), t, v)["position_m"][0]
    y0 = 100 * 6.7e-7 * 100
    k = int(round(0.8 / 5e-4)) - 1          # t = 0.7995 s: 0.4995 s after the step
    expected = 1 + 0.02 * sum(1 - np.exp(-0.4995 / tau) for tau in (0.01, 0.1, 1.0, 10.0))
    assert expected == pytest.approx(1.048710, abs=2e-5)
    assert y[k] / y0 == pytest.approx(expected, rel=2e-3)


def test_air_strain_by_hand():
    # 1 bar gauge (2 bar absolute), 3 % air, kappa 1.4, oil 1.5 GPa:
    # s = 0.97e5 / 1.5e9 + 0.03 (1 - 0.5^(1/1.4)) = 6.4667e-5 + 0.03 x 0.390490 = 0.0117794
    # 1/beta = 0.97 / 1.5e9 + 0.03 x 0.609510 / (1.4 x 2e5) = 6.4667e-10 + 6.53046e-8
    s, ds = ph.air_strain(1e5, 0.03, 1.4, 1.5e9)
    assert s == pytest.approx(0.0117794, rel=1e-4)
    assert ds == pytest.approx(6.59513e-8, rel=1e-4)
    s0, ds0 = ph.air_strain(0.0, 0.03, 1.4, 1.5e9)
    assert s0 == 0.0 and ds0 == pytest.approx(0.97 / 1.5e9 + 0.03 / 1.4e5, rel=1e-12)


def test_air_equilibrium_carries_the_load_on_the_air_curve():
    """Rest under a 10 N load with 2 % air: p = F0 / A_n and the compressed
    volume A_w x - A_n y is V0 s(p)."""
    V0 = A_W * 3e-3 + A_N * 0.02
    x, y, p = ph._air_equilibrium(K, 0.0, A_W, A_N, V0, 1.5e9, 10.0, 0.0, 0.02, 1.4)
    assert p == pytest.approx(10.0 / A_N, rel=1e-9)
    s, _ = ph.air_strain(p, 0.02, 1.4, 1.5e9)
    assert A_W * x - A_N * y == pytest.approx(V0 * s, rel=1e-6)


def test_air_softens_the_oil_under_a_step_of_load():
    """The static stroke lost to a load step: with air the oil column gives
    the secant volume V0 (s(p2) - s(p1)) more than the stiff oil (here the
    wide piston is held by its seal, so the output alone takes it up)."""
    t = np.arange(0.0, 0.4, 5e-4)
    m_air = prototype(load_force=5.0, air_fraction=0.01, wide_friction=1e4)
    m_oil = prototype(load_force=5.0, wide_friction=1e4)
    # no load change in a run: rest positions differ by the air's volume at p = F0 / A_n
    y_air = simulate(m_air, t, np.zeros_like(t))["position_m"][0]
    assert np.allclose(y_air, 0.0, atol=1e-9)          # rest is an equilibrium of the air form too
    V0 = A_W * 3e-3 + A_N * 0.02
    p = 5.0 / A_N
    x_a, y_a, _ = ph._air_equilibrium(K, 0.0, A_W, A_N, V0, 1.5e9, 5.0, 0.0, 0.01, 1.4)
    x_o, y_o, _ = ph._equilibrium(K, 0.0, A_W, A_N, V0, 1.5e9, 5.0, 0.0)
    s, _ = ph.air_strain(p, 0.01, 1.4, 1.5e9)
    assert (y_o - y_a) * A_N == pytest.approx(V0 * (s - 0.99 * p / 1.5e9) - V0 * 0.01 * p / 1.5e9, rel=1e-3)
    assert m_oil is not None


def test_orifice_leak_sinks_the_loaded_output_at_Q_over_A_n():
    """10 N on the 3/8 in output (p = 140.34 kPa), Cd A = 1e-10 m^2, oil
    870 kg/m^3: Q = 1e-10 sqrt(2 p / rho) = 1.79617e-9 m^3/s, and with the
    stacks holding the wide piston the output sinks at Q / A_n = 25.21 um/s."""
    t = np.arange(0.0, 1.0, 1e-3)
    y = simulate(prototype(load_force=10.0, leak_orifice_area=1e-10), t, np.zeros_like(t))["position_m"][0]
    p = 10.0 / A_N
    rate = 1e-10 * np.sqrt(2 * p / 870.0) / A_N
    assert rate == pytest.approx(2.5208e-5, rel=1e-3)
    assert (y[900] - y[400]) / 0.5 == pytest.approx(-rate, rel=0.02)


def test_amplifier_bandwidth_and_slew_by_hand():
    """A 100 V step command: a 100 rad/s amplifier gives 100 (1 - e^-1) =
    63.212 V after 10 ms; slew-limited at 5000 V/s it ramps to 50 V in 10 ms
    (where w (100 - V) = 5000), then 100 - 50 e^-1 = 81.606 V 10 ms later."""
    t = np.arange(0.0, 0.05, 1e-4)
    v = np.where(t > 0.0, 100.0, 0.0)
    out = simulate(prototype(amp_bandwidth=np.array([100.0, 100.0]), slew_rate=np.array([0.0, 5000.0])), t, v)
    V = out["voltage_V"]
    assert V[0, 100] == pytest.approx(63.212, rel=2e-3)
    assert V[1, 100] == pytest.approx(50.0, rel=2e-3)
    assert V[1, 200] == pytest.approx(81.606, rel=2e-3)


def test_every_form_is_an_alternative_of_a_contract_family():
    names = {"seal_stick_slip", "fluid_compressibility", "viscous_damping", "leakage", "stack_creep",
             "amplifier_slew_limit", "no_return", "sensor_delay",
             "sensor_vibration"}        # beyond the list of docs/formats.md: a sensor on a bracket rings on any rig
    forms = {(e.name, e.form) for e in library("piezohydraulic")}
    assert {n for n, _ in forms} == names
    assert {("seal_stick_slip", "lugre"), ("stack_creep", "log"), ("fluid_compressibility", "air"),
            ("leakage", "orifice"), ("amplifier_slew_limit", "bandwidth")} <= forms
    for e in library("piezohydraulic"):
        assert e.source and len(e.sizes_for(None, prototype())) == 2


def test_treated_voltage_keeps_fast_ramps():
    """A staircase commanded as 40 ms ramps (2.4 V a sample) with 0.3 V of
    white noise: the treated voltage is closer to the clean one than the raw
    log is (before the odd-reflection smoothing the ramps cut into short
    stretches were flattened and the treatment doubled the error)."""
    rng = np.random.default_rng(3)
    t = np.arange(0.0, 2.0, 1e-3)
    clean = 150 * np.interp(t, [0, 0.5, 0.54, 1.0, 1.04, 1.5, 1.54, 2.0], [0, 0, 0.65, 0.65, 0.0, 0.0, 1.0, 1.0])
    raw = clean + 0.3 * rng.normal(size=t.size)
    err = np.sqrt(np.mean((treat_voltage(raw) - clean) ** 2))
    assert err < 0.3


def test_compressibility_only_softens_the_oil():
    """The bulk-modulus form is searched from 5 MPa up to the rig's nominal
    bulk modulus (1.5 GPa here), not to the 2 GPa of its declared range: its
    stiffest value is the nominal oil, no effect, and its realistic sizes
    (10 x and 40 x softer) stay inside."""
    from types import SimpleNamespace

    from sizing.diagnose.effects.fluid_compressibility import BULK_MODULUS

    model = SimpleNamespace(bulk_modulus=np.array([1.5e9]))
    bounded = BULK_MODULUS.for_rig(None, model)
    (p,) = bounded.params
    assert BULK_MODULUS.params[0].hi == 2e9 and p.hi == 1.5e9 and p.lo == 5e6
    assert float(p.from_unit(1.0)) == pytest.approx(1.5e9)
    assert bounded.model_changes(model, bounded.values(np.ones((1, 1))))["bulk_modulus"][0] == pytest.approx(1.5e9)
    for size in bounded.sizes_for(None, model):
        assert 0.0 < bounded.unit(size)[0] < 1.0
