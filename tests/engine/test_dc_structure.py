"""The DC structure sized by the load (technologies/dc_motor/structure.py) and the
frameless-kit housing rule (technologies/dc_motor/parts.py), against hand numbers and
the data they come from."""
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from sizing.technologies.dc_motor import parts as dc_parts
from sizing.technologies.dc_motor import structure as dc_structure
from sizing.physics import column

ROOT = Path(__file__).resolve().parents[2]


def _values(n=1, **over):
    """Part values of a 12 x 2 THK screw (BNK1202-3) for ``size``."""
    v = {"screw_mass_per_length": 0.71, "screw_nut_mass": 0.05, "screw_diameter": 0.011,
         "screw_elastic_modulus": 2.0e11}
    v.update(over)
    return {k: np.full(n, val, float) for k, val in v.items()}


def test_rod_is_the_thinnest_column_that_carries_the_design_force():
    """The rod's wall, re-checked with the column formula by hand: at the
    sized diameter the critical load is the design force (or the floor
    carries more); 1 % thinner it is not enough."""
    F = np.array([2000.0, 20000.0, 60000.0])
    r = dc_structure.rod(F, 0.012, 0.055)
    bore, L = 0.012 + 2 * dc_structure.ROD_CLEARANCE, 0.055 + dc_structure.ROD_END_LENGTH
    assert r["bore_m"] == pytest.approx(bore)
    cap = lambda D: column.critical_load(205e9, 834e6, column.tube_area(D, bore),
                                         column.tube_radius_of_gyration(D, bore), L, 2.0)
    assert cap(r["outer_diameter_m"]) == pytest.approx(r["critical_load_N"])
    sized = r["outer_diameter_m"] > bore + 2 * dc_structure.ROD_MIN_WALL + 1e-9
    assert sized[-1]                                      # 60 kN is above the floor's capacity
    assert r["critical_load_N"][sized] == pytest.approx(F[sized], rel=1e-6)
    thinner = bore + 0.99 * (r["outer_diameter_m"][sized] - bore)
    assert np.all(cap(thinner) < F[sized])
    # mass: steel tube over its length
    assert r["mass_kg"] == pytest.approx(7850 * math.pi / 4 * (r["outer_diameter_m"] ** 2 - bore**2) * L)


def test_bearing_pair_by_life_and_static_safety_hand_computed():
    """A 12 mm shaft at 1 kN holding, 40 rev/s: the 7200 pair gives L10 =
    (7020 / 570)^3 10^6 / (40 x 3600) = 12 972 h; at a 6 kN peak its s0 =
    3350 / (0.26 x 6000) = 2.15 >= 2; at 7 kN, 1.84: the 7201 (C0 3.8 kN,
    bore 12 mm fits a 12 mm shaft) gives 2.09."""
    b = dc_structure.thrust_bearing(np.array([6000.0, 7000.0]), 1000.0, 40.0, 0.012)
    assert [dc_structure.BEARINGS[i][0] for i in b["index"]] == ["7200 BECBP", "7201 BECBP"]
    assert b["life_h"][0] == pytest.approx((7020 / 570) ** 3 * 1e6 / (40 * 3600))
    assert b["static_safety"] == pytest.approx([3350 / 1560, 3800 / 1820])
    assert b["mass_kg"] == pytest.approx([0.060, 0.072])
    # a journal too small for any bearing of the series: the check fails, not passes
    tiny = dc_structure.size(_values(screw_mass_per_length=0.3), 0.05, np.array([100.0]), 50.0,
                             np.array([10.0]), 0.1)
    assert tiny["margins"]["bearing_life"][0] < 0 and tiny["margins"]["bearing_static"][0] < 0


def test_housing_wall_from_its_rules():
    """Small load: the wall floor or the stiffness rule binds (E_al A_h >= E_s A_screw);
    large load: the column or eccentric stress, whose capacity then equals the design force."""
    bore, L, screw_k = 0.03, 0.12, 2e11 * math.pi / 4 * 0.011**2 / 0.1
    h = dc_structure.housing(np.array([100.0, 400e3]), bore, L, screw_k)
    need = screw_k * L / 68.9e9
    floor = max(bore + 2 * dc_structure.HOUSING_MIN_WALL, math.sqrt(bore**2 + 4 * need / math.pi))
    assert h["outer_diameter_m"][0] == pytest.approx(floor)
    assert h["capacity_N"][1] == pytest.approx(400e3, rel=1e-6)
    # eccentric stress at the sized wall is at most the yield strength
    D = h["outer_diameter_m"][1]
    assert column.eccentric_stress(400e3, dc_structure.ECCENTRICITY, D, bore) <= 276e6 * (1 + 1e-6)


def test_structure_grows_with_the_force_and_margins_are_finite():
    F = np.array([100.0, 1000.0, 5000.0, 20000.0])
    out = dc_structure.size(_values(4, screw_mass_per_length=1.387, screw_nut_mass=0.3, screw_diameter=0.013),
                            0.055, F, F / 2, np.full(4, 5.0), 0.1)
    assert np.all(np.diff(out["mass_kg"]) >= 0)
    assert out["mass_kg"][-1] > out["mass_kg"][0]
    for name, m in out["margins"].items():
        assert np.all(np.isfinite(m)), name
    assert set(out["margins"]) == set(dc_structure.MARGINS)


def test_frameless_housing_rule_refits_the_database():
    """The housed (maxon outer-rotor flat) and frameless (Allied) fits of
    mass over continuous torque, recomputed from catalogs/motors-mgdb.toml."""
    motors = tomllib.loads((ROOT / "catalogs" / "motors-mgdb.toml").read_text())["motor"]

    def fit(rows):
        T = np.array([m["continuous_torque"] for m in rows])
        M = np.array([m["mass"] for m in rows])
        b, log_a = np.polyfit(np.log(T), np.log(M), 1)
        return math.exp(log_a), b

    flat = [m for m in motors if m["manufacturer"] == "Maxon" and "Outer-rotor" in (m.get("notes") or "")]
    kits = [m for m in motors if (m.get("notes") or "").startswith("Frameless")]
    assert len(flat) == 26 and len(kits) == 148
    for (a, b), (a0, b0) in ((fit(flat), dc_parts.HOUSED_FIT), (fit(kits), dc_parts.FRAMELESS_FIT)):
        assert a == pytest.approx(a0, rel=0.01) and b == pytest.approx(b0, abs=0.002)
    # at 1 N m: 0.842 - 0.543 = 0.299 kg of housing, bearings and feedback
    assert dc_parts.frameless_housing_mass(1.0) == pytest.approx(0.299, abs=1e-3)
    assert np.all(dc_parts.frameless_housing_mass(np.array([0.0, 0.05])) >= 0)


def _dc_records(data):
    from sizing.technologies.dc_motor.record import actuator_candidate, parts_candidate
    from sizing.technologies.dc_motor.catalog_actuators import actuator_designs
    from sizing.technologies.dc_motor.from_parts import dc_parts_designs
    from sizing.engine.evaluate import load_cases
    from sizing.io.catalog import load_catalog
    from sizing.io.requirements import parse_requirements
    catalog = load_catalog()
    req = parse_requirements(data, "requirements.toml")
    loads = [c["load_N"] for c in load_cases(req.load)]
    return ([parts_candidate(req, catalog, d) for d in dc_parts_designs(req, catalog, loads).designs]
            + [actuator_candidate(req, catalog, d) for d in actuator_designs(req, catalog, loads)])


@pytest.mark.parametrize("blocked", [None, pytest.param(100.0, marks=pytest.mark.slow), 1e3,
                                     pytest.param(5e3, marks=pytest.mark.slow), 20e3])
def test_no_dc_margin_is_infinite(blocked):
    """The seed's case (blocked None) and the force probe (50 mm, 20 mm/s at
    half the blocked force, 40 degC): every DC record's margins are finite
    (an unrated part is named in ``unchecked``, never passed with inf), and
    the record is strict JSON."""
    import json
    if blocked is None:
        data = tomllib.loads((ROOT / "studies" / "seed-requirements.toml").read_text())
    else:
        data = {"requirements": {"stroke": "50 mm", "blocked_force": blocked, "speed": "20 mm/s",
                                 "max_temperature": "40 degC"},
                "load": {"force": [blocked / 2]}, "duty": {"strokes_per_second": 0.1}}
    records = _dc_records(data)
    assert records
    for c in records:
        assert all(math.isfinite(v) for v in c["margins"].values()), (c["id"], c["margins"])
        json.dumps(c["margins"], allow_nan=False)
        if c["variant"] == "parts":
            assert set(dc_structure.MARGINS) <= set(c["margins"])
            assert c["metrics"]["mass_kg"] == pytest.approx(sum(c["mass_breakdown_kg"].values()))
            for u in c["unchecked"]:
                assert u["check"] not in c["margins"] and u["reason"]


def test_supply_voltage_chooses_the_drives_and_sets_the_bus():
    """At 24 V: the 28 V and 48 V drives run from it (within 4:1 of their
    rated bus), the 96 V one too, the 270 V one does not; each runs at 24 V,
    so the screen's voltage limit is at most 24 V. Without a supply the
    catalog is untouched. A bad value is refused naming the field."""
    from sizing.errors import InputError
    from sizing.io.catalog import load_catalog
    from sizing.io.requirements import parse_requirements
    catalog = load_catalog()
    at24 = dc_parts.drives_for_supply(catalog, 24.0)
    assert dc_parts.drives_for_supply(catalog, None) is catalog
    rated = {k: d.bus_voltage for k, d in catalog.drives.items()}
    assert set(at24.drives) == {k for k, u in rated.items() if u / 4 <= 24.0 <= u}
    assert "servo-270v-10a" not in at24.drives and "servo-48v-10a" in at24.drives
    assert all(d.bus_voltage == 24.0 for d in at24.drives.values())
    data = {"requirements": {"stroke": "50 mm", "blocked_force": "200 N", "speed": "20 mm/s",
                             "max_temperature": "40 degC", "supply_voltage": "24 V"}, "load": {"force": [100.0]}}
    req = parse_requirements(data, "r.toml")
    assert req.requirements.supply_voltage == pytest.approx(24.0)
    p = dc_parts.enumerate_parts(dc_parts.drives_for_supply(catalog, req.requirements.supply_voltage))
    _, st, _ = dc_parts.static_screen(p.take(np.arange(min(len(p), 2000))), req, [100.0])
    assert np.all(st["drive_voltage_V"] <= 24.0 + 1e-9)
    data["requirements"]["supply_voltage"] = "24 kg"
    with pytest.raises(InputError, match="supply_voltage"):
        parse_requirements(data, "r.toml")


def test_output_samples_scale_with_the_duration():
    """The seed's 1.6 s response keeps 2 kHz; a 100 mm stroke at 3 mm/s
    (133 s simulated) keeps the same 3200 samples, 800 per stroke time."""
    from sizing.technologies.dc_motor import actuator as dc
    assert dc.output_rate(1.6) == dc.OUTPUT_RATE_HZ
    assert len(dc.output_times(1.6)) == 3201
    T = 4 * 0.1 / 0.003
    t = dc.output_times(T)
    assert len(t) == pytest.approx(3201, abs=1) and t[-1] == pytest.approx(T, rel=1e-3)
    assert dc.output_rate(T) * (T / 4) == pytest.approx(800)


def test_brake_holds_the_load_and_weighs_its_rule():
    """[options] dc_brake: the winding carries no current while holding, so
    the holding margin is at least the one without; the brake's mass is
    0.05 kg + 0.5 kg per N m of the back-driven holding torque, and the
    design's mass grows by exactly it."""
    from sizing.io.catalog import load_catalog
    from sizing.io.requirements import load_requirements
    from sizing.physics import screw
    req, _ = load_requirements(ROOT / "studies" / "seed-requirements.toml")
    braked = req.model_copy(update={"options": req.options.model_copy(update={"dc_brake": True})})
    p = dc_parts.enumerate_parts(load_catalog())
    p = p.take(np.arange(0, len(p), max(1, len(p) // 500)))
    loads = [500.0, 1209.675]
    _, st0, m0 = dc_parts.static_screen(p, req, loads)
    _, st1, m1 = dc_parts.static_screen(p, braked, loads)
    v = p.values
    t_hold = screw.holding_torque(1209.675, v["screw_lead"], dc_parts.SCREW_BACK_EFFICIENCY, v["gear_ratio"],
                                  v["gear_efficiency"])
    assert st1["brake_mass_kg"] == pytest.approx(0.05 + 0.5 * t_hold)
    assert np.all(st0["brake_mass_kg"] == 0)
    assert dc_parts.metrics(p, braked, st1)["mass_kg"] == pytest.approx(
        dc_parts.metrics(p, req, st0)["mass_kg"] + st1["brake_mass_kg"])
    assert np.all(m1["holding"] >= m0["holding"] - 1e-12)
    assert np.all(st1["holding_power_W"] == 0)


def test_a_24_v_braked_design_round_trips_through_evaluate(tmp_path):
    """The design block of a design solved on a 24 V supply with a brake
    carries both; evaluated, it reproduces the mass and margins."""
    from sizing import api
    from sizing.technologies.dc_motor.record import parts_candidate
    from sizing.technologies.dc_motor.from_parts import dc_parts_designs
    from sizing.engine.rank import verdict
    from sizing.io.catalog import load_catalog
    from sizing.io.requirements import parse_requirements
    catalog = load_catalog()
    data = {"requirements": {"stroke": "50 mm", "blocked_force": "300 N", "speed": "30 mm/s",
                             "max_temperature": "40 degC", "supply_voltage": "24 V"},
            "load": {"force": [150.0]}, "duty": {"strokes_per_second": 0.1}, "options": {"dc_brake": True}}
    req = parse_requirements(data, "r.toml")
    feasible = [d for d in dc_parts_designs(req, catalog, [150.0]).designs if verdict(dict(d.margins))[0]]
    c = parts_candidate(req, catalog, min(feasible, key=lambda d: d.metrics["mass_kg"]))
    assert c["design"]["supply_voltage"] == 24.0 and c["design"]["brake"] is True
    assert c["controller"]["bus_voltage_V"] == 24.0 and c["mass_breakdown_kg"]["brake"] > 0
    import tomlkit
    design = {k: v for k, v in c["design"].items() if v is not None}
    (tmp_path / "d.toml").write_text(tomlkit.dumps({**design, "load": {"force": [150.0]}}))
    e = api.evaluate(tmp_path / "d.toml")
    assert e["metrics"]["mass_kg"] == pytest.approx(c["metrics"]["mass_kg"], rel=0.005)
    for k, v in e["margins"].items():
        assert v == pytest.approx(c["margins"][k], rel=0.005, abs=0.005), k


def test_end_cap_plate_and_clevis_hand_computed_and_sized_members_pass_their_check():
    """45 kN on a 40 mm bore: q = 45000 / (pi 0.02^2) = 35.81 MPa, the
    simply supported plate t = a sqrt(3 (3 + nu) q / (8 S_y)) = 0.02 x
    sqrt(1.24875 x 35.81 / 276) = 8.05 mm (Roark table 11.2 case 10a). The
    clevis pin: shear sqrt(2 F / (pi S_y / sqrt 3)) = 7.71 mm, bending
    (8 / pi)^(1/4) sqrt(F / S_y) = 9.28 mm (binds); eye t = F / (d S_y) =
    5.81 mm. Sized to the force, each member's margin is zero, never a
    rounding below it (a margin of -2e-16 used to fail every design whose
    plate the stress set)."""
    F = 45000.0
    caps = dc_structure.end_caps(np.array([F]), 0.06, 0.04, 0.035, 0.011, 0.02)
    assert caps["plate_thickness_m"][0] == pytest.approx(8.05e-3, rel=2e-3)
    c = dc_structure.clevises(np.array([F]))
    assert c["pin_diameter_m"][0] == pytest.approx(9.28e-3, rel=2e-3)
    assert c["eye_thickness_m"][0] == pytest.approx(5.81e-3, rel=3e-3)
    assert c["capacity_N"][0] == pytest.approx(F, rel=1e-9)
    forces = np.geomspace(500.0, 60000.0, 40)
    out = dc_structure.size(_values(40, screw_mass_per_length=6.313, screw_nut_mass=0.64, screw_diameter=0.0289),
                            0.055, forces, forces / 2, np.full(40, 2.0), 0.105)
    for name in ("end_cap_stress", "clevis"):
        m = out["margins"][name]
        assert np.all(m >= 0), (name, m.min())
        assert np.any(m < 1e-6), name          # some are sized by the force, not the floor


def test_members_sized_once_per_distinct_row_are_the_same_to_the_bit():
    """``once_per_distinct`` sizes each distinct (force, shaft) row once: the
    rod and housing of 600 rows with 40 distinct ones (a zero of either sign
    and a NaN among them) equal the member sized row by row."""
    from sizing.technologies.dc_motor import structure as st
    rng = np.random.default_rng(5)
    F = rng.uniform(2e3, 2e4, 40)
    F[:3] = (0.0, -0.0, np.nan)
    shaft = rng.uniform(6e-3, 2e-2, 40)
    pick = rng.integers(0, 40, 600)
    force, d = F[pick], shaft[pick]
    for sized, direct in ((st.once_per_distinct(st.rod, force, d, travel=0.05), st.rod(force, d, 0.05)),
                          (st.once_per_distinct(st.housing, force, d + 0.01, 0.12, 3e7),
                           st.housing(force, d + 0.01, 0.12, 3e7))):
        assert sized.keys() == direct.keys()
        for k in direct:
            a, b = np.broadcast_arrays(sized[k], direct[k])
            assert a.dtype == b.dtype and a.tobytes() == b.tobytes(), k
    assert np.array_equal(st.once_per_distinct(st.nut_diameter, np.full(600, 0.05), d),
                          st.nut_diameter(0.05, d))
