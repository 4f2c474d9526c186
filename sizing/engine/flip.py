"""What would flip each technology's verdict, and the recommendation:
found by re-solving, not read off the margins of designs already sized.

For each technology and each requirement (stroke, blocked force, speed,
maximum temperature, each envelope limit given), and for each assumed
catalog value in its best design's binding margin, the value is moved in
the direction that can change the verdict (stricter for a feasible
technology, looser for an infeasible one) and the technology is re-solved
there (``resolve.py``: its own enumeration, sizing, screen and simulation).
Bisection between today's value and the end of the range (a quarter to
four times the value; the maximum temperature within ``TEMPERATURE_SPAN``
degC of the requirement, never below ``COLD_LIMIT``) finds the value at
which the verdict changes, to ``TOLERANCE`` of the value. Nothing changes
at the end of the range: ``to`` is null and ``within`` says where it was
looked for.

The recommendation (the lightest technology's best design, ``Search.
recommended``) is searched the same way for the recommended technology's
requirements and catalog values, in both directions: stricter, it changes
where that design stops complying or another technology's best overtakes
it; looser, the same, with the other technologies bounded from below by
their mass floor before any whole re-solve (``loosening_flip``). When no technology is
feasible, the recommendation changes where the first one becomes feasible
(the smallest of their feasibility flips, no further solve).

The ``[objectives] min_compliance`` policy (``studies/compliance.py``)
then names the recommendation: the entries say which design they are for
(``design``) and what of the policy they hold fixed (``held``): the
probabilities of compliance are estimated once, at today's values, never
at a bisection step. When the policy picks another design than the
nominal lightest, its entries are searched anew for that design
(``policy_flips``: where it stops complying nominally, stricter only).

Bisection assumes the verdict changes once in the range (feasibility is
monotone in each requirement); the acceptance test re-solves on both sides
of each flip.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

from . import resolve
from .rank import verdict
from ..settings import FLIP_COLD_LIMIT as COLD_LIMIT
from ..settings import FLIP_RANGE as RANGE
from ..settings import FLIP_TEMPERATURE_SPAN as TEMPERATURE_SPAN
from ..settings import FLIP_TOLERANCE as TOLERANCE

if TYPE_CHECKING:
    from .candidate import Candidate

# catalog fields whose larger value makes a design worse; any other field
# (ratings, capacities, stiffness, efficiency) is worse smaller
HIGHER_HURTS = ("capacitance", "mass", "inertia", "cost_usd", "resistance", "viscous_damping", "friction",
                "leak", "thermal_expansion", "loss", "compliance", "backlash", "self_heating")

# how a person reads each value: (unit shown, factor from SI)
DISPLAY = {"stroke": ("mm", 1e3), "speed": ("mm/s", 1e3), "blocked_force": ("N", 1.0),
           "max_temperature": ("degC", 1.0), "max_length": ("mm", 1e3), "max_diameter": ("mm", 1e3),
           "max_width": ("mm", 1e3), "max_mass": ("kg", 1.0), "continuous_current": ("A", 1.0),
           "max_current": ("A", 1.0), "pressure_rating": ("MPa", 1e-6), "capacity": ("cm^3", 1e6),
           "max_frequency": ("Hz", 1.0), "capacitance": ("uF", 1e6), "peak_duration": ("ms", 1e3),
           "max_winding_temperature": ("degC", 1.0)}


@dataclass(frozen=True)
class Probe:
    """One value a flip moves: ``what`` people read, ``field`` (a
    requirement's name or "part.field"), today's ``value`` (SI), ``stricter``
    (+1: a larger value is harder to meet, -1: a smaller one), ``linear``
    (a temperature: searched in degC steps), ``apply(req, catalog, x)``
    -> (req, catalog) with the value x, and ``holding``: the catalog entry
    it changes (None for a requirement)."""

    what: str
    field: str
    value: float
    stricter: int
    linear: bool
    apply: Callable
    holding: str | None = None

    def end(self, direction: int) -> float:
        """The end of the range in ``direction`` (+1 larger, -1 smaller)."""
        if self.linear:
            return max(COLD_LIMIT, self.value + direction * TEMPERATURE_SPAN)
        return self.value * RANGE ** direction

    def close(self, a: float, b: float) -> bool:
        if self.linear:
            return abs(b - a) <= TOLERANCE * max(abs(self.value), 1.0)
        return max(a, b) / min(a, b) <= 1.0 + TOLERANCE

    def middle(self, a: float, b: float) -> float:
        return 0.5 * (a + b) if self.linear else math.sqrt(a * b)

    def shown(self, x: float) -> str:
        unit, factor = DISPLAY.get(self.field.split(".")[-1], ("", 1.0))
        value = x * factor
        return f"{value:,.0f} {unit}".strip() if abs(value) >= 1e4 else f"{value:.4g} {unit}".strip()


def _requirement(table: str, name: str, what: str, value, stricter: int, linear: bool = False) -> Probe:
    def apply(req, catalog, x):
        part = getattr(req, table)
        return req.model_copy(update={table: part.model_copy(update={name: x})}), catalog
    return Probe(what, name, float(value), stricter, linear, apply)


def requirement_probes(req) -> list[Probe]:
    """The requirements and each envelope limit given."""
    r, env = req.requirements, req.envelope
    probes = [_requirement("requirements", "stroke", "requirement stroke", r.stroke, +1),
              _requirement("requirements", "blocked_force", "requirement blocked_force", r.blocked_force, +1),
              _requirement("requirements", "speed", "requirement speed", r.speed, +1),
              _requirement("requirements", "max_temperature", "requirement max_temperature", r.max_temperature, +1,
                           linear=True)]
    for name in ("max_length", "max_diameter", "max_width", "max_mass"):
        if getattr(env, name) is not None:
            probes.append(_requirement("envelope", name, f"envelope {name}", getattr(env, name), -1))
    return probes


def catalog_probes(catalog, deciding: list[str]) -> list[Probe]:
    """The assumed catalog values ("part.field") in a binding margin."""
    probes = []
    for key in deciding:
        ident, _, name = key.rpartition(".")
        try:
            value = getattr(catalog.get(ident)[1], name)
        except (KeyError, AttributeError):
            continue
        if not isinstance(value, (int, float)) or not math.isfinite(value) or value == 0:
            continue

        def apply(req, cat, x, ident=ident, name=name):
            return req, resolve.with_value(cat, ident, name, x)
        hurts = +1 if any(word in name for word in HIGHER_HURTS) else -1
        probes.append(Probe(f"assumed {ident} {name}", key, float(value), hurts, "temperature" in name, apply, ident))
    return probes


class Search:
    """The re-solves behind every flip of one solve. ``today``: each
    technology's verdict as solved; ``known``: per (technology, value
    changed), per value, what each design re-solved there gave
    ({id: (feasible, first objective)})."""

    def __init__(self, req, catalog, loads, candidates: list[Candidate], stages):
        self.req, self.catalog, self.loads, self.stages = req, catalog, loads, stages
        self.key = resolve.OBJECTIVE_KEYS[req.objectives.minimize[0]]
        self.solved = {t: [c for c in candidates if c.technology == t]
                       for t in dict.fromkeys(c.technology for c in candidates)}
        self.today = {t: resolve.verdict_of(req, cs) for t, cs in self.solved.items()}
        self.known: dict[tuple, dict[float, dict]] = {}
        self.pool: dict[tuple, list] = {}
        self.screens: dict[tuple, dict[float, bool]] = {}
        self.bests: dict[tuple, float] = {}
        self.solves = 0

    # --- designs at one value -----------------------------------------------
    def known_at(self, tech: str, probe: Probe, x: float, c: Candidate) -> bool | None:
        """Whether design ``c`` complies with the value ``x``, from what is
        known without a re-solve: at ``x`` itself, at a stricter value where
        it complied or at a looser one where it did not; None when unknown."""
        if probe.holding is not None and not resolve.holds(c, probe.holding):
            return bool(c.feasible)                       # the change does not touch it
        known = self.known.setdefault((tech, probe.field), {})
        if x in known and c.id in known[x]:
            return known[x][c.id][0]
        s = self._strictness(probe, x)
        for y, found in known.items():
            ok = found.get(c.id, (None,))[0]
            if ok is True and self._strictness(probe, y) >= s or ok is False and self._strictness(probe, y) <= s:
                return ok
        return None

    def solve_at(self, tech: str, probe: Probe, x: float, cs: list[Candidate]) -> dict:
        """Re-solve the combinations of designs ``cs`` with the value ``x``:
        {id: (feasible, first objective)} of every design they give (a
        design of ``cs`` that is not among them was ruled out)."""
        req, catalog = probe.apply(self.req, self.catalog, x)
        self.solves += 1
        found = self._record(tech, probe, x, resolve.units(self.stages, tech, req, catalog, self.loads, cs))
        for c in cs:
            found.setdefault(c.id, (False, math.inf, -math.inf))
        return found

    def _record(self, tech: str, probe: Probe, x: float, fresh) -> dict:
        """What the re-solved designs ``fresh`` gave at ``x``, kept with what
        is known there: {id: (feasible, first objective, slack)}."""
        found = self.known.setdefault((tech, probe.field), {}).setdefault(x, {})
        for c in fresh:
            ok, driver = verdict(c.margins)
            found[c.id] = (ok, _objective(c, self.key), _slack_of(c.margins, driver))
        return found

    def design_at(self, tech: str, probe: Probe, x: float, c: Candidate) -> tuple[bool, float]:
        """(feasible, first objective) of design ``c`` with the value ``x``."""
        if probe.holding is not None and not resolve.holds(c, probe.holding):
            return bool(c.feasible), _objective(c, self.key)
        found = self.known.get((tech, probe.field), {}).get(x, {})
        return (found[c.id] if c.id in found else self.solve_at(tech, probe, x, [c])[c.id])[:2]

    @staticmethod
    def _strictness(probe: Probe, x: float) -> float:
        return (x - probe.value) * probe.stricter

    # --- one technology at one value -----------------------------------------
    def feasible_at(self, tech: str, probe: Probe, x: float) -> bool:
        """Whether ``tech`` has a complying design with the value ``x``."""
        if resolve.by_complying(tech):
            return self._lightest(tech, probe, x) is not None
        undecided = []
        for c in self._pool(tech, probe, x):
            ok = self.known_at(tech, probe, x, c)
            if ok:
                return True
            if ok is None:
                undecided.append(c)
        if not undecided:
            return False
        # the most slack design first (it often still complies), then the rest at once
        for batch in (undecided[:1], undecided[1:]):
            if batch:
                found = self.solve_at(tech, probe, x, batch)
                if any(found[c.id][0] for c in batch):
                    return True
        return False

    def tightening_flip(self, tech: str, probe: Probe, end: float) -> float | None:
        """Where a technology feasible today stops complying, stricter: the
        largest flip of its feasible designs' (``_largest_flip``), confirmed
        by re-solving the whole technology there. A solve simulates only
        some of the designs that pass its screen, so the whole re-solve can
        find one that still complies: the search goes on from it."""
        alive, start = self.today[tech].alive, probe.value
        if resolve.unsettled(tech, self.solved[tech]) is None and self._still_complying(tech, probe, end):
            return None         # a whole re-solve at the end of the range still complies: nothing flips
        while True:
            to = self._largest_flip(tech, probe, end, alive, start)
            if to is None:
                return None
            alive = self._still_complying(tech, probe, to)
            if not alive:
                return to
            start = to

    def _still_complying(self, tech: str, probe: Probe, x: float) -> list[Candidate]:
        """The designs that comply with the value ``x`` in a re-solve of the
        whole technology (those that hold the part, for a catalog value).
        When today's solve judged every part combination in full
        (``resolve.unsettled``: no design left unsimulated that a simulation
        could make comply), only the combinations it left open and those
        feasible today can comply at a stricter value, and those already
        found failing there need no re-solve: the others are re-solved by
        combination (every design simulated, more than a whole re-solve
        would). Otherwise the whole technology is re-solved."""
        req, catalog = probe.apply(self.req, self.catalog, x)
        unsettled = resolve.unsettled(tech, self.solved[tech])
        if unsettled is None:
            self.solves += 1
            fresh = resolve.whole(self.stages, tech, req, catalog, self.loads)
        else:
            cs = [c for c in (*self.today[tech].alive, *unsettled) if self.known_at(tech, probe, x, c) is not False]
            if not cs:
                return []
            self.solves += 1
            fresh = resolve.units(self.stages, tech, req, catalog, self.loads, cs)
            self._record(tech, probe, x, fresh)
        alive = []
        for c in fresh:
            ok, driver = verdict(c.margins)
            if ok and (probe.holding is None or resolve.holds(c, probe.holding)):
                alive.append(c.with_fields(feasible=True, driver=driver))
        return alive

    def _largest_flip(self, tech: str, probe: Probe, end: float, alive, start: float) -> float | None:
        """The largest flip, from ``start``, of the designs ``alive`` (feasible
        at ``start``): the most slack combination's own flip is bisected;
        then the others are re-solved at once at that value, and only one
        that still complies there is bisected further, until none does.
        None when one still complies at the end of the range."""
        groups: dict[str, list] = {}
        for c in sorted(alive, key=_slack, reverse=True):
            groups.setdefault(resolve.unit_key(tech, c), []).append(c)
        if probe.holding is not None:
            groups = {k: g for k, g in groups.items() if resolve.holds(g[0], probe.holding)}
        survivors, first = list(groups.values()), start == probe.value
        while survivors:           # a combination that fails at ``start`` fails at every stricter value
            group, others = survivors[0], survivors[1:]
            fails = lambda x, group=group: not self._complies(tech, probe, x, group)    # noqa: E731
            start = bisect(fails, probe, end, start) if first else gallop(fails, probe, end, start)
            if start is None:      # it still complies at the end of the range: nothing flips
                return None
            first = False
            rest = [c for g in others for c in g]
            found = self.solve_at(tech, probe, start, rest) if rest else {}
            survivors = [g for g in others if any(found[c.id][0] for c in g)]
            # the one with the most slack there is likely the last to fail: bisected next
            survivors.sort(key=lambda g: max(found[c.id][2] for c in g), reverse=True)
        return start

    def _complies(self, tech: str, probe: Probe, x: float, group: list) -> bool:
        known = [self.known_at(tech, probe, x, c) for c in group]
        if any(known):
            return True
        if all(k is False for k in known):
            return False
        found = self.solve_at(tech, probe, x, group)
        return any(found[c.id][0] for c in group)

    def _pool(self, tech: str, probe: Probe, x: float) -> list:
        """The designs that can comply at ``x``, most slack first: those
        feasible today (stricter values), or those feasible at the loosest
        value searched (looser values; one whole re-solve there)."""
        if self._strictness(probe, x) >= 0 and self.today[tech].feasible:
            return sorted(self.today[tech].alive, key=_slack, reverse=True)
        end = probe.end(-probe.stricter)
        if (tech, probe.field) not in self.pool:
            req, catalog = probe.apply(self.req, self.catalog, end)
            self.solves += 1
            fresh = resolve.whole(self.stages, tech, req, catalog, self.loads)
            ok = [(verdict(c.margins)[0], c) for c in fresh]
            self.known.setdefault((tech, probe.field), {})[end] = {c.id: (f, _objective(c, self.key))
                                                                  for f, c in ok}
            self.pool[(tech, probe.field)] = sorted((c for f, c in ok if f), key=_slack, reverse=True)
        return self.pool[(tech, probe.field)]

    def _lightest(self, tech: str, probe: Probe, x: float):
        """(id, first objective) of ``tech``'s best complying design with the
        value ``x``, read off its complying designs (``resolve.lightest``)."""
        known = self.known.setdefault((tech, probe.field), {})
        if x not in known:
            req, catalog = probe.apply(self.req, self.catalog, x)
            self.solves += 1
            known[x] = resolve.lightest(tech, req, catalog, self.loads)
        return known[x]

    def best_at(self, tech: str, probe: Probe, x: float) -> float:
        """The first objective of ``tech``'s best complying design with the
        value ``x`` (a whole re-solve, kept per value; inf when none complies)."""
        if resolve.by_complying(tech):
            found = self._lightest(tech, probe, x)
            return math.inf if found is None else found[1]
        key = (tech, probe.field, x)
        if key not in self.bests:
            req, catalog = probe.apply(self.req, self.catalog, x)
            self.solves += 1
            self.bests[key] = resolve.verdict_of(req, resolve.whole(self.stages, tech, req, catalog, self.loads)).objective
        return self.bests[key]

    def floor_at(self, tech: str, probe: Probe, x: float) -> float:
        """A lower bound on ``best_at`` without sizing (``resolve.mass_floor``,
        when the first objective is mass); -inf where none is known."""
        key = ("floor", tech, probe.field, x)
        if key not in self.bests:
            floor = None
            if self.key == "mass_kg":
                req, catalog = probe.apply(self.req, self.catalog, x)
                floor = resolve.mass_floor(tech, req, catalog)
            self.bests[key] = -math.inf if floor is None else floor
        return self.bests[key]

    @staticmethod
    def loosest(probes: list[Probe]) -> Probe:
        """Every one of ``probes`` at the looser end of its range at once (a
        technology's best there is no heavier than at any looser value of any
        one of them: monotone in each)."""
        return Probe("every requirement at its loosest", "loosest", 0.0, +1, True,
                     lambda req, catalog, x: _applied(probes, req, catalog))

    def no_lighter(self, tech: str, probe: Probe, x: float, today: float) -> bool:
        """Whether ``tech``'s best with the value ``x`` is no lighter than
        ``today``: its mass floor first, a whole re-solve only when the
        floor does not settle it."""
        return self.floor_at(tech, probe, x) >= today or self.best_at(tech, probe, x) >= today

    def touches(self, tech: str, probe: Probe) -> bool:
        """Whether moving the value can change ``tech``'s designs (a catalog
        value only those that hold the part)."""
        return probe.holding is None or any(resolve.holds(c, probe.holding) for c in self.solved[tech])

    def screen_at(self, tech: str, probe: Probe, x: float) -> bool:
        """Whether some design of ``tech`` passes its static screen with the value ``x``."""
        screens = self.screens.setdefault((tech, probe.field), {})
        if x not in screens:
            req, catalog = probe.apply(self.req, self.catalog, x)
            screens[x] = resolve.could_comply(tech, req, catalog, self.loads)
        return screens[x]

    # --- the recommendation --------------------------------------------------
    def recommended(self) -> tuple[str, Candidate] | None:
        """(technology, design) recommended today: the technologies' best
        (by rank), the lightest of them in the first objective."""
        feasible = [(v.objective, t) for t, v in self.today.items() if v.feasible]
        if not feasible:
            return None
        tech = min(feasible)[1]
        best = self.today[tech].best
        return tech, next(c for c in self.solved[tech] if c.id == best)

    def recommendation_changes(self, probe: Probe, x: float) -> bool:
        """Whether the design recommended today is not recommended at a
        stricter ``x``: it no longer complies, a lighter design of its own
        technology that misses today complies there (a stricter value is
        not always harder for every design: docs/validation.md, "The
        seed's flips, re-solved"), or another technology's complying
        design is lighter in the first objective."""
        lead, d0 = self.recommended()
        ok, mine = self.design_at(lead, probe, x, d0)
        if not ok:
            return True
        lighter = [c for c in self.solved[lead] if not c.feasible and _objective(c, self.key) < mine
                   and c.margins and (probe.holding is None or resolve.holds(c, probe.holding))]
        if lighter:
            found = self.solve_at(lead, probe, x, lighter)
            if any(found[c.id][0] and found[c.id][1] < mine for c in lighter):
                return True
        for tech, v in self.today.items():
            if tech == lead or not v.feasible or v.objective >= mine:
                continue              # stricter values only make it heavier
            if resolve.by_complying(tech):
                found = self._lightest(tech, probe, x)
                if found is not None and found[1] < mine:
                    return True
                continue
            for c in sorted(v.alive, key=lambda c: _objective(c, self.key)):
                if _objective(c, self.key) >= mine:
                    break
                ok, value = self.design_at(tech, probe, x, c)
                if ok and value < mine:
                    return True
        return False


def _objective(c: Candidate, key: str) -> float:
    value = (c.metrics or {}).get(key)
    return float(value) if value is not None else math.inf


def _slack(c: Candidate) -> float:
    """A design's smallest margin (its driver's): the most slack is tried first."""
    return _slack_of(c.margins, c.driver)


def _slack_of(margins, driver: str | None) -> float:
    """The margin ``driver`` of ``margins``, -inf when there is none."""
    m = margins.get(driver) if driver else None
    return m if m is not None and math.isfinite(m) else -math.inf


def bisect(changed: Callable[[float], bool], probe: Probe, end: float, start: float | None = None) -> float | None:
    """The value nearest ``start`` (today's value by default), to the
    tolerance, at which ``changed`` holds, between ``start`` (where it does
    not) and ``end``; None when it does not hold at ``end``."""
    if not changed(end):
        return None
    a, b = (probe.value if start is None else start), end
    while not probe.close(a, b):
        m = probe.middle(a, b)
        if changed(m):
            b = m
        else:
            a = m
    return b


def gallop(changed: Callable[[float], bool], probe: Probe, end: float, start: float,
           direction: int | None = None) -> float:
    """``bisect`` from ``start`` where the change is expected close by (the
    next combination of a technology, just past the last one's flip): steps
    of 1, 2, 4 ... tolerances until it holds, then bisection in the last step.
    ``direction``: +1 towards larger values, -1 smaller (stricter by default)."""
    step, a = 2.0 * TOLERANCE, start
    sense = probe.stricter if direction is None else direction
    while True:
        b = (a + step * max(abs(probe.value), 1.0) * sense if probe.linear
             else a * (1.0 + step) ** sense)
        if (b - end) * sense >= 0:
            return bisect(changed, probe, end, a)
        if changed(b):
            return bisect(changed, probe, b, a)
        a, step = b, 2.0 * step


def _entry(probe: Probe, to: float | None, end: float, changes: str) -> dict:
    return {"what": probe.what, "field": probe.field, "from": probe.value, "to": to, "changes": changes,
            "method": "re-solve", "tolerance": TOLERANCE, "within": sorted([probe.value, end])}


def technology_flips(search: Search, tech: str, probes: list[Probe]) -> list[dict]:
    """Where ``tech``'s feasibility changes, one entry per probe."""
    today = search.today[tech]
    out = []
    for probe in probes:
        end = probe.end(probe.stricter if today.feasible else -probe.stricter)
        if probe.holding is not None and today.feasible and any(
                not resolve.holds(c, probe.holding) for c in today.alive):
            out.append(_entry(probe, None, end, "feasibility"))   # a feasible design without the part survives
            continue
        if today.feasible and not resolve.by_complying(tech):
            to = search.tightening_flip(tech, probe, end)
        elif resolve.screens(tech) and not today.feasible:
            to = screened_flip(search, tech, probe, end)
        else:
            to = bisect(lambda x: search.feasible_at(tech, probe, x) != today.feasible, probe, end)
        out.append(_entry(probe, to, end, "feasibility"))
    return out


def screened_flip(search: Search, tech: str, probe: Probe, end: float) -> float | None:
    """Where ``tech``, infeasible today, becomes feasible (looser values).
    Its static screen (``Resolving.screen``) decides "infeasible" wherever
    no design passes it, and a re-solve there is that screen alone;
    so the screen's own flip is bisected first, on the screen alone, and the
    whole re-solves (simulation) go on from it, a tolerance, then two, four
    ... at a time, where the verdict is expected close by."""
    feasible = lambda x: search.feasible_at(tech, probe, x)     # noqa: E731
    if not feasible(end):
        return None
    if search.screen_at(tech, probe, probe.value):       # the screen decides nothing here
        return bisect(feasible, probe, end)
    screened = bisect(lambda x: search.screen_at(tech, probe, x), probe, end)
    if feasible(screened):
        return screened
    return gallop(feasible, probe, end, screened, -probe.stricter)


def recommendation_flips(search: Search, probes: list[Probe], feasibility: list[dict]) -> list[dict]:
    """Where the recommended design changes, two entries per probe: stricter
    values (it changes at the latest where its technology's feasibility
    does) and looser ones (``loosening_flip``)."""
    ends = {f["field"]: f["to"] for f in feasibility if f["to"] is not None}
    out = []
    for probe in probes:
        end = ends.get(probe.field, probe.end(probe.stricter))
        # from today's value outwards: the nearest change, where a lighter
        # design that enters may leave again further on
        to = gallop(lambda x: search.recommendation_changes(probe, x), probe, end, probe.value)
        out.append(dict(_entry(probe, to, probe.end(probe.stricter), "recommendation"), direction="stricter"))
        looser = probe.end(-probe.stricter)
        loosest = [p for p in probes if p.holding is None]
        out.append(dict(_entry(probe, loosening_flip(search, probe, looser, loosest), looser, "recommendation"),
                        direction="looser"))
    return out


def _applied(probes: list[Probe], req, catalog):
    """``req`` and ``catalog`` with each probe at the looser end of its range."""
    for p in probes:
        req, catalog = p.apply(req, catalog, p.end(-p.stricter))
    return req, catalog


def loosening_flip(search: Search, probe: Probe, end: float, loosest: list[Probe] = ()) -> float | None:
    """Where, at a looser value, the recommended design stops being the
    recommendation: it stops complying (a looser value is not always easier:
    a design must reach the mean speed over a shorter stroke in less
    time), or another technology's best gets lighter (first objective) than
    it. Its own row is re-solved a step (cheap); the other technologies are
    bounded from below by their mass floor (``Search.no_lighter``) and
    re-solved whole only when that does not settle it, every requirement of
    ``loosest`` at its loosest at once first (monotone in each for them, as
    in their feasibility flips). Held, for the cost (a whole re-solve of
    the recommended technology a step, about 2 s for the DC designs): a
    lighter design of the recommended technology at the looser value, and
    whether one of its designs still complies where the recommended one
    stops (the recommendation then passes to it, or to another technology).
    Bisection, as every flip, assumes one change in the range."""
    lead, d0 = search.recommended()
    others = [t for t in search.today if t != lead and search.touches(t, probe)]
    corner = search.loosest(list(loosest)) if probe in loosest else None

    def settled(t: str, x: float, mine: float) -> bool:
        return ((corner is not None and search.no_lighter(t, corner, 0.0, mine))
                or search.no_lighter(t, probe, x, mine))

    def kept(x: float) -> bool:
        """The recommended design complies and no other technology's best is lighter."""
        ok, mine = search.design_at(lead, probe, x, d0)
        return ok and all(settled(t, x, mine) for t in others)

    return bisect(lambda x: not kept(x), probe, end)


def flips(req, catalog, loads, candidates: list[Candidate], deciding: dict[str, list[str]], stages) -> tuple[dict, int]:
    """Per technology its ``flips`` entries (docs/formats.md), and the
    number of re-solves they took. ``deciding``: per technology, the
    assumed catalog values in its best design's binding margin;
    ``stages``: the technologies' stages of the solve (``solve.technology_stages``)."""
    search = Search(req, catalog, loads, candidates, stages)
    reqs = requirement_probes(req)
    out = {}
    for tech in search.today:
        probes = reqs + catalog_probes(catalog, deciding.get(tech, []))
        out[tech] = technology_flips(search, tech, probes)
    lead = search.recommended()
    if lead is not None:
        probes = reqs + catalog_probes(catalog, deciding.get(lead[0], []))
        out[lead[0]] += recommendation_flips(search, probes, out[lead[0]])
    else:
        out = _first_feasible(out)
    return out, search.solves


def held_text(target: float, meets: bool | None, nominal: bool) -> str:
    """What a recommendation flip holds fixed of the ``[objectives]
    min_compliance`` policy (``studies/compliance.py``): the probabilities
    of compliance are estimated once, for today's values, and not at each
    bisection step (a Monte Carlo through the simulation per step and design).
    ``meets`` None: no technology is feasible, nothing is recommended."""
    if meets is None:
        return ("no technology is feasible: the recommendation changes where the first becomes feasible, "
                "its probability of compliance there not estimated")
    if target <= 0:
        return "min_compliance 0: the nominal recommendation, no probability enters it"
    if not meets:
        return (f"the probabilities of compliance as solved: no design meets min_compliance {target:.0%}, so the "
                "nominal lightest is recommended; whether one would meet it at another value is not re-estimated")
    if nominal:
        return (f"the probabilities of compliance as solved: the nominal lightest meets min_compliance {target:.0%} "
                "and is not re-estimated at other values")
    return (f"the policy's pick as solved: the lightest design meeting min_compliance {target:.0%}, its lighter "
            "rivals missing it; none is re-estimated at other values, so only where the picked design stops "
            "complying nominally is searched (stricter values), and looser values are not searched")


def restate(techs: dict, pick: Candidate | None, held: str, redo: Callable[[], list[dict]] | None = None) -> None:
    """The recommendation's flips (``techs[T]["flips"]``, in place) made
    those of ``pick``, the design the policy recommends: each entry gains
    ``design`` (its id) and ``held``; ``redo()`` gives the entries anew when
    the pick is not the design they were searched for (the nominal
    lightest). ``flip`` is chosen again from the entries."""
    if any(t.get("flips") is None for t in techs.values()):
        return
    if redo is not None:
        for t in techs.values():
            t["flips"] = [e for e in t["flips"] if e["changes"] != "recommendation"]
        techs[pick.technology]["flips"] += redo()
    for t in techs.values():
        t["flips"] = [dict(e, design=pick and pick.id, held=held) if e["changes"] == "recommendation" else e
                      for e in t["flips"]]
        t["flip"] = smallest(t["flips"])


def policy_flips(req, catalog, candidates: list[Candidate], techs: dict, pick: Candidate, stages) -> list[dict]:
    """The recommendation's flips for ``pick``, a design the
    ``min_compliance`` policy recommends over the nominal lightest, with the
    policy's estimates held (``held_text``): stricter values only, where
    the picked design (its combination re-sized there) stops complying
    nominally, at the latest where its technology's feasibility flips.
    ``stages``: the technologies' stages of the solve (``solve.technology_stages``)."""
    from . import stage_cache
    from .loads import load_cases
    tech = pick.technology
    search = Search(req, catalog, [c["load_N"] for c in load_cases(req.load)], candidates, stages)
    deciding = [f"{r['part']}.{r['field']}" for r in pick.rests_on_assumed or () if r.get("decides")]
    ends = {e["field"]: e["to"] for e in techs[tech]["flips"] if e["changes"] == "feasibility" and e["to"] is not None}
    out = []
    with stage_cache.reuse():
        for probe in requirement_probes(req) + catalog_probes(catalog, deciding):
            end = ends.get(probe.field, probe.end(probe.stricter))
            to = bisect(lambda x: not search.design_at(tech, probe, x, pick)[0], probe, end)
            out.append(dict(_entry(probe, to, probe.end(probe.stricter), "recommendation"), direction="stricter"))
    return out


def _first_feasible(out: dict) -> dict:
    """No technology feasible: the recommendation changes where the first
    one becomes feasible, the nearest of their feasibility flips."""
    out = {t: list(entries) for t, entries in out.items()}
    fields = {e["field"] for entries in out.values() for e in entries}
    for field in fields:
        found = [(abs(_relative(e)), t, e) for t, entries in out.items() for e in entries
                 if e["field"] == field and e["to"] is not None]
        if found:
            _, tech, e = min(found, key=lambda f: f[0])
            out[tech].append(dict(e, changes="recommendation"))
    return out


def _relative(e: dict) -> float:
    """How far ``to`` is from ``from``, relative (degC for a temperature)."""
    a, b = e["from"], e["to"]
    return (b - a) / max(abs(a), 1.0) if "temperature" in e["field"] else b / a - 1.0


def smallest(entries: list[dict] | None) -> dict | None:
    """The flip that needs the smallest change, with a line people read
    (results.json ``flip``); None when nothing flips in range."""
    found = [e for e in entries or [] if e["to"] is not None]
    if not found:
        return None
    e = min(found, key=lambda e: abs(_relative(e)))
    return dict(e, relative_change=abs(_relative(e)), text=flip_text(e))


def flip_text(e: dict) -> str:
    """One flip as people read it, in their units."""
    probe = Probe(e["what"], e["field"], e["from"], 0, False, None)
    name = e["what"].removeprefix("requirement ")
    what = "the recommendation changes" if e["changes"] == "recommendation" else "the verdict flips"
    if e["to"] is None:
        lo, hi = e["within"]
        return f"{name}: nothing flips between {probe.shown(lo)} and {probe.shown(hi)}"
    sign = "+" if e["to"] > e["from"] else "-"
    return (f"{name} {probe.shown(e['from'])} -> {probe.shown(e['to'])} ({sign}{abs(_relative(e)):.0%}"
            f"{' of its degC' if 'temperature' in e['field'] else ''}): {what}")
