"""One ranked design as the solve passes it from ranking to report: a
``Candidate``, built once from the results.json record its technology's
serialiser makes (``technologies/<name>/record.py``) and turned back into
that record, field for field and in the same order, only where results are
written (``to_dict``).

The fields every technology's record has (docs/formats.md, results.json)
are typed attributes; what a technology adds of its own (a force path, a
structure, a valve's resonance, ...) stays in ``own``, in its record's
order. The ranking (``with_fields``: feasible, driver, rank, pareto), the
names and the probability of compliance give new candidates; none is
changed after it is made. A results.json read back from a file (a
baseline, robust's input) and the records of a technology's re-solve (the
flips) become candidates once (``as_candidate``, ``from_dict``).
"""
from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any


@dataclass(frozen=True, eq=True)
class Candidate:
    """A ranked design (results.json ``candidates[]``, docs/formats.md).

    ``order`` is its record's keys in order: a field its technology's record
    leaves out (a combination ruled out before sizing has no ``design``; a
    design not yet ranked has no ``rank``) is absent from it and from
    ``to_dict``, and reads as its default here."""

    id: str
    technology: str
    variant: str | None = None
    stage: str | None = None
    components: Mapping[str, Any] = field(default_factory=dict)
    static: Mapping[str, Any] = field(default_factory=dict)
    simulated: Mapping[str, Any] = field(default_factory=dict)
    margins: Mapping[str, float] = field(default_factory=dict)
    metrics: Mapping[str, float] = field(default_factory=dict)
    design: Mapping[str, Any] | None = None
    reason: str | None = None
    feasible: bool | None = None        # the standing: None until ranked
    driver: str | None = None
    rank: int | None = None
    pareto: bool | None = None
    pareto_level: int | None = None
    rests_on_assumed: tuple = ()
    name: str = ""
    p_compliance: float | None = None
    p_ci95: Any = None
    own: Mapping[str, Any] = field(default_factory=dict)     # the technology's own fields, by name
    order: tuple[str, ...] = ()                       # the record's keys, in order

    @classmethod
    def from_dict(cls, record: Mapping) -> "Candidate":
        """The candidate of a results.json record (its technology's
        serialiser's, or one read back from a file)."""
        typed = {k: _typed(k, v) for k, v in record.items() if k in TYPED}
        own = {k: v for k, v in record.items() if k not in TYPED}
        return cls(**typed, own=own, order=tuple(record))

    def to_dict(self) -> dict:
        """Its results.json record: the record it was built from, with what
        was given since, in the same key order."""
        own = self.own
        return {k: (_plain(k, getattr(self, k)) if k in TYPED else own[k]) for k in self.order}

    def with_fields(self, **fields) -> "Candidate":
        """A new candidate with ``fields`` given (a field it lacked is added
        after the others, as ``dict(record, **fields)`` would)."""
        own = {k: v for k, v in fields.items() if k not in TYPED}
        new = object.__new__(type(self))        # a copy, its fields set once here: a frozen dataclass's way
        state = new.__dict__
        state.update(self.__dict__)
        state.update((k, _typed(k, v)) for k, v in fields.items() if k in TYPED)
        state["own"] = {**self.own, **own} if own else self.own
        state["order"] = self.order + tuple(k for k in fields if k not in self.order)
        return new

    __hash__ = None         # its figures are mappings


# the typed attributes (every other field of a record is the technology's own)
TYPED = frozenset(f.name for f in dataclasses.fields(Candidate)) - {"own", "order"}


def _typed(key: str, value):
    """A record's field as the attribute holds it (a list as a tuple)."""
    return tuple(value) if key == "rests_on_assumed" and value is not None else value


def _plain(key: str, value):
    """An attribute as its record holds it."""
    return list(value) if key == "rests_on_assumed" and value is not None else value


def as_candidate(c: Mapping) -> Candidate:
    """``c`` as a candidate: itself, or the candidate of a results.json
    record (one read back from a file, a technology's record)."""
    return c if isinstance(c, Candidate) else Candidate.from_dict(c)


def records(candidates: list[Candidate]) -> list[dict]:
    """The results.json records of ``candidates``."""
    return [c.to_dict() for c in candidates]
