"""Slow computations kept on disk (sizing/disk_cache.py): read back as
computed, computed again when the folder cannot be written."""
from __future__ import annotations

from sizing import disk_cache
from sizing.physics import plate_fe


def test_a_value_is_computed_once_and_read_back_the_same(tmp_path, monkeypatch):
    monkeypatch.setenv("SIZING_CACHE_DIR", str(tmp_path))
    calls = []

    @disk_cache.memo("numpy")
    def slow(x, edge):
        calls.append(x)
        return x / 3.0

    assert slow(0.1, "clamped") == 0.1 / 3.0 and calls == [0.1]
    assert slow(0.1, "clamped") == 0.1 / 3.0 and calls == [0.1]
    disk_cache.flush()
    files = list((tmp_path / "computed").glob("*.json"))
    assert len(files) == 1

    @disk_cache.memo("numpy")
    def slow(x, edge):          # noqa: F811  a new process: the same function, nothing in memory
        calls.append(x)
        return x / 3.0

    assert slow(0.1, "clamped") == 0.1 / 3.0 and calls == [0.1]        # read from the file, bit for bit


def test_an_unwritable_folder_only_costs_the_computation(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("SIZING_CACHE_DIR", str(blocker))     # a file where the folder would be

    @disk_cache.memo()
    def half(x):
        return x / 2

    assert half(3.0) == 1.5
    disk_cache.flush()
    assert half(3.0) == 1.5


def test_the_plate_solve_read_back_is_the_solve(tmp_path, monkeypatch):
    """The finite-element factor from the file equals a fresh solve's."""
    monkeypatch.setenv("SIZING_CACHE_DIR", str(tmp_path))
    fresh = plate_fe._compliance_factor.__wrapped__.__wrapped__(0.5, 0.33, "clamped", 10, 4)
    plate_fe._compliance_factor.cache_clear()
    first = plate_fe._compliance_factor(0.5, 0.33, "clamped", 10, 4)
    disk_cache.flush()
    files = list((tmp_path / "computed").glob("*.json"))
    assert len(files) == 1 and "0.5, 0.33, 'clamped', 10, 4" in files[0].read_text()
    assert first == fresh


def test_a_quantity_read_back_is_pint_s_conversion(tmp_path, monkeypatch):
    """A text's SI value from the file equals pint's own conversion, and a
    bad one is still refused (errors are not kept)."""
    import pytest
    from sizing import units
    monkeypatch.setenv("SIZING_CACHE_DIR", str(tmp_path))
    texts = [("40 mm", "length"), ("2.5 kN", "force"), ("100 degC", "temperature"), ("1.96e7 N/m", "stiffness"),
             ("0.6 mm", "length"), ("31 uF", "capacitance")]
    pint_says = [float(units.parse_quantity(t).to(units.KINDS[k][0]).magnitude) if k != "temperature"
                 else float(units.parse_quantity(t).to("degC").magnitude) for t, k in texts]
    assert [units.to_si(t, k) for t, k in texts] == pint_says
    disk_cache.flush()
    units._text_to_si.forget()
    assert [units.to_si(t, k) for t, k in texts] == pint_says
    with pytest.raises(units.UnitError):
        units.to_si("40 furlongs/fortnight", "length")
