"""Plot layouts that do not overprint at any page width (1000 to 1400 px
and beyond): the axes make room for their tick labels and titles
(plotly's automargin), the title keeps the top of the figure, and the
legend sits where no axis title, tick label or colour bar is.

``legend="right"``: a column right of the plot (many entries);
``legend="top"``: a row between the title and the plot (a few entries,
when a colour bar takes the right side)."""
from __future__ import annotations

TITLE = dict(yref="container", y=0.98, yanchor="top", x=0.01, xanchor="left", xref="container")
LEGENDS = {"right": dict(orientation="v", x=1.02, xanchor="left", y=1.0, yanchor="top"),
           "top": dict(orientation="h", x=0.0, xanchor="left", y=1.02, yanchor="bottom")}
TOP_MARGIN = {"right": 60, "top": 100}       # px above the plot: the title, and the legend row


def no_overprint(fig, legend: str = "right"):
    """``fig`` (plotly's graph objects, or a figure's JSON as ``report.plain``
    builds it) laid out so that no text overprints another; returns it."""
    if isinstance(fig, dict):
        fig["layout"] = laid_out(fig["layout"], legend)
    else:
        fig.update_layout(laid_out(fig.layout.to_plotly_json(), legend))
    return fig


def laid_out(layout: dict, legend: str = "right") -> dict:
    """A layout's JSON with ``no_overprint``'s changes (a new dict)."""
    out = dict(layout)
    axes = [k for k in out if k.startswith(("xaxis", "yaxis"))]
    for k in ("xaxis", "yaxis", *axes):
        out[k] = {**out.get(k, {}), "automargin": True}
    out["legend"] = {**out.get("legend", {}), **LEGENDS[legend]}
    out["margin"] = {**out.get("margin", {}), "t": TOP_MARGIN[legend]}
    title = out.get("title")
    if isinstance(title, str):
        title = {"text": title}
    if title and title.get("text"):
        out["title"] = {**title, **TITLE}
    return out
