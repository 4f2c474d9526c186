"""Shared fixtures. Every random step takes a seed (STYLE.md)."""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[1]
STUDIES = REPO / "studies"
CATALOGS = REPO / "catalogs"
# A requirements file that solves in about a second: two stack counts, two
# simulated candidates, no compensator variants, no DC actuators.
FAST_REQUIREMENTS = """[requirements]
stroke = "40 mm"
blocked_force = "2.5 kN"
speed = "100 mm/s"
max_temperature = "100 degC"

[load]
force = ["1 kN"]

[options]
max_stacks = 2
max_simulated = 2
thermal_compensation = false
dc_motors = false
"""
SEED_BOUC_WEN = dict(d33=8.15e-7, alpha=-2.23e-7, beta=0.134, gamma=0.0755, delta=-5.46e-8, n=1.14)  # seed Table 1


@pytest.fixture
def rng():
    return np.random.default_rng(20251201)


@pytest.fixture
def catalog_copy(tmp_path):
    """A writable copy of the shipped catalog."""
    target = tmp_path / "catalogs"
    shutil.copytree(CATALOGS, target)
    return target


def run_cli(*args: str):
    """Run the console entry point in-process; returns (exit code, stdout, stderr)."""
    import contextlib
    import io
    import sys

    from sizing.cli import main

    out, err = io.StringIO(), io.StringIO()
    argv = sys.argv
    sys.argv = ["sizing", *map(str, args)]
    code = 0
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            main()
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    finally:
        sys.argv = argv
    return code, out.getvalue(), err.getvalue()
