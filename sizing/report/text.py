"""Plain-text summaries for the terminal."""
from __future__ import annotations

from ..display import interval, label, number, of_kind, quantity
from ..io.catalog import Catalog, Entry



def _fmt(key: str, value) -> str:
    return quantity(key, value)


def _label(key: str) -> str:
    return label(key)


def evaluation_summary(result: dict) -> str:
    lines = [f"{result['technology']} design: " + ", ".join(
        f"{k}={number(v) if isinstance(v, float) else v}" for k, v in result["design"].items()
        if not isinstance(v, dict) and v is not None)]
    lines.append("static:")
    lines += [f"  {_label(k):<28} {_fmt(k, v)}" for k, v in result["static"].items()]
    if result.get("controller"):
        lines.append("controller: " + ", ".join(f"{k} {_fmt(k, v)}" for k, v in result["controller"].items()))
    lines.append("simulated (per load case):")
    for case in result["simulated"]["cases"]:
        lines.append("  load " + _fmt("load_N", case["load_N"]) + ": " + ", ".join(
            f"{_label(k)} {_fmt(k, v)}" for k, v in case.items()
            if k in ("stroke_m", "time_to_stroke_s", "speed_m_s", "overshoot", "peak_speed_m_s", "max_speed_m_s")))
    for key in ("rms_current_A", "winding_temperature_degC"):
        if key in result["simulated"]:
            lines.append(f"  {_label(key):<28} {_fmt(key, result['simulated'][key])}")
    if result.get("margins"):
        lines.append("margins: " + ", ".join(f"{k} {v:+.1%}" if v is not None else f"{k} missed (no value)"
                                             for k, v in result["margins"].items()))
    if "feasible" in result:
        judged = result.get("judged", {})
        lines.append(f"against {judged.get('requirements', 'the requirements')}: "
                     + ("feasible" if result["feasible"] else "infeasible")
                     + (f" (binding check {result['driver']})" if result.get("driver") else ""))
    lines.append("metrics: " + ", ".join(f"{_label(k)} {_fmt(k, v)}" for k, v in result["metrics"].items()))
    if result.get("force_path"):
        lines.append("force path (in series, referred to the wide piston; share of the compliance):")
        lines += [f"  {m['member']:<14} {m['stiffness_N_m'] or float('inf'):10.3g} N/m  {m['compliance_share']:6.1%}"
                  + (f"  {m['material']}" if m.get("material") else "") for m in result["force_path"]]
    for warning in [w for w in result.get("warnings", []) if w.startswith("cannot be built")]:
        lines.append(warning)
    if result.get("assumed"):
        lines.append("rests on assumed catalog values (status \"assumed\"; see `sizing catalog show ID`):")
        lines += [f"  {entry_id}: {', '.join(fields)}" for entry_id, fields in result["assumed"].items()]
    return "\n".join(lines)


def catalog_table(catalog: Catalog) -> str:
    rows = [(e.id, kind, e.name, e.retrieved.isoformat(), str(len(e.assumed()))) for kind, e in catalog.entries()]
    header = ("id", "kind", "name", "retrieved", "assumed")
    widths = [max(len(r[i]) for r in rows + [header]) for i in range(len(header))]
    fmt = "  ".join(f"{{:<{w}}}" for w in widths)
    return "\n".join([fmt.format(*header)] + [fmt.format(*r) for r in rows])


# what the status in brackets after each value means (README, "The catalog")
STATUS_WORDS = {"datasheet": "read from the vendor document named in source",
                "seed": "from the seed report ARL-TR-10251",
                "measured": "fitted to test data (sizing fit)",
                "sourced": "from the makers' table named in source",
                "rule": "derived by a stated rule from sourced values",
                "assumed": "an engineering estimate, its reason given",
                "default": "not given in the catalog file: the schema's default"}


def entry_details(kind: str, entry: Entry) -> str:
    """Every value of a catalog entry in the unit an engineer reads it, its
    status in brackets and, at the end, what each status shown means."""
    from ..io.catalog_diff import quantity_kind
    lines = [f"{entry.id} ({kind}): {entry.name}", f"  manufacturer: {entry.manufacturer}",
             f"  source: {entry.source}", f"  retrieved: {entry.retrieved.isoformat()}"]
    shown = set()
    for name in entry.quantity_fields():
        value = getattr(entry, name)
        if value is None:
            continue
        status = entry.status.get(name, "default")
        shown.add(status.partition(":")[0].strip())
        text = of_kind(value, quantity_kind(type(entry), name), name) if isinstance(value, (int, float)) else str(value)
        lines.append(f"  {name:<36} {text:<14} [{status}]")
    for sub in ("bouc_wen", "pid"):
        table = getattr(entry, sub, None)
        if table is not None:
            lines.append(f"  [{sub}] " + ", ".join(f"{k} = {number(v)}" for k, v in table.model_dump().items()))
    if entry.notes:
        lines.append(f"  notes: {entry.notes}")
    lines.append("status: " + "; ".join(f"{s} = {STATUS_WORDS[s]}" for s in STATUS_WORDS if s in shown))
    return "\n".join(lines)


def knife_edge_text(comparison: dict) -> str:
    """The margins under ``KNIFE_EDGE`` (sizing/settings.py) of the
    recommended design and of each technology's best (``knife_edges``,
    studies/compliance.py), one line; "" when there are none."""
    from ..settings import KNIFE_EDGE
    rec = comparison.get("recommended") or {}
    entries = [(rec.get("name"), rec.get("knife_edges"))]
    entries += [(t.get("name"), t.get("knife_edges")) for t in comparison.get("technologies", {}).values()]
    parts, named = [], set()
    for name, edges in entries:
        if edges and name not in named:
            named.add(name)
            parts.append(f"{name}: " + ", ".join(f"{k} {v:+.2%}" for k, v in edges.items()))
    return f"knife edges (checks met by less than {100 * KNIFE_EDGE:g} %): " + "; ".join(parts) if parts else ""


# units of the fitted parameters (seed eq. 1-2 and 13-14; docs/formats.md);
# beta and gamma are in SI (1/m^(n-1)), n is a plain number
FIT_UNITS = {"d33": "m/V", "alpha": "m/V", "delta": "m/V", "c1": "1/s", "c2": "rad/(s^2 A)",
             "kp": "A/m", "ki": "A/(m s)", "kd": "A s/m"}


def _percent(x) -> str:
    return "n/a" if x is None else f"{100 * x:.2f} %"


def _parameter_rows(params: dict, ci95: dict, plain: dict | None = None) -> list[str]:
    rows = []
    for name, value in params.items():
        lo, hi = ci95.get(name) or (None, None)
        unit = FIT_UNITS.get(name, "")
        text = f"  {name:<6} {number(value):>10} {unit:<12} 95 % interval {interval(lo, hi)}"
        if plain is not None and name in plain:
            text += f"; plain least squares {number(plain[name])}"
        rows.append(text.rstrip())
    return rows


def fit_summary(kind: str, result: dict) -> str:
    """What ``sizing fit`` found, before any warning: the model carried, its
    held-out NRMSE (share of the measured range) and the parameters with
    their 95 % intervals."""
    summary = result["summary"]
    held = any(s.get("nrmse_holdout") is not None for s in summary.values())
    which = "held-out" if held else "training"
    score = ", ".join(f"{m} {_percent(s.get('nrmse_holdout') if held else s.get('nrmse_train'))}"
                      for m, s in summary.items())
    if kind != "hysteresis":
        return "\n".join([f"fit dc-motor: {which} NRMSE {score} of the measured range",
                          "parameters (seed eq. 13-14, through the closed loop):",
                          *_parameter_rows(result["params"], result["ci95"])])
    bw, pi = result["bouc_wen"], result.get("prandtl_ishlinskii") or {}
    operators = (f"Prandtl-Ishlinskii: {len(pi.get('weights_m_V', []))} play operators, weights in the TOML's "
                 "[prandtl_ishlinskii]") if pi else ""
    return "\n".join([f"model carried: {result['model']} ({which} NRMSE, share of the measured range: {score})",
                      *([operators] if operators else []),
                      "Bouc-Wen [stack] for a rig.toml, regularised toward the prior (beta, gamma SI; n a number):",
                      *_parameter_rows(bw["params"], bw["ci95"], bw.get("plain"))])
