"""sweep.html: feasible counts per technology over the grid, the best
design per point, where each technology stops being feasible and how the
Pareto front moves."""
from __future__ import annotations

import plotly.graph_objects as go

from ..display import requirement
from .layout import no_overprint
from .page import esc, figure_div, page, table
from .words import tech_label, varied_text


def _label(g: dict) -> str:
    return varied_text(g["varied"])


def _fmt(field: str, v: float) -> str:
    return requirement(field, v)


def _counts(data: dict) -> go.Figure:
    grid = data["grid"]
    labels = [_label(g) for g in grid]
    techs = sorted({t for g in grid for t in g["feasible"]})
    fig = go.Figure([go.Bar(name=tech_label(t), x=labels, y=[g["feasible"][t] for g in grid]) for t in techs])
    fig.update_layout(barmode="group", title="Feasible designs per technology at each grid point",
                      yaxis_title="feasible candidates", height=460, xaxis_tickangle=-90)
    return no_overprint(fig)


def _fronts(data: dict) -> go.Figure:
    fig = go.Figure()
    for g in data["grid"]:
        pts = sorted(g["front"], key=lambda p: p.get("mass_kg", 0.0))
        if not pts:
            continue
        fig.add_trace(go.Scatter(x=[p.get("mass_kg") for p in pts], y=[p.get("cost_usd") for p in pts],
                                 mode="lines+markers", name=_label(g), text=[p.get("name", p["id"]) for p in pts],
                                 hovertemplate="%{text}<br>%{x:.1f} kg, %{y:.0f} USD<extra></extra>"))
    fig.update_layout(title="Pareto front (feasible designs) at each grid point", xaxis_title="mass, kg",
                      yaxis_title="cost, USD", height=480)
    return no_overprint(fig)


def render(data: dict) -> str:
    grid = data["grid"]
    rows = []
    for g in grid:
        b = g["best"]
        rows.append([_label(g), *(g["feasible"][t] for t in sorted(g["feasible"])),
                     b.get("name", b["id"]) if b else "none feasible",
                     f"{b['metrics'].get('mass_kg', float('nan')):.1f}" if b else "",
                     f"{b['metrics'].get('cost_usd', float('nan')):.0f}" if b else ""])
    techs = sorted({t for g in grid for t in g["feasible"]})
    lim_rows = []
    for t, per_field in data["limits"].items():
        for field, lines in per_field.items():
            for line in lines:
                others = varied_text(line["others"]) or "-"
                last, bad = line["last_feasible"], line["first_infeasible"]
                lim_rows.append([tech_label(t), field, others, "feasible at every point" if line["feasible_everywhere"] else
                                 ("never feasible" if last is None else _fmt(field, last)),
                                 "-" if bad is None else _fmt(field, bad)])
    vary = "; ".join(f"{v['field']} over {len(v['values'])} values" for v in data["vary"])
    body = f"""
<p class="stamp">{len(grid)} full solves ({esc(vary)}), run on {esc(data['where'])}; catalog sha256
{esc(data['catalog_sha256'])}.</p>
{figure_div(_counts(data), 0)}
<h2>Best design per point</h2>
{table(['point', *(f'feasible {tech_label(t)}' for t in techs), 'best design', 'mass kg', 'cost USD'], rows)}
<h2>Where each technology stops being feasible</h2>
{table(['technology', 'varied field', 'other fields at', 'last feasible value', 'first infeasible value'], lim_rows)}
<h2>How the front moves</h2>
{figure_div(_fronts(data), 1)}
"""
    return page("Requirement sweep", body)
