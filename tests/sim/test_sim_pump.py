"""The pump's cycle-resolved simulation (sim/pump.py) converges and keeps
to the energy the stacks put in."""
from __future__ import annotations

import math

import numpy as np

from sizing.sim.pump import PumpModel, simulate

# the Georgia Tech build of benchmarks/pump_published.py (Mauck, Oates and
# Lynch 2001, 60 Hz): a 1e8 N/m stack of 48.95 um free stroke on a 12 mm
# piston, 0.5 mm of oil over it, 80 psi bias, a 3.2 mm bore, a 0.02 kg load
GEORGIA_TECH = dict(
    k_stacks=1e8, d33=48.95e-9, alpha=0.0, beta=0.0, gamma=0.0, delta=0.0, n_bw=1.0, stroke_scale=1.0,
    voltage=1000.0, frequency=60.0, pump_area=math.pi * 0.006**2, chamber_volume=math.pi * 0.006**2 * 0.5e-3,
    bulk_modulus=1.5e9, air_fraction=0.005, wall_compliance=0.0, density=870.0, cracking_pressure=20e3,
    port_area=20e-6, reed_stiffness=2e4, max_lift=0.5e-3, discharge_coefficient=0.6, bias_pressure=80 * 6894.76,
    cylinder_area=math.pi * 0.0032**2 / 4, dead_length=0.02, load_mass=0.02, load_force=0.0, target_stroke=0.01,
    t_end=2.0)


def test_published_build_converges_when_the_step_halves():
    """Mean speed at the automatic step, half and an eighth of it: within 1 %
    (an explicit high side, counting the last cycle whole, gives 6.00 /
    5.00 / 5.45 cm/s here)."""
    m = PumpModel(**GEORGIA_TECH)
    v = [float(simulate(m, k)["mean_speed_m_s"][0]) for k in (1.0, 0.5, 0.125)]
    assert v[0] > 0.01
    assert abs(v[0] / v[1] - 1) < 0.01 and abs(v[1] / v[2] - 1) < 0.01, v


def test_output_work_never_exceeds_the_stacks_work():
    """Energy balance over the run: the work on the load (F dy summed) is at
    most the stacks' work (p dV summed), and under a quasi-static load (the
    output's resonance far above the pumping) at most K x_f^2 / 4 a cycle."""
    m = PumpModel(**dict(GEORGIA_TECH, load_force=np.array([50.0, 100.0, 150.0, 200.0]), t_end=0.5))
    s = simulate(m)
    assert np.all(s["output_work_J"] > 0)
    assert np.all(s["output_work_J"] <= s["stack_work_J"])
    assert np.all(s["output_work_J"] <= s["quasi_static_bound_J"])
    # the bound by hand: 1e8 x (48.95 um)^2 / 4 = 0.0599 J a cycle, 60 cycles a second
    assert np.allclose(s["quasi_static_bound_J"] / s["cycles"], 0.0599, rtol=0.02)
