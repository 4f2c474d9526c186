"""The piezo pump's physics (physics/pump.py) and its cycle-resolved
simulation (sim/pump.py): published or hand-computed values, the two models
against each other, and the bound no pump can beat."""
from __future__ import annotations

import math

import numpy as np
import pytest

from sizing.physics import pump
from sizing.sim.pump import PumpModel, simulate

from ..cli.test_bad_input import one_line_exit_2
from ..conftest import STUDIES, run_cli

# a 3 mm reed: k 3.1e3 N/m over 7.07 mm^2, 20 kPa cracking, 0.3 mm stop
REED = dict(cracking_pressure=20e3, port_area=7.07e-6, reed_stiffness=3.1e3, max_lift=0.3e-3, discharge_coefficient=0.6)


def test_valve_stays_shut_below_cracking_and_opens_linearly_above():
    args = (850.0, *REED.values())
    assert pump.valve_flow(np.array([0.0, 10e3, 19.999e3]), *args).tolist() == [0.0, 0.0, 0.0]
    # hand: 30 kPa is 10 kPa over cracking: lift 10e3 x 7.07e-6 / 3.1e3 = 22.8 um,
    # curtain pi x 3.0 mm x 22.8 um = 2.15e-7 m^2 (below the port),
    # Q = 0.6 x 2.15e-7 x sqrt(2 x 30e3 / 850) = 1.084e-6 m^3/s
    assert pump.valve_lift(30e3, 20e3, 7.07e-6, 3.1e3, 0.3e-3) == pytest.approx(22.806e-6, rel=1e-3)
    assert float(pump.valve_flow(30e3, *args)) == pytest.approx(1.084e-6, rel=5e-3)
    # full lift at 20 kPa + k x_max / A = 151.5 kPa: the lift stops growing
    assert pump.valve_lift(1e6, 20e3, 7.07e-6, 3.1e3, 0.3e-3) == pytest.approx(0.3e-3)


def test_valve_drop_inverts_valve_flow():
    args = (850.0, *REED.values())
    dp = np.array([25e3, 60e3, 150e3, 2e6])
    q = pump.valve_flow(dp, *args)
    assert pump.valve_drop(q, *args) == pytest.approx(dp, rel=1e-6)


def test_valve_resonance_of_the_catalog_reed():
    # sqrt(3.1e3 / 6.8e-6) / 2 pi = 3398 Hz (the catalog's "resonance 3.4 kHz")
    assert pump.valve_resonance(3.1e3, 6.8e-6) == pytest.approx(3398.2, rel=1e-3)


def test_chamber_stiffness_with_air_by_hand():
    """1 % air at atmospheric pressure, 1 MPa gauge: the air is compressed to
    0.01 (101325 / 1101325)^(1/1.4) = 1.819e-3 of the volume (fraction 1.834e-3),
    1 / beta = 0.998166 / 1.5e9 + 1.834e-3 / (1.4 x 1101325) = 1.8565e-9: 5.386e8 Pa."""
    beta = float(pump.effective_bulk_modulus(1.5e9, 0.01, 1e6 + pump.P_ATM))
    assert beta == pytest.approx(5.386e8, rel=2e-3)
    # no air, no wall: the oil's own modulus; the wall adds D / (E t) in series
    assert float(pump.effective_bulk_modulus(1.5e9, 0.0, 1e6)) == pytest.approx(1.5e9)
    wall = float(pump.wall_compliance(0.02, 0.005, 69e9))          # 5.80e-11 1/Pa
    assert float(pump.effective_bulk_modulus(1.5e9, 0.0, 1e6, wall)) == pytest.approx(1 / (1 / 1.5e9 + 5.797e-11), rel=1e-3)
    # beta A^2 / V: 20 mm piston over 1 mm of oil, 5.386e8 x (3.1416e-4)^2 / 3.1416e-7
    assert float(pump.chamber_stiffness(beta, math.pi * 0.01**2, math.pi * 0.01**2 * 1e-3)) == pytest.approx(1.692e8, rel=2e-3)


def test_bias_pressure_stiffens_the_chamber():
    low, high = pump.effective_bulk_modulus(1.5e9, 0.005, np.array([0.5e6, 3.45e6]) + pump.P_ATM)
    assert high > 2 * low


def test_reactive_power_is_pi_over_4_c_v2_f_and_matches_the_waveform():
    C, V, f = 50e-6, 1000.0, 200.0
    assert float(pump.reactive_power(C, V, f)) == pytest.approx(math.pi / 4 * C * V**2 * f)
    t = np.linspace(0.0, 1.0 / f, 20001)
    v = 0.5 * V * (1 - np.cos(2 * np.pi * f * t))
    i = C * np.gradient(v, t)
    v_ac_rms = np.sqrt(np.mean((v - v.mean()) ** 2))
    i_rms = np.sqrt(np.mean(i**2))
    assert v_ac_rms * i_rms == pytest.approx(float(pump.reactive_power(C, V, f)), rel=1e-3)
    peak, rms = pump.sine_current(C, V, f)
    assert float(peak) == pytest.approx(np.max(np.abs(i)), rel=1e-3)
    assert float(rms) == pytest.approx(i_rms, rel=1e-3)
    # against the duty's mean current 2 C V f (physics/amplifier.py): rms / mean = pi / (2 sqrt 2)
    assert float(rms) / (2 * C * V * f) == pytest.approx(math.pi / (2 * math.sqrt(2)))


def test_stall_pressure_and_delivered_volume():
    # 20 mm piston, 100 um stroke, stacks 1e8 N/m, 1 mm of oil at 1.5 GPa:
    # C = 3.1416e-7 / 1.5e9 + (3.1416e-4)^2 / 1e8 = 2.0944e-16 + 9.8696e-16 = 1.1964e-15
    A = math.pi * 0.01**2
    C = float(pump.chamber_compliance(A * 1e-3, 1.5e9, A, 1e8))
    assert C == pytest.approx(1.1964e-15, rel=1e-3)
    swept = float(pump.swept_volume(A, 100e-6))
    assert float(pump.stall_pressure(swept, C)) == pytest.approx(3.1416e-8 / 1.1964e-15, rel=1e-3)   # 26.3 MPa
    assert float(pump.delivered_volume(swept, C, 10e6)) == pytest.approx(3.1416e-8 - 1.1964e-8, rel=1e-3)
    assert float(pump.delivered_volume(swept, C, 40e6)) == 0.0


def _model(**over):
    K, x, V = 3.25e8, 168.9e-6, 1000.0
    A_p = math.pi * 0.008**2
    base = dict(k_stacks=K, d33=x / V, alpha=0.0, beta=0.0, gamma=0.0, delta=0.0, n_bw=1.0, stroke_scale=1.0,
                voltage=V, frequency=100.0, pump_area=A_p, chamber_volume=A_p * (x + 0.3e-3), bulk_modulus=1.3e9,
                air_fraction=0.0, wall_compliance=0.0, density=850.0, bias_pressure=0.5e6,
                cylinder_area=math.pi * 0.006**2, dead_length=0.02, load_mass=0.02, load_force=800.0,
                target_stroke=0.04, t_end=3.0, **REED)
    base.update(over)
    return PumpModel(**base)


def _averaged(m: PumpModel, load_pressure):
    return pump.cycle_averaged(m.pump_area * m.d33 * m.voltage, m.chamber_volume, m.bulk_modulus, m.air_fraction,
                               m.wall_compliance, m.pump_area, m.k_stacks, np.asarray(m.frequency), m.bias_pressure,
                               load_pressure, m.cracking_pressure)


def test_cycle_averaged_flow_against_the_simulated_cycles():
    """A light load, well below the output's resonance: the quasi-static
    model (eq. P4) and the simulated cycles agree within 5 % (docs/models.md)."""
    m = _model(frequency=np.array([50.0, 100.0, 200.0]), air_fraction=np.array([0.0, 0.005, 0.0]))
    sim = simulate(m)
    avg = _averaged(m, m.load_force / m.cylinder_area)
    assert np.all(sim["reached"] > 0)
    assert np.all(sim["cycles"] > 100)                          # many pumping cycles a stroke
    ratio = sim["mean_speed_m_s"] / (avg["flow_m3_s"] / m.cylinder_area)
    assert np.all(np.abs(ratio - 1) < 0.05), ratio


def test_no_design_delivers_more_oil_than_it_pumps():
    """Inside the quasi-static validity (pumping below 0.4 x the output's
    natural frequency, here 1.1-3.5 kHz): no more oil than pumped, over whole cycles."""
    m = _model(frequency=np.array([50.0, 200.0, 400.0]), load_force=np.array([0.0, 800.0, 300.0]),
               load_mass=np.array([0.02, 0.2, 0.02]))
    sim = simulate(m)
    bound = m.pump_area * m.d33 * m.voltage * m.frequency / m.cylinder_area
    assert np.all(sim["mean_speed_m_s"] <= bound * (1 + 1e-9))
    assert np.all(sim["delivered_volume_m3"] <= sim["pumped_volume_m3"] * (1 + 1e-9))


def test_blocked_pump_holds_still():
    """A load above the stall force: the output does not move forward."""
    m = _model()
    stall = float(pump.stall_pressure(m.pump_area * m.d33 * m.voltage,
                                      pump.chamber_compliance(m.chamber_volume, m.bulk_modulus, m.pump_area, m.k_stacks)))
    sim = simulate(m.replace(t_end=0.2, load_force=1.1 * stall * m.cylinder_area))
    assert sim["reached"][0] == 0 and sim["stroke_m"][0] <= 1e-4


@pytest.mark.parametrize("file, edit, words", [
    ("valves.toml", ('max_frequency = "600 Hz"', 'max_frequency = "4000 Hz"'), ("valves.toml", "max_frequency", "resonance")),
    # below the reed's 3.4 kHz in air, above its 1.88 kHz in oil
    ("valves.toml", ('max_frequency = "600 Hz"', 'max_frequency = "2000 Hz"'), ("valves.toml", "max_frequency", "in oil")),
    ("valves.toml", ('port_area = "7.07 mm^2"\n', ''), ("valves.toml", "port_area")),
    ("accumulators.toml", ('bias_pressure = "0.5 MPa"', 'bias_pressure = "-0.5 MPa"'), ("accumulators.toml", "bias_pressure", "non-negative")),
])
def test_bad_pump_parts_exit_2_with_one_line_and_write_nothing(tmp_path, catalog_copy, file, edit, words):
    path = catalog_copy / file
    text = path.read_text()
    assert edit[0] in text
    path.write_text(text.replace(edit[0], edit[1], 1))
    one_line_exit_2(*run_cli("catalog", "validate", catalog_copy)[::2], *words)
    out = tmp_path / "o"
    req = tmp_path / "req.toml"
    req.write_text((STUDIES / "seed-requirements.toml").read_text())
    one_line_exit_2(*run_cli("solve", req, "--catalog", catalog_copy, "--out", out, "--quiet")[::2], *words[:2])
    assert not out.exists()


def test_line_inertance_and_reflected_mass_by_hand():
    # 0.3 m of 5 mm line, rho 850: A = 1.9635e-5 m^2, rho L / A = 1.2987e7 Pa s^2/m^3;
    # into a 20 mm bore (3.1416e-4 m^2): 1.2987e7 x 9.8696e-8 = 1.2818 kg on the load
    assert float(pump.line_inertance(850.0, 0.3, 0.005)) == pytest.approx(1.2987e7, rel=1e-3)
    assert float(pump.reflected_mass(850.0, 0.3, 0.005, math.pi * 0.01**2)) == pytest.approx(1.2818, rel=1e-3)
    # the low end of the review's range: 0.2 m of 6 mm line into an 18 mm bore, 0.389 kg
    assert float(pump.reflected_mass(850.0, 0.2, 0.006, math.pi * 0.009**2)) == pytest.approx(0.3894, rel=2e-3)
    # Hagen-Poiseuille: 128 x 0.0128 x 0.3 / (pi x 0.005^4) = 2.5033e8 Pa s/m^3
    assert float(pump.line_resistance(0.0128, 0.3, 0.005)) == pytest.approx(2.5033e8, rel=1e-3)


def test_annulus_leakage_against_the_exact_concentric_annulus():
    """pi D c^3 / (12 mu L): 10 mm piston, 5 um clearance, 10 mm land, 0.0128
    Pa s: 2.5566e-15 m^3/(s Pa); the exact annulus flow (White, Viscous Fluid
    Flow, eq. 3-49) pi / (8 mu L) [r_o^4 - r_i^4 - (r_o^2 - r_i^2)^2 / ln(r_o / r_i)]
    agrees for a thin gap."""
    G = float(pump.annulus_leakage(0.010, 5e-6, 0.010, 0.0128))
    assert G == pytest.approx(2.5566e-15, rel=1e-3)
    ri, ro, mu, L = 0.005, 0.005 + 5e-6, 0.0128, 0.010
    exact = math.pi / (8 * mu * L) * (ro**4 - ri**4 - (ro**2 - ri**2) ** 2 / math.log(ro / ri))
    assert G == pytest.approx(exact, rel=2e-3)
    # the cube of the clearance: twice the gap, eight times the leak
    assert float(pump.annulus_leakage(0.010, 10e-6, 0.010, 0.0128)) == pytest.approx(8 * G)


def test_wetted_reed_resonance_against_the_strip_added_mass():
    """The catalog's 0.15 x 4 x 6 mm steel reed (k 3.1e3 N/m, effective mass
    6.8e-6 kg, 3.40 kHz in air) in oil (850 kg/m^3): a strip of width 4 mm
    carries (pi / 4) rho b^2 per metre, 6.409e-5 kg over 6 mm, 1.538e-5 kg
    with the cantilever's modal factor 0.24; wetted resonance
    sqrt(3.1e3 / 2.218e-5) / 2 pi = 1882 Hz (the review's 'about 1.9 kHz')."""
    ma = float(pump.added_mass_strip(850.0, 0.004, 0.006, 0.24))
    assert ma == pytest.approx(1.538e-5, rel=1e-3)
    assert float(pump.wetted_resonance(3.1e3, 6.8e-6, ma)) == pytest.approx(1881.6, rel=1e-3)
    # Lamb's disc: (8 / 3) rho a^3, a 5 mm disc in oil 2.833e-4 kg
    assert float(pump.added_mass_disc(850.0, 0.005)) == pytest.approx(2.8333e-4, rel=1e-3)
    # in air (1.2 kg/m^3) the reed keeps its resonance within 0.1 %
    air = float(pump.wetted_resonance(3.1e3, 6.8e-6, pump.added_mass_strip(1.2, 0.004, 0.006, 0.24)))
    assert air == pytest.approx(float(pump.valve_resonance(3.1e3, 6.8e-6)), rel=2e-3)


def test_air_dissolution_by_hand_and_against_the_mixture_volume():
    """P8: 0.5 % free air at atmospheric pressure, all dissolved at 3 MPa
    (absolute). At 1 MPa gauge 65.50 % of it stays free, compressed to
    0.18191 of its volume: 5.958e-4 of the mixture; the compliance
    (0.995 / 1.5e9 + 0.005 / 2.8987e6 x 0.18191 + 5.958e-4 / (1.4 x 1.1013e6))
    / 0.99560 = 1.3695e-9 1/Pa, beta 7.302e8 Pa; above 3 MPa the oil's own
    1.5 GPa. Cross-check: -dV / (V dp) of the mixture's volume by finite
    differences."""
    p = 1e6 + pump.P_ATM
    assert float(pump.free_air(0.005, p, 3e6)) == pytest.approx(0.005 * 0.65501, rel=1e-4)
    beta = float(pump.effective_bulk_modulus(1.5e9, 0.005, p, dissolution_pressure=3e6))
    assert beta == pytest.approx(7.3017e8, rel=1e-3)
    assert float(pump.effective_bulk_modulus(1.5e9, 0.005, 4e6, dissolution_pressure=3e6)) == pytest.approx(1.5e9)
    # below atmospheric pressure nothing more is released than the free air
    assert float(pump.free_air(0.005, 5e4, 3e6)) == pytest.approx(0.005)

    def volume(q):
        return (1 - 0.005) * math.exp(-(q - pump.P_ATM) / 1.5e9) + float(pump.free_air(0.005, q, 3e6)) * (pump.P_ATM / q) ** (1 / 1.4)
    h = 10.0
    numeric = -(volume(p + h) - volume(p - h)) / (2 * h) / volume(p)
    assert 1 / beta == pytest.approx(numeric, rel=2e-3)
    # without dissolution (P2 alone) the chamber is stiffer: the dissolving air adds compliance below 3 MPa
    assert float(pump.effective_bulk_modulus(1.5e9, 0.005, p)) > beta


def test_viscous_loss_across_the_seat_by_hand():
    """P9: the 3 mm reed at 30 kPa (lift 22.806 um, curtain 2.1497e-7 m^2,
    orifice coefficient 6.2565e-9) in oil of 0.0128 Pa s over a 0.5 mm land:
    12 mu w / (pi d x^3) = 6.869e11 Pa s/m^3 in series with the orifice,
    Q = 4.360e-8 m^3/s (the orifice alone 1.084e-6): at small lifts the
    laminar gap decides. The drop it takes back is the one given."""
    args = (850.0, *REED.values(), 0.0128, 0.5e-3)
    q = float(pump.valve_flow(30e3, *args))
    assert q == pytest.approx(4.3604e-8, rel=2e-3)
    # dp = R Q + Q^2 / k^2 by hand: 6.869e11 x 4.3604e-8 + (4.3604e-8 / 6.2565e-9)^2 = 30000 Pa
    assert 6.869e11 * q + (q / 6.2565e-9) ** 2 == pytest.approx(30e3, rel=3e-3)
    assert float(pump.valve_drop(q, *args)) == pytest.approx(30e3, rel=1e-6)
    assert float(pump.valve_flow(30e3, *args[:-2])) == pytest.approx(1.084e-6, rel=5e-3)


def test_a_seated_reed_leaks_through_its_seat_gap():
    """P7 through P9's law: the 3 mm reed shut (10 kPa, below its 20 kPa
    cracking) on a 2 um gap in 0.0128 Pa s oil over a 0.5 mm land:
    R = 12 x 0.0128 x 5e-4 / (pi x 3.0003e-3 x 8e-18) = 1.0185e15 Pa s/m^3,
    the orifice of pi d h = 1.8851e-8 m^2 negligible beside it:
    Q = 1e4 / 1.0185e15 = 9.82e-12 m^3/s; without a gap none."""
    args = (850.0, *REED.values(), 0.0128, 0.5e-3)
    assert float(pump.valve_flow(10e3, *args)) == 0.0
    assert float(pump.valve_flow(10e3, *args, 2e-6)) == pytest.approx(1e4 / 1.0185e15, rel=2e-3)
