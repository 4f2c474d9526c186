"""Relative spreads of the Bouc-Wen parameters from a ``sizing fit
hysteresis`` output (docs/formats.md, fit output): each parameter's standard
error (``[fit].stderr``) over the fitted value (``[stack].d33``,
``[stack.bouc_wen]``), as ``stack.bouc_wen.PARAM`` tolerances for
``sizing robust --bouc-wen-fit``."""
from __future__ import annotations

import math
from pathlib import Path

from ..errors import InputError
from .schema import load_toml

PARAMS = ("d33", "alpha", "beta", "gamma", "delta", "n")


def bouc_wen_spreads(path: str | Path) -> dict[str, float]:
    data = load_toml(path)
    fit, stack = data.get("fit", {}), data.get("stack", {})
    if not isinstance(fit, dict) or fit.get("model") != "bouc-wen":
        raise InputError(str(path), "[fit].model", 'expected a Bouc-Wen fit ("bouc-wen") from sizing fit hysteresis')
    stderr = fit.get("stderr")
    if not isinstance(stderr, dict):
        raise InputError(str(path), "[fit].stderr", "expected the standard error of each parameter")
    values = {"d33": stack.get("d33"), **(stack.get("bouc_wen") or {})}
    out = {}
    for p in PARAMS:
        value, err = values.get(p), stderr.get(p)
        if not all(isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in (value, err)):
            raise InputError(str(path), f"[fit].stderr.{p}", "expected a finite standard error and fitted value")
        if value == 0 or err < 0:
            raise InputError(str(path), f"[fit].stderr.{p}", f"expected a non-zero value and a non-negative error, got {value!r} +/- {err!r}")
        out[f"stack.bouc_wen.{p}"] = abs(err / value)
    return out
