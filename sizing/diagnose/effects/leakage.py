"""Leakage past the wide piston seal: a laminar flow Q = G p out of the
pressurised oil column, so under load the output drifts back.

Model: V_leak' = G p in the oil spring. Sizes: G = 1e-13 and 4e-13
m^3/(s Pa): at 0.1-0.2 MPa a drift of 0.1-1 mm/s of a 9.5 mm bore, the order
of a worn PTFE seal. Visible only when the run loads the oil.
"""
from __future__ import annotations

from .base import Effect, Param


EFFECT = Effect(
    name="leakage", technology="piezohydraulic",
    params=(Param("leak_conductance_m3_s_Pa", 1e-15, 1e-11, log=True, doc="laminar leak conductance"),),
    sizes=({"leak_conductance_m3_s_Pa": 1e-13}, {"leak_conductance_m3_s_Pa": 4e-13}),
    fields={"leak_conductance_m3_s_Pa": "leak_conductance"},
    source="laminar annular leakage, Q = G dp (Merritt 1967, sec. 3)")
