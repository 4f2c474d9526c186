"""Every TOML file the tool writes reads back with tomllib, whatever the
names and strings hold: non-ASCII letters, quotes, backslashes, tabs,
carriage returns and other control characters (io/toml_text.py)."""
import datetime as dt
import math
import tomllib

import numpy as np
import pytest

from sizing.io import toml_text
from sizing.io.catalog_import import entry_toml
from sizing.report.fit_toml import render_toml

HOSTILE = ["Messung_ü", 'quote"d', "back\\slash", "tab\there", "cr\rlf\n", "bell\x07", "del\x7f", "plain", "a.b", ""]


@pytest.mark.parametrize("name", HOSTILE)
def test_a_key_and_a_string_read_back_as_written(name):
    text = toml_text.line(name, name) + "\n"
    assert tomllib.loads(text) == {name: name}


def test_bare_keys_only_where_the_spec_allows():
    assert toml_text.key("bouc_wen-2") == "bouc_wen-2"
    assert toml_text.key("Messung_ü") == '"Messung_ü"'      # a Unicode letter is no bare-key character
    assert toml_text.table_name("stack", "bouc_wen") == "stack.bouc_wen"


def test_values_of_every_kind_read_back():
    values = {"f": 0.1, "tiny": 1.5e-7, "big": 2.5e20, "i": -3, "b": True, "d": dt.date(2026, 1, 2),
              "list": [1.0, 2, "x\ty"], "np": np.float64(0.25), "npi": np.int64(7)}
    back = tomllib.loads("\n".join(toml_text.line(k, v) for k, v in values.items()))
    assert back == {**values, "np": 0.25, "npi": 7}
    nonfinite = tomllib.loads("\n".join(toml_text.line(k, v) for k, v in {"n": math.nan, "p": math.inf, "m": -math.inf}.items()))
    assert math.isnan(nonfinite["n"]) and nonfinite["p"] == math.inf and nonfinite["m"] == -math.inf


def test_a_comment_stays_on_its_line():
    comment = toml_text.comment("one\ntwo\rthree")
    text = f"[a]  {comment}\nx = 1\n"
    assert tomllib.loads(text) == {"a": {"x": 1}}


def test_fit_tables_with_hostile_run_names_read_back():
    runs = {name: 0.01 * i for i, name in enumerate(HOSTILE)}
    tables = {"stack": {"d33": 1.23456789e-9, "bouc_wen": {"alpha": 0.5}},
              "fit": {"holdout_runs": HOSTILE[:4], "nrmse_per_run": runs, "rig": 'Prüfstand "B"\\\t2'}}
    back = tomllib.loads(render_toml(tables, {"fit": "a comment\nwith a newline"}))
    assert back["fit"]["nrmse_per_run"] == runs
    assert back["fit"]["holdout_runs"] == HOSTILE[:4] and back["fit"]["rig"] == 'Prüfstand "B"\\\t2'
    assert back["stack"]["d33"] == pytest.approx(1.23457e-9, rel=1e-12)    # six significant digits


def test_catalog_entries_with_hostile_strings_read_back():
    raw = {"id": "stack-ü", "maker": 'Maker "Q"\\GmbH', "model": "P\t1", "source": "datasheet\r\nrev. 2",
           "retrieved": dt.date(2026, 3, 4), "notes": "bell\x07",
           "stiffness": 4.33e8, "status": {"stiffness": "measured: bench \"3\""}}
    back = tomllib.loads(entry_toml("stack", raw))["stack"][0]
    assert back == raw
