"""The solve report's figures, built from its results only (its ranked
``Candidate``s and the time traces), never from the stages' records; each
is plotly's JSON (``report.plain``: built on every solve, written without
the graph objects' checks, which tests/report/test_figures.py makes)."""
from __future__ import annotations

import json
from functools import lru_cache
from typing import TYPE_CHECKING

import numpy as np

from . import plain
from .layout import no_overprint
from ..technologies.registry import presentation, technologies
from .words import tech_label

if TYPE_CHECKING:
    from ..engine.candidate import Candidate

UNITS = {"mass": ("mass_kg", 1.0, "mass (kg)"), "cost": ("cost_usd", 1.0, "cost (USD)"),
         "volume": ("volume_m3", 1e3, "volume (L)"), "power": ("power_W", 1.0, "peak power (W)")}
MARGIN_ORDER = ("stroke", "blocked_force", "speed", "temperature", "amplifier_temperature", "pressure",
                "drive_current", "amplifier_continuous_current", "natural_frequency", "overshoot", "thermal_drift",
                "wide_gap", "packing", "compensator_capacity", "compensator_hold", "amplifier_units", "stack_temperature", "holding_force", "work")


def _axes(objectives: list[str]) -> tuple[str, str]:
    x = objectives[0]
    y = objectives[1] if len(objectives) > 1 else ("cost" if x != "cost" else "mass")
    return x, y


HOVER_MARGINS = 3


def hover_text(c: Candidate) -> str:
    hover = presentation(c.technology).hover
    # a technology with no drawing of its own: its short name
    head = hover(c) if hover is not None else f"{tech_label(c.technology)} {c.name or c.id}"
    # the three smallest margins: what decides the design (the full list is in results.json)
    shown = sorted(c.margins.items(), key=lambda kv: kv[1] if kv[1] is not None else -float("inf"))[:HOVER_MARGINS]
    margins = ", ".join(f"{k} {v:+.0%}" if v is not None else f"{k} n/a" for k, v in shown)
    state = "feasible" if c.feasible else "infeasible"
    m = c.metrics
    figures = ", ".join(x for x in (f"{m['mass_kg']:.4g} kg" if m.get("mass_kg") is not None else "",
                                    f"{m['cost_usd']:,.0f} USD" if m.get("cost_usd") is not None else "") if x)
    return (f"<b>{c.name or c.id}</b> ({figures})<br>{head}<br>rank {c.rank}, {state}, "
            f"binding {c.driver}<br>{margins}")


def _front_2d(points):
    """The non-dominated points of (x, y), both minimised, sorted by x."""
    front, best_y = [], float("inf")
    for x, y in sorted(points):
        if y < best_y:
            front.append((x, y))
            best_y = y
    return front


def pareto_figure(results: dict) -> dict:
    """Objective space: feasible and infeasible distinct, DC options marked,
    the Pareto front joined by a line."""
    xo, yo = _axes(results["objectives"])
    (xk, xs, xl), (yk, ys, yl) = UNITS[xo], UNITS[yo]
    groups = {f"{m.legend}, {verdict}": dict(symbol=symbol, color=color, size=m.size)
              for t in technologies() for m in t.report.markers
              for verdict, symbol, color in (("feasible", m.symbol, m.color),
                                             ("infeasible", m.open_symbol, m.open_color or m.color))}
    pts = {k: ([], [], []) for k in groups}
    fronts: dict[str, list] = {}
    for c in results["candidates"]:
        m = c.metrics
        if m.get(xk) is None or m.get(yk) is None:
            continue
        marker = next((k for k in presentation(c.technology).markers if k.takes(c)), None)
        if marker is not None:
            if marker.stages is not None and c.stage not in marker.stages:
                continue
            key = marker.legend
        else:                               # a technology with no markers of its own: a brown hexagon
            key = tech_label(c.technology)
            for verdict, symbol in (("feasible", "hexagon"), ("infeasible", "hexagon-open")):
                groups.setdefault(f"{key}, {verdict}", dict(symbol=symbol, color="#8c564b", size=8))
                pts.setdefault(f"{key}, {verdict}", ([], [], []))
        key += ", feasible" if c.feasible else ", infeasible"
        pts[key][0].append(m[xk] * xs)
        pts[key][1].append(m[yk] * ys)
        pts[key][2].append(hover_text(c))
        if c.feasible:
            fronts.setdefault(c.technology, []).append((m[xk] * xs, m[yk] * ys))
    data = []
    for key, style in groups.items():
        x, y, text = pts[key]
        if not x:
            continue
        data.append(dict(type="scatter", x=x, y=y, mode="markers", name=key, text=text, hoverinfo="text",
                         marker=dict(symbol=style["symbol"], color=style["color"], size=style["size"],
                                     line=dict(width=1.5, color=style["color"]))))
    for tech, pts_ in fronts.items():
        front = _front_2d(pts_)
        data.append(dict(type="scatter", x=[p[0] for p in front], y=[p[1] for p in front], mode="lines",
                         name=f"{tech_label(tech)} front (feasible)",
                         line=dict(color=presentation(tech).front_color, dash="dot"), hoverinfo="skip"))
    # dtick D2: 1, 2, 5 per decade (the 7, 8, 9 labels crowd)
    return no_overprint(plain.figure(data, dict(
        title=dict(text=f"Designs in objective space ({xo} vs {yo}); hover for the design"),
        xaxis=dict(title=dict(text=xl), type="log", dtick="D2"), yaxis=dict(title=dict(text=yl), type="log", dtick="D2"),
        height=520)))


def traces_figure(results: dict, traces: list[dict]) -> dict:
    """Output position against time of the top designs, one panel per load case."""
    cases = results["load_cases"]
    n = max(1, len(cases))
    titles = [f"load case {i + 1}: {c['load_N']:.0f} N" + (f" ({c['dynamic_pressure_Pa'] / 1e3:g} kPa)"
                                                            if "dynamic_pressure_Pa" in c else "")
              for i, c in enumerate(cases)] or ["no load"]
    layout = _panels(n)
    for note, text in zip(layout["annotations"], titles):
        note["text"] = text
    stroke = results["requirements"]["stroke_m"] * 1e3
    palette = ["#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#d62728", "#e377c2", "#17becf"]
    data = []
    for k, tr in enumerate(traces):
        color = palette[k % len(palette)]
        for i, case in enumerate(tr["cases"][:n]):
            data.append(dict(type="scatter", x=plain.typed(case["t"]), y=plain.typed(np.asarray(case["position_m"], float) * 1e3),
                             mode="lines", name=tr.get("name", tr["id"]) + ("" if tr["feasible"] else " (infeasible)"),
                             legendgroup=tr["id"], showlegend=(i == 0),
                             line=dict(color=color, dash=presentation(tr["technology"]).trace_dash),
                             xaxis=_axis("x", i), yaxis=_axis("y", i)))
    t_req, dotted = results["requirements"]["stroke_time_s"], dict(color="gray", dash="dot")
    layout["shapes"] = [shape for i in range(n)
                        for shape in (plain.line(_axis("y", i), stroke, dotted), plain.line(_axis("x", i), t_req, dotted))]
    for i in range(n):
        layout[_axis("xaxis", i)]["title"] = dict(text="time (s)")
    layout["yaxis"]["title"] = dict(text="output position from loaded rest (mm)")
    layout.update(title=dict(text="Time traces of the top designs (dotted: required stroke and the time allowed for it)"),
                  height=480)
    return no_overprint(plain.figure(data, layout))


def _axis(name: str, i: int) -> str:
    """Panel i's axis: x, x2, x3, ... (xaxis, xaxis2, ... in the layout)."""
    return name if i == 0 else f"{name}{i + 1}"


@lru_cache(maxsize=None)
def _panels_json(n: int) -> str:
    """The layout of n panels side by side sharing their y axis, titled, as
    plotly's make_subplots lays them out (its axes' domains and title
    annotations; made once per count)."""
    from plotly.subplots import make_subplots
    layout = make_subplots(rows=1, cols=n, subplot_titles=[" "] * n, shared_yaxes=True).to_plotly_json()["layout"]
    layout.pop("template", None)
    return json.dumps(layout)


def _panels(n: int) -> dict:
    return json.loads(_panels_json(n))


def comparison_figure(results: dict, picks: list[Candidate], title: str) -> dict:
    """Margins of the best designs of each technology (``title``: which
    against which), one row per requirement (horizontal bars: the
    requirement names read level, however many there are)."""
    keys = [k for k in MARGIN_ORDER if any(k in c.margins for c in picks)]
    data = []
    for c in picks:
        x = [c.margins.get(k) for k in keys]
        data.append(dict(type="bar", y=keys, x=[v * 100 if v is not None else None for v in x], name=c.name or c.id,
                         orientation="h",
                         hovertext=[f"{c.name or c.id}<br>{k}: {v:+.1%}" if v is not None else f"{k}: n/a"
                                    for k, v in zip(keys, x)], hoverinfo="text"))
    return no_overprint(plain.figure(data, dict(
        shapes=[plain.line("x", 0, dict(color="black"))], barmode="group",
        title=dict(text=f"Margin per requirement, {title} (left of zero: missed)"),
        xaxis=dict(title=dict(text="margin (%)"), range=[-100, 200]), yaxis=dict(autorange="reversed"),
        height=160 + len(keys) * (6 * max(1, len(picks)) + 12))))     # 6 px a bar, 12 px between rows
