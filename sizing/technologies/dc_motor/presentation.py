"""How the report shows DC motor designs (``Presentation``): catalog
actuators as large red diamonds, designs from parts as orange triangles,
their parts and gains on hover and what the static screen ruled out."""
from __future__ import annotations

from typing import TYPE_CHECKING


from ..presentation import ruled_out_by_part, SIZED_STAGES, Marker, Presentation, escaped as _e

if TYPE_CHECKING:
    from ...engine.candidate import Candidate

COMBINATIONS = "DC motor x screw x gear x drive combinations"


def parts(c: Candidate) -> str:
    k = c.components
    return (f"DC actuator {k['actuator']}" if "actuator" in k else
            f"DC from parts: {k['motor']}, {k['screw']}, {k['gear'] or 'no gear'}, {k['drive']}")


def hover(c: Candidate) -> str:
    if "actuator" in c.components:
        return parts(c)
    ctl = c.own.get("controller") or {}
    return (parts(c) + f"<br>I-PD kp {ctl.get('kp', 0):.3g} A/m, ki {ctl.get('ki', 0):.3g} A/(m s), "
            f"kd {ctl.get('kd', 0):.3g} A s/m")


def comparison_picks(own: list[Candidate]) -> list[Candidate]:
    """Every catalog actuator and the two best simulated designs from parts."""
    return ([c for c in own if "actuator" in c.components]
            + [c for c in own if c.variant == "parts" and c.stage == "simulated"][:2])


def _parts_line(counts: dict) -> str:
    p = counts.get("dc_parts") or {}
    if not p.get("combinations"):
        return "no DC designs from parts"
    return (f"{p['combinations']} {COMBINATIONS} ({p['pruned']} ruled out by the "
            f"static screen, {p['simulated']} verified by simulation)")


def counts_words(results: dict) -> str:
    n = sum(1 for c in results["candidates"] if c.technology == "dc_motor" and "actuator" in c.components)
    return f"{n} catalog DC actuator{'' if n == 1 else 's'};\n{_parts_line(results['counts'])}"


def pruned_words(results: dict) -> str:
    """Combinations ruled out by the static screen, by motor and the
    requirement that rules them out (the smallest margin)."""
    pruned = [c for c in results["candidates"] if c.stage == "pruned" and c.variant == "parts"]
    if not pruned:
        return ""
    rows = ruled_out_by_part(pruned, "motor")
    return (f"<p>{len(pruned)} {COMBINATIONS} were ruled out by the static screen "
            f"(force through screw and gear, back-EMF speed at the drive voltage, winding temperature at the "
            f"holding current, buckling, life). By motor and the requirement that rules them out:</p>"
            f"<table><tr><th class='l'>motor</th><th class='l'>ruled out by</th><th>combinations</th></tr>{rows}</table>")


PRESENTATION = Presentation(
    markers=(Marker("catalog", "DC motor", "diamond", "diamond-open", "#d62728", size=13),
             Marker("parts", "DC motor from parts", "triangle-up", "triangle-up-open", "#ff7f0e", stages=SIZED_STAGES)),
    front_color="#d62728", trace_dash="dash", hover=hover, parts=parts, comparison_picks=comparison_picks,
    counts_words=counts_words, pruned_words=pruned_words,
)
