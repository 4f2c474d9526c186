"""Makers' tables into the catalog (``sizing catalog import-mgdb``): what the
import holds, the provenance of each value, and bad tables exiting 2 with
one line naming file and field, nothing written."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from sizing.io.catalog import load_catalog
from sizing.api import catalog_import_mgdb as import_mgdb
from sizing.io.mgdb import MGDB_COMMIT

from ..conftest import run_cli

ROOT = Path(__file__).resolve().parents[2]
TABLES = Path("/work/shared/data/mgdb")
SCREWS = Path("/work/shared/data/screws-sourced.csv")
need_tables = pytest.mark.skipif(not TABLES.is_dir(), reason="makers' tables not on this machine")


@pytest.fixture(scope="module")
def shipped():
    return load_catalog()


def test_shipped_catalog_holds_the_sourced_brushless_motors(shipped):
    sourced = [m for m in shipped.motors.values() if m.status["torque_constant"].startswith("sourced")]
    makers = {m.manufacturer for m in sourced}
    assert len(sourced) >= 300 and {"Maxon", "Faulhaber", "Allied Motion"} <= makers
    for m in sourced:
        assert MGDB_COMMIT in m.source and ".csv, key " in m.source
        # every value says where it comes from: a table cell, a maker's rule, or an assumption
        assert all(s.split(":")[0] in ("sourced", "rule", "assumed") for s in m.status.values())
        assert not m.status["max_winding_temperature"].startswith("sourced")
        assert not m.status["max_temperature"].startswith("sourced")
    # the gearheads that mount on them, by mount
    mounts = {g.mount for g in shipped.gears.values() if g.mount}
    assert len([g for g in shipped.gears.values() if g.mount]) >= 1000
    assert all(set(m.gear_mounts or ()) <= mounts for m in sourced)
    # the generic parts stay, assumed
    generic = shipped.motors["gen-bldc42-28v-h"]
    assert all(s.startswith("assumed") for s in generic.status.values())


def test_a_value_against_its_table_row(shipped):
    """maxon 597974 (MGDB maxon_motors.csv, key MM_597974): k_t 0.136, R 0.28,
    V 30, omega_nl 217.817 rad/s, I_nom 10.5 A, Rth 0.848 + 0.867 K/W."""
    m = shipped.motors["maxon-597974"]
    assert m.torque_constant == 0.136 and m.winding_resistance == 0.28
    assert m.back_emf_constant == pytest.approx(30 / 217.817090648892)
    assert m.continuous_torque == pytest.approx(0.136 * 10.5)
    assert m.thermal_resistance == pytest.approx(0.848 + 0.867)
    assert m.status["torque_constant"] == "sourced: maxon_motors.csv MM_597974 k_t"
    s = shipped.screws["thk-bnk1202-3"]
    assert (s.dynamic_load_rating, s.static_load_rating, s.lead) == (1700.0, 3600.0, pytest.approx(0.002))


@need_tables
def test_import_reproduces_the_shipped_files(tmp_path):
    folder = tmp_path / "catalogs"
    shutil.copytree(ROOT / "catalogs", folder)
    done = import_mgdb(TABLES, SCREWS, folder)
    assert done["motors"] >= 300
    for name in done["files"]:
        assert (folder / name).read_text() == (ROOT / "catalogs" / name).read_text()


def _tables(tmp_path) -> Path:
    folder = tmp_path / "mgdb"
    shutil.copytree(TABLES, folder)
    return folder


def _exit_2_nothing_written(tmp_path, tables, *words):
    folder = tmp_path / "catalogs"
    if not folder.exists():
        shutil.copytree(ROOT / "catalogs", folder)
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    code, out, err = run_cli("catalog", "import-mgdb", tables, "--screws", SCREWS, "--catalog", folder)
    assert code == 2, err
    lines = [line for line in err.strip().splitlines() if line.strip()]
    assert len(lines) == 1, err
    for w in words:
        assert w in lines[0], (w, lines[0])
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == before


@need_tables
def test_missing_unit_column_exits_2(tmp_path):
    tables = _tables(tmp_path)
    path = tables / "maxon_motors.csv"
    path.write_text(path.read_text().replace(",k_t,", ",kt_missing,", 1))
    _exit_2_nothing_written(tmp_path, tables, "maxon_motors.csv", "k_t", "torque constant")


@need_tables
def test_gearhead_key_matching_no_motor_exits_2(tmp_path):
    tables = _tables(tmp_path)
    path = tables / "faulhaber_compatibility.csv"
    path.write_text(path.read_text() + "FH_NO_SUCH_MOTOR,FH_32A_R*\n")
    _exit_2_nothing_written(tmp_path, tables, "faulhaber_compatibility.csv", "FH_NO_SUCH_MOTOR", "matches no motor")
    path.write_text(path.read_text().replace("FH_NO_SUCH_MOTOR,FH_32A_R*\n", "")
                    .replace("FH_32A_R*", "FH_NO_SUCH_GEARHEAD_R*", 1))
    _exit_2_nothing_written(tmp_path, tables, "faulhaber_compatibility.csv", "FH_NO_SUCH_GEARHEAD", "matches no gearhead")


BAD_CELLS = {
    # a negative resistance
    "negative": ("allied_motion_motors.csv", ",48.0,0.1,0.92,", ",48.0,0.1,-0.92,",
                 ("allied_motion_motors.csv", "column R", "positive resistance", "-0.92")),
    # k_t in mN m/A under a header without unit: 136 N m/A is no motor's
    "unit slip": ("maxon_motors.csv", "MM_597974,Maxon,597974,BLDC,30,0.136,", "MM_597974,Maxon,597974,BLDC,30,136,",
                  ("maxon_motors.csv", "MM_597974", "torque_constant", "unit error")),
}


@need_tables
@pytest.mark.parametrize("case", sorted(BAD_CELLS))
def test_a_bad_cell_exits_2(tmp_path, case):
    name, old, new, words = BAD_CELLS[case]
    tables = _tables(tmp_path)
    path = tables / name
    path.write_text(path.read_text().replace(old, new, 1))
    _exit_2_nothing_written(tmp_path, tables, *words)


@need_tables
def test_a_unit_in_the_header_is_converted(tmp_path):
    tables = _tables(tmp_path)
    path = tables / "allied_motion_motors.csv"
    lines = path.read_text().splitlines()
    header = lines[0].split(",")
    k = header.index("k_t")
    header[k] = "k_t [mN*m/A]"
    rows = []
    for line in lines[1:]:
        cells = line.split(",")
        cells[k] = repr(float(cells[k]) * 1000)
        rows.append(",".join(cells))
    path.write_text("\n".join([",".join(header)] + rows) + "\n")
    folder = tmp_path / "catalogs"
    shutil.copytree(ROOT / "catalogs", folder)
    import_mgdb(tables, None, folder)
    assert load_catalog(folder).motors["allied-mf0076008-48v"].torque_constant == pytest.approx(0.1)
