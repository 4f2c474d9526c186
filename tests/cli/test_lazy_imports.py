"""The command line answers ``--help`` and bad input before the heavy
libraries load: each case runs in a fresh interpreter and lists the modules
it imported. (pint loads ``dask``'s core when it is installed; the
scheduler, ``distributed``, is what the studies need and must stay out.)"""
from __future__ import annotations

import json
import subprocess
import sys

from ..conftest import STUDIES

HEAVY = ("cvxpy", "plotly", "numba", "distributed", "pandas")

# argv[1]: modules to import first (the self-check), argv[2]: command lines
# run one after the other; after each, the heavy modules loaded so far.
PROBE = """
import importlib, json, sys
for name in json.loads(sys.argv[1]):
    importlib.import_module(name)
from sizing.cli import main
report = []
for args in json.loads(sys.argv[2]):
    try:
        main(args)
        code = 0
    except SystemExit as exc:
        code = exc.code
    report.append({"args": args, "code": code, "heavy": [m for m in %r if m in sys.modules]})
sys.__stdout__.write("\\nPROBE " + json.dumps(report))
""" % (HEAVY,)

CASES = [
    ("--help",),
    ("solve", "--help"),
    ("solve", "missing-requirements.toml"),
    ("solve", str(STUDIES / "seed-requirements.toml"), "--detail", "everything"),
    ("evaluate", "missing-design.toml"),
    ("fit", "hysteresis", "missing-run.csv"),
    ("fit", "dc-motor", "missing-run.csv", "--rig", "missing-rig.toml"),
    ("diagnose", "missing-campaign", "--holdout", "a"),
    ("diagnose", "missing-campaign", "--check"),
    ("robust", "missing-requirements.toml"),
    ("sweep", "missing-requirements.toml", "--vary", "stroke=35mm..50mm:2"),
]


def _probe(cases, preload: tuple[str, ...] = ()) -> list[dict]:
    """Each command line's exit code and the heavy modules loaded by then, in
    one fresh interpreter (one start-up for all cases)."""
    done = subprocess.run([sys.executable, "-c", PROBE, json.dumps(preload),
                           json.dumps([[str(a) for a in args] for args in cases])],
                          capture_output=True, text=True, timeout=300)
    assert "PROBE " in done.stdout, done.stderr
    return json.loads(done.stdout.rpartition("PROBE ")[2])


def test_help_and_input_errors_answer_before_the_heavy_libraries():
    for got in _probe(CASES):
        assert got["code"] in (0, 2), got
        assert got["heavy"] == [], f"{' '.join(got['args'])} loaded {got['heavy']}"


def test_the_probe_sees_a_heavy_library_that_is_loaded():
    """The check above can fail: the same probe, with cvxpy imported first."""
    (got,) = _probe([("solve", "missing-requirements.toml")], preload=("cvxpy",))
    assert got["code"] == 2 and got["heavy"] == ["cvxpy"], got
