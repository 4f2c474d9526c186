"""The verdict of a diagnosis as a typed record.

``Verdict`` holds what the rules of judge.py decide: the status, the
effect named (with its form), the holdout shrink, the separation test and
the reasons, plus the figures the verdict rests on (``details``: the gap
energy removed, the floor, the runner-up, the spectral lines, the
per-channel floors, where the residual is). ``to_dict`` gives the
``verdict`` object of diagnosis.json (docs/formats.md); the record also
reads like that object (``v["status"]``, ``v.get("form")``), so code that
reads diagnosis.json's verdict reads the record the same way.
"""
from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass, field

STATUSES = ("explained", "partial", "unexplained", "no_significant_gap", "undetectable")


@dataclass(frozen=True, eq=False)
class Verdict(Mapping):
    """status: one of STATUSES; effect: the family named ("a+b" for a pair;
    None for the three statuses that name nothing); form: its form; shrink: the holdout
    shrink of the measure it was judged on (0 when nothing is named);
    separation: the block-bootstrap test ({"test", "p_vs_baseline",
    "p_vs_runner_up", "alpha"}) or None when no candidate was judged;
    reasons: the sentences of the reason, joined by "; " in diagnosis.json;
    rule: the name of the rule that decided it (judge.RULES)."""

    status: str
    effect: str | None = None
    form: str | None = None
    shrink: float = 0.0
    separation: Mapping | None = None
    reasons: tuple[str, ...] = ()
    rule: str = ""
    details: Mapping = field(default_factory=dict)

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"unknown verdict status {self.status!r}")
        if self.effect is None and self.status in ("explained", "partial"):
            raise ValueError(f"a verdict {self.status!r} names an effect")
        object.__setattr__(self, "details", dict(self.details))      # a copy: the caller's dict may change

    @property
    def reason(self) -> str:
        return "; ".join(self.reasons)

    def to_dict(self) -> dict:
        """The ``verdict`` object of diagnosis.json."""
        out = {"status": self.status, "effect": self.effect}
        if self.effect is not None:
            out["form"] = self.form
        out["shrink_holdout"] = float(self.shrink)
        out["reason"] = self.reason
        if self.separation is not None:
            out["separation"] = dict(self.separation)
        out.update(self.details)
        return out

    def with_details(self, **details) -> "Verdict":
        """A copy with ``details`` added (e.g. where the residual is)."""
        return dataclasses.replace(self, details={**self.details, **details})

    def replace(self, **changes) -> "Verdict":
        return dataclasses.replace(self, **changes)

    # read like diagnosis.json's verdict object (and compare equal to it: Mapping)
    def __getitem__(self, key: str):
        return self.to_dict()[key]

    def __iter__(self):
        return iter(self.to_dict())

    def __len__(self) -> int:
        return len(self.to_dict())
