"""How the report shows piezo pump designs (``Presentation``): cyan stars,
the stacks, pump, valve and drive in the design table."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..presentation import Marker, Presentation, shown

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def hover(c: Candidate) -> str:
    comp = c.components
    return f"{comp['n_stacks']} x {comp['stack']}"


def parts(c: Candidate) -> str:
    d, s = (c.design or {}), (c.static or {})
    return (f"pump: {d.get('n_stacks')} x {d.get('stack')} at {shown(d.get('pump_frequency'), fmt='{:.0f}')} Hz, "
            f"piston {shown(d.get('pump_diameter'), 1e3, '{:.0f}')} mm, bore {shown(d.get('cylinder_diameter'), 1e3, '{:.0f}')} mm, "
            f"{d.get('valve')}, bias {shown(d.get('bias_pressure'), 1e-6, '{:.2g}')} MPa, "
            f"{shown(s.get('output_power_W'), fmt='{:.0f}')} W out, {shown(s.get('amplifier_power_VA'), fmt='{:.0f}')} VA drive, {d.get('amplifier')}")


PRESENTATION = Presentation(
    markers=(Marker(None, "piezo pump", "star", "star-open", "#17becf"),),
    hover=hover, parts=parts,
)
