"""Seal stick-slip: spring-energised PTFE seals whose breakaway (static)
friction exceeds the running friction, so the output sticks, loads up the
oil column and jumps ("stepped" motion, seed sec. 4, first prototype).

Model: Karnopp friction on the output (narrow) seal with running force F_run
and breakaway F_run * ratio; the wide seal keeps its nominal running force
and takes the same breakaway ratio. Size: the seed's 7 mm measured against
7.5 mm simulated means about 0.5 mm lost against the output stiffness of the
stacks (n k_s / R^2, about 5.9 kN/m for Table 3): some 3 N of extra
running friction; spring-energised seals break away at 1.5-2.5 times it.

Form "stribeck" (velocity weakening): the output seal's friction falls
from its breakaway value at rest to its running value as
F_run + (F_break - F_run) exp(-(u / v_s)^2) (Stribeck curve, Armstrong-
Helouvry, Dupont and Canudas de Wit, Automatica 30 (1994) 1083; Olsson et
al., Eur. J. Control 4 (1998) 176), with a Stribeck velocity v_s of 1-10
mm/s for lubricated elastomer and PTFE seals; the wide seal keeps its
nominal friction (only the output seal is changed: a stuck output seal
against a sliding wide seal is the stepped motion). Sizes: 1.5 N, 1.8 x,
5 mm/s and 3 N, 2 x, 1 mm/s. (STRIBECK is kept for use and tests; the
library holds the "lugre" form, whose steady state is this curve, to keep
one extra seal form's fitting time.)

Form "lugre" (dynamic friction with presliding): the same Stribeck curve
as the steady state of a LuGre bristle state (Canudas de Wit, Olsson,
Astrom and Lischinsky, IEEE Trans. Autom. Control 40 (1995) 419): below
breakaway the seal deflects elastically (presliding, a few to tens of
micrometres for elastomer and PTFE lip seals) and damps the motion with
its bristle damping sqrt(sigma0 m), so the output creeps instead of
sticking hard. Sizes: as "stribeck", with 10 um and 30 um of presliding.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from .base import Effect, Param

# A Karnopp stick-slip's training cost is rugged: between two nearby
# parameter sets a slip stops a whole slip further, and the cost jumps
# (on a campaign of the project's own simulator the injected seal leaves
# the noise and 1 % away in the running friction more than ten times it),
# so a local least squares stops on the first step it meets. The Karnopp
# form is fitted from ``fit_starts`` distinct screened points among its
# regular screen and ``screen_factor`` - 1 times as many further points
# (starts only: the families are ranked on the regular screen), the best
# on the training runs kept (attribution.screen_ranked,
# fit_best_of_starts): on the independent generator's c01 the fit ends at
# 0.0075 of the training runs (0.030 from starts among 30 points on a log
# scale of the friction, 0.0089 among 240). The LuGre
# form's presliding softens the stick; its extra starts moved its
# training fit by less than 0.3 % on the campaigns measured, at twice the
# Karnopp form's time per fit, so it keeps one start.
RUGGED = {"fit_starts": 3, "screen_factor": 8}
# judged on its events too when the point-by-point verdict names nothing (events.py)
EVENTS = {"events": True}

# The output seal's running friction, N, searched on a linear scale up to
# 20 N; on a rig, from its stated running friction (``AddedFriction``).
# Not a log scale (to reach a seal that only sticks, at the stated 0.2 N,
# with more screened points): it names no such seal of another simulator
# (no library seal at that size removes any of their gap), and ranks the
# seal among the families paired with a creep, which moves that creep's
# verdict to unexplained.
RUNNING_N = (0.02, 20.0)


class AddedFriction(Effect):
    """A seal form whose running friction is bounded below by the rig's
    stated running friction of the output seal: a stick-slip adds a
    breakaway above a running friction, and a seal that runs below the
    stated one is a restated nominal, not stick-slip. Searched from 0.02 N
    on the log scale, a LuGre seal at 0.14 N (breakaway 2.5 x) took up an
    independent simulator's viscous damping as well as the damping did (p =
    0.06 between them)."""

    def for_rig(self, rig, model):
        nominal = float(np.min(getattr(model, "narrow_friction")))
        first, *rest = self.params
        if not first.lo < nominal < first.hi:
            return self
        return replace(self, params=(replace(first, lo=nominal), *rest))


class SealStribeck(AddedFriction):


    def model_changes(self, model, values):
        return {"narrow_friction": values["narrow_friction_N"], "narrow_breakaway": values["breakaway_ratio"],
                "narrow_stribeck_velocity": values["stribeck_velocity_m_s"]}


class SealLuGre(SealStribeck):
    def model_changes(self, model, values):
        return {**super().model_changes(model, values), "narrow_presliding": values["presliding_m"]}


class SealStickSlip(AddedFriction):
    def model_changes(self, model, values):
        ratio = values["breakaway_ratio"]
        return {"narrow_friction": values["narrow_friction_N"],
                "narrow_breakaway": ratio, "wide_breakaway": ratio}


KARNOPP = SealStickSlip(
    form="karnopp", extra={**RUGGED, **EVENTS},
    name="seal_stick_slip", technology="piezohydraulic",
    params=(Param("narrow_friction_N", *RUNNING_N, doc="running friction of the output seal"),
            Param("breakaway_ratio", 1.0, 4.0, doc="breakaway / running friction of both seals")),
    sizes=({"narrow_friction_N": 1.5, "breakaway_ratio": 1.8},
           {"narrow_friction_N": 3.0, "breakaway_ratio": 2.0}),
    source="seed sec. 4 (stepped response of the first prototype); Karnopp (1985) friction")


STRIBECK = SealStribeck(
    name="seal_stick_slip", technology="piezohydraulic", form="stribeck",
    params=(Param("narrow_friction_N", *RUNNING_N, doc="running friction of the output seal"),
            Param("breakaway_ratio", 1.0, 4.0, doc="breakaway / running friction of the output seal"),
            Param("stribeck_velocity_m_s", 2e-4, 5e-2, log=True, doc="Stribeck velocity of the output seal")),
    sizes=({"narrow_friction_N": 1.5, "breakaway_ratio": 1.8, "stribeck_velocity_m_s": 5e-3},
           {"narrow_friction_N": 3.0, "breakaway_ratio": 2.0, "stribeck_velocity_m_s": 1e-3}),
    source="Stribeck curve (Armstrong-Helouvry et al., Automatica 30 (1994) 1083) on Karnopp stick")


LUGRE = SealLuGre(
    name="seal_stick_slip", technology="piezohydraulic", form="lugre",
    params=STRIBECK.params + (Param("presliding_m", 5e-6, 2e-4, log=True,
                                    doc="bristle deflection of the output seal at breakaway"),),
    sizes=({"narrow_friction_N": 1.5, "breakaway_ratio": 1.8, "stribeck_velocity_m_s": 5e-3, "presliding_m": 1e-5},
           {"narrow_friction_N": 3.0, "breakaway_ratio": 2.0, "stribeck_velocity_m_s": 1e-3, "presliding_m": 3e-5}),
    source="LuGre friction (Canudas de Wit et al., IEEE TAC 40 (1995) 419)")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (KARNOPP, LUGRE)
