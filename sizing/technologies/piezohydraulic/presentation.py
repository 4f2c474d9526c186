"""How the report shows piezohydraulic designs (``Presentation``): three
markers (one per variant), the stacks and bores in the tables, the force
path section and what the screen ruled out before sizing."""
from __future__ import annotations

from typing import TYPE_CHECKING


from ..presentation import ruled_out_by_part, SIZED_STAGES, Marker, Presentation, escaped as _e, shown

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def hover(c: Candidate) -> str:
    comp = c.components
    ratio = comp.get("ratio")
    head = (f"{comp['n_stacks']} x {comp['stack']}, R = {ratio:.0f}<br>{comp['fluid']}, {comp['seal']}, "
            f"{comp['amplifier']}" if ratio else f"{comp['n_stacks']} x {comp['stack']}")
    if c.variant == "compensated":
        head += "<br>with thermal compensator"
    return head


def parts(c: Candidate) -> str:
    k, s = c.components, (c.static or {})
    return (f"{k['n_stacks']} x {k['stack']}, R = {shown(k['ratio'], fmt='{:.1f}')}, "
            f"bores {shown(s.get('wide_diameter_m'), 1e3, '{:.0f}')}/{shown(s.get('narrow_diameter_m'), 1e3, '{:.1f}')} mm, "
            f"{k['fluid']}, {k['seal']}, {k['amplifier']}")


def comparison_picks(own: list[Candidate]) -> list[Candidate]:
    """The best compensated and the best uncompensated design."""
    picks = []
    for variant in ("compensated", "uncompensated"):
        group = [c for c in own if c.variant == variant and c.stage != "pruned"]
        if group:
            picks.append(group[0])
    return picks


def counts_words(results: dict) -> str:
    counts = results["counts"]
    ph = (results["summary"].get("counts") or {}).get("piezohydraulic") or {
        "combinations": counts["combinations"], "ruled_out_before_sizing": counts["pruned"], "sized": counts["sized"],
        "simulated": counts["simulated"]}      # a results.json written before summary.counts
    return (f"{ph['combinations']:,} piezohydraulic combinations ({ph['ruled_out_before_sizing']:,} ruled out before sizing,\n"
            f"{ph['sized']:,} sized by geometric programs, {ph['simulated']:,} designs verified by simulation)")


def pruned_words(results: dict) -> str:
    """The combinations ruled out before sizing: by stack and requirement
    when recorded one by one, else by the requirement each misses most."""
    pruned = [c for c in results["candidates"] if c.stage == "pruned" and c.technology == "piezohydraulic"]
    counted = ((results["summary"].get("counts") or {}).get("piezohydraulic") or {}).get("ruled_out_before_sizing", 0)
    if counted and not pruned:        # counted by reason, not recorded (solve --detail full records each)
        reasons = (results["summary"].get("ruled_out_by_technology") or {}).get("piezohydraulic") or {}
        rows = "".join(f"<tr><td class='l'>{_e(k)}</td><td>{v:,}</td></tr>" for k, v in reasons.items())
        return (f"<p>{counted:,} piezohydraulic combinations were ruled out before sizing; they are counted by the "
                f"requirement each misses most, not recorded one by one (<code>sizing solve --detail full</code> "
                f"keeps a record of each with its margins). Left out before ranking, by reason (combinations "
                f"before sizing, designs after):</p><table><tr><th class='l'>ruled out by</th><th>count</th></tr>"
                f"{rows}</table>")
    if not pruned:
        return "<p>No combination was ruled out before sizing.</p>"
    rows = ruled_out_by_part(pruned, "stack")
    return (f"<p>{len(pruned)} combinations were ruled out before sizing; each stays in results.json with its "
            f"margins. By stack and the requirement that rules them out:</p><table><tr><th class='l'>stack</th>"
            f"<th class='l'>ruled out by</th><th>combinations</th></tr>{rows}</table>")


def force_path_section(cands: list[Candidate], to_div) -> str:
    from .force_path_html import section         # plotly loads with the report, not with the registry
    return section(cands, to_div)


PRESENTATION = Presentation(
    markers=(Marker("compensated", "piezohydraulic, compensated", "circle", "circle-open", "#1f77b4",
                    stages=SIZED_STAGES),
             Marker("uncompensated", "piezohydraulic, uncompensated", "square", "x-thin-open", "#2ca02c",
                    stages=SIZED_STAGES, open_color="#7f7f7f"),
             Marker("passive", "piezohydraulic, passive", "triangle-up", "triangle-up-open", "#9467bd",
                    stages=SIZED_STAGES)),
    hover=hover, parts=parts, comparison_picks=comparison_picks, counts_words=counts_words, checks_table=True,
    section=force_path_section, pruned_words=pruned_words,
    comparison_titles=("Piezohydraulic against the DC motor", "piezohydraulic against DC"),
)
