"""The solve report's figures are written as plotly's JSON without the
graph objects' checks (sizing/report/plain.py): here every figure the
seed's report holds goes through those checks, so a misspelt property or
a value plotly would refuse fails a test instead of vanishing from the
page; and the typed arrays hold the doubles they were given."""
from __future__ import annotations

import base64
import json
import re

import numpy as np
import plotly.graph_objects as go
import pytest

from sizing.report import plain

NEW_PLOT = re.compile(r"Plotly\.newPlot\(\s*")


def figures_in(page: str) -> list[dict]:
    """Every figure a page draws: (data, layout) of each Plotly.newPlot call."""
    decoder = json.JSONDecoder()
    out = []
    for match in NEW_PLOT.finditer(page):
        at = match.end()
        parts = []
        for _ in range(3):                     # the div's id, the data, the layout
            value, at = decoder.raw_decode(page, at)
            parts.append(value)
            at = page.index(",", at) + 1 if len(parts) < 3 else at
            while page[at].isspace():
                at += 1
        out.append({"data": parts[1], "layout": parts[2]})
    return out


def test_every_figure_of_the_report_passes_plotly_s_checks(seed_solve_fast):
    figures = figures_in((seed_solve_fast.out / "report.html").read_text())
    assert len(figures) >= 7        # Pareto, traces, comparison, force path, three thermal budgets
    for fig in figures:
        checked = go.Figure(fig)        # raises ValueError on a property plotly does not know
        assert len(checked.data) == len(fig["data"])
    kinds = {trace["type"] for fig in figures for trace in fig["data"]}
    assert {"scatter", "bar", "waterfall"} <= kinds


def test_a_misspelt_property_is_what_the_checks_refuse():
    fig = plain.figure([dict(type="scatter", x=[1, 2], y=[3, 4], markr=dict(size=3))], dict(height=300))
    with pytest.raises(ValueError):
        go.Figure(fig)


def test_typed_arrays_hold_the_doubles_given():
    values = np.array([0.1, 1 / 3, -2.5e-300, 1e300])
    spec = plain.typed(values)
    assert spec["dtype"] == "f8"
    assert np.array_equal(np.frombuffer(base64.b64decode(spec["bdata"]), dtype="<f8"), values)


def test_lines_are_drawn_where_plotly_s_own_helpers_draw_them():
    fig = go.Figure()
    fig.add_hline(y=40.0, line=dict(color="gray"))
    fig.add_vline(x=0.4, line=dict(color="gray"))
    mine = go.Figure(plain.figure([], dict(shapes=[plain.line("y", 40.0, dict(color="gray")),
                                                   plain.line("x", 0.4, dict(color="gray"))])))
    assert mine.layout.shapes == fig.layout.shapes
