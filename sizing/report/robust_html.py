"""robust.html: probability of compliance of the best designs under part
tolerances, what drives it, and the robust Pareto front (mass, cost, P)."""
from __future__ import annotations

import plotly.graph_objects as go

from ..display import interval
from .layout import no_overprint
from .page import esc, figure_div, page, table


def _front(data: dict) -> go.Figure:
    ds = data["designs"]
    fig = go.Figure()
    for front, name, symbol in ((True, "robust Pareto front", "diamond"), (False, "dominated", "circle")):
        sel = [d for d in ds if d.get("robust_pareto") == front]
        fig.add_trace(go.Scatter(
            x=[d["metrics"].get("mass_kg") for d in sel], y=[d["p_compliance"] for d in sel], mode="markers",
            name=name, text=[d.get("name", d["id"]) for d in sel],
            error_y=dict(type="data", symmetric=False, array=[d["p_ci95"][1] - d["p_compliance"] for d in sel],
                         arrayminus=[d["p_compliance"] - d["p_ci95"][0] for d in sel]),
            marker=dict(symbol=symbol, size=11, color=[d["metrics"].get("cost_usd") for d in sel],
                        colorscale="Viridis", showscale=front,
                        colorbar=dict(title=dict(text="cost, USD", side="right"), x=1.02, xanchor="left")),
            hovertemplate="%{text}<br>mass %{x:.1f} kg<br>P %{y:.3f}<br>cost %{marker.color:.0f} USD<extra></extra>"))
    fig.update_layout(title="Robust front: mass, cost (colour) and probability of compliance (95 % interval)",
                      xaxis_title="mass, kg", yaxis_title="P(compliance)", height=480)
    return no_overprint(fig, legend="top")     # the colour bar has the right side


def _sensitivity(data: dict) -> go.Figure:
    ds = data["designs"]
    keys = list(data["tolerances"])
    fig = go.Figure([go.Bar(name=k, x=[d.get("name", d["id"]) for d in ds], y=[d["sensitivity"].get(k, 0.0) for d in ds])
                     for k in keys])
    fig.update_layout(barmode="group", title="First-order sensitivity of the worst margin (RBD-FAST)",
                      yaxis_title="S1", height=480, xaxis_tickangle=-90)   # upright: a slanted first label runs into the y ticks
    return no_overprint(fig)


def render(data: dict) -> str:
    ds = data["designs"]
    rows = [[d["rank"], d.get("name", d["id"]), f"{d['metrics'].get('mass_kg', float('nan')):.1f}",
             f"{d['metrics'].get('cost_usd', float('nan')):.0f}", f"{d['p_compliance']:.3f}",
             interval(*d["p_ci95"], lambda p: f"{p:.3f}"),
             ", ".join(f"{k} {d['p_requirement'][k]:.3f}" for k in d["failing_requirements"]) or "none",
             d["driving_tolerance"] or "-", "yes" if d.get("robust_pareto") else ""] for d in ds]
    tol = ", ".join(f"{k} {v:.3g}" for k, v in data["tolerances"].items())
    body = f"""
<p class="stamp">{data['samples']} samples per design, seed {data['seed']}, run on {esc(data['where'])};
{data['simulated_candidate_s']:.0f} simulated candidate-seconds.</p>
<p>Tolerances ({esc(data['tolerances_source'])}; relative 1-sigma normal spreads, fluid.air_fraction an absolute
half-normal air volume fraction): {esc(tol)}. Every sample is re-verified by the checks of <code>sizing solve</code>
(static margins and a full simulation under the load cases {esc(', '.join(f'{f:.0f} N' for f in data['load_cases_N']))}).
A tolerance applies to the designs whose parts have that field: stack, fluid, seal and amplifier fields to
designs of stacks and oil, motor, screw, gear and drive fields to motor designs from parts (whose controller gains and
drive limits stay as designed on the nominal parts), operating.temperature to all.
Interval: {esc(data['interval'])}. Sensitivity: {esc(data['sensitivity_method'])}.</p>
<h2>Probability of compliance</h2>
{table(['rank', 'design', 'mass kg', 'cost USD', 'P', '95 % interval', 'requirements that fail (P each)',
        'driving tolerance', 'robust front'], rows)}
{figure_div(_front(data), 0)}
<h2>What drives failure</h2>
{figure_div(_sensitivity(data), 1)}
"""
    return page("Robust sizing: probability of compliance under tolerances", body)
