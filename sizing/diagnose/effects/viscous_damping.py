"""Viscous damping: a force proportional to the output speed (seal
lubrication films, oil shear in the narrow bore) that the seed's model
leaves out (it has only the flow loss of eqs. 8-9).

Model: F = -c u on the output piston. Sizes: 200 and 600 N s/m, so that at
the 10-50 mm/s of the test runs the force is a few newtons, comparable to
the seal friction.
"""
from __future__ import annotations

from .base import Effect, Param


VISCOUS = Effect(
    name="viscous_damping", technology="piezohydraulic",
    params=(Param("viscous_damping_N_s_m", 1.0, 1e4, log=True, doc="viscous damping of the output piston"),),
    sizes=({"viscous_damping_N_s_m": 200.0}, {"viscous_damping_N_s_m": 600.0}),
    fields={"viscous_damping_N_s_m": "viscous_damping"},
    source="linear viscous friction of a lubricated seal (Merritt 1967, sec. 6)")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (VISCOUS,)
