"""Model fits to measured runs. The DC rig's estimator and record are
read from here (``DCMotorEstimator``, ``DCRecord``), imported when first asked
for: ``sizing fit hysteresis`` does not load them."""
from __future__ import annotations

_LAZY = {"DCMotorEstimator": "dc_motor", "DCRecord": "dc_motor"}


def __getattr__(name: str):
    if name in _LAZY:
        import importlib
        return getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
