"""diagnosis.html: a self-contained plotly page (plotly.js embedded) built
from a Diagnosis only: measured against simulated traces (baseline and best
effect), the gap map and the ranking of effects."""
from __future__ import annotations

import html

import numpy as np
import plotly.graph_objects as go
from plotly.subplots import make_subplots

from ..display import interval, label, number, quantity
from .bundle import plotly_tag

# the nominal parameters ``sizing diagnose --recalibrate`` re-fits, and their units
# (docs/formats.md: d33 m/V; seal friction N; c1 1/s and c2 rad/(s^2 A), seed eq. 13)
RECALIBRATED_UNITS = {"d33": "m/V", "wide_friction": "N", "narrow_friction": "N", "c1": "1/s", "c2": "rad/(s^2 A)"}


def _per_run(nrmse: dict) -> str:
    """NRMSE per run: "steps_a 0.0123, steps_b 0.0456"."""
    return ", ".join(f"{run} {x:.4f}" for run, x in nrmse.items())


def _traces(diagnosis) -> go.Figure:
    bench = diagnosis.bench
    runs, channels = bench.runs, bench.channels
    titles = [f"run {r.name}{' (holdout)' if r.holdout else ' (training)'}: {c}" for r in runs for c in channels]
    fig = make_subplots(rows=len(runs) * len(channels), cols=1, shared_xaxes=False, subplot_titles=titles)
    best_name = diagnosis.verdict.get("effect") or (diagnosis.fits[0].name if diagnosis.fits else None)
    nominal = bench.nominal_channels()
    best = diagnosis.extra.get("best_channels")
    scale = {"position_m": (1e3, "position, mm"), "current_A": (1.0, "current, A")}
    for k, r in enumerate(runs):
        measured = bench.measured(k)
        for j, c in enumerate(channels):
            row, first = k * len(channels) + j + 1, k == 0 and j == 0
            f, label = scale[c]
            fig.add_trace(go.Scattergl(x=r.t, y=measured[j] * f, name="measured", mode="lines",
                                       line=dict(color="black", width=1), showlegend=first), row=row, col=1)
            fig.add_trace(go.Scattergl(x=r.t, y=nominal[k][j] * f, name="baseline model",
                                       line=dict(color="#d62728"), showlegend=first), row=row, col=1)
            if best is not None:
                fig.add_trace(go.Scattergl(x=r.t, y=best[k][j] * f, name=f"with {best_name}",
                                           line=dict(color="#1f77b4", dash="dash"), showlegend=first), row=row, col=1)
            fig.update_yaxes(title_text=label, row=row, col=1)
            fig.update_xaxes(title_text="time, s", row=row, col=1)
    fig.update_layout(height=300 * len(runs) * len(channels), title="Measured against simulated channels")
    return fig


def _gap_map(diagnosis) -> go.Figure:
    colors = {"rising": "#2ca02c", "falling": "#ff7f0e", "hold": "#7f7f7f", "reversal": "#9467bd",
              "steady_state": "#8c564b", "high_frequency": "#e377c2", "low_frequency": "#17becf"}
    entries = [e for e in diagnosis.where if e["label"] not in ("high_frequency", "low_frequency")]
    several = len(diagnosis.bench.channels) > 1
    for e in entries:
        e["row"] = f"{e['run']} / {e.get('channel', 'position_m')}" if several else e["run"]
    names = [f"{r.name} / {c}" if several else r.name for r in diagnosis.bench.runs for c in diagnosis.bench.channels]
    fig = go.Figure()
    for label, color in colors.items():
        sel = [e for e in entries if e["label"] == label]
        if not sel:
            continue
        fig.add_trace(go.Bar(y=[e["row"] for e in sel], x=[e["t_end_s"] - e["t_start_s"] for e in sel],
                             base=[e["t_start_s"] for e in sel], orientation="h", name=label,
                             marker=dict(color=color, opacity=[min(1.0, 0.15 + 3 * e["share"]) for e in sel]),
                             text=[f"{100 * e['share']:.0f}%" if e["share"] > 0.03 else "" for e in sel],
                             hovertemplate="%{y} %{base:.3f}-%{x:.3f} s<br>share %{text}<extra>" + label + "</extra>"))
    fig.update_layout(barmode="overlay", title="Gap map: share of the residual energy by segment (top entries)",
                      xaxis_title="time, s", yaxis=dict(categoryorder="array", categoryarray=names), height=300)
    return fig


def _ranking(diagnosis) -> go.Figure:
    fits = diagnosis.fits[:12]
    fig = go.Figure(go.Bar(x=[f.nrmse_holdout for f in fits], y=[f.name for f in fits], orientation="h",
                           marker_color=["#1f77b4" if i == 0 else "#aec7e8" for i in range(len(fits))]))
    fig.add_vline(x=diagnosis.baseline_holdout, line=dict(color="#d62728"), annotation_text="baseline")
    fig.add_vline(x=diagnosis.noise_floor_holdout, line=dict(color="gray", dash="dot"), annotation_text="noise floor")
    # log axis: a wrong effect can leave a gap 100x the best one's
    fig.update_layout(title="Effects ranked by the holdout NRMSE they leave (lower is better)",
                      xaxis_title="holdout NRMSE (log scale)", xaxis_type="log", yaxis=dict(autorange="reversed"),
                      height=120 + 28 * len(fits))
    return fig


def _interval(key: str, ci) -> str:
    """A 95 % interval in the parameter's unit, or why there is none (not identifiable)."""
    if ci is None or not all(np.isfinite(ci)):
        return "[CI n/a: not identifiable from these runs]"
    return f"({interval(ci[0], ci[1], lambda x: quantity(key, x))})"


def render(diagnosis, title: str = "Sim-to-real gap diagnosis") -> str:
    data = diagnosis.to_json()
    v = data["verdict"]
    verdict = (f"<b>{v['status']}</b>: <b>{html.escape(v['effect'])}</b>, holdout measure "
               f"{diagnosis.baseline_holdout:.4f} &rarr; {diagnosis.baseline_holdout * (1 - v['shrink_holdout']):.4f} "
               f"(shrink {100 * v['shrink_holdout']:.0f} %)" if v["effect"] else f"<b>{v['status']}</b>")
    second = v.get("runner_up")
    sep = v.get("separation")
    separation = ""
    if sep:
        separation = (f"<p>Runner-up: {html.escape(second['effect']) if second else 'none'}"
                      + (f" (shrink {100 * second['shrink_holdout']:.0f} %, {100 * second['explained_gap_energy']:.0f} % of "
                         f"the gap energy above the floor)" if second else "")
                      + f". Separation test: {html.escape(sep['test'])}; p against the baseline "
                      f"{sep['p_vs_baseline']:.3f}, against the runner-up {sep['p_vs_runner_up']:.3f} "
                      f"(significant below {sep['alpha']:g}). Floor (noise and model form): "
                      f"{v.get('floor_holdout', float('nan')):.4f}.</p>")
    remaining = "".join(f"<tr><td>{html.escape(e['run'])}</td><td>{html.escape(str(e.get('channel', '')))}</td>"
                        f"<td>{html.escape(e['label'])}</td><td>{e['t_start_s']:.3f}-{e['t_end_s']:.3f} s</td>"
                        f"<td>{100 * e['share']:.0f} %</td></tr>" for e in v.get("remaining", []))
    if remaining:
        remaining = ("<h2>What remains " + ("after the best effect" if v["effect"] else "(baseline)")
                     + "</h2><table><tr><th>run</th><th>channel</th><th>where</th><th>time</th><th>share</th></tr>"
                     + remaining + "</table>")
    channels = "".join(f"<tr><td>{html.escape(c['effect'])}</td>" + "".join(
        f"<td>{100 * c['shrink_holdout_channels'].get(ch, 0.0):.0f} %</td>" for ch in diagnosis.bench.channels)
        + "</tr>" for c in data["candidates"][:12])
    channels = ("<h2>Holdout shrink per channel</h2><table><tr><th>effect</th>"
                + "".join(f"<th>{ch}</th>" for ch in diagnosis.bench.channels) + "</tr>" + channels + "</table>")
    rows = []
    for c in data["candidates"][:12]:
        params = ", ".join(f"{label(k)} = {quantity(k, val)} {_interval(k, c['params_ci95'].get(k))}"
                           for k, val in c["params"].items())
        rows.append(f"<tr><td>{html.escape(c['effect'])}</td><td>{c['nrmse_train']:.4f}</td>"
                    f"<td>{c['nrmse_holdout']:.4f}</td><td>{100 * c['shrink_holdout']:.0f} %</td>"
                    f"<td>{html.escape(params) or '-'}</td></tr>")
    tests = "".join(
        f"<tr><td>{html.escape(run)}</td><td>{t['whiteness']['max_autocorrelation']:.2f} "
        f"({'white' if t['whiteness']['white'] else 'not white'})</td>"
        f"<td>{t['cross_correlation_input']['max']:.2f} at {1e3 * t['cross_correlation_input']['lag_s']:.0f} ms</td>"
        f"<td>{t['cross_correlation_velocity']['max']:.2f} at {1e3 * t['cross_correlation_velocity']['lag_s']:.0f} ms</td></tr>"
        for run, t in data["residual_tests"].items())
    figs = [_traces(diagnosis), _gap_map(diagnosis), _ranking(diagnosis)]
    body = [figs[0].to_html(full_html=False, include_plotlyjs=False)]
    body += [f.to_html(full_html=False, include_plotlyjs=False) for f in figs[1:]]
    baseline = ", ".join(f"{k}: {val:.4f}" for k, val in data["baseline"]["nrmse"].items())
    recal = ""
    if diagnosis.recalibration:
        r = diagnosis.recalibration
        values = ", ".join(f"{k} = {number(v)} {RECALIBRATED_UNITS.get(k, '')}".strip() for k, v in r["recalibrated"].items())
        recal = (f"<p>Re-calibrated on the training runs: {html.escape(values)}; NRMSE before "
                 f"{html.escape(_per_run(r['nrmse_before']))}, after {html.escape(_per_run(r['nrmse_after']))}.</p>")
    return f"""<!DOCTYPE html><html><head><meta charset="utf-8"><title>{html.escape(title)}</title>
<style>body{{font-family:sans-serif;margin:2em;max-width:1100px}} td,th{{padding:2px 8px;text-align:left}}
table{{border-collapse:collapse}} tr:nth-child(even){{background:#f4f4f4}}</style>{plotly_tag()}</head><body>
<h1>{html.escape(title)}</h1>
<p>Verdict: {verdict}. {html.escape(v.get('reason', ''))}</p>
{separation}
{remaining}
<p>Baseline NRMSE per run: {html.escape(baseline)}; holdout {diagnosis.baseline_holdout:.4f};
noise floor (holdout) {diagnosis.noise_floor_holdout:.4f}. Input treatment: {html.escape(diagnosis.bench.input_treatment)}.</p>
{recal}
<h2>Effects</h2><table><tr><th>effect</th><th>NRMSE train</th><th>NRMSE holdout</th><th>shrink</th>
<th>fitted parameters (95 % CI)</th></tr>{''.join(rows)}</table>
{channels}
<h2>Residual tests (baseline)</h2><table><tr><th>run</th><th>whiteness (max autocorrelation)</th>
<th>cross-correlation with input</th><th>with velocity</th></tr>{tests}</table>
{''.join(body)}
</body></html>"""
