"""The report's section of its own (``Presentation.section``): the force
path as a bar of compliance shares, the thermal budget as a waterfall, the
seal friction at pressure and what each design rests on that is assumed."""
from __future__ import annotations

from typing import TYPE_CHECKING

import html

from ...report import plain
from ...report.layout import no_overprint

if TYPE_CHECKING:
    from ...engine.candidate import Candidate

MEMBER_COLORS = {"stacks": "#1f77b4", "spacer": "#aec7e8", "base_plate": "#ff7f0e", "frame": "#2ca02c",
                 "wide_piston": "#98df8a", "oil_column": "#9467bd", "compensator": "#c5b0d5",
                 "end_cap": "#d62728", "narrow_piston": "#8c564b"}
TERMS = (("oil_m", "oil"), ("casing_m", "casing"), ("stacks_m", "stacks"), ("pistons_m", "pistons"),
         ("frame_m", "frame"), ("compensator_m", "compensator"))


def _e(text) -> str:
    return html.escape(str(text))


def piezo_designs(cands: list[Candidate], limit: int = 6) -> list[Candidate]:
    """The best-ranked sized designs, one per variant first."""
    sized = [c for c in cands if c.technology == "piezohydraulic" and c.own.get("force_path")]
    picks, known = [], set()
    for c in sized:
        if c.variant not in known:
            picks.append(c)
            known.add(c.variant)
    picks += [c for c in sized if c not in picks]
    return picks[:limit]


def force_path_figure(designs: list[Candidate]) -> dict:
    """Each design's compliance shares, member by member (plotly's JSON, ``report.plain``)."""
    names = [d.name or d.id for d in designs]
    members = [m for m in MEMBER_COLORS if any(x["member"] == m for d in designs for x in d.own["force_path"])]
    data = [dict(type="bar", y=names, name=m, orientation="h", marker=dict(color=MEMBER_COLORS[m]),
                 x=[next((x["compliance_share"] for x in d.own["force_path"] if x["member"] == m), 0.0) for d in designs],
                 hovertemplate=m + ": %{x:.1%} of the compliance<extra></extra>") for m in members]
    return no_overprint(plain.figure(data, dict(
        barmode="stack", height=max(300, 140 + 40 * len(designs)), margin=dict(l=10, r=10, b=30),
        xaxis=dict(title=dict(text="share of the force path's compliance (stacks alone = ideal)"), tickformat=".0%"),
        yaxis=dict(autorange="reversed")), template_name=None))


def thermal_figure(design: Candidate) -> dict:
    """A design's thermal budget as a waterfall to its net drift (plotly's JSON, ``report.plain``)."""
    tb = design.own["thermal_budget"]
    labels = [label for key, label in TERMS] + ["net"]
    values = [tb[key] * 1e3 for key, _ in TERMS] + [tb["net_m"] * 1e3]
    return plain.figure([dict(type="waterfall", x=labels, y=values, measure=["relative"] * len(TERMS) + ["total"],
                              hovertemplate="%{x}: %{y:.2f} mm<extra></extra>")],
                        dict(height=330, margin=dict(l=10, r=10, t=30, b=30), showlegend=False,
                             title=dict(text=f"thermal budget of {design.name or design.id}"),
                             yaxis=dict(title=dict(text="output displacement, mm"))), template_name=None)


def section(cands: list[Candidate], to_div) -> str:
    """HTML of the section; ``to_div(fig)`` renders a figure without plotly.js."""
    designs = piezo_designs(cands)
    if not designs:
        return "<h2>Force path, thermal budget, seals</h2><p>No piezohydraulic design was sized.</p>"
    rows = "".join(
        f"<tr><td class='id' title='{_e(d.id)}'>{_e(d.name or d.id)}</td><td class='l'>{_e(d.variant or '')}</td>"
        f"<td>{d.static['blocked_force_ideal_N']:.0f}</td><td>{d.static['blocked_force_N']:.0f}</td>"
        f"<td>{d.static.get('blocked_force_net_N', float('nan')):.0f}</td>"
        f"<td>{d.own['seal_friction_N']['wide']:.0f}</td><td>{d.own['seal_friction_N']['narrow']:.1f}</td>"
        f"<td>{d.own['seal_friction_N']['at_pressure_Pa'] / 1e6:.2f}</td>"
        f"<td>{d.own['thermal_budget']['net_m'] * 1e3:.1f}</td>"
        f"<td class='l'>{_e(', '.join(_assumed_names(d)[:8]))}"
        f"{' ...' if len(_assumed_names(d)) > 8 else ''}</td></tr>" for d in designs)
    table = ("<div class='scroll'><table><tr><th class='l'>design</th><th class='l'>variant</th>"
             "<th>blocked force ideal, N</th><th>with the force path, N</th><th>less seal friction, N</th>"
             "<th>wide seal, N</th><th>narrow seal, N</th><th>at, MPa</th><th>thermal net, mm</th>"
             "<th class='l'>rests on assumed catalog values</th></tr>" + rows + "</table></div>")
    waterfalls = "".join(to_div(thermal_figure(d)) for d in designs[:3])
    return (f"<h2>Force path, thermal budget, seals</h2>"
            f"<p>Every member between the stacks and the output is a spring in series, referred to the wide "
            f"piston; the blocked force is the stack stroke over the summed compliances, over R. End caps and the "
            f"stack base plate are circular plates under pressure, simply supported (Roark; the conservative "
            f"edge; the clamped value is in results.json). Seal friction is at the pressure of the largest load "
            f"case.</p>{to_div(force_path_figure(designs))}{table}{waterfalls}")


def _assumed_names(d: Candidate) -> list[str]:
    """part.field of each assumed value, those that decide the binding margin first."""
    rows = sorted(d.rests_on_assumed or [], key=lambda r: not r.get("decides"))
    return [f"{r['part']}.{r['field']}" + (" (decides)" if r.get("decides") else "") for r in rows]
