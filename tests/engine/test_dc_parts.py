"""DC actuators sized from parts: the static screen against hand numbers,
and bad part catalogs exit 2 naming file, entry and field."""
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from sizing.technologies.dc_motor import parts as dc_parts
from sizing.technologies.dc_motor import from_parts as dc_sizing
from sizing.technologies.dc_motor.record import parts_candidate
from sizing.engine.evaluate import load_cases
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements

from ..conftest import run_cli

ROOT = Path(__file__).resolve().parents[2]
CATALOGS = ROOT / "catalogs"


def generic_parts(catalog):
    """The catalog with the hand-entered DC parts only (no imported tables):
    small enough to enumerate whole."""
    from dataclasses import replace
    own = lambda group: {k: v for k, v in group.items() if "mgdb" not in catalog.origin[k]
                         and "sourced" not in catalog.origin[k]}
    return replace(catalog, motors=own(catalog.motors), gears=own(catalog.gears), screws=own(catalog.screws))


@pytest.fixture(scope="module")
def seed():
    req, _ = load_requirements(ROOT / "studies" / "seed-requirements.toml")
    return req, generic_parts(load_catalog()), [c["load_N"] for c in load_cases(req.load)]


def _row(p, motor, screw, gear, drive):
    hit = np.flatnonzero((p.motor == motor) & (p.screw == screw) & (p.gear == gear) & (p.drive == drive))
    assert len(hit) == 1
    return int(hit[0])


def test_enumeration_covers_every_combination(seed):
    _, cat, _ = seed
    p = dc_parts.enumerate_parts(cat)
    assert len(p) == len(cat.motors) * len(cat.screws) * (len(cat.gears) + 1) * len(cat.drives)
    assert len(cat.motors) >= 10 and len(cat.screws) >= 6
    # with makers' gearheads, each motor takes the generic ones and those of its mounts
    full = load_catalog()
    n = sum(1 + len(g) for g in dc_parts.mountable(full))
    assert n < len(full.motors) * (len(full.gears) + 1) / 10
    some = {k: full.motors[k] for k in list(full.motors)[:3] + list(full.motors)[-3:]}
    from dataclasses import replace
    small = replace(full, motors=some)
    pairs = sum(1 + len(g) for g in dc_parts.mountable(small))
    assert len(dc_parts.enumerate_parts(small)) == pairs * len(full.screws) * len(full.drives)


def test_static_screen_hand_numbers(seed):
    """gen-bldc42-28v-h (k_t 0.05 N m/A, no k_t drift) on ball-12x2 (2 mm, 90 %)
    without gear, servo-48v-10a (20 A peak; the motor's 1.2 N m / 0.05 = 24 A):
    blocked force 2 pi 0.9 0.05 20 / 0.002 = 2827.4 N; holding current at the
    1209.7 N case F l / (2 pi eta k_t) = 8.557 A."""
    req, cat, loads = seed
    p = dc_parts.enumerate_parts(cat)
    i = _row(p, "gen-bldc42-28v-h", "ball-12x2", None, "servo-48v-10a")
    _, st, m = dc_parts.static_screen(p, req, loads)
    assert st["blocked_force_N"][i] == pytest.approx(2 * math.pi * 0.9 * 0.05 * 20 / 0.002)
    assert st["load_current_A"][i] == pytest.approx(1209.675 * 0.002 / (2 * math.pi * 0.9 * 0.05))
    # the drive caps its voltage at k_e x the screw's 4500 rpm: no-load 4500 rpm x 2 mm = 0.15 m/s;
    # under the load the back-EMF ceiling (U - R_hot i) / k_e is lower
    assert st["mechanical_speed_limit_m_s"][i] == pytest.approx(4500 / 60 * 0.002)
    r_hot = st["hot_resistance_ohm"][i]
    w = (st["drive_voltage_V"][i] - r_hot * st["load_current_A"][i]) / 0.05
    assert st["max_speed_m_s"][i] == pytest.approx(w * 0.002 / (2 * math.pi))
    assert m["blocked_force"][i] == pytest.approx(2827.43 / 2500 - 1, rel=1e-4)


def test_duty_rms_of_a_held_current():
    """Constant current (its square's integral 9 t): its RMS is itself
    whatever the period; a current held for a fraction f of the period has
    RMS i sqrt(f)."""
    t = np.arange(0, 1.0, 1e-3)
    held = np.full((1, len(t)), 3.0)
    assert dc_sizing.duty_rms(t, 9.0 * t[None, :], held, 2.0)[0] == pytest.approx(3.0)
    assert dc_sizing.duty_rms(t, 9.0 * t[None, :], held, 0.5)[0] == pytest.approx(3.0)
    pulse = np.where(t < 0.25, 4.0, 0.0)[None, :]
    heat = 16.0 * np.minimum(t, 0.25)[None, :]
    assert dc_sizing.duty_rms(t, heat, pulse, 1.0)[0] == pytest.approx(4.0 * math.sqrt(0.25), rel=1e-9)


def _catalog_copy(tmp_path) -> Path:
    folder = tmp_path / "catalogs"
    shutil.copytree(CATALOGS, folder)
    return folder


def _one_line_exit_2(folder, *words):
    code, _, err = run_cli("catalog", "validate", folder)
    assert code == 2, err
    lines = [line for line in err.strip().splitlines() if line.strip()]
    assert len(lines) == 1, err
    for w in words:
        assert w in lines[0], (w, lines[0])


def test_motor_without_thermal_resistance_exits_2(tmp_path):
    folder = _catalog_copy(tmp_path)
    path = folder / "motors.toml"
    text = path.read_text()
    first, rest = text.split('thermal_resistance = "4.5 K/W"\n', 1)
    rest = rest.replace('thermal_resistance = "assumed', 'x_unused = "assumed', 1).replace("x_unused", "#", 1)
    path.write_text(first + rest)
    _one_line_exit_2(folder, "motors.toml", "maxon-ec4pole32hd-220w-48v", "thermal_resistance")


def test_screw_efficiency_above_one_exits_2(tmp_path):
    folder = _catalog_copy(tmp_path)
    path = folder / "screws.toml"
    path.write_text(path.read_text().replace("efficiency = 0.9\n", "efficiency = 1.2\n", 1))
    _one_line_exit_2(folder, "screws.toml", "ball-12x2", "efficiency")


def test_drive_below_the_motor_voltage_exits_2(tmp_path):
    folder = _catalog_copy(tmp_path)
    path = folder / "drives.toml"
    path.write_text(path.read_text().replace('bus_voltage = "28 V"', 'bus_voltage = "2 V"', 1))
    _one_line_exit_2(folder, "drives.toml", "servo-28v-20a", "bus_voltage")
    # and the solve refuses the same catalog, before writing anything
    out = tmp_path / "out"
    code, _, err = run_cli("solve", ROOT / "studies" / "seed-requirements.toml", "--catalog", folder, "--out", out, "--quiet")
    assert code == 2 and "drives.toml" in err and not out.exists()


def test_evaluate_reproduces_a_solved_design(seed, tmp_path):
    """The `design` entry of a DC design from parts is a `sizing evaluate`
    input giving the same figures (same screen, controller and simulation)."""
    from sizing import api
    req, cat, loads = seed
    found = [parts_candidate(req, cat, d) for d in dc_sizing.dc_parts_designs(req, cat, loads).designs]
    best = min((c for c in found if c["stage"] == "simulated" and c["components"]["gear"]),
               key=lambda c: c["metrics"]["mass_kg"])
    d = best["design"]
    lines = ['technology = "dc_motor"'] + [f'{k} = "{d[k]}"' for k in ("motor", "screw", "gear", "drive")]
    lines += [f"{k} = {d[k]!r}" for k in ("step", "duration", "temperature", "speed", "strokes_per_second",
                                          "electronics_bay_temperature")]
    lines += [f'amplifier_location = "{d["amplifier_location"]}"', "[load]",
              'dynamic_pressure = ["10 kPa", "25 kPa"]']
    path = tmp_path / "dc.toml"
    path.write_text("\n".join(lines) + "\n")
    ev = api.evaluate(path)
    assert ev["controller"] == best["controller"]
    assert ev["static"]["max_speed_m_s"] == pytest.approx(best["static"]["max_speed_m_s"], rel=1e-12)
    for a, b in zip(ev["simulated"]["cases"], best["simulated"]["cases"]):
        assert a["speed_m_s"] == pytest.approx(b["speed_m_s"], rel=1e-9)
    assert ev["simulated"]["winding_temperature_degC"] == pytest.approx(best["simulated"]["winding_temperature_degC"])
    # a drive below the motor's rated voltage is evaluated as the solve ranks it (the motor runs at
    # the bus voltage), with a warning that names the drive
    path.write_text(path.read_text().replace(f'drive = "{d["drive"]}"', 'drive = "servo-28v-20a"')
                    .replace(f'motor = "{d["motor"]}"', 'motor = "gen-bldc60-96v-h"'))
    code, _, err = run_cli("evaluate", path)
    assert code == 0 and "servo-28v-20a has a 28 V bus" in err


def test_ratio_interval_closed_form_and_against_the_screen(seed):
    """Hand numbers: k_t = k_e = 0.05, R 0.2 ohm, 20 A, lead 2 mm, eta 0.81,
    48 V, 2.5 kN, 1210 N, 0.1 m/s, no rating cap. a = 3.183e-4 m;
    force: N >= 2500 a / (0.81 x 0.05 x 20) = 0.9824; speed: roots of
    (0.05 x 0.1 / a) N^2 - 48 N + 0.2 x 1210 a / (0.81 x 0.05) = 0."""
    a = 0.002 / (2 * math.pi)
    lo, hi = dc_parts.ratio_interval(0.05, 0.05, 0.2, 20.0, 0.002, 0.81, 48.0, np.inf, 2500.0, 1210.0, 0.1)
    A, C = 0.05 * 0.1 / a, 0.2 * 1210 * a / (0.81 * 0.05)
    assert lo == pytest.approx(max(2500 * a / (0.81 * 0.05 * 20), (48 - math.sqrt(48**2 - 4 * A * C)) / (2 * A)))
    assert hi == pytest.approx((48 + math.sqrt(48**2 - 4 * A * C)) / (2 * A))
    # consistency with the screen: a design whose ratio lies inside its interval
    # meets force and speed at the bus voltage (ratings aside)
    req, cat, loads = seed
    p = dc_parts.enumerate_parts(cat)
    _, st, m = dc_parts.static_screen(p, req, loads)
    N = p.values["gear_ratio"]
    inside = (N >= st["ratio_low"] * 1.001) & (N <= st["ratio_high"] * 0.999) & (st["drive_voltage_V"] == p.values["drive_bus_voltage"])
    assert inside.any()
    assert np.all(m["blocked_force"][inside] >= 0) and np.all(m["speed"][inside] >= 0)
