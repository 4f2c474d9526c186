"""Shared pieces for validating input files with pydantic.

``Qty("length", positive=True)`` is a float field that accepts ``"40 mm"`` or
a bare SI number, rejects NaN and wrong dimensions, and converts to SI once.
``parse_model`` turns pydantic's errors into one ``InputError`` line naming
the file and the field, as docs/formats.md states.
"""
from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Annotated, Any, TypeVar

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, ValidationError

from ..errors import InputError
from ..units import KINDS, UnitError, to_si

M = TypeVar("M", bound=BaseModel)


class Strict(BaseModel):
    """Base of every input model: unknown keys are typos, values are final."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False, defer_build=True)


def _quantity_validator(kind: str, positive: bool, nonnegative: bool):
    word = KINDS[kind][1]

    def convert(value: Any) -> float:
        try:
            number = to_si(value, kind)
        except UnitError as exc:
            raise ValueError(str(exc)) from None
        if positive and not number > 0:
            raise ValueError(f"expected a positive value ({word}), got {value!r}")
        if nonnegative and number < 0:
            raise ValueError(f"expected a non-negative value ({word}), got {value!r}")
        return number

    return convert


def Qty(kind: str, *, positive: bool = False, nonnegative: bool = False):
    """Annotated float type for a quantity of ``kind`` (see ``units.KINDS``)."""
    return Annotated[float, BeforeValidator(_quantity_validator(kind, positive, nonnegative))]


def Bounded(low: float, high: float):
    """A plain model coefficient (no unit) that must lie in [low, high]:
    outside it the simulations overflow or never finish (a rig's
    alpha = 1e300 crashed diagnose, beta = 1e12 ran for minutes)."""
    return Annotated[float, Field(ge=low, le=high, allow_inf_nan=False)]


# assumed: bounds wide around every published and fitted value (seed Table 1:
# alpha -2.23e-7 m/V, beta 0.134, gamma 0.0755, delta -5.46e-8 m/V, n 1.14;
# the shipped catalog's fits lie inside), narrow enough to integrate.
BW_LINEAR = Bounded(-1e-3, 1e-3)      # alpha, delta: m/V
BW_SHAPE = Bounded(-1e3, 1e3)         # beta, gamma
BW_EXPONENT = Bounded(1e-6, 10.0)     # n (a shipped catalog fit has 0.0072)
GAIN = Bounded(-1e9, 1e9)             # PID gains, SI


def finite(value: float, name: str = "value") -> float:
    if not math.isfinite(value):
        raise ValueError(f"expected a finite {name}, got {value!r}")
    return value


MAX_TOML_BYTES = 10_000_000   # an input TOML is a few kB; refuse to parse a huge one


def read_input_bytes(path: str | Path, expected: str = "a file", limit: int | None = None) -> bytes:
    """The bytes of an input file, or an InputError naming it: missing, a
    folder, a symlink loop, unreadable, or larger than ``limit`` bytes."""
    path = Path(path)
    try:
        if limit is not None and path.stat().st_size > limit:
            raise InputError(str(path), None, f"expected {expected} of at most {limit:,} bytes, "
                                              f"got {path.stat().st_size:,} bytes")
        return path.read_bytes()
    except FileNotFoundError:
        raise InputError(str(path), None, "file not found") from None
    except IsADirectoryError:
        raise InputError(str(path), None, f"expected {expected}, got a folder") from None
    except OSError as exc:   # symlink loop, permission denied, a device, ...
        raise InputError(str(path), None, f"cannot read {expected}: {exc.strerror or exc}") from None


def load_toml(path: str | Path) -> dict:
    """Read a TOML file; a missing or malformed file is an InputError. A
    UTF-8 byte-order mark (what some editors write) is accepted."""
    path = Path(path)
    raw = read_input_bytes(path, "a TOML file", MAX_TOML_BYTES)
    try:
        return tomllib.loads(raw.decode("utf-8").removeprefix("\ufeff"))
    except tomllib.TOMLDecodeError as exc:
        raise InputError(str(path), None, f"malformed TOML: {exc}") from None
    except UnicodeDecodeError:
        raise InputError(str(path), None, "not a text file") from None
    except RecursionError:
        raise InputError(str(path), None, "malformed TOML: nested too deep") from None


def field_path(loc: tuple) -> str:
    """('load', 'span') -> '[load].span'; ('ratio',) -> 'ratio'."""
    names = [str(p) if not isinstance(p, int) else f"#{p + 1}" for p in loc]
    if not names:
        return ""
    if len(names) == 1:
        return names[0]
    return "[" + ".".join(names[:-1]) + "]." + names[-1]


def first_error(exc: ValidationError, model=None) -> tuple[str, str]:
    """The first pydantic error as (field path, message for a person). An
    unknown key is reported before a missing one (a misspelt key causes
    both), with the nearest known key of its table when ``model`` is given."""
    errors = exc.errors()
    err = next((e for e in errors if e.get("type") == "extra_forbidden"), errors[0])
    loc = tuple(err.get("loc", ()))
    message = err.get("msg", "invalid value")
    message = message.removeprefix("Value error, ")
    kind = err.get("type", "")
    if kind == "missing":
        message = "required field is missing"
    elif kind == "extra_forbidden":
        near = _nearest_key(model, loc)
        message = (f'unknown field; did you mean "{near}"?' if near else
                   "unknown field (check the spelling against docs/formats.md)")
    elif "input" in err and "expected" not in message:
        message = f"{message}, got {err['input']!r}"
    return field_path(loc), message


def _nearest_key(model, loc: tuple) -> str | None:
    """The known key of the table at ``loc[:-1]`` closest to the unknown ``loc[-1]``."""
    import difflib
    table = model
    for part in loc[:-1]:
        field = getattr(table, "model_fields", {}).get(part) if isinstance(part, str) else None
        if field is None:
            return None
        table = field.annotation
        if not hasattr(table, "model_fields"):       # Optional[...] and the like
            args = [a for a in getattr(table, "__args__", ()) if hasattr(a, "model_fields")]
            table = args[0] if args else None
    known = list(getattr(table, "model_fields", {}))
    if not known or not loc or not isinstance(loc[-1], str):
        return None
    match = difflib.get_close_matches(loc[-1], known, n=1, cutoff=0.6)
    return match[0] if match else None


def parse_model(model: type[M], data: Any, file: str | Path, prefix: tuple = ()) -> M:
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        field, message = first_error(exc, model)
        if prefix:
            field = field_path(prefix + tuple(_split(field)))
        raise InputError(str(file), field or None, message) from None


def parse_tagged(path: str | Path, key: str, models: dict[str, type[M]]) -> M:
    """Read a TOML file whose ``key`` says which model validates it
    (``technology`` of a design, ``kind`` of a rig)."""
    data = load_toml(path)
    tag = data.get(key)
    if not isinstance(tag, str) or tag not in models:   # a list or table here is unhashable
        choices = " or ".join(f'"{name}"' for name in models)
        raise InputError(str(path), key, f"expected {choices}, got {tag!r}")
    return parse_model(models[tag], data, path)


def _split(field: str) -> list[str]:
    return [p for p in field.replace("[", "").replace("]", "").split(".") if p]
