"""requirements.toml: the contract's format, SI conversion and bad input."""
from __future__ import annotations

import pytest

from sizing.errors import InputError
from sizing.io.requirements import load_requirements

from ..conftest import STUDIES, run_cli

SEED = """
[requirements]
stroke = "40 mm"
blocked_force = "2.5 kN"
speed = "100 mm/s"
max_temperature = "100 degC"

[load]
span = "15 in"
chord = "10 in"
thickness = "0.0625 in"
dynamic_pressure = ["10 kPa", "25 kPa"]

[objectives]
minimize = ["mass", "cost"]
"""


def write(tmp_path, text, name="req.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_seed_file_converts_to_si():
    # seed section 1: 40 mm, 2.5 kN, 100 mm/s, 100 degC; Figure 7 surface 15 x 10 in
    req, sha = load_requirements(STUDIES / "seed-requirements.toml")
    r = req.requirements
    assert (r.stroke, r.blocked_force, r.speed, r.max_temperature) == pytest.approx((0.04, 2500.0, 0.1, 100.0))
    assert req.load.span == pytest.approx(15 * 0.0254)
    assert req.load.dynamic_pressure == pytest.approx([10e3, 25e3])
    assert req.objectives.minimize == ["mass", "cost"]
    assert req.stroke_time == pytest.approx(0.4)
    assert len(sha) == 64


def test_bare_numbers_are_si_and_options_have_defaults(tmp_path):
    text = SEED.replace('"40 mm"', "0.04").replace('"2.5 kN"', "2500")
    req, _ = load_requirements(write(tmp_path, text + "\n[options]\nmax_stacks = 12\nwide_gap = \"2 mm\"\n"))
    assert req.requirements.stroke == pytest.approx(0.04)
    assert req.options.max_stacks == 12 and req.options.wide_gap == pytest.approx(2e-3)
    assert req.options.thermal_compensation is True


@pytest.mark.parametrize("old, new, field, expected", [
    ('stroke = "40 mm"', 'stroke = "40 kg"', r"\[requirements\]\.stroke", "expected a length"),
    ('stroke = "40 mm"', 'stroke = "-40 mm"', r"\[requirements\]\.stroke", "positive"),
    ('stroke = "40 mm"', "stroke = nan", r"\[requirements\]\.stroke", "finite"),
    ('speed = "100 mm/s"', 'speed = "100 mm"', r"\[requirements\]\.speed", "expected a speed"),
    ('["mass", "cost"]', '["mass", "beauty"]', r"\[objectives", "mass"),
    ('["mass", "cost"]', '["mass", "mass"]', r"\[objectives\]\.minimize", "once"),
    ('["mass", "cost"]', "[]", r"\[objectives\]\.minimize", "at least 1"),
    ('["mass", "cost"]', '["mass", "cost"]\nmin_compliance = 1.5', r"\[objectives\]\.min_compliance", "from 0 to 1"),
    ('["mass", "cost"]', '["mass", "cost"]\nmin_compliance = "-5 %"', r"\[objectives\]\.min_compliance", "negative"),
    ('blocked_force = "2.5 kN"\n', "", r"\[requirements\]\.blocked_force", "missing"),
    ('max_temperature = "100 degC"', 'max_temperature = "100 degC"\nmax_temprature = 3', "max_temprature", "unknown"),
    ('max_temperature = "100 degC"', 'max_temperature = "-300 degC"', "max_temperature", "absolute zero"),
])
def test_bad_values_name_file_and_field(tmp_path, old, new, field, expected):
    path = write(tmp_path, SEED.replace(old, new))
    with pytest.raises(InputError, match=field) as info:
        load_requirements(path)
    assert "req.toml" in str(info.value)
    assert expected in str(info.value)


def test_malformed_toml(tmp_path):
    with pytest.raises(InputError, match="malformed TOML"):
        load_requirements(write(tmp_path, "[requirements\nstroke = 1"))


@pytest.mark.parametrize("old, new, field", [
    ('stroke = "40 mm"', 'stroke = "40 kg"', "[requirements].stroke"),
    ('["mass", "cost"]', '["mass", "beauty"]', "[objectives"),
    ("[requirements]", "[requirements", None),
])
def test_cli_bad_input_exits_2_with_one_line_and_writes_nothing(tmp_path, old, new, field):
    path = write(tmp_path, SEED.replace(old, new))
    out = tmp_path / "out"
    code, stdout, stderr = run_cli("solve", path, "--out", out, "--quiet")
    assert code == 2
    lines = stderr.strip().splitlines()
    assert len(lines) == 1 and "req.toml" in lines[0] and "Traceback" not in stderr
    if field:
        assert field in lines[0]
    assert not out.exists() or not any(out.iterdir())
