"""The solve report: one self-contained HTML file (plotly.js embedded once,
no network access when opened)."""
from __future__ import annotations

import html
from typing import TYPE_CHECKING

from ..display import requirement as display_requirement
from ..engine.comparison import format_metric
from .text import knife_edge_text
from .words import tech_label
from . import plain
from .bundle import plotly_tag

from ..technologies.presentation import shown as _num
from ..technologies.registry import presentation, technologies
from .figures import MARGIN_ORDER, comparison_figure, pareto_figure, traces_figure

if TYPE_CHECKING:
    from ..engine.candidate import Candidate

CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;margin:2em auto;max-width:1200px;color:#222;padding:0 1em}
table{border-collapse:collapse;margin:0.6em 0;font-size:0.86em}
td,th{border:1px solid #ccc;padding:3px 6px;text-align:right}
th{background:#f3f3f3}
td.l,th.l{text-align:left}
td.id{text-align:left;white-space:nowrap;font-family:monospace;font-size:0.95em}
.scroll{overflow-x:auto}
td.parts{text-align:left;min-width:30em}
.neg{background:#fbdada}.drv{font-weight:bold;outline:2px solid #444}
.box{border-left:6px solid #d62728;background:#fff4f4;padding:0.6em 1em;margin:1em 0}
.ok{border-left-color:#2ca02c;background:#f3fbf3}
.stamp{font-family:monospace;font-size:0.8em;color:#555}
.words{font-size:0.9em;color:#444}
ul.ruled details{display:inline;color:#555}ul.ruled summary{display:inline;cursor:pointer;font-size:0.9em}
"""

CHECKS = {
    "stroke": "simulated stroke from the loaded rest (static: free stroke R d33 V) against the required stroke",
    "blocked_force": "blocked force with the whole force path in series (stacks, base plate, frame, wide piston, oil, "
                     "compensator, end cap, narrow piston), less the seal friction at the blocked pressure",
    "amplifier_continuous_current": "the amplifier units' continuous rating against the rms current of the duty "
                                    "(two ramps of n C_large V / t_ramp per cycle, [duty])",
    "amplifier_units": "amplifier units in parallel allowed (options.max_amplifier_units) against the units the ramp "
                       "and the duty need",
    "stack_temperature": "stack rating against the required temperature plus its self-heating at the duty",
    "wide_gap": "wide oil gap against the stack stroke plus 0.5 mm clearance and 0.1 mm tolerance",
    "packing": "stacks that fit under the wide piston (circle packing, 1 mm spacing) against the stack count",
    "compensator_capacity": "compensator capacity against the hydraulic volume change it takes up",
    "compensator_hold": "orifice compensator: output creep under the largest load over the hold time ([duty] hold_time)",
    "speed": "required stroke / simulated time to reach it, slowest load case (static: planned drive ramp)",
    "temperature": "every actuator component's rating (stacks, fluid, seals; DC actuator) against the required maximum",
    "amplifier_temperature": "amplifier rating against where it sits (electronics bay or actuator, see assumptions)",
    "pressure": "seal pressure rating against the blocked pressure in the wide chamber",
    "drive_current": "amplifier units' current (peak within its rated pulse, else continuous) against n C_large dV/dt "
                     "needed to reach the stroke in time",
    "natural_frequency": "sqrt(k / (m_wide + R^2 m_narrow)) with the fluid spring, against the minimum",
    "overshoot": "simulated overshoot against the allowed overshoot",
    "thermal_drift": "net of the thermal budget (oil, casing, stacks, pistons, frame, compensator) against the allowed drift",
    "holding_force": "DC actuator continuous force against the largest load case",
    "work": "work bound n k_s (d33 V)^2 >= F S",
    "amplifier_voltage": "amplifier voltage against the voltage the work bound needs",
}


def _e(x) -> str:
    return html.escape(str(x))


def _margin_table(cands: list[Candidate]) -> str:
    keys = [k for k in MARGIN_ORDER if any(k in c.margins for c in cands)]
    keys += sorted({k for c in cands for k in c.margins} - set(keys))
    head = "".join(f"<th>{_e(k)}</th>" for k in keys)
    rows = []
    for c in cands:
        cells = []
        for k in keys:
            v = c.margins.get(k, "")
            cls = []
            if isinstance(v, float) and v < 0:
                cls.append("neg")
            if k == c.driver:
                cls.append("drv")
            text = "" if v == "" else ("n/a" if v is None else f"{v:+.1%}")
            cells.append(f"<td class='{' '.join(cls)}'>{text}</td>")
        rows.append(f"<tr><td>{c.rank}</td>{design_cell(c.id, c.name)}"
                    f"<td>{'yes' if c.feasible else 'no'}</td><td class='l'>{_e(c.driver)}</td>{''.join(cells)}</tr>")
    return (f"<div class='scroll'><table><tr><th>rank</th><th class='l'>design</th><th>feasible</th>"
            f"<th class='l'>driver</th>{head}</tr>" + "".join(rows) + "</table></div>")


def design_cell(ident: str, name: str | None) -> str:
    """A design's short name; its full id (the parts list) on hover."""
    return f"<td class='id' title='{_e(ident)}'>{_e(name or ident)}</td>"


def _design_table(cands: list[Candidate]) -> str:
    rows = []
    for c in cands:
        m, s, sim = c.metrics, c.static, c.simulated
        words = presentation(c.technology).parts
        if words is not None:
            parts = words(c)
        else:                       # no table of parts of its own: its parts by kind
            parts = f"{tech_label(c.technology)}: " + ", ".join(f"{v}" for v in c.components.values())
        rows.append(
            f"<tr><td>{c.rank}</td>{design_cell(c.id, c.name)}<td class='parts'>{_e(parts)}</td>"
            f"<td>{_num(m.get('mass_kg'), fmt='{:.1f}')}</td><td>{_num(m.get('cost_usd'), fmt='{:,.0f}')}</td>"
            f"<td>{_num(m.get('volume_m3'), 1e3, '{:.2f}')}</td><td>{_num(m.get('power_W'), fmt='{:.0f}')}</td>"
            f"<td>{_num(s.get('free_stroke_m'), 1e3, '{:.1f}')}</td>"
            f"<td>{_num(s.get('blocked_force_compliant_N', s.get('blocked_force_N')), fmt='{:.0f}')}</td>"
            f"<td>{_num(sim.get('stroke_m'), 1e3, '{:.1f}')}</td><td>{_num(sim.get('speed_m_s'), 1e3, '{:.0f}')}</td>"
            f"<td>{_num(sim.get('overshoot'), 100, '{:.1f}')}</td></tr>")
    return ("<div class='scroll'><table><tr><th>rank</th><th class='l'>design</th><th class='l'>parts</th><th>mass kg</th><th>cost USD</th>"
            "<th>volume L</th><th>power W</th><th>static stroke mm</th><th>blocked force N (compliant)</th>"
            "<th>sim. stroke mm</th><th>sim. speed mm/s</th><th>overshoot %</th></tr>" + "".join(rows) + "</table></div>")


def _checks_table(cands: list[Candidate]) -> str:
    """The physics checks beyond the seed, with their values."""
    rows = []
    for c in cands:
        if not presentation(c.technology).checks_table or not c.static:
            continue
        s, f = c.static, c.own.get("fluid_at_temperature", {})
        temps = "; ".join(f"{k} {v['rated_degC']:g}/{v['required_degC']:g}" for k, v in c.own.get("temperatures", {}).items())
        rows.append(
            f"<tr>{design_cell(c.id, c.name)}<td>{_num(s.get('blocked_pressure_Pa'), 1e-6, '{:.1f}')}</td>"
            f"<td>{_num(s.get('compliance_force_fraction'), 100, '{:.0f}')}</td>"
            f"<td>{_num(s.get('required_current_A'), fmt='{:.2f}')}</td>"
            f"<td>{_num(s.get('natural_frequency_Hz'), fmt='{:.0f}')}</td>"
            f"<td>{_num(c.simulated.get('overshoot'), 100, '{:.1f}')}</td>"
            f"<td>{_num(f.get('kinematic_viscosity_m2_s'), 1e6, '{:.2f}')}</td>"
            f"<td>{_num(f.get('bulk_modulus_Pa'), 1e-9, '{:.2f}')}</td>"
            f"<td>{_num(s.get('thermal_drift_m'), 1e3, '{:.1f}')}</td><td class='l'>{_e(temps)}</td></tr>")
    return ("<div class='scroll'><table><tr><th class='l'>design</th><th>blocked pressure MPa</th><th>force kept with fluid compliance %</th>"
            "<th>drive current needed A</th><th>natural freq. Hz</th><th>sim. overshoot %</th>"
            "<th>viscosity at T mm&sup2;/s</th><th>bulk modulus at T GPa</th><th>thermal drift mm</th>"
            "<th class='l'>rated/required degC</th></tr>" + "".join(rows) + "</table></div>")


def _pruned_table(results: dict) -> str:
    """What each technology's screen ruled out before sizing."""
    return "".join(t.report.pruned_words(results) for t in technologies())


def _changes(results: dict, limit: int = 60) -> str:
    changes = results.get("changes")
    if changes is None:
        return ""
    if not changes:
        return "<h2>What changed</h2><p>Nothing changed against the baseline.</p>"
    names = {c.id: c.name or c.id for c in results.get("candidates", [])}
    items = []
    for ch in changes[:limit]:
        text = ch.get("summary") or ", ".join(f"{k}: {v}" for k, v in ch.items() if k != "id")
        cid = ch.get("id", "")
        items.append(f"<li><b title='{_e(cid)}'>{_e(names.get(cid) or ch.get('name') or cid)}</b>: {_e(text)}</li>")
    more = f"<p>... and {len(changes) - limit} more in results.json (\"changes\").</p>" if len(changes) > limit else ""
    summary = results.get("changes_summary") or {}
    cause = summary.get("text")
    lead = f"<div class='box'><b>{_e(cause)}</b></div>" if cause else ""
    if summary.get("answer"):
        lead = (f"<div class='box'><b>{_e(summary['answer'])}</b><ul>"
                + "".join(f"<li>{_e(t)}</li>" for t in summary.get("technologies", [])) + "</ul>"
                + _e(cause.split(". ")[-1]) + "</div>")
    return (f"<h2>What changed</h2>{lead}<p>{len(changes)} candidates changed standing against the baseline "
            f"(most important first):</p><ul>{''.join(items)}</ul>{more}")


def _requirement_value(requirement: str, value) -> str:
    """A figure compared with a requirement, in that requirement's unit."""
    return display_requirement(requirement, value)


def _pick_comparison(cands: list[Candidate]) -> list[Candidate]:
    """The designs the comparison shows: each technology's own picks (its
    best design when it names none), in the technologies' order."""
    picks = []
    for t in technologies():
        own = [c for c in cands if c.technology == t.name]
        picks += t.report.comparison_picks(own) if t.report.comparison_picks is not None else own[:1]
    return picks


def _comparison_titles() -> tuple[str, str]:
    """The comparison section's heading and its figure's title: those of the
    technology the others are compared against."""
    return next((t.report.comparison_titles for t in technologies() if t.report.comparison_titles),
                ("The best designs compared", "best designs of each technology"))


def _counts_words(results: dict) -> str:
    """Each technology's counts, as it states them."""
    return " and\n".join(t.report.counts_words(results) for t in technologies() if t.report.counts_words is not None)


def _answer(summary: dict) -> str:
    """The first section: per technology its best design, binding check,
    what it rests on and what would flip its verdict; what was ruled out."""
    techs = summary.get("comparison", {}).get("technologies", {})
    if not techs:
        return ""
    rows = []
    for tech, t in techs.items():
        metrics = ", ".join(format_metric(k, v) for k, v in t.get("metrics", {}).items())
        margin = t.get("binding_margin")
        binding = f"{_e(t.get('binding'))} ({margin:+.1%})" if margin is not None else _e(t.get("binding"))
        if t.get("p_compliance") is not None:
            lo, hi = t.get("p_ci95") or (None, None)
            interval = f" [{lo:.0%}, {hi:.0%}]" if lo is not None else ""
            binding += f"<br>complies in {t['p_compliance']:.0%}{interval} of robust samples"
        binding += _compliance_cell(t)
        deciding = t.get("deciding_assumed_words") or t.get("deciding_assumed") or []
        rests = (f"{len(t.get('rests_on_assumed') or [])} assumed values; in its binding margin: "
                 + (_e("; ".join(deciding)) if deciding else "none"))
        flip = _flips_cell(t)
        rows.append(f"<tr><td class='l'><b>{_e(tech_label(tech))}</b></td><td class='l'>{'feasible' if t.get('feasible') else 'infeasible'}"
                    f"</td><td class='l' title='{_e(t.get('best'))}'><b>{_e(t.get('name') or t.get('best'))}</b>"
                    f"{_description(t)}<br>{_e(metrics)}</td>"
                    f"<td class='l'>{binding}</td>"
                    f"<td class='l'>{rests}</td><td class='l'>{flip}</td></tr>")
    by_tech = summary.get("ruled_out_by_technology") or {"": summary.get("ruled_out") or {}}
    ruled_text = _ruled_out_text(by_tech, summary.get("counts") or {})
    sourced = (summary.get("dc_sourced") or {}).get("text")
    if sourced:
        ruled_text = f"{_e(sourced)}</p><p>{ruled_text}"
    advice = summary.get("comparison", {}).get("recommendation")
    box = f"<div class='box ok'><b>{_e(advice)}</b></div>" if advice else ""
    knife = knife_edge_text(summary.get("comparison", {}))
    if knife:
        box += f"<div class='box warn'>{_e(knife)}</div>"
    return ("<h2>The answer</h2>" + box + "<table><tr><th class='l'>technology</th><th class='l'>verdict</th>"
            "<th class='l'>best design</th><th class='l'>binding check</th><th class='l'>rests on</th>"
            "<th class='l'>what would flip the verdict</th></tr>" + "".join(rows) + f"</table><p>{ruled_text}</p>")


def _compliance_cell(t: dict) -> str:
    """A technology's best under tolerance (studies/compliance.py) and its
    knife edges, for the answer table."""
    c = t.get("compliance") or {}
    out = ""
    if c.get("p") is not None:
        out += (f"<br>complies in {c['p']:.0%} [{c['low']:.0%}, {c['high']:.0%}] of {c['samples']} samples "
                "under tolerance")
    elif c.get("method"):
        out += f"<br>{_e(c['method'])}"
    edges = t.get("knife_edges") or {}
    if edges:
        out += "<br><b>knife edge</b>: " + _e(", ".join(f"{k} {v:+.2%}" for k, v in edges.items()))
    return out


def _description(t: dict) -> str:
    """The best design in words (parts by maker and model, key dimensions)."""
    return f"<br><span class='words'>{_e(t['description'])}</span>" if t.get("description") else ""


def _flips_cell(t: dict) -> str:
    """What would flip a technology's verdict (and the recommendation), in
    people's units: each value that flips, then the ranges where none does."""
    from ..engine.flip import flip_text
    flips = t.get("flips")
    if flips is None:
        return "not computed (solve --fast)" if "flips" in t else (_e(t["flip"]["text"]) if t.get("flip") else "none known")
    found = sorted((f for f in flips if f.get("to") is not None), key=lambda f: f["changes"] != "feasibility")
    none = [f for f in flips if f.get("to") is None]
    return "<br>".join([_e(flip_text(f)) for f in found] + [_e(flip_text(f)) for f in none]) or "nothing examined"


def _ruled_out_text(by_tech: dict, counts: dict | None = None) -> str:
    """Per technology, how many combinations were ruled out before sizing
    and how many designs were left out before ranking (``summary.counts``)
    and the three checks that left out most; the whole count by check one
    click away."""
    lines = []
    for tech, reasons in by_tech.items():
        if not reasons:
            continue
        top = sorted(reasons.items(), key=lambda kv: -kv[1])
        head = ", ".join(f"{_e(k)} {v:,}" for k, v in top[:3]) + (f", {len(top) - 3} other checks" if len(top) > 3 else "")
        rest = ", ".join(f"{_e(k)} {v:,}" for k, v in top)
        own = (counts or {}).get(tech) or {}
        if own.get("ruled_out_before_sizing"):
            total = (f"{own['ruled_out_before_sizing']:,} of {own['combinations']:,} combinations ruled out before "
                     f"sizing, {own['left_out']:,} designs left out after")
        elif "left_out" in own:            # no sizing stage: the screen and the simulation leave them out
            total = f"{own['left_out']:,} of {own['combinations']:,} combinations left out"
        else:
            total = f"{sum(reasons.values()):,}"
        lines.append(f"<li><b>{_e(tech_label(tech) if tech else 'all')}</b>: {total} "
                     f"({head}) <details><summary>every check</summary>{rest}</details></li>")
    if not lines:
        return ""
    return ("Left out before ranking, by the check each misses most:</p><ul class='ruled'>" + "".join(lines)
            + "</ul><p>")


def _names(cands: list[Candidate], ids: list[str]) -> list[str]:
    """Short names of the candidates ``ids``, in order (the id where none)."""
    by_id = {c.id: c.name or c.id for c in cands}
    return [by_id.get(i, i) for i in ids]


def _figure_div(fig: dict) -> str:
    """A figure of a technology's own section (plotly's JSON, ``report.plain``), without plotly.js."""
    return plain.div(fig, config={"displaylogo": False})


def render(results: dict, traces: list[dict]) -> str:
    """report.html of a solve's results (its candidates ``Candidate``s)."""
    cands = results["candidates"]
    heading, title = _comparison_titles()
    figs = [pareto_figure(results), traces_figure(results, traces),
            comparison_figure(results, _pick_comparison(cands), title)]
    divs = [plain.div(f, div_id=f"plot-{i}", config={"displaylogo": False, "responsive": True})
            for i, f in enumerate(figs)]
    req = results["requirements"]
    summary = results["summary"]
    feasible = [c for c in cands if c.feasible]
    top = feasible[:10]
    shown_ids = {c.id for c in top}
    best_each = []
    for g in summary["groups"]:
        for key in ("best", "closest"):
            cid = g.get(key)
            if cid and cid not in shown_ids:
                best_each.extend(c for c in cands if c.id == cid)
                shown_ids.add(cid)
    verdicts = "".join(f"<li><b>{_e(g['label'])}</b>: {_e(g['text'])}</li>" for g in summary["groups"])
    headline = ("<div class='box ok'>" + f"{len(feasible)} feasible designs; Pareto front: "
                + _e(", ".join(_names(cands, summary["pareto"])) or "empty") + "</div>") if feasible else (
        "<div class='box'><b>No design meets every requirement.</b> What blocks each technology is listed below.</div>")
    comp = [c for c in cands if c.variant == "compensated" and c.stage != "pruned"][:10]
    as_built = [c for c in cands if c.variant == "uncompensated" and c.stage not in ("pruned",)][:10]
    checks = "".join(f"<li><b>{_e(k)}</b>: {_e(v)}</li>" for k, v in CHECKS.items())
    assumptions = "".join(f"<li>{_e(a)}</li>" for a in results["assumptions"])
    dis = results["disagreements"]
    short = {c.id: c.name for c in results.get("candidates", [])}
    dis_html = ("<p>The static screen and the simulation agree within 10 % on stroke and speed for every "
                "simulated design, and never disagree on a verdict.</p>" if not dis else
                "<table><tr><th class='l'>design</th><th class='l'>requirement</th><th>static</th><th>simulated</th>"
                "<th>static margin</th><th>simulated margin</th><th>verdict changes</th></tr>" + "".join(
                    f"<tr>{design_cell(d['id'], d.get('name') or short.get(d['id']))}<td class='l'>{_e(d['requirement'])}</td>"
                    f"<td>{_e(_requirement_value(d['requirement'], d['static']))}</td>"
                    f"<td>{_e(_requirement_value(d['requirement'], d['simulated']))}</td><td>{d['static_margin']:+.1%}</td>"
                    f"<td>{d['simulated_margin']:+.1%}</td><td>{'yes' if d['verdict_changes'] else 'no'}</td></tr>"
                    for d in dis[:50]) + "</table>")
    loads = ", ".join(f"{c['load_N']:.0f} N" + (f" ({c['dynamic_pressure_Pa'] / 1e3:g} kPa)" if "dynamic_pressure_Pa" in c else "")
                      for c in results["load_cases"])
    stamp = (f"sizing {_e(results['tool_version'])} &middot; requirements sha256 {_e(results['requirements_sha256'])}"
             f" &middot; catalog sha256 {_e(results['catalog_sha256'])} &middot; solved in {results.get('runtime_s', 0):.1f} s")
    body = f"""
<h1>Sizing report</h1>
<p class="stamp">{stamp}</p>
{_answer(summary)}
<p>Requirements: stroke {req['stroke_m'] * 1e3:g} mm, blocked force {req['blocked_force_N'] / 1e3:g} kN,
speed {req['speed_m_s'] * 1e3:g} mm/s (stroke within {req['stroke_time_s']:g} s), every component to
{req['max_temperature_degC']:g} degC. Load cases: {_e(loads)}. Objectives: minimise {_e(', '.join(results['objectives']))}.
{_counts_words(results)}.</p>
{headline}
<h2>Verdict per technology</h2><ul>{verdicts}</ul>
<div class="box ok"><b>Technologies compared</b> (best of each, its binding check, and the ratio of their objectives):
{_e(summary.get('comparison', {}).get('text', ''))}</div>
<h2>100 degC: the thermal budget</h2>
<div class="box">{_e(summary['thermal'])}</div>
<h2>Pareto front</h2>{divs[0]}
<h2>Margins per requirement</h2>
<p>Margin = achieved / required - 1 (ceilings: 1 - achieved / allowed); below zero the requirement is missed
(red). The outlined cell is the design driver, the smallest margin. Simulated figures replace static ones where
they exist. Top feasible designs, then the best candidate of each technology:</p>
{_margin_table(top + best_each)}
{_design_table(top + best_each)}
<h2>Compensated designs (thermal compensator assumed)</h2>
{_margin_table(comp) if comp else '<p>None evaluated.</p>'}
<h2>Uncompensated designs (as built)</h2>
{_margin_table(as_built) if as_built else '<p>No combination reached sizing.</p>'}
{"".join(t.report.section(cands, _figure_div) for t in technologies())}
<h2>Checks beyond the seed</h2><ul>{checks}</ul>
{_checks_table(top + best_each)}
<h2>Time traces under each load case</h2>{divs[1]}
<h2>{_e(heading)}</h2>{divs[2]}
{_margin_table(_pick_comparison(cands))}
<h2>Where the static screen and the simulation disagree</h2>{dis_html}
<h2>Ruled out before sizing</h2>{_pruned_table(results)}
{_changes(results)}
<h2>Assumptions</h2><ul>{assumptions}</ul>
"""
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>sizing report</title><style>{CSS}</style>"
            f"{plotly_tag()}</head><body>{body}</body></html>")
