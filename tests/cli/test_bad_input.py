"""Hostile input: every case once reported against the tool, rebuilt
from its description. Each must end in exit 2 with one line on stderr naming
the file (or option) and the field, no traceback, nothing written; the
dialects people produce must be accepted."""
from __future__ import annotations

import os
import shutil
import time

import numpy as np
import pytest

from sizing.errors import InputError
from sizing.io.runs import estimate_samples, read_run
from sizing.units import PLAUSIBLE, UnitError, to_si

from ..conftest import CATALOGS, STUDIES, run_cli

REQ = (STUDIES / "seed-requirements.toml").read_text()
DC_DESIGN = (STUDIES / "seed-dc-step.toml").read_text()


def one_line_exit_2(code, err, *words):
    assert code == 2, err
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    for word in words:
        assert word in lines[0], lines[0]
    return lines[0]


def write_csv(path, header, rows, newline="\n", encoding="utf-8"):
    path.write_text(newline.join([header] + rows) + newline, encoding=encoding, newline="")
    return path


def piezo_rows(n=50):
    t = np.arange(n) * 1e-3
    v = 75 * (1 - np.cos(2 * np.pi * 5 * t))
    return [f"{a:.6g},{b:.6g},{b * 4e-7 / 150:.6g}" for a, b in zip(t, v)]


# --- the quantity parser ----------------------------------------------------

@pytest.mark.parametrize("field, value, words", [
    ("stroke", '"1/0 mm"', ["[requirements].stroke", "unknown unit"]),
    ("stroke", '"1 mm/0"', ["[requirements].stroke", "unknown unit"]),            # ZeroDivisionError in pint
    ("stroke", '"40 (mm"', ["[requirements].stroke", "unbalanced"]),               # TokenError in pint
    ("stroke", '"(40 mm"', ["[requirements].stroke", "number with a unit"]),
    ("max_temperature", '"50 delta_degC"', ["max_temperature", "relative"]),        # DimensionalityError
    ("max_temperature", '"50 %"', ["max_temperature", "relative"]),                 # was accepted and solved
    ("stroke", '"1e30 mm"', ["[requirements].stroke", "between"]),                 # allocation error further in
    ("stroke", '"1 ' + "(" * 3000 + "mm" + ")" * 3000 + '"', ["at most 100 characters"]),  # RecursionError
    ("stroke", '"1 ' + "mm*" * 33_333 + 'mm"', ["at most 100 characters"]),        # 100,000 characters: 99 s
    ("stroke", '"1 m**2**2**2**2**2**2"', ["exponent"]),                            # never returned
    ("speed", "1e300", ["[requirements].speed", "between"]),
    ("stroke", "1e-300", ["[requirements].stroke", "at least"]),                   # overflowed the convex sizing
])
def test_hostile_quantities_exit_2_before_any_work(tmp_path, field, value, words):
    lines = [f"{field} = {value}" if line.startswith(f"{field} =") else line for line in REQ.splitlines()]
    req = tmp_path / "req.toml"
    req.write_text("\n".join(lines) + "\n")
    code, _, err = run_cli("solve", req, "--out", tmp_path / "out", "--quiet")
    one_line_exit_2(code, err, "req.toml", *words)
    assert not (tmp_path / "out").exists()


def test_long_unit_string_is_refused_fast():
    start = time.monotonic()
    with pytest.raises(UnitError, match="at most"):
        to_si("1 " + "m*" * 50_000 + "m", "length")
    assert time.monotonic() - start < 0.05


@pytest.mark.parametrize("text", ["5 %", "0.05", "50 ppm"])
def test_relative_units_stay_fine_where_a_fraction_is_meant(text):
    assert 0 < to_si(text, "dimensionless") <= 0.05


def test_temperature_units_still_convert():
    # 212 degF = 100 degC, 373.15 K = 100 degC (definitions)
    assert to_si("212 degF", "temperature") == pytest.approx(100.0)
    assert to_si("373.15 K", "temperature") == pytest.approx(100.0)


def test_catalog_ranges_lie_inside_the_plausible_kinds():
    """catalog validate's per-field ranges and the parser's per-kind ranges
    are one scale: no catalog range reaches beyond its kind's."""
    from sizing.io.catalog import KINDS as FILES
    from sizing.io.catalog_diff import quantity_kind
    from sizing.io.validate import RANGES
    models = {kind: model for kind, model in FILES.values()}
    for part, fields in RANGES.items():
        for name, (low, high) in fields.items():
            kind = quantity_kind(models[part], name)
            assert kind is not None, (part, name)
            plo, phi = PLAUSIBLE[kind]
            assert plo <= low and high <= phi, (part, name, kind)


# --- TOML files ------------------------------------------------------------------

def test_toml_with_bom_is_accepted(tmp_path):
    from sizing.io.requirements import load_requirements
    plain, bom = tmp_path / "plain.toml", tmp_path / "bom.toml"
    plain.write_text(REQ, encoding="utf-8")
    bom.write_text(REQ, encoding="utf-8-sig")
    assert bom.read_bytes()[:3] == b"\xef\xbb\xbf"
    assert load_requirements(bom)[0] == load_requirements(plain)[0]


def test_evaluate_rejects_an_empty_force_list_like_solve(tmp_path):
    design = tmp_path / "d.toml"
    design.write_text(DC_DESIGN.replace('force = ["0 N", "484 N", "1210 N"]', "force = []"))
    code, out, err = run_cli("evaluate", design)
    one_line_exit_2(code, err, "d.toml", "[load].force", "at least one")
    req = tmp_path / "r.toml"
    req.write_text(REQ.replace('dynamic_pressure = ["10 kPa", "25 kPa"]', "force = []"))
    one_line_exit_2(*run_cli("solve", req, "--out", tmp_path / "o", "--quiet")[::2], "[load].force")


def test_catalog_array_given_as_a_number(tmp_path, catalog_copy):
    (catalog_copy / "stacks.toml").write_text("stack = 3\n")
    one_line_exit_2(*run_cli("catalog", "validate", catalog_copy)[::2], "stacks.toml", "stack", "array of tables")
    req = tmp_path / "req.toml"
    req.write_text(REQ)
    one_line_exit_2(*run_cli("solve", req, "--catalog", catalog_copy, "--out", tmp_path / "o", "--quiet")[::2],
                    "stacks.toml")


@pytest.mark.parametrize("command", ["solve", "evaluate", "fit", "diagnose", "catalog"])
def test_symlink_loop_as_input(tmp_path, command):
    loop = tmp_path / "loop.toml"
    os.symlink(loop, loop)
    if command == "solve":
        args = ["solve", loop, "--out", tmp_path / "o", "--quiet"]
    elif command == "evaluate":
        args = ["evaluate", loop]
    elif command == "fit":
        csv = tmp_path / "loop.csv"
        os.symlink(csv, csv)
        args = ["fit", "hysteresis", csv]
    elif command == "diagnose":
        camp = tmp_path / "camp"
        shutil.copytree(STUDIES / "campaigns" / "dc-motor", camp)
        (camp / "rig.toml").unlink()
        os.symlink(camp / "rig.toml", camp / "rig.toml")
        args = ["diagnose", camp, "--holdout", "steps_b", "--out", tmp_path / "o"]
    else:
        cat = tmp_path / "cat"
        shutil.copytree(CATALOGS, cat)
        (cat / "seals.toml").unlink()
        os.symlink(cat / "seals.toml", cat / "seals.toml")
        args = ["catalog", "validate", cat]
    code, _, err = run_cli(*args)
    if command == "catalog":      # a loop where a catalog file may be: an error, not skipped silently
        one_line_exit_2(code, err, "seals.toml")
    else:
        one_line_exit_2(code, err)
    assert not (tmp_path / "o").exists()


# --- run CSVs: dialects, values, size --------------------------------------------

def test_csv_dialects_are_accepted(tmp_path):
    header, rows = "time_s,voltage_V,position_m", piezo_rows()
    plain = read_run(write_csv(tmp_path / "plain.csv", header, rows))
    bom = read_run(write_csv(tmp_path / "bom.csv", header, rows + ["", ""], newline="\r\n", encoding="utf-8-sig"))
    quoted = read_run(write_csv(tmp_path / "quoted.csv", header,
                                [",".join(f'"{cell}"' for cell in row.split(",")) for row in rows]))
    spaced = read_run(write_csv(tmp_path / "spaced.csv", header,      # 0, "1.5", "2e-06"
                                [", ".join(f'"{c}"' if i else c for i, c in enumerate(row.split(","))) for row in rows]))
    for run in (bom, quoted, spaced):
        np.testing.assert_array_equal(run.time, plain.time)
        np.testing.assert_array_equal(run["voltage_V"], plain["voltage_V"])
        np.testing.assert_array_equal(run["position_m"], plain["position_m"])


@pytest.mark.parametrize("header, edit, words", [
    ("time_s,voltage_V,position_m,voltage_V", lambda rows: [r + ",1" for r in rows], ["line 1", "duplicated column 'voltage_V'"]),
    ("time_s,voltage_V,position_m", lambda rows: rows[:7] + [rows[7].replace(",", ";")] + rows[8:], ["line 9", "mixed separators"]),
    ("time_s;voltage_V;position_m", lambda rows: [r.replace(",", ";") for r in rows], ["line 1", "';'"]),
    ("time_s,voltage_V,position_m", lambda rows: rows[:4] + ["0.0035,1e300,0"] + rows[5:], ["line 6", "voltage_V", "between"]),
    ("time_s,voltage_V,position_m", lambda rows: rows[:4] + ["0.0035,1,2,3"] + rows[5:], ["line 6", "fields"]),
])
def test_csv_rejections_name_the_line(tmp_path, header, edit, words):
    path = write_csv(tmp_path / "bad.csv", header, edit(piezo_rows()))
    with pytest.raises(InputError) as info:
        read_run(path)
    for word in words:
        assert word in str(info.value)


def test_1e300_in_a_run_csv_exits_2(tmp_path):
    rows = piezo_rows()
    rows[10] = "0.01,1e300,0"
    path = write_csv(tmp_path / "big.csv", "time_s,voltage_V,position_m", rows)
    one_line_exit_2(*run_cli("fit", "hysteresis", path)[::2], "big.csv", "line 12")


def test_sample_estimate_against_the_real_row_count(tmp_path):
    # the count of data lines, by hand (len of the list), against the size-based estimate
    rows = piezo_rows(20_000)
    path = write_csv(tmp_path / "long.csv", "time_s,voltage_V,position_m", rows)
    assert estimate_samples(path) == pytest.approx(len(rows), rel=0.1)


def test_huge_run_csv_is_refused_with_the_estimate_and_the_option_raises_it(tmp_path):
    rows = piezo_rows(3000)
    path = write_csv(tmp_path / "run.csv", "time_s,voltage_V,position_m", rows)
    code, _, err = run_cli("fit", "hysteresis", path, "--max-samples", "1000", "--out", tmp_path / "f.toml")
    line = one_line_exit_2(code, err, "run.csv", "about", "samples", "--max-samples")
    estimate = int(line.split("about ")[1].split()[0].replace(",", ""))
    assert estimate == pytest.approx(3000, rel=0.1)
    assert not (tmp_path / "f.toml").exists()
    # the same two runs together exceed it, alone each fits
    assert run_cli("fit", "hysteresis", path, path.rename(tmp_path / "b.csv"), "--max-samples", "5000")[0] == 2


# --- simulations too long ------------------------------------------------------

def test_dc_rig_at_1e9_hz_is_refused(tmp_path):
    camp = tmp_path / "camp"
    shutil.copytree(STUDIES / "campaigns" / "dc-motor", camp)
    rig = camp / "rig.toml"
    rig.write_text(rig.read_text().replace('rate = "1250 Hz"', 'rate = "1e9 Hz"'))
    start = time.monotonic()
    code, _, err = run_cli("diagnose", camp, "--holdout", "steps_b", "--out", tmp_path / "o")
    one_line_exit_2(code, err, "rig.toml", "[controller].rate", "about", "--max-steps")
    code, _, err = run_cli("fit", "dc-motor", *sorted((camp / "runs").glob("*.csv")), "--rig", rig)
    one_line_exit_2(code, err, "rig.toml", "[controller].rate")
    assert time.monotonic() - start < 30
    assert not (tmp_path / "o").exists()


def test_piezo_campaign_spanning_1e6_s_is_refused(tmp_path):
    camp = tmp_path / "camp"
    shutil.copytree(STUDIES / "campaigns" / "piezo-prototype", camp)
    run = camp / "runs" / "ramp.csv"
    lines = run.read_text().splitlines()
    lines[-1] = "1e6," + lines[-1].split(",", 1)[1]      # the last sample a million seconds later
    run.write_text("\n".join(lines) + "\n")
    line = one_line_exit_2(*run_cli("diagnose", camp, "--holdout", "steps", "--out", tmp_path / "o")[::2],
                           "runs", "time_s", "--max-steps")
    assert "2e+10" in line       # 1e6 s x 20 kHz (by hand), plus the other run's seconds


def test_evaluate_with_a_1e9_s_duration_is_refused(tmp_path):
    design = tmp_path / "d.toml"
    design.write_text(DC_DESIGN.replace('duration = "1 s"', 'duration = "1e9 s"'))
    line = one_line_exit_2(*run_cli("evaluate", design)[::2], "d.toml", "duration", "--max-steps")
    # 1e9 s x 1250 Hz controller x 3 load cases = 3.75e12 steps (by hand; the
    # output is sampled 3200 times over the duration, far fewer)
    assert "3.75e+12" in line


# --- options ------------------------------------------------------------------

@pytest.mark.parametrize("args, option", [
    (["fit", "hysteresis", "x.csv", "--cutoff-hz", "nan"], "--cutoff-hz"),
    (["fit", "hysteresis", "x.csv", "--cutoff-hz", "-5"], "--cutoff-hz"),
    (["fit", "hysteresis", "x.csv", "--cutoff-hz", "inf"], "--cutoff-hz"),
    (["fit", "hysteresis", "x.csv", "--operators", "0"], "--operators"),
    (["fit", "hysteresis", "x.csv", "--starts", "-3"], "--starts"),
    (["fit", "dc-motor", "x.csv", "--rig", "r.toml", "--starts", "-3"], "--starts"),
    (["fit", "dc-motor", "x.csv", "--rig", "r.toml", "--seed", "-1"], "--seed"),
    (["diagnose", "c", "--holdout", "a", "--seed", "-1"], "--seed"),
    (["catalog", "validate", "--max-age-days", "-1"], "--max-age-days"),
    (["solve", "r.toml", "--max-steps", "nan"], "--max-steps"),
    (["fit", "hysteresis", "x.csv", "--max-samples", "0"], "--max-samples"),
])
def test_numeric_options_are_checked(args, option):
    one_line_exit_2(*run_cli(*args)[::2], option)


@pytest.mark.parametrize("value", ["[]", "{}", "3"])
def test_technology_of_the_wrong_type(tmp_path, value):
    # found by the fuzz test: technology = [] raised TypeError (unhashable)
    design = tmp_path / "d.toml"
    design.write_text(DC_DESIGN.replace('technology = "dc_motor"', f"technology = {value}"))
    one_line_exit_2(*run_cli("evaluate", design)[::2], "d.toml", "technology")


@pytest.mark.parametrize("old, new, field", [
    ("alpha = -2.23e-7", "alpha = 1e300", "alpha"),       # crashed diagnose (infs in least squares)
    ("beta = 0.134", "beta = 1e12", "beta"),               # ran for minutes
])
def test_rig_coefficients_outside_their_bounds(tmp_path, old, new, field):
    camp = tmp_path / "camp"
    shutil.copytree(STUDIES / "campaigns" / "piezo-prototype", camp)
    rig = camp / "rig.toml"
    assert old in rig.read_text()
    rig.write_text(rig.read_text().replace(old, new))
    one_line_exit_2(*run_cli("diagnose", camp, "--holdout", "steps", "--out", tmp_path / "o")[::2],
                    "rig.toml", field)
