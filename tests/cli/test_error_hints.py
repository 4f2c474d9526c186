"""Errors that say how to fix them: each bad input exits 2 with one line
naming the file, the field and the fix, and writes nothing."""
from __future__ import annotations

import time

import pytest

from ..conftest import STUDIES, run_cli

SEED = (STUDIES / "seed-requirements.toml").read_text()


@pytest.mark.parametrize("old, new, expected", [
    ('stroke = "40 mm"', "stroke = 40", ['[requirements].stroke', '40 means 40 m', '"40 mm"']),
    ('"100 degC"', '"100 C"', ["[requirements].max_temperature", "degC"]),
    ("max_temperature", "max_temprature", ["[requirements].max_temprature", 'did you mean "max_temperature"']),
    ('stroke = "40 mm"', 'stroke = "1 um"', ["[requirements].stroke", "at least 0.1 mm"]),
])
def test_requirement_errors_name_the_fix(tmp_path, old, new, expected):
    req = tmp_path / "req.toml"
    req.write_text(SEED.replace(old, new, 1))
    out = tmp_path / "out"
    start = time.perf_counter()
    code, _, stderr = run_cli("solve", req, "--out", out, "--quiet")
    assert code == 2 and len(stderr.strip().splitlines()) == 1, stderr
    assert all(e in stderr for e in expected), stderr
    assert not out.exists()
    assert time.perf_counter() - start < 30          # refused, not searched (a 1 um stroke ran for minutes)


def test_catalog_show_suggests_near_ids():
    code, _, stderr = run_cli("catalog", "show", "pi-p-056.9")
    assert code == 2 and "did you mean pi-p-056.90" in stderr and len(stderr.strip().splitlines()) == 1


def test_catalog_add_accepts_the_units_the_catalog_uses(catalog_copy, tmp_path):
    """A seal sheet with the catalog's own unit for the pressure coefficient
    in its header, N/(m*Pa) (catalogs/seals.toml), is read, not refused."""
    from sizing.io.catalog import load_catalog
    sheet = tmp_path / "seals.csv"
    sheet.write_text(
        "id,name,manufacturer,source,retrieved,material,type,friction_per_length [N/m],"
        "friction_pressure_coefficient [N/(m*Pa)],breakaway_ratio,min_temperature [degC],"
        "max_temperature [degC],pressure_rating [MPa],cost_usd\n"
        "test-seal,Test seal,Test maker,hand,2026-11-25,PTFE,lip,30,4e-5,1.5,-50,200,21,25\n")
    code, _, err = run_cli("catalog", "add", "seal", sheet, "--catalog", catalog_copy)
    assert code == 0, err
    seal = load_catalog(catalog_copy).seals["test-seal"]
    assert seal.friction_pressure_coefficient == pytest.approx(4e-5) and seal.pressure_rating == pytest.approx(21e6)
