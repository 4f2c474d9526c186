"""The margins a DC design from real parts adds, each against its hand
formula on one combination of the shipped catalog: the drive's ambient where
it sits, the screw's static safety, the motor's continuous rating at the
ambient, the gear's continuous torque and the winding after a hold."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from sizing.technologies.dc_motor import parts as dc_parts
from sizing.engine.evaluate import load_cases
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def seed():
    req, _ = load_requirements(ROOT / "studies" / "seed-requirements.toml")
    return req, load_catalog(), [c["load_N"] for c in load_cases(req.load)]


def _one(cat, motor, screw, gear, drive):
    lists = dc_parts.part_lists(cat)
    M, S, G, D = lists
    pos = lambda seq, ident: next(i for i, e in enumerate(seq) if (e.id if e is not None else None) == ident)
    idx = lambda k, ident: np.array([pos(k, ident)])
    return dc_parts.parts_at(lists, idx(M, motor), idx(S, screw), idx(G, gear), idx(D, drive))


def test_drive_ambient_where_it_sits(seed):
    """TGdrives TGZ-D-48 is rated 0-40 degC: in the 30 degC bay (40 - 30) / 30 = +33 %;
    at the actuator, 100 degC: (40 - 100) / 100 = -60 %."""
    req, cat, loads = seed
    p = _one(cat, "maxon-597974", "thk-bnk1202-3", None, "tgdrives-tgz-d-48-13-26")
    _, _, m = dc_parts.static_screen(p, req, loads)
    assert m["drive_temperature"][0] == pytest.approx(10 / 30)
    at_actuator = req.model_copy(update={"options": req.options.model_copy(update={"amplifier_location": "actuator"})})
    _, _, m2 = dc_parts.static_screen(p, at_actuator, loads)
    assert m2["drive_temperature"][0] == pytest.approx(-0.6)


def test_static_safety_and_continuous_torque(seed):
    """maxon 597974 (flat, 125 degC rule) on THK BNK1202-3 (C0a 3.6 kN):
    static safety C0 / F_peak against THK's 2.0; continuous torque
    k_t I_nom = 1.428 N m at 25 degC, sqrt((125 - 100) / 100) = 0.5 of it at
    100 degC, against the holding torque k_t(T_w) i."""
    req, cat, loads = seed
    p = _one(cat, "maxon-597974", "thk-bnk1202-3", None, "tgdrives-tgz-d-48-13-26")
    _, st, m = dc_parts.static_screen(p, req, loads)
    F_peak = st["blocked_force_N"][0]
    assert m["static_safety"][0] == pytest.approx(3600 / F_peak / 2.0 - 1)
    assert st["continuous_torque_rated_N_m"][0] == pytest.approx(0.136 * 10.5 * 0.5)
    torque = st["torque_constant_at_temperature"][0] * st["load_current_A"][0]
    assert torque == pytest.approx(max(loads) * 0.002 / (2 * math.pi * 0.9))
    assert m["continuous_torque"][0] == pytest.approx(0.714 / torque - 1)


def test_gear_continuous_torque_and_hold(seed):
    """A maxon gearhead's continuous output torque (MGDB max_cont_torque)
    against the screw torque of the worst load F l / (2 pi eta_s); the winding
    after the 60 s hold, first order from the duty's temperature."""
    req, cat, loads = seed
    motor = next(m for m in cat.motors.values() if m.gear_mounts and m.id.startswith("maxon-") and m.mass > 0.5)
    gear = next(g for g in cat.gears.values() if g.mount in motor.gear_mounts)
    p = _one(cat, motor.id, "thk-bif1605-5", gear.id, "tgdrives-tgz-d-48-13-26")
    _, st, m = dc_parts.static_screen(p, req, loads)
    t_screw = max(loads) * 0.005 / (2 * math.pi * 0.9)
    assert m["gear_torque"][0] == pytest.approx(gear.continuous_output_torque / t_screw - 1)
    assert np.isfinite(m["holding"][0]) and m["holding"][0] >= m["winding_temperature"][0] - 1e-12


def test_evaluate_refuses_a_gearhead_that_does_not_mount(tmp_path):
    from ..conftest import run_cli
    cat = load_catalog()
    motor = next(m for m in cat.motors.values() if m.gear_mounts)
    gear = next(g for g in cat.gears.values() if g.mount and g.mount not in motor.gear_mounts)
    path = tmp_path / "dc.toml"
    path.write_text(f'technology = "dc_motor"\nmotor = "{motor.id}"\nscrew = "thk-bnk1202-3"\ngear = "{gear.id}"\n'
                    f'drive = "servo-48v-10a"\nstep = 0.04\n[load]\ndynamic_pressure = ["10 kPa"]\n')
    code, _, err = run_cli("evaluate", path)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "dc.toml" in err and "gear" in err and "does not mount" in err
