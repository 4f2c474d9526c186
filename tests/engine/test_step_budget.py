"""A slow, long stroke: the piezohydraulic simulations fit within the step
limit (fewer of them, or none) instead of stopping the solve; the DC
actuators' own steps are still checked."""
import tomllib
from pathlib import Path

import pytest

from sizing.api.checks import check_solve_steps
from sizing.technologies.dc_motor.stage import dc_actuator_steps
from sizing.technologies.piezohydraulic.stage import piezo_simulation_budget
from sizing.errors import InputError
from sizing.io.catalog import load_catalog
from sizing.io.requirements import parse_requirements
from sizing.limits import simulations_within, use_limits

ROOT = Path(__file__).resolve().parents[2]


def _slow(stroke="100 mm", speed="3 mm/s"):
    data = tomllib.loads((ROOT / "studies" / "seed-requirements.toml").read_text())
    data["requirements"].update(stroke=stroke, speed=speed)
    return parse_requirements(data, "slow.toml")


def test_simulations_within_hand_computed():
    assert simulations_within(1.343e6, 400, 1e8) == 74        # 1e8 // 1.343e6
    assert simulations_within(1.343e6, 50, 1e8) == 50
    assert simulations_within(2e8, 400, 1e8) == 0
    assert simulations_within(1e6, 400, -5.0) == 0


def test_100_mm_at_3_mm_s_is_solved_with_fewer_piezo_simulations():
    """100 mm at 3 mm/s: 33.3 s of stroke plus 0.25 s of settling at 20 kHz
    over two load cases is 1.343e6 steps a design (by hand), so at most 74
    of the 400 designs fit the 1e8 limit, less the DC actuators' steps."""
    cat, req = load_catalog(), _slow()
    check_solve_steps(req, cat, "slow.toml")          # no longer refused
    dc = dc_actuator_steps(req, cat)
    each = 2 * (0.1 / 0.003 + 0.25) * 20e3
    assert each == pytest.approx(1.343e6, rel=1e-3)
    assert piezo_simulation_budget(req, cat, 2) == int((1e8 - dc) // each) <= 74
    # the seed's own case keeps its 400
    seed = parse_requirements(tomllib.loads((ROOT / "studies" / "seed-requirements.toml").read_text()), "seed")
    assert piezo_simulation_budget(seed, cat, 2) == seed.options.max_simulated


def test_a_limit_below_the_dc_actuators_steps_still_refuses():
    cat, req = load_catalog(), _slow()
    dc = dc_actuator_steps(req, cat)
    assert dc > 0
    with use_limits(steps=dc / 2):
        with pytest.raises(InputError, match="DC actuators"):
            check_solve_steps(req, cat, "slow.toml")
    with use_limits(steps=dc * 1.01):       # room for the DC actuators, none for a piezo design
        check_solve_steps(req, cat, "slow.toml")
        assert piezo_simulation_budget(req, cat, 2) == 0


@pytest.mark.slow
def test_the_dc_design_of_a_slow_long_stroke_is_simulated_and_found():
    """100 mm at 3 mm/s under 250 N (500 N blocked) at 40 degC: the DC parts
    are simulated over the 133 s the controller needs and a feasible design
    is found (about 90 s: the search and its simulations)."""
    from sizing.technologies.dc_motor.from_parts import dc_parts_designs
    from sizing.engine.rank import verdict
    data = {"requirements": {"stroke": "100 mm", "blocked_force": 500.0, "speed": "3 mm/s",
                             "max_temperature": "40 degC"},
            "load": {"force": [250.0]}, "duty": {"strokes_per_second": 0.01}}
    req = parse_requirements(data, "slow.toml")
    check_solve_steps(req, load_catalog(), "slow.toml")
    out = dc_parts_designs(req, load_catalog(), [250.0])
    simulated = [d for d in out.designs if d.stage == "simulated"]
    assert simulated
    assert any(verdict(dict(d.margins))[0] for d in simulated)
