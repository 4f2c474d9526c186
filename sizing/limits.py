"""Resource limits, checked before any work starts.

Hostile or mistaken input can ask for more than the machine has: a 200 MB
run CSV reached 14 GB of memory in ``sizing fit``, a DC rig at
``rate = "1e9 Hz"`` never returns, an evaluate for a 1e9 s duration asked
for 14.6 TiB. So each command first *estimates* what it will
need (samples read, integration steps of one simulation pass, memory) and
refuses with exit 2 and the estimate when it exceeds a stated limit. The
limits are plain numbers in ``Limits``; the CLI's ``--max-samples`` and
``--max-steps`` raise them for one command (``use_limits``).

    with use_limits(samples=5_000_000):
        check_samples(n, "runs/a.csv")          # InputError if n > 5e6

Pure: no I/O, no printing. The estimates are deliberately simple (counts
times rates); the figures in the messages say "about".
"""
from __future__ import annotations

import contextlib
import contextvars
from dataclasses import dataclass, replace

from .errors import InputError

# Memory per measured sample while fitting or diagnosing: the issue measured
# 14 GB for a 200 MB run CSV (about 5.3 million rows of ~38 bytes) in fit,
# i.e. ~2.7 kB per sample; rounded up.
BYTES_PER_SAMPLE = 3000
# Memory per simulated step kept as output (3 channels x 8 bytes, plus the
# input and work arrays): ~64 bytes.
BYTES_PER_STEP = 64
# Stack-and-oil integration: sub-steps of at most 50 us (the stack-and-oil
# simulator's dt_max), i.e. at least 20 kHz.
PIEZO_STEP_RATE_HZ = 20_000.0


@dataclass(frozen=True)
class Limits:
    """What one command may ask for before it is refused (exit 2).

    samples: measured samples read from run CSVs, all runs together
             (1,000,000 ~ 3 GB while fitting; the real 150 V record has 50,000).
    steps:   integration steps of one simulation pass over every candidate
             and load case (1e8 ~ a minute; the seed's solve needs ~2e7).
    """

    samples: int = 1_000_000
    steps: float = 1e8


OPTIONS = {"samples": "--max-samples", "steps": "--max-steps"}
_current: contextvars.ContextVar[Limits] = contextvars.ContextVar("sizing_limits", default=Limits())


def current() -> Limits:
    """The limits in force (defaults unless raised by ``use_limits``)."""
    return _current.get()


@contextlib.contextmanager
def use_limits(**changes):
    """Run a block with some limits changed; ``None`` values keep the default."""
    token = _current.set(replace(_current.get(), **{k: v for k, v in changes.items() if v is not None}))
    try:
        yield _current.get()
    finally:
        _current.reset(token)


def _human_bytes(n: float) -> str:
    for unit in ("B", "kB", "MB", "GB", "TB"):
        if n < 1000 or unit == "TB":
            return f"{n:.3g} {unit}"
        n /= 1000.0
    return f"{n:.3g} TB"   # pragma: no cover


def check_samples(n_samples: float, file: str, field: str | None = None, what: str = "samples") -> None:
    """Refuse reading about ``n_samples`` measured samples above the limit."""
    limit = current().samples
    if n_samples > limit:
        raise InputError(file, field, f"about {n_samples:,.0f} {what} (~{_human_bytes(n_samples * BYTES_PER_SAMPLE)} "
                                      f"of memory to fit), above the limit of {limit:,}; "
                                      f"{OPTIONS['samples']} N raises it")


def check_steps(n_steps: float, file: str, field: str | None = None, what: str = "simulation steps") -> None:
    """Refuse a simulation pass of about ``n_steps`` steps above the limit."""
    limit = current().steps
    if not n_steps <= limit:     # also refuses a NaN estimate
        raise InputError(file, field, f"about {n_steps:.3g} {what} (~{_human_bytes(n_steps * BYTES_PER_STEP)} "
                                      f"of memory), above the limit of {limit:.3g}; "
                                      f"{OPTIONS['steps']} N raises it")


def dc_steps(duration_s: float, rate_hz: float, n_cases: int = 1, output_rate_hz: float = 0.0) -> float:
    """Steps of a DC closed-loop simulation: the controller runs at
    ``rate_hz`` and the output is sampled at ``output_rate_hz``."""
    return float(n_cases) * duration_s * max(rate_hz, output_rate_hz)


def piezo_steps(duration_s: float, n_cases: int = 1) -> float:
    """Steps of a stack-and-oil simulation (sub-steps of at most 50 us)."""
    return float(n_cases) * duration_s * PIEZO_STEP_RATE_HZ


def simulations_within(steps_each: float, wanted: int, spare_steps: float) -> int:
    """How many simulations of ``steps_each`` steps fit in ``spare_steps``,
    at most ``wanted`` (0 when not even one fits)."""
    if not steps_each > 0:
        return int(wanted)
    return int(min(wanted, max(spare_steps, 0.0) // steps_each))
