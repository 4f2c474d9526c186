"""Figures as plotly's own JSON (plain dicts), written without plotly's
graph objects.

The solve report draws seven figures on every solve. plotly's graph
objects check every property as it is set: 10-50 ms a figure, 0.13 s of
CPU for the report's figures against a 2 s ``--fast`` solve; the same JSON
built as dicts and written unchecked takes under 1 ms a figure
(benchmarks/tool_speed.py). The check is kept where a mistake would
show: tests/report/test_figures.py passes every figure of the seed's
report through the graph objects, so a misspelt property fails a test
rather than going unseen in the page."""
from __future__ import annotations

import base64
from functools import lru_cache

import numpy as np

TEMPLATE = "plotly_white"      # the report's; None: plotly's default (``plotly.io.templates.default``)


def template(name: str | None = TEMPLATE) -> dict:
    """A plotly template's JSON."""
    import plotly.io as pio
    return _template(name or pio.templates.default)


@lru_cache(maxsize=None)
def _template(name: str) -> dict:
    import plotly.io as pio
    return pio.templates[name].to_plotly_json()


def figure(data: list[dict], layout: dict, template_name: str | None = TEMPLATE) -> dict:
    """A figure's JSON: ``data`` (traces, each with its ``type``) and
    ``layout``, in the template ``template_name``."""
    return {"data": data, "layout": {"template": template(template_name), **layout}}


def line(axis: str, at: float, style: dict) -> dict:
    """A line across subplot ``axis`` ("x", "x2", ..., or "y", ...) at ``at``
    on it: a vertical line on an x axis, a horizontal one on a y axis (as
    plotly's add_vline and add_hline draw them)."""
    across = "y" if axis[0] == "x" else "x"
    other = across + axis[1:] + " domain"
    ends = {f"{axis[0]}0": at, f"{axis[0]}1": at, f"{across}0": 0, f"{across}1": 1}
    return {"type": "line", "xref": axis if axis[0] == "x" else other,
            "yref": axis if axis[0] == "y" else other, **ends, "line": style}


def typed(values) -> dict:
    """An array of doubles as plotly.js's typed-array JSON (base64 of its
    little-endian bytes): the same doubles as a list, a third of the text."""
    array = np.ascontiguousarray(values, dtype="<f8")
    return {"dtype": "f8", "bdata": base64.b64encode(array.tobytes()).decode("ascii")}


def div(fig: dict, **options) -> str:
    """The figure as an HTML div without plotly.js (``plotly.io.to_html``'s
    options: ``div_id``, ``config``)."""
    import plotly.io as pio
    return pio.to_html(fig, full_html=False, include_plotlyjs=False, validate=False, **options)
