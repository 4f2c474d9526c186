"""An HTML page for the study reports (robust.html, sweep.html): plotly.js
from the output folder's own bundle (``bundle.py``), no CDN."""
from __future__ import annotations

import html

from .bundle import plotly_tag
from .html import CSS


def esc(x) -> str:
    return html.escape(str(x))


def figure_div(fig, i: int) -> str:
    return fig.to_html(full_html=False, include_plotlyjs=False, div_id=f"plot-{i}",
                       config={"displaylogo": False, "responsive": True})


def table(header: list[str], rows: list[list]) -> str:
    head = "".join(f"<th class='l'>{esc(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td class='l'>{esc(v)}</td>" for v in r) + "</tr>" for r in rows)
    return f"<div class='scroll'><table><tr>{head}</tr>{body}</table></div>"


def page(title: str, body: str) -> str:
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{esc(title)}</title><style>{CSS}</style>"
            f"{plotly_tag()}</head>"
            f"<body><h1>{esc(title)}</h1>{body}</body></html>")
