"""Plain-text summaries for the terminal."""
from __future__ import annotations

from ..io.catalog import Catalog, Entry

_SCALES = {"_m": (1e3, "mm"), "_N": (1.0, "N"), "_Pa": (1e-6, "MPa"), "_Hz": (1.0, "Hz"),
           "_A": (1.0, "A"), "_s": (1.0, "s"), "_m_s": (1e3, "mm/s"), "_J": (1.0, "J"),
           "_kg": (1.0, "kg"), "_usd": (1.0, "USD"), "_m3": (1e6, "cm^3"), "_W": (1.0, "W"),
           "_N_m": (1.0, "N/m"), "_V": (1.0, "V")}


def _fmt(key: str, value) -> str:
    if value is None:
        return "n/a"
    if not isinstance(value, (int, float)):
        return str(value)
    for suffix in sorted(_SCALES, key=len, reverse=True):
        if key.endswith(suffix):
            scale, unit = _SCALES[suffix]
            return f"{value * scale:.4g} {unit}"
    return f"{value:.4g}"


def _label(key: str) -> str:
    for suffix in sorted(_SCALES, key=len, reverse=True):
        if key.endswith(suffix):
            key = key[: -len(suffix)]
            break
    return key.replace("_", " ")


def evaluation_summary(result: dict) -> str:
    lines = [f"{result['technology']} design: " + ", ".join(
        f"{k}={v}" for k, v in result["design"].items() if not isinstance(v, dict) and v is not None)]
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


def entry_details(kind: str, entry: Entry) -> str:
    lines = [f"{entry.id} ({kind}): {entry.name}", f"  manufacturer: {entry.manufacturer}",
             f"  source: {entry.source}", f"  retrieved: {entry.retrieved.isoformat()}"]
    for name in entry.quantity_fields():
        value = getattr(entry, name)
        if value is None:
            continue
        lines.append(f"  {name:<36} {value!r:<14} [{entry.status.get(name, '?')}]")
    for sub in ("bouc_wen", "pid"):
        table = getattr(entry, sub, None)
        if table is not None:
            lines.append(f"  [{sub}] " + ", ".join(f"{k}={v}" for k, v in table.model_dump().items()))
    if entry.notes:
        lines.append(f"  notes: {entry.notes}")
    return "\n".join(lines)


def knife_edge_text(comparison: dict) -> str:
    """The margins under 1 % of the recommended design and of each
    technology's best (``knife_edges``, studies/compliance.py), one line;
    "" when there are none."""
    rec = comparison.get("recommended") or {}
    entries = [(rec.get("name"), rec.get("knife_edges"))]
    entries += [(t.get("name"), t.get("knife_edges")) for t in comparison.get("technologies", {}).values()]
    parts, named = [], set()
    for name, edges in entries:
        if edges and name not in named:
            named.add(name)
            parts.append(f"{name}: " + ", ".join(f"{k} {v:+.2%}" for k, v in edges.items()))
    return "knife edges (checks met by less than 1 %): " + "; ".join(parts) if parts else ""
