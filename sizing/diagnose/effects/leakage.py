"""Leakage past the wide piston seal: a laminar flow Q = G p out of the
pressurised oil column, so under load the output drifts back.

Model: V_leak' = G p in the oil spring. Sizes: G = 1e-13 and 4e-13
m^3/(s Pa): at 0.1-0.2 MPa a drift of 0.1-1 mm/s of a 9.5 mm bore, the order
of a worn PTFE seal. Visible only when the run loads the oil.

Form "orifice" (laminar and orifice leakage): a damaged seal or a scratch
across it leaks through a short passage, turbulent, Q = G p + Cd A sgn(p)
sqrt(2 |p| / rho) (Merritt 1967, sec. 3.2 orifice flow; laminar as above):
it grows with the square root of the pressure, so it matters most at low
pressure. Sizes: G = 1e-13 with Cd A = 5e-11 m^2, and G = 1e-14 with
Cd A = 2e-10 m^2 (a 10-20 um scratch across the seal lip, Cd 0.6).
"""
from __future__ import annotations

from .base import Effect, Param


LAMINAR = Effect(
    form="laminar",
    name="leakage", technology="piezohydraulic",
    params=(Param("leak_conductance_m3_s_Pa", 1e-15, 1e-11, log=True, doc="laminar leak conductance"),),
    sizes=({"leak_conductance_m3_s_Pa": 1e-13}, {"leak_conductance_m3_s_Pa": 4e-13}),
    fields={"leak_conductance_m3_s_Pa": "leak_conductance"},
    source="laminar annular leakage, Q = G dp (Merritt 1967, sec. 3)")


ORIFICE = Effect(
    name="leakage", technology="piezohydraulic", form="orifice",
    params=(Param("leak_conductance_m3_s_Pa", 1e-15, 1e-11, log=True, doc="laminar leak conductance"),
            Param("orifice_area_m2", 1e-13, 1e-8, log=True, doc="discharge coefficient x area of the orifice leak")),
    sizes=({"leak_conductance_m3_s_Pa": 1e-13, "orifice_area_m2": 5e-11},
           {"leak_conductance_m3_s_Pa": 1e-14, "orifice_area_m2": 2e-10}),
    fields={"leak_conductance_m3_s_Pa": "leak_conductance", "orifice_area_m2": "leak_orifice_area"},
    source="laminar plus orifice leakage, Q = G p + Cd A sqrt(2 p / rho) (Merritt 1967, sec. 3)")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (LAMINAR, ORIFICE)
