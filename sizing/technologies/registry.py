"""The registry of technologies: one ``Technology`` per folder of
``sizing/technologies/``, which every stage that treats technologies alike
iterates (the solve, the ranking's counts, the summary, the comparison,
names, descriptions, the report, robust and sweep) instead of naming them.

A technology's package registers itself in its ``technology`` module
(``TECHNOLOGY = Technology(...)``); ``technologies()`` finds those modules
the first time it is asked, and ``register`` adds one at run time (a
technology written outside the package, as a test does)."""
from __future__ import annotations

import importlib
import pkgutil
import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from .presentation import PLAIN, Presentation

if TYPE_CHECKING:
    from ..engine.candidate import Candidate

_REGISTERED: dict[str, "Technology"] = {}
_FOUND = False
_FINDING = threading.RLock()        # solves may run in threads: the first finds the packages, the others wait


def on_call(module: str, name: str) -> Callable:
    """``module.name``, imported when first called rather than with the
    registry (a technology's evaluate or perturbed checks load the engine)."""
    def call(*args, **kwargs):
        return getattr(importlib.import_module(module), name)(*args, **kwargs)
    call.__name__ = call.__qualname__ = name
    call.__doc__ = f"``{module}.{name}``, imported when first called."
    return call


def _nothing(*_args, **_kwargs):
    return None


def _by_own_id(records) -> dict:
    return {r.id: r for r in records}


def _no_words(*_args, **_kwargs) -> str:
    return ""


@dataclass(frozen=True)
class Group:
    """One group of a technology's designs in the summary (results.json
    ``summary.groups``): the candidates whose ``variant`` is ``variant``."""

    variant: str
    label: str
    empty: str = "not evaluated"            # the summary's words when the group has no design
    caveat: Callable = _no_words            # (req, feasible candidates, catalog) -> words after the verdict


def _own_id(c: Candidate) -> str:
    return c.id


@dataclass(frozen=True)
class Resolving:
    """How the flips (``engine/flip.py``, ``engine/resolve.py``) re-solve one
    technology beyond re-running its ``solve`` whole. Every field has a
    default: a technology that says nothing is re-solved whole.

    ``units(its solve, req, catalog, loads, candidates)`` re-solves only the
    part combinations of ``candidates`` (None: it cannot, and the flips
    re-solve it whole); ``unit_key(c)`` names what one such re-solve covers;
    ``unsettled(candidates)`` lists the designs its solve left open (None:
    its solve does not record every design it leaves unsimulated);
    ``mass_floor(req, catalog)`` bounds the mass of every design it can give
    from its enumeration alone (None: none known). A technology whose
    verdict the flips read off its complying designs alone gives
    ``complying(req, catalog, loads)`` (candidate records of the designs
    that can comply, simulated) and ``screen(req, catalog, loads)`` (whether
    any design passes its static screen)."""

    units: Callable | None = None
    unit_key: Callable[[Candidate], str] = _own_id
    unsettled: Callable = _nothing
    mass_floor: Callable = _nothing
    complying: Callable | None = None
    screen: Callable | None = None


WHOLE = Resolving()


@dataclass(frozen=True)
class Technology:
    """What the shared stages need of one technology.

    ``solve(req, catalog, loads, progress, detail)`` enumerates, sizes and
    verifies its designs and returns ``(records.Outcome, its records)``;
    ``short_name(c)`` and ``describe(c, catalog)`` read a candidate's
    attributes (``engine.candidate.Candidate``: the fields every record has,
    the technology's own in ``own``); ``traces(req, candidate, stages, loads)`` re-simulates
    one design with its time traces kept (None: it has none);
    ``disagreements(records, names)`` lists where its static screen and its
    simulation disagree (results.json ``disagreements``)."""

    name: str                               # results.json ``technology``
    label: str                              # in tables and sentences: "DC motor"
    order: int                              # where it stands among the others (results, tables)
    part_kinds: tuple[str, ...]             # the catalog groups its designs draw on
    solve: Callable
    groups: tuple[Group, ...]
    short_name: Callable[[Candidate], str]
    describe: Callable[[Candidate, object], str]
    rests_on: tuple[str, ...] = ()          # the models (modules of sizing.physics and sizing.sim) its figures rest on
    noun: str = ""                          # "DC motor actuator" (defaults to label + " actuator")
    traces: Callable = _nothing
    disagreements: Callable = field(default=lambda records, names: [])
    counts_key: str | None = ""             # where results.json ``counts`` holds its counts ("": its name; None: at the top)
    prunes_before_sizing: bool = False      # its ruled-out combinations count as "ruled out before sizing"
    extra_counts: tuple[str, ...] = ()      # its own counts ``summary.counts`` repeats
    results_fields: Callable = field(default=lambda catalog: {})    # results.json fields of its own
    summary_fields: Callable = field(default=lambda catalog, candidates: {})    # results.json ``summary`` fields of its own
    in_every_sweep_point: bool = False      # sweep.json counts it at every point, with or without designs
    compared_with: str = ""                 # the technology the comparison states its best against, ratio by ratio
    comparison_fields: Callable | None = None   # (req, candidates) -> its own fields of the comparison's entry
    comparison_words: Callable | None = None    # (its comparison entry) -> the sentence that states them
    # (candidate, the technology robust was asked for or None) -> whether robust perturbs the candidate's parts
    perturbable: Callable = field(default=lambda candidate, asked: False)
    thermal_statement: Callable | None = None   # (req, candidates) -> its words in results.json ``summary.thermal``
    evaluate: Callable | None = None        # (its design file, catalog, file name) -> ``sizing evaluate``'s figures
    # (req, catalog, candidate, the solve's records.Stages or None) -> what robust perturbs of the candidate
    study_design: Callable | None = None
    # (robust's BatchTask, its tolerances, their factors, temperatures) -> (candidate per sample, simulated s)
    verify_perturbed: Callable | None = None
    report: Presentation = PLAIN            # how the report draws, tables and counts its designs
    resolving: Resolving = WHOLE            # how the flips re-solve it (``Resolving``)
    # (req, catalog, its design files, their file names, load cases) -> per file ``engine.judge.Judged``
    judge: Callable | None = None
    reached: str = ""                       # when a step counts as reached, if short of the whole stroke: "98 % of it"
    held: Callable = _by_own_id             # (its records of a solve) -> {design id: design} (``records.Stages``)
    # its ``solve`` may run in a worker thread while the others run: it reads
    # only its inputs, its compiled kernels release the GIL and its parallel
    # ones are launched under ``sim.PARALLEL_LAUNCH``
    alongside: bool = False

    @property
    def actuator(self) -> str:
        return self.noun or f"{self.label} actuator"

    def counts_of(self, counts: dict) -> dict:
        """Its own counts in results.json ``counts``."""
        if self.counts_key is None:
            return counts
        return counts.get(self.counts_key or self.name) or {}


def register(technology: Technology) -> Technology:
    """Add ``technology`` (or replace the one of that name)."""
    _find()
    _REGISTERED[technology.name] = technology
    return technology


def unregister(name: str) -> None:
    _REGISTERED.pop(name, None)


def technologies() -> tuple[Technology, ...]:
    """Every registered technology, in order."""
    _find()
    return tuple(sorted(_REGISTERED.values(), key=lambda t: (t.order, t.name)))


def names() -> tuple[str, ...]:
    """Every technology's name without importing any (a folder's name is its
    technology's): an option can be checked before the engine loads."""
    if _FOUND:
        return tuple(t.name for t in technologies())
    package = importlib.import_module(__package__)
    return tuple(sorted({info.name for info in pkgutil.iter_modules(package.__path__) if info.ispkg}
                        | set(_REGISTERED)))


def folder_module(name: str, module: str):
    """The ``module`` of a technology's folder, imported by the folder's name
    (``technologies()`` would load every technology's engine); None when
    it has none."""
    dotted = f"{__package__}.{name}.{module}"
    try:
        return importlib.import_module(dotted)
    except ModuleNotFoundError as exc:
        if exc.name and dotted.startswith(exc.name):
            return None
        raise


def checks_module(name: str):
    """A technology's ``checks`` module (``folder_module``); None when it has none."""
    return folder_module(name, "checks")


def reserved_steps(req, catalog, but: str) -> float:
    """The simulation steps the other technologies' verification needs
    whatever is sized (their ``checks.required_steps``): what a technology
    that fits its own simulations within the limit leaves them."""
    total = 0.0
    for name in names():
        required = getattr(checks_module(name), "required_steps", None) if name != but else None
        if required is not None:
            total += required(req, catalog)
    return total


def held(name: str, records) -> dict:
    """A technology's designs of a solve by id, from its records
    (``Technology.held``; by each record's ``id`` when it is not registered)."""
    tech = get(name)
    return (tech.held if tech is not None else _by_own_id)(records)


def resolving(name: str) -> Resolving:
    """How the flips re-solve a technology (whole, when it is not registered)."""
    tech = get(name)
    return tech.resolving if tech is not None else WHOLE


def get(name: str) -> Technology | None:
    _find()
    return _REGISTERED.get(name)


def presentation(name: str) -> Presentation:
    """How the report shows a technology's designs (the plain way when it is
    not registered)."""
    tech = get(name)
    return tech.report if tech is not None else PLAIN


def label(name: str) -> str:
    """A technology's label, or its name in words when it is not registered."""
    tech = get(name)
    return tech.label if tech is not None else str(name).replace("_", " ")


def _find() -> None:
    """Import the ``technology`` module of every package here, once."""
    global _FOUND
    if _FOUND:
        return
    with _FINDING:
        if _FOUND:
            return
        package = importlib.import_module(__package__)
        found = [importlib.import_module(f"{__package__}.{info.name}.technology").TECHNOLOGY
                 for info in pkgutil.iter_modules(package.__path__) if info.ispkg]
        for technology in found:
            _REGISTERED.setdefault(technology.name, technology)
        _FOUND = True
