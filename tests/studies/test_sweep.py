"""sizing sweep: a full solve per grid point."""
from __future__ import annotations

import pytest

from sizing.engine.solve import solve
from sizing.io.requirements import parse_requirements
from sizing.io.schema import load_toml
from sizing.studies.executor import Executor
from sizing.studies.sweep import limits, parse_vary, point_summary, sweep

from ..conftest import ONE_DESIGN, STUDIES, run_cli, subset_catalog
from ..documented import missing_fields

FAST = {"max_stacks": 11, "max_simulated": 6, "thermal_compensation": True}


@pytest.fixture(scope="module")
def small_catalog():
    return subset_catalog(**ONE_DESIGN, dc_actuators=1)


@pytest.fixture
def seed_data():
    data = load_toml(STUDIES / "seed-requirements.toml")
    data["options"] = dict(FAST)
    # at one stroke per second the amplifier's continuous current fails every
    # piezohydraulic design; at 0.1 some are feasible, so "best" exists (given a
    # two-hour warm-up, within which a restrictor compensator takes up most of the oil's growth)
    data["duty"] = {"strokes_per_second": 0.1, "warm_up_time": "2 h"}
    return data


def test_vary_parses_units_as_in_the_file(seed_data):
    path = STUDIES / "seed-requirements.toml"
    v = parse_vary("stroke=35mm..50mm:4", seed_data, path)
    assert v.name == "stroke" and v.values == pytest.approx((0.035, 0.040, 0.045, 0.050))
    t = parse_vary("max_temperature=80degC..120degC:3", seed_data, path)
    assert t.values == pytest.approx((80.0, 100.0, 120.0))
    f = parse_vary("blocked_force = 2 kN .. 3000 N : 2", seed_data, path)
    assert f.values == pytest.approx((2000.0, 3000.0))


@pytest.mark.parametrize("text, says", [
    ("stroke=35kg..50mm:4", "expected a length"),
    ("strok=35mm..50mm:4", "strok"),
    ("stroke=35mm..50mm", "FROM..TO:N"),
    ("stroke=35mm..50mm:0", "points"),
])
def test_bad_vary_is_an_input_error(seed_data, text, says):
    from sizing.errors import InputError
    with pytest.raises(InputError) as exc:
        parse_vary(text, seed_data, "req.toml")
    assert "--vary" in str(exc.value) and says in str(exc.value)


def test_sweep_over_stroke_reproduces_solve_at_each_point(seed_data, small_catalog):
    out = sweep(seed_data, "req.toml", small_catalog, ["stroke=38mm..44mm:2"], Executor(0))
    assert not missing_fields("sweep.json", out)         # every field docs/formats.md documents
    assert [g["varied"]["stroke"] for g in out["grid"]] == pytest.approx([0.038, 0.044])
    for g in out["grid"]:
        data = dict(seed_data, requirements=dict(seed_data["requirements"], stroke=f"{g['varied']['stroke'] * 1e3:g} mm"))
        results = solve(parse_requirements(data, "point.toml"), "x", small_catalog).results
        ref = point_summary(results, g["varied"])
        assert g["feasible"] == ref["feasible"]
        assert g["best"] == ref["best"]
        assert g["best_by_technology"] == ref["best_by_technology"]
        assert g["front"] == ref["front"]
        assert g["requirements"]["stroke_m"] == pytest.approx(g["varied"]["stroke"])
    from sizing.report.sweep_html import render
    page = render(out)                    # self-contained: plotly.js inline, no CDN
    assert out["grid"][0]["best"]["name"] in page and len(out["grid"][0]["best"]["name"]) <= 32 and "Plotly" in page and "<script src" not in page
    # feasible counts computed independently of point_summary, from the solve's own flags
    assert g["feasible"]["piezohydraulic"] == sum(1 for c in results["candidates"]
                                                  if c.technology == "piezohydraulic" and c.feasible)


def test_limits_name_the_last_feasible_and_first_infeasible_value():
    grid = [{"varied": {"stroke": s}, "feasible": {"piezohydraulic": n, "dc_motor": 1}}
            for s, n in ((0.035, 4), (0.040, 2), (0.045, 0), (0.050, 0))]
    from sizing.studies.sweep import Vary
    lim = limits(grid, [Vary("requirements", "stroke", (0.035, 0.040, 0.045, 0.050))])
    row = lim["piezohydraulic"]["stroke"][0]
    assert row["last_feasible"] == 0.040 and row["first_infeasible"] == 0.045 and not row["feasible_everywhere"]
    assert lim["dc_motor"]["stroke"][0]["feasible_everywhere"]


def test_cli_bad_vary_exits_2_and_writes_nothing(tmp_path):
    out = tmp_path / "out"
    code, _, err = run_cli("sweep", STUDIES / "seed-requirements.toml", "--vary", "stroke=35kg..50mm:4",
                           "--out", out, "--workers", "0", "--quiet")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "--vary stroke" in err
    assert not out.exists()


@pytest.mark.parametrize("command", ["robust", "sweep"])
def test_study_commands_have_help_and_docs(command):
    code, out, _ = run_cli(command, "--help")
    assert code == 0 and "--scheduler" in out and "--workers" in out
    readme = (STUDIES.parent / "README.md").read_text()
    assert f"sizing {command} " in readme
