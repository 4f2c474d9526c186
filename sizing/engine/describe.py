"""A design in words, beside its short name: the parts by maker and model
and the key dimensions, as an engineer would say it ("17 x PI P-056.90 PICA
high-power piezo stack actuator; ...; bores 504/33 mm (R = 233), 554 mm
long, 546 mm across"). Read from the candidate and the catalog only."""
from __future__ import annotations

from ..display import number


def _part(catalog, part_id) -> str:
    """The part's maker and model as the catalog names it, cut before its
    first comma or parenthesis; the id where the catalog does not hold it."""
    if not part_id:
        return ""
    try:
        _, entry = catalog.get(part_id)
    except (KeyError, AttributeError):
        return str(part_id)
    name = entry.name.split(",")[0].split(" (")[0].strip()
    maker = entry.manufacturer
    if maker.lower().startswith(("generic", "various", "qualified")) or name.split()[0].lower() in maker.lower():
        return name                         # the name already says who makes it
    return f"{maker.split(' (')[0].split(',')[0].strip()} {name}"


def _mm(value) -> str:
    return number(value * 1e3, 3) if isinstance(value, (int, float)) else "?"


def _piezohydraulic(c: dict, catalog) -> str:
    k, s = c["components"], c.get("static") or {}
    parts = [f"{k.get('n_stacks')} x {_part(catalog, k.get('stack'))}", _part(catalog, k.get("fluid")),
             _part(catalog, k.get("seal")), f"{_part(catalog, k.get('material'))} structure" if k.get("material") else "",
             _part(catalog, k.get("compensator")) if k.get("compensator") else ""]
    size = f"bores {_mm(s.get('wide_diameter_m'))}/{_mm(s.get('narrow_diameter_m'))} mm (R = {number(k.get('ratio'), 3)})"
    if s.get("length_m") and s.get("outer_diameter_m"):
        size += f", {_mm(s['length_m'])} mm long, {_mm(s['outer_diameter_m'])} mm across"
    units = s.get("amplifier_units")
    drive = f"{number(units, 3) if units else 1} x {_part(catalog, k.get('amplifier'))}"
    return "; ".join(p for p in parts + [size, f"driven by {drive}"] if p)


def _dc(c: dict, catalog) -> str:
    k, s = c["components"], c.get("static") or {}
    if "actuator" in k:
        return f"{_part(catalog, k['actuator'])}, stroke {_mm(s.get('stroke_m'))} mm"
    parts = [_part(catalog, k.get("motor")), _part(catalog, k.get("screw")),
             _part(catalog, k.get("gear")) if k.get("gear") else "no gear (direct drive)", _part(catalog, k.get("drive"))]
    lead = s.get("effective_lead_m")
    if lead:
        parts.append(f"{number(lead * 1e3, 3)} mm of travel per motor turn")
    return "; ".join(p for p in parts if p)


def _pump(c: dict, catalog) -> str:
    k, d, s = c["components"], c.get("design") or {}, c.get("static") or {}
    return "; ".join(p for p in (
        f"{k.get('n_stacks')} x {_part(catalog, k.get('stack'))} pumping at {number(d.get('pump_frequency'), 3)} Hz",
        f"{_mm(d.get('pump_diameter'))} mm piston into a {_mm(d.get('cylinder_diameter'))} mm bore cylinder",
        _part(catalog, k.get("valve")), _part(catalog, k.get("accumulator")),
        f"{number(s.get('output_power_W'), 3)} W out" if s.get("output_power_W") else "") if p)


def describe(c: dict, catalog) -> str:
    """Candidate ``c`` (results.json) in words ("" when it names no parts)."""
    if not c.get("components"):
        return ""
    tech = c.get("technology")
    if tech == "piezohydraulic":
        return _piezohydraulic(c, catalog)
    if tech == "piezo_pump":
        return _pump(c, catalog)
    return _dc(c, catalog)
