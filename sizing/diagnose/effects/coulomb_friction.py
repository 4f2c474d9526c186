"""Coulomb friction of the screw and seals: the motor must overcome a
constant force before it moves, so the loop sticks short of the reference
and the integrator hunts.

Model: Karnopp friction in the plant (sizing.sim.dc_motor). Sizes: 20 and
60 N at the output, 1.4 % and 4 % of the 1.41 kN peak force of the seed's
actuator (ball-screw and rod-seal drag).
"""
from __future__ import annotations

from .base import Effect, Param


EFFECT = Effect(
    name="coulomb_friction", technology="dc_motor",
    params=(Param("coulomb_friction_N", 0.5, 500.0, log=True, doc="running friction at the output"),),
    sizes=({"coulomb_friction_N": 20.0}, {"coulomb_friction_N": 60.0}),
    fields={"coulomb_friction_N": "coulomb_friction"},
    source="Karnopp (1985); Olsson et al., Eur. J. Control 4 (1998) 176")
