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


class Interrupted(BaseException):
    """SIGINT or SIGTERM arrived. A BaseException, so no ``except Exception``
    swallows it, while every ``finally`` (temporary outputs) still runs."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


# Signals received by the command line's handler. A library may swallow the
# Interrupted raised inside it (cvxpy's solver import catches everything), so
# the output writer asks here again before it swaps any file in.
RECEIVED_SIGNALS: list[int] = []
# Non-empty while the output writer swaps files in: the handler then only
# records the signal, and the writer raises once the swap is done. Blocking
# the signal in the main thread is not enough: another thread (a BLAS or
# Dask worker) takes it, and Python runs the handler in the main thread all
# the same, between two renames.
HOLDING_SIGNALS: list[int] = []


def raise_if_interrupted() -> None:
    """Raise Interrupted when a signal arrived earlier and was swallowed."""
    if RECEIVED_SIGNALS:
        raise Interrupted(RECEIVED_SIGNALS[0])
