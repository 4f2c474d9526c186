"""plotly.js, once per output folder: every page of a folder loads the
``plotly.min.js`` written beside it (no CDN, so the pages open offline),
instead of each page carrying its own 4-5 MB copy."""
from __future__ import annotations

PLOTLY_FILE = "plotly.min.js"


def plotly_tag() -> str:
    """The page's reference to the folder's bundle."""
    return f"<script type='text/javascript' src='{PLOTLY_FILE}' charset='utf-8'></script>"


def plotly_js() -> str:
    """The bundle itself (the plotly package's own copy, as offline use wants)."""
    import plotly.offline
    return plotly.offline.get_plotlyjs()
