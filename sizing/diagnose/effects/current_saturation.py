"""Current saturation below the rated limit: a drive set to a lower peak
current, a supply that sags, or a thermal fold-back, so large steps are
acceleration-limited and the loop winds up.

Two forms, met in practice:
- ``command``: the controller's own command is clipped at a lower limit
  (a limit set in the controller's firmware, which the controller knows: its
  conditional integration stops wind-up, and the logged current is the
  clipped command).
- ``drive``: the servo drive (amplifier) limits the *actual* motor current
  behind the controller's back: its peak-current setting, an I^2 t
  fold-back, or a supply that cannot deliver. The controller keeps
  computing and logging an unclipped command and its integrator winds up;
  only the motor's acceleration shows the limit. This is how a separate
  current-mode amplifier (e.g. a Maxon ESCON or Copley Accelnet set to a
  peak current) behaves when the position loop runs on another controller
  that logs its command: the amplifier's limit is invisible to the logger
  (sizing.sim.dc_motor, ``drive_current_limit``).
Sizes: 50 % and 25 % of the nominal limit for both (a drive configured at
half or a quarter of the rated peak, or folded back to its continuous rating).
"""
from __future__ import annotations

import numpy as np

from .base import Effect, Param

SOURCE = "seed eq. 13 with a saturated input; docs/models.md (DC motor under load)"

COMMAND = Effect(
    name="current_saturation", technology="dc_motor", form="command",
    params=(Param("current_limit_A", 0.05, 20.0, log=True, doc="current limit of the controller's command"),),
    fields={"current_limit_A": "current_limit"}, nominal_factors=(0.5, 0.25), source=SOURCE)

class DriveLimit(Effect):
    def sizes_for(self, rig, model):
        """Fractions of the nominal (controller) current limit: the drive's
        own field is unlimited in the nominal."""
        nominal = float(np.min(model.current_limit))
        return tuple({"current_limit_A": f * nominal} for f in self.nominal_factors)


DRIVE = DriveLimit(
    name="current_saturation", technology="dc_motor", form="drive",
    params=(Param("current_limit_A", 0.05, 20.0, log=True,
                  doc="actual current limit of the drive, unknown to the controller (logged command unclipped)"),),
    fields={"current_limit_A": "drive_current_limit"}, nominal_factors=(0.5, 0.25),
    source=SOURCE + "; servo amplifier peak-current limit / I^2 t fold-back in current mode "
                    "(e.g. Maxon ESCON 50/5 hardware reference, 'current limit')")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (COMMAND, DRIVE)
