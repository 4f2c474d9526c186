"""The shipped catalog: loads, has the seed's parts, rejects bad entries."""
import pytest

from sizing.errors import InputError
from sizing.io.catalog import load_catalog
from sizing.io.validate import validate_catalog

from ..conftest import run_cli


def test_shipped_catalog_is_valid_and_complete():
    cat = load_catalog()
    assert {"pi-p-056.90", "thorlabs-pk4ga7p1"} <= set(cat.stacks)
    assert len(cat.stacks) >= 6
    assert "iso-vg-15-mineral" in cat.fluids and len(cat.fluids) >= 2
    assert {"ptfe-spring-energised", "ptfe-o-ring", "fkm-o-ring"} <= set(cat.seals)
    assert cat.amplifiers and "ultramotion-amcx8b-b0m1" in cat.dc_actuators and len(cat.dc_actuators) >= 2
    for kind, entry in cat.entries():
        assert entry.source and entry.retrieved


def test_seed_values_in_catalog():
    cat = load_catalog()
    pi = cat.stacks["pi-p-056.90"]
    assert pi.stiffness == pytest.approx(4.33e8) and pi.stroke_per_volt == pytest.approx(1.8e-7)
    th = cat.stacks["thorlabs-pk4ga7p1"]
    assert th.bouc_wen.d33 == pytest.approx(8.15e-7) and th.bouc_wen.n == pytest.approx(1.14)
    um = cat.dc_actuators["ultramotion-amcx8b-b0m1"]
    assert um.c1 == pytest.approx(-25.5552) and um.c2 == pytest.approx(2987.02)
    assert um.screw_lead == pytest.approx(0.002) and um.pid.rate == pytest.approx(1250)


def _edit(folder, file, old, new):
    path = folder / file
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new, 1))


def test_negative_stiffness_names_file_entry_field(catalog_copy):
    _edit(catalog_copy, "stacks.toml", 'stiffness = "4.33e8 N/m"', 'stiffness = "-4.33e8 N/m"')
    with pytest.raises(InputError, match=r"stacks.toml: \[\[stack\]\] pi-p-056.90: stiffness: expected a positive"):
        load_catalog(catalog_copy)


def test_wrong_unit_exits_2(catalog_copy):
    _edit(catalog_copy, "stacks.toml", 'stiffness = "4.33e8 N/m"', 'stiffness = "4.33e8 kg"')
    code, out, err = run_cli("catalog", "validate", catalog_copy)
    assert code == 2
    assert "stacks.toml" in err and "pi-p-056.90" in err and "stiffness" in err and "expected a stiffness" in err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_inconsistent_stack_is_implausible(catalog_copy):
    _edit(catalog_copy, "stacks.toml", 'blocked_force = "77.9 kN"', 'blocked_force = "7.79 kN"')
    with pytest.raises(InputError, match="blocked_force"):
        validate_catalog(catalog_copy)


def test_cli_list_and_show():
    code, out, _ = run_cli("catalog", "list")
    assert code == 0 and "pi-p-056.90" in out and "exlar" in out
    code, out, _ = run_cli("catalog", "show", "thorlabs-pk4ga7p1")
    assert code == 0 and "stiffness" in out and "seed" in out
    code, _, err = run_cli("catalog", "show", "no-such-part")
    assert code == 2 and "no-such-part" in err
