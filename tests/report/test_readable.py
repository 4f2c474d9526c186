"""What a person reads holds no program internals: the terminal output and
the pages of solve, evaluate, robust, sweep, fit, diagnose and catalog show
on the shipped examples are scanned for a Python dict or list (``{'``,
``[0.``), a design's machine id instead of its short name, and floats with
more than six significant digits (float noise such as
0.00017999999999999998). The pages are read as shown: their text without
markup, and the names, texts and titles of their plots.

Cheap variants: two robust samples of one design, a sweep of two points,
one fit start."""
from __future__ import annotations

import html
import json
import re
from pathlib import Path

import pytest

from ..conftest import FAST_REQUIREMENTS, STUDIES, run_cli

FLOAT = re.compile(r"(?<![\w.])-?(\d*\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
PLOT_KEYS = {"name", "text", "hovertext", "title", "ticktext"}


def significant_digits(token: str) -> int:
    mantissa = re.split(r"[eE]", token.lstrip("-"))[0].replace(".", "")
    return len(mantissa.lstrip("0")) or 1


def _plot_strings(node, key=None):
    """The strings a plot shows: trace names, texts, hover texts, titles."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _plot_strings(v, k)
    elif isinstance(node, list):
        for v in node:
            yield from _plot_strings(v, key)
    elif isinstance(node, str) and key in PLOT_KEYS:
        yield node


def page_text(path: Path) -> str:
    """A page as a reader sees it: the text without markup, then what its plots show."""
    raw = path.read_text(encoding="utf-8")
    shown = []
    decoder = json.JSONDecoder()
    for m in re.finditer(r"Plotly\.newPlot\(\s*\"[^\"]*\",\s*", raw):
        data, end = decoder.raw_decode(raw, m.end())
        layout, _ = decoder.raw_decode(raw, raw.index("{", end))
        shown += list(_plot_strings(data)) + list(_plot_strings(layout))
    # a file quoted whole (the TOML a fit wrote, in <pre>) is in that file's syntax, not prose
    text = re.sub(r"<(script|style|pre)\b.*?</\1>", " ", raw, flags=re.S | re.I)
    text = html.unescape(re.sub(r"<[^>]+>", " ", text))
    return text + "\n" + "\n".join(html.unescape(s) for s in shown)


def problems(text: str, ids: set[str]) -> list[str]:
    found = []
    for pattern in ("{'", "[0."):
        if pattern in text:
            i = text.index(pattern)
            found.append(f"{pattern!r} in ...{text[max(0, i - 60):i + 60]}...")
    found += [f"raw id {i}" for i in ids if i in text]
    for m in FLOAT.finditer(text):
        if significant_digits(m.group(0)) > 6:
            found.append(f"float {m.group(0)} in ...{text[max(0, m.start() - 50):m.end() + 20]}...")
    return found


def design_ids(*documents) -> set[str]:
    """Machine ids (longer than any short name) of the designs in written JSON."""
    ids = set()

    def walk(node):
        if isinstance(node, dict):
            if isinstance(node.get("id"), str) and len(node["id"]) > 32:
                ids.add(node["id"])
            for v in node.values():
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)
    for doc in documents:
        walk(doc)
    return ids


# every command run once, the seed's full solve among them: the slow tier
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def outputs(tmp_path_factory, seed_solve):
    """(name, terminal text, pages) of every command, and the design ids they
    could leak. The seed's solve is the one run once per test run (conftest)."""
    tmp = tmp_path_factory.mktemp("readable")
    req = tmp / "req.toml"
    req.write_text(FAST_REQUIREMENTS.replace("max_stacks = 2", "max_stacks = 12").replace("max_simulated = 2", "max_simulated = 4"))
    bipolar = STUDIES / "piezo-bipolar" / "runs"
    dc = STUDIES / "campaigns" / "dc-motor"
    commands = {
        "evaluate table 2": (["evaluate", STUDIES / "seed-table2-full-scale.toml"], []),
        "evaluate dc": (["evaluate", STUDIES / "seed-dc-step.toml"], []),
        "robust": (["robust", req, "--samples", "2", "--designs", "1", "--workers", "0", "--out", tmp / "robust"],
                   [tmp / "robust" / "robust.html"]),
        "sweep": (["sweep", req, "--vary", "stroke=35mm..40mm:2", "--workers", "0", "--out", tmp / "sweep"],
                  [tmp / "sweep" / "sweep.html"]),
        "fit hysteresis": (["fit", "hysteresis", *sorted(bipolar.glob("*.csv")), "--holdout", "t03-07", "--starts", "1",
                            "--out", tmp / "fit" / "bipolar.toml"], [tmp / "fit" / "bipolar.html"]),
        "fit dc-motor": (["fit", "dc-motor", *sorted((dc / "runs").glob("*.csv")), "--rig", dc / "rig.toml",
                          "--holdout", "steps_b", "--out", tmp / "fit" / "dc.toml"], [tmp / "fit" / "dc.html"]),
        "diagnose": (["diagnose", dc, "--holdout", "steps_b", "--out", tmp / "diagnose"], [tmp / "diagnose" / "diagnosis.html"]),
        "catalog show": (["catalog", "show", "pi-p-056.90"], []),
        "catalog show motor": (["catalog", "show", "allied-mf0127008-48v"], []),
    }
    runs = {"solve": (seed_solve.terminal, [seed_solve.out / "report.html"])}
    for name, (args, pages) in commands.items():
        code, out, err = run_cli(*args)
        assert code == 0, (name, err)
        runs[name] = (out + err, pages)
    written = [json.loads(p.read_text()) for p in (seed_solve.out / "results.json", tmp / "robust" / "robust.json",
                                                   tmp / "sweep" / "sweep.json")]
    return runs, design_ids(*written)


@pytest.mark.parametrize("name", ["solve", "evaluate table 2", "evaluate dc", "robust", "sweep", "fit hysteresis",
                                  "fit dc-motor", "diagnose", "catalog show", "catalog show motor"])
def test_terminal_and_pages_read_as_words_and_units(outputs, name):
    runs, ids = outputs
    terminal, pages = runs[name]
    assert not problems(terminal, ids), (name, problems(terminal, ids)[:5])
    for page in pages:
        found = problems(page_text(page), ids)
        assert not found, (page.name, found[:5])


def test_the_fit_page_of_the_shipped_record_stays_under_1_5_mb(outputs):
    runs, _ = outputs
    [page] = runs["fit hysteresis"][1]
    assert page.stat().st_size < 1_500_000, page.stat().st_size     # three runs, each plotted in six traces


def test_the_scan_finds_what_it_looks_for():
    ids = {"ph-pi-p-056.90-n11-silicone-pmx200-10cst-fkm-o-ring-pi-e-481-steel-4340"}
    assert problems("recalibrated {'d33': 7.951615392113761e-07}", set())
    assert problems("stroke [0.04, 0.05]", set())
    assert problems("ph-pi-p-056.90-n11-silicone-pmx200-10cst-fkm-o-ring-pi-e-481-steel-4340 stroke", ids)
    assert problems("stroke 0.00017999999999999998", set())
    assert not problems("stroke 40 mm, 0.861 to 0.987, d33 4.589e-7 m/V, 601335 USD, PI P-056.90", ids)


def test_catalog_show_gives_units_and_explains_each_status():
    code, out, _ = run_cli("catalog", "show", "pi-p-056.90")
    assert code == 0
    assert "433 N/um" in out and "180 um" in out and "150 degC" in out      # stiffness 4.33e8 N/m, stroke 0.18 mm
    assert "[?]" not in out and "[default]" in out
    legend = out.strip().splitlines()[-1]
    assert legend.startswith("status:") and "default = not given in the catalog file" in legend and "seed =" in legend
