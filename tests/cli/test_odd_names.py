"""Outputs read back whatever the names hold: run names and catalog strings
with non-ASCII letters, quotes, a backslash and a tab go through `fit
hysteresis`, `catalog add` and `diagnose`, and what each writes reads back
identically with tomllib (or json) and with the tool's own readers."""
import json
import shutil
import tomllib

import numpy as np

from sizing.io.catalog import load_catalog
from sizing.physics.bouc_wen import BoucWen, free_displacement

from ..conftest import CATALOGS, SEED_BOUC_WEN, STUDIES, run_cli

ODD = ['Messung_ü', 'Lauf "B"', 'back\\slash', 'tab\there']


def _write_run(path, header, columns):
    rows = [",".join(f"{v:.9g}" for v in row) for row in zip(*columns)]
    path.write_text(",".join(header) + "\n" + "\n".join(rows) + "\n")
    return path


def test_fit_hysteresis_with_odd_run_names_reads_back(tmp_path):
    seed = BoucWen(**SEED_BOUC_WEN)
    rng = np.random.default_rng(3)
    t = np.arange(0.0, 1.0, 1 / 500)
    paths = []
    for name, amplitude in zip(ODD, (60.0, 90.0, 120.0, 150.0)):
        v = amplitude / 2 * (1 - np.cos(2 * np.pi * t))
        x = free_displacement(t, v, seed) + 3e-7 * rng.standard_normal(len(t))
        paths.append(_write_run(tmp_path / f"{name}.csv", ["time_s", "voltage_V", "position_m"], [t, v, x]))
    out = tmp_path / "fit.toml"
    code, _, stderr = run_cli("fit", "hysteresis", *paths, "--holdout", ODD[0], "--holdout", ODD[3],
                              "--out", out, "--starts", "1", "--model", "bouc-wen")
    assert code == 0, stderr
    data = tomllib.loads(out.read_text(encoding="utf-8"))
    assert data["fit"]["holdout_runs"] == [ODD[0], ODD[3]]
    named = json.dumps(data, ensure_ascii=False)
    for name in ODD:
        assert json.dumps(name, ensure_ascii=False) in named      # every run name back as it was


def test_catalog_add_with_odd_strings_reads_back(tmp_path):
    catalog = tmp_path / "catalogs"
    shutil.copytree(CATALOGS, catalog)
    maker, source = 'Dichtungen Müller "GmbH"', "sheet\\rev\t2"
    sheet = tmp_path / "seals.csv"
    sheet.write_text(
        "id,name,manufacturer,source,retrieved,material,type,friction_per_length [N/m],"
        "friction_pressure_coefficient [N/(m*Pa)],breakaway_ratio,min_temperature [degC],"
        "max_temperature [degC],pressure_rating [MPa],cost_usd\n"
        f'odd-seal,Dichtung ü,"{maker.replace(chr(34), chr(34) * 2)}","{source}",2026-11-25,PTFE,lip,'
        "30,4e-5,1.5,-50,200,21,25\n", encoding="utf-8")
    code, _, err = run_cli("catalog", "add", "seal", sheet, "--catalog", catalog)
    assert code == 0, err
    entry = next(e for e in tomllib.loads((catalog / "seals.toml").read_text(encoding="utf-8"))["seal"]
                 if e["id"] == "odd-seal")
    assert (entry["name"], entry["manufacturer"], entry["source"]) == ("Dichtung ü", maker, source)
    seal = load_catalog(catalog).seals["odd-seal"]
    assert (seal.manufacturer, seal.source) == (maker, source)


def test_diagnose_with_odd_run_names_reads_back(tmp_path):
    campaign = tmp_path / "campaign"
    shutil.copytree(STUDIES / "campaigns" / "dc-motor", campaign)
    rig = campaign / "rig.toml"
    rig.write_text(rig.read_text().replace('notes = "', 'notes = "Prüfstand \\"7\\" \\\\ \\t '), encoding="utf-8")
    runs = sorted((campaign / "runs").glob("*.csv"))
    for run, name in zip(runs, ODD):
        run.rename(run.with_name(f"{name}.csv"))
    holdout = ODD[len(runs) - 1]
    code, _, stderr = run_cli("diagnose", campaign, "--holdout", holdout, "--out", tmp_path / "out")
    assert code == 0, stderr
    result = json.loads((tmp_path / "out" / "diagnosis.json").read_text(encoding="utf-8"))
    text = json.dumps(result, ensure_ascii=False)
    for name in ODD[:len(runs)]:
        assert json.dumps(name, ensure_ascii=False)[1:-1] in text
