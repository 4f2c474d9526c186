"""Friction of the screw and seals: the motor must overcome a force before
it moves, so the loop sticks short of the reference and the integrator
hunts.

Three forms (sizing.sim.dc_motor):
- ``coulomb``: Karnopp friction with a constant running force (a piston at
  rest stays at rest while the net force is inside the band). Sizes: 20 and
  60 N at the output, 1.4 % and 4 % of the 1.41 kN peak force of the seed's
  actuator (ball-screw and rod-seal drag).
- ``stribeck``: the static (breakaway) force exceeds the running force and
  the friction falls from one to the other over a Stribeck velocity,
  F(v) = F_c + (F_s - F_c) exp(-(v / v_s)^2) (the steady-state curve of the
  LuGre model; Armstrong-Helouvry, Dupont and Canudas de Wit, Automatica 30
  (1994) 1083, survey: F_s / F_c of 1.1-2 and v_s of 0.1-10 mm/s for
  lubricated metal contacts and rod seals; Olsson et al., Eur. J. Control 4
  (1998) 176). Viscous friction is linear in the speed and is absorbed by the
  re-calibrated pole c1, so it needs no parameter of its own. Sizes: 20 N
  with F_s / F_c = 1.5 and v_s = 1 mm/s; 60 N with 1.25 and 10 mm/s.
- ``asymmetric``: Coulomb friction of another size in each direction
  (F+ while extending, F- while retracting: a rod seal whose lip faces one
  way, a screw nut preloaded on one flank; Armstrong-Helouvry et al. 1994,
  sec. 2, direction-dependent friction). Karnopp friction with running
  force (F+ + F-) / 2 and a constant force (F+ - F-) / 2 against extension
  is exactly this: moving out the motor overcomes F+, moving in F-, and at
  rest the band is [-F-, F+]; so the form is the nominal's load force plus
  that bias, no new simulator field (the one difference: the controller's
  integrator starts holding the bias, a real one starts inside the band).
  Sizes: 20 N out and 30 N in; 60 N and 45 N (asymmetries of 25-50 %).
"""
from __future__ import annotations

import numpy as np

from .base import Effect, Param

SOURCE = "Karnopp (1985); Olsson et al., Eur. J. Control 4 (1998) 176"

COULOMB = Effect(
    name="coulomb_friction", technology="dc_motor", form="coulomb",
    params=(Param("coulomb_friction_N", 0.5, 500.0, log=True, doc="running friction at the output"),),
    sizes=({"coulomb_friction_N": 20.0}, {"coulomb_friction_N": 60.0}),
    fields={"coulomb_friction_N": "coulomb_friction"}, source=SOURCE)


class Stribeck(Effect):
    def model_changes(self, model, values):
        fc = values["coulomb_friction_N"]
        return {"coulomb_friction": fc, "static_friction": fc * values["static_ratio"],
                "stribeck_velocity": values["stribeck_velocity_m_s"]}


STRIBECK = Stribeck(
    name="coulomb_friction", technology="dc_motor", form="stribeck",
    params=(Param("coulomb_friction_N", 0.5, 500.0, log=True, doc="running (Coulomb) friction at the output"),
            Param("static_ratio", 1.0, 3.0, doc="breakaway / running friction"),
            Param("stribeck_velocity_m_s", 1e-4, 0.05, log=True, doc="speed over which the friction falls to running")),
    sizes=({"coulomb_friction_N": 20.0, "static_ratio": 1.5, "stribeck_velocity_m_s": 1e-3},
           {"coulomb_friction_N": 60.0, "static_ratio": 1.25, "stribeck_velocity_m_s": 1e-2}),
    source="Stribeck curve: Armstrong-Helouvry, Dupont, Canudas de Wit, Automatica 30 (1994) 1083; " + SOURCE)

class Asymmetric(Effect):
    def model_changes(self, model, values):
        up, down = values["extend_friction_N"], values["retract_friction_N"]
        return {"coulomb_friction": 0.5 * (up + down),
                "load_force": np.asarray(model.load_force, float) + 0.5 * (up - down)}


ASYMMETRIC = Asymmetric(
    name="coulomb_friction", technology="dc_motor", form="asymmetric",
    params=(Param("extend_friction_N", 0.5, 500.0, log=True, doc="running friction while extending"),
            Param("retract_friction_N", 0.5, 500.0, log=True, doc="running friction while retracting")),
    sizes=({"extend_friction_N": 20.0, "retract_friction_N": 30.0},
           {"extend_friction_N": 60.0, "retract_friction_N": 45.0}),
    source="direction-dependent friction: Armstrong-Helouvry, Dupont, Canudas de Wit, Automatica 30 (1994) 1083; "
           + SOURCE)

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (COULOMB, STRIBECK, ASYMMETRIC)
