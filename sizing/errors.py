"""Typed exceptions. The library raises them; only ``cli.py`` turns them
into messages and exit codes (InputError -> 2, anything else -> 1)."""
from __future__ import annotations


class InputError(Exception):
    """Bad user input: names the file, the field (or CSV line) and what was
    expected, e.g. ``req.toml: [requirements].stroke: expected a length, got "40 kg"``."""

    def __init__(self, file: str | None, field: str | None, message: str):
        self.file = str(file) if file is not None else None
        self.field = field
        self.message = message
        super().__init__(str(self))

    def __str__(self) -> str:
        parts = [p for p in (self.file, self.field) if p]
        return ": ".join(parts + [self.message])


class SimulationError(Exception):
    """A simulation that failed (diverged, produced non-finite values)."""


class FitError(Exception):
    """Data cannot support the requested fit (too short, no reversal, ...)."""
