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
    """``fig`` laid out so that no text overprints another; returns it."""
    fig.update_xaxes(automargin=True)
    fig.update_yaxes(automargin=True)
    fig.update_layout(legend=LEGENDS[legend], margin=dict(t=TOP_MARGIN[legend]))
    if fig.layout.title.text:
        fig.update_layout(title=TITLE)
    return fig
