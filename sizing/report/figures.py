"""Plotly figures of a solve, built from its results only (its ranked
``Candidate``s and the time traces), never from the stages' records."""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import plotly.graph_objects as go
from plotly.subplots import make_subplots

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


def pareto_figure(results: dict) -> go.Figure:
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
    fig = go.Figure()
    for key, style in groups.items():
        x, y, text = pts[key]
        if not x:
            continue
        fig.add_trace(go.Scatter(x=x, y=y, mode="markers", name=key, text=text, hoverinfo="text",
                                 marker=dict(symbol=style["symbol"], color=style["color"], size=style["size"],
                                             line=dict(width=1.5, color=style["color"]))))
    for tech, pts_ in fronts.items():
        front = _front_2d(pts_)
        fig.add_trace(go.Scatter(x=[p[0] for p in front], y=[p[1] for p in front], mode="lines",
                                 name=f"{tech_label(tech)} front (feasible)",
                                 line=dict(color=presentation(tech).front_color, dash="dot"),
                                 hoverinfo="skip"))
    fig.update_layout(title=f"Designs in objective space ({xo} vs {yo}); hover for the design",
                      xaxis_title=xl, yaxis_title=yl, xaxis_type="log", yaxis_type="log",
                      xaxis_dtick="D2", yaxis_dtick="D2",      # 1, 2, 5 per decade: the 7, 8, 9 labels crowd
                      template="plotly_white", height=520)
    return no_overprint(fig)


def traces_figure(results: dict, traces: list[dict]) -> go.Figure:
    """Output position against time of the top designs, one panel per load case."""
    cases = results["load_cases"]
    n = max(1, len(cases))
    titles = [f"load case {i + 1}: {c['load_N']:.0f} N" + (f" ({c['dynamic_pressure_Pa'] / 1e3:g} kPa)"
                                                            if "dynamic_pressure_Pa" in c else "")
              for i, c in enumerate(cases)] or ["no load"]
    fig = make_subplots(rows=1, cols=n, subplot_titles=titles, shared_yaxes=True)
    stroke = results["requirements"]["stroke_m"] * 1e3
    palette = ["#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#d62728", "#e377c2", "#17becf"]
    for k, tr in enumerate(traces):
        color = palette[k % len(palette)]
        for i, case in enumerate(tr["cases"][:n]):
            # arrays: plotly checks a list element by element, an array at once
            # (and writes it as a typed array, the same doubles)
            fig.add_trace(go.Scatter(x=np.asarray(case["t"], float), y=np.asarray(case["position_m"], float) * 1e3,
                                     mode="lines",
                                     name=tr.get("name", tr["id"]) + ("" if tr["feasible"] else " (infeasible)"),
                                     legendgroup=tr["id"], showlegend=(i == 0),
                                     line=dict(color=color, dash=presentation(tr["technology"]).trace_dash)),
                          row=1, col=i + 1)
    t_req = results["requirements"]["stroke_time_s"]
    for i in range(n):
        fig.add_hline(y=stroke, line=dict(color="gray", dash="dot"), row=1, col=i + 1)
        fig.add_vline(x=t_req, line=dict(color="gray", dash="dot"), row=1, col=i + 1)
        fig.update_xaxes(title_text="time (s)", row=1, col=i + 1)
    fig.update_yaxes(title_text="output position from loaded rest (mm)", row=1, col=1)
    fig.update_layout(title="Time traces of the top designs (dotted: required stroke and the time allowed for it)",
                      template="plotly_white", height=480)
    return no_overprint(fig)


def comparison_figure(results: dict, picks: list[Candidate], title: str) -> go.Figure:
    """Margins of the best designs of each technology (``title``: which
    against which), one row per requirement (horizontal bars: the
    requirement names read level, however many there are)."""
    fig = go.Figure()
    keys = [k for k in MARGIN_ORDER if any(k in c.margins for c in picks)]
    for c in picks:
        x = [c.margins.get(k) for k in keys]
        fig.add_trace(go.Bar(y=keys, x=[v * 100 if v is not None else None for v in x], name=c.name or c.id,
                             orientation="h",
                             hovertext=[f"{c.name or c.id}<br>{k}: {v:+.1%}" if v is not None else f"{k}: n/a"
                                        for k, v in zip(keys, x)], hoverinfo="text"))
    fig.add_vline(x=0, line=dict(color="black"))
    fig.update_layout(barmode="group", title=f"Margin per requirement, {title} (left of zero: missed)", xaxis_title="margin (%)", template="plotly_white",
                      height=160 + len(keys) * (6 * max(1, len(picks)) + 12))     # 6 px a bar, 12 px between rows
    fig.update_xaxes(range=[-100, 200])
    fig.update_yaxes(autorange="reversed")
    return no_overprint(fig)
