"""Shared fixtures. Every random step takes a seed (STYLE.md)."""
from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

# One BLAS thread: the fits' small least-squares problems ran about 5x slower
# with OpenBLAS threads fighting over CI's 2 cores. Set before numpy loads.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

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


def subset_catalog(stacks, fluids, seals, amplifiers, dc_actuators=0):
    """The shipped catalog cut down to the named parts (and the first
    ``dc_actuators`` DC actuators), for quick solves. Every structure
    material and compensator is kept; no DC parts (motors, screws...)."""
    from sizing.io.catalog import Catalog, load_catalog
    full = load_catalog(CATALOGS)
    pick = lambda group, ids: {k: v for k, v in group.items() if k in ids}  # noqa: E731
    return Catalog(folder=full.folder, stacks=pick(full.stacks, stacks), fluids=pick(full.fluids, fluids),
                   seals=pick(full.seals, seals), amplifiers=pick(full.amplifiers, amplifiers),
                   dc_actuators=dict(list(full.dc_actuators.items())[:dc_actuators]),
                   materials=dict(full.materials), compensators=dict(full.compensators), files=dict(full.files))


ONE_DESIGN = dict(stacks={"pi-p-056.90"}, fluids={"mil-prf-87257"}, seals={"ptfe-spring-energised"},
                  amplifiers={"pi-e-481"})


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


# --- solves shared by the whole test run ---------------------------------------
# Several test files read the same seed solve. Each is computed once per run:
# under pytest-xdist the first worker to ask computes it into a folder beside
# every worker's temporary folder, under a file lock, and the others read it.

def _run_folder(tmp_path_factory) -> Path:
    """A folder every worker of this test run sees (the run's own with xdist)."""
    base = tmp_path_factory.getbasetemp()
    return base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base


def computed_once(tmp_path_factory, name: str, compute) -> Path:
    """``compute(folder)`` run once per test run into ``folder`` (returned);
    a worker that finds it done, or waits for the one computing it, reads it."""
    import fcntl
    folder = _run_folder(tmp_path_factory) / name
    with open(folder.with_name(name + ".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)          # released when the file closes
        if not (folder / ".done").exists():
            shutil.rmtree(folder, ignore_errors=True)
            folder.mkdir(parents=True)
            compute(folder)
            (folder / ".done").write_text("")
    return folder


class SolvedSeed:
    """``sizing solve studies/seed-requirements.toml`` as run once for the
    test run: ``out`` (results.json, report.html, ...), ``results`` (read
    from results.json), ``terminal`` (what it printed)."""

    def __init__(self, folder: Path):
        self.out = folder / "out"
        self.results = json.loads((self.out / "results.json").read_text())
        self.terminal = (folder / "terminal.txt").read_text()


def _solved_seed(tmp_path_factory, *options: str) -> SolvedSeed:
    def compute(folder):
        code, out, err = run_cli("solve", STUDIES / "seed-requirements.toml", "--out", folder / "out", *options)
        assert code == 0, err
        (folder / "terminal.txt").write_text(out + err)
    return SolvedSeed(computed_once(tmp_path_factory, "seed-solve" + "".join(options), compute))


@pytest.fixture(scope="session")
def seed_solve(tmp_path_factory) -> SolvedSeed:
    """The seed's full solve (flips and probability of compliance)."""
    return _solved_seed(tmp_path_factory)


@pytest.fixture(scope="session")
def seed_solve_fast(tmp_path_factory) -> SolvedSeed:
    """The seed's solve with --fast (verdicts, no flips, no compliance)."""
    return _solved_seed(tmp_path_factory, "--fast")
