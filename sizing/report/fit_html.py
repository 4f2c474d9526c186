"""Self-contained HTML report of a fit (plotly inlined, no CDN): measured and
fitted traces, the hysteresis loop, the residual and the fit figures."""
from __future__ import annotations

import html

import numpy as np
import plotly.graph_objects as go
from plotly.subplots import make_subplots

from ..display import interval, number
from .bundle import plotly_tag

MAX_POINTS = 4000
COLORS = {"measured": "#222222", "bouc-wen": "#d62728", "prandtl-ishlinskii": "#1f77b4", "dc-motor": "#d62728"}
UM = 1e6


def _thin(n: int) -> slice:
    return slice(None, None, max(1, int(np.ceil(n / MAX_POINTS))))


def _f4(values) -> np.ndarray:
    """Single precision for plotting: plotly embeds numpy arrays as binary,
    and 4-byte floats (7 digits, far below a pixel) halve the page."""
    return np.asarray(values, dtype=np.float32)


def _table(rows: list[list], header: list[str]) -> str:
    head = "".join(f"<th>{html.escape(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _pct(x) -> str:
    return "-" if x is None else f"{100 * x:.3f} %"


def _run_figure(trace: dict, kind: str) -> go.Figure:
    t = trace["time"]
    s = _thin(len(t))
    x = trace["measured"]
    if kind == "hysteresis":
        fig = make_subplots(rows=2, cols=2, column_widths=[0.62, 0.38], row_heights=[0.65, 0.35],
                            specs=[[{}, {"rowspan": 2}], [{}, None]],
                            subplot_titles=("displacement", "loop: voltage vs displacement", "residual (measured - fitted)"))
        fig.add_trace(go.Scatter(x=_f4(t[s]), y=_f4(x[s] * UM), name="measured", line=dict(color=COLORS["measured"])), 1, 1)
        fig.add_trace(go.Scatter(x=_f4(trace["voltage"][s]), y=_f4(x[s] * UM), name="measured loop", showlegend=False,
                                 line=dict(color=COLORS["measured"])), 1, 2)
        for model, y in trace["fitted"].items():
            c = COLORS[model]
            fig.add_trace(go.Scatter(x=_f4(t[s]), y=_f4(y[s] * UM), name=model, line=dict(color=c, dash="dash")), 1, 1)
            fig.add_trace(go.Scatter(x=_f4(trace["voltage_filtered"][s]), y=_f4(y[s] * UM), name=f"{model} loop",
                                     showlegend=False, line=dict(color=c, dash="dash")), 1, 2)
            fig.add_trace(go.Scatter(x=_f4(t[s]), y=_f4((x - y)[s] * UM), name=f"residual {model}", showlegend=False,
                                     line=dict(color=c)), 2, 1)
        fig.update_yaxes(title_text="um", row=1, col=1)
        fig.update_yaxes(title_text="um", row=2, col=1)
        fig.update_xaxes(title_text="time (s)", row=2, col=1)
        fig.update_xaxes(title_text="voltage (V)", row=1, col=2)
        fig.update_yaxes(title_text="displacement (um)", row=1, col=2)
    else:
        fig = make_subplots(rows=2, cols=1, row_heights=[0.65, 0.35], shared_xaxes=True,
                            subplot_titles=("position", "residual (measured - fitted)"))
        fig.add_trace(go.Scatter(x=_f4(t[s]), y=_f4(trace["reference"][s] * 1e3), name="reference",
                                 line=dict(color="#999999")), 1, 1)
        fig.add_trace(go.Scatter(x=_f4(t[s]), y=_f4(x[s] * 1e3), name="measured", line=dict(color=COLORS["measured"])), 1, 1)
        for model, y in trace["fitted"].items():
            fig.add_trace(go.Scatter(x=_f4(t[s]), y=_f4(y[s] * 1e3), name="fitted (eq. 14 closed loop)",
                                     line=dict(color=COLORS[model], dash="dash")), 1, 1)
            fig.add_trace(go.Scatter(x=_f4(t[s]), y=_f4((x - y)[s] * 1e3), name="residual", showlegend=False,
                                     line=dict(color=COLORS[model])), 2, 1)
        fig.update_yaxes(title_text="mm", row=1, col=1)
        fig.update_yaxes(title_text="mm", row=2, col=1)
        fig.update_xaxes(title_text="time (s)", row=2, col=1)
    fig.update_layout(title=f"run {trace['name']} ({trace['role']})", height=520, margin=dict(t=70, l=60, r=20, b=50))
    return fig


def _hysteresis_sections(result: dict) -> str:
    """Model choice, the rig-ready Bouc-Wen values next to the plain fit,
    what the data determine, the prior, the PI weights, the input filter."""
    parts = []
    choice = result.get("model_choice")
    if choice:
        parts.append("<h2>Model choice</h2><p>" + html.escape(
            f"{choice['winner']} wins on the {choice['criterion']}: Bouc-Wen {_pct(choice['bouc_wen'])}, "
            f"Prandtl-Ishlinskii {_pct(choice['prandtl_ishlinskii'])}, margin {_pct(choice['margin'])} "
            f"({100 * choice['margin_relative']:.0f} % of the loser's).") + "</p>")
    bw = result["bouc_wen"]
    plain = bw.get("plain", bw["params"])
    plain_ci = bw.get("plain_ci95", bw["ci95"])
    share = (bw.get("prior") or {}).get("prior_share", {})
    rows = [[n, number(v), interval(*bw['ci95'][n]), number(plain[n]),
             interval(*plain_ci[n]), f"{share[n]:.2f}" if n in share else "-"]
            for n, v in bw["params"].items()]
    parts.append("<h2>Bouc-Wen parameters (seed eq. 1-2, SI)</h2>" + _table(
        rows, ["parameter", "rig-ready ([stack])", "95 % interval", "plain least squares", "95 % interval",
               "prior share (0 data, 1 prior)"]))
    if bw.get("prior"):
        parts.append(f"<p><b>Prior:</b> {html.escape(bw['prior']['source'])}; {html.escape(bw['prior']['weight'])}.</p>")
    combos = bw.get("combinations") or {}
    if combos:
        rows = [[n, number(c['value']), interval(*c['ci95']), f"{100 * c['relative_half_width']:.2f} %"]
                for n, c in combos.items()]
        parts.append("<h2>What the data determine</h2>" + _table(rows, ["combination", "value", "95 % interval", "+/- relative"]))
    pi = result["prandtl_ishlinskii"]
    rows = [[f"{r:.4g}", f"{w:.4g}"] for r, w in zip(pi["thresholds_V"], pi["weights_m_V"])]
    parts.append("<h2>Prandtl-Ishlinskii weights (w >= 0)</h2>" + _table(rows, ["threshold (V)", "weight (m/V)"]))
    parts.append(f"<p><b>Input filter:</b> {html.escape(result['filter'])}.</p>")
    return "".join(parts)


def render(result: dict, kind: str, toml: str) -> str:
    """The whole report as one HTML string (plotly.js inlined once)."""
    summary = result["summary"]
    models = list(summary)
    parts = [f"<h1>sizing fit {html.escape(kind)}</h1>",
             f"<p>Runs: {html.escape(', '.join(result['sources']))}</p>"]
    rows = [[m, _pct(summary[m]["nrmse_train"]), _pct(summary[m]["nrmse_holdout"])] for m in models]
    parts.append("<h2>Fit figures</h2>" + _table(rows, ["model", "NRMSE train (mean)", "NRMSE holdout (mean)"]))
    names = list(summary[models[0]]["nrmse_runs"])
    roles = {t["name"]: t["role"] for t in result["traces"]}
    rows = [[n, roles.get(n, "")] + [_pct(summary[m]["nrmse_runs"].get(n)) for m in models] for n in names]
    parts.append("<h3>NRMSE per run</h3>" + _table(rows, ["run", "role"] + models))
    parts.append("<p>NRMSE = RMS(measured - fitted) / (max - min of measured), docs/formats.md. "
                 f"The chosen model (in the TOML) is <b>{html.escape(result['model'])}</b>.</p>")
    if kind == "hysteresis":
        parts.append(_hysteresis_sections(result))
    else:
        rows = [[n, number(v), interval(*result['ci95'][n])]
                for n, v in result["params"].items()]
        parts.append("<h2>Parameters (seed eq. 13-14, closed loop)</h2>" + _table(rows, ["parameter", "value", "95 % interval"]))
    warns = result["fit"].get("warnings") or []
    if warns:
        parts.append("<h2>Identifiability</h2><ul>" + "".join(f"<li>{html.escape(w)}</li>" for w in warns) + "</ul>")
    parts.append("<h2>Runs</h2>")
    for trace in result["traces"]:
        fig = _run_figure(trace, kind)
        parts.append(fig.to_html(full_html=False, include_plotlyjs=False))
    parts.append("<h2>TOML written</h2><pre>" + html.escape(toml) + "</pre>")
    style = ("body{font-family:sans-serif;max-width:1200px;margin:auto;padding:1em}"
             "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}")
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>sizing fit {html.escape(kind)}</title>"
            f"<style>{style}</style>{plotly_tag()}</head><body>{''.join(parts)}</body></html>")
