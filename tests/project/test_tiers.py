"""The two tiers of the suite add up to every test: the README's test
command runs all but the ``slow`` tier, and CI (.ci/run) runs that command
as written and then the slow tier; markers are strict, so a mistyped one
fails instead of moving a test out of both."""
from __future__ import annotations

import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _readme_test_command() -> str:
    return next(line for line in (ROOT / "README.md").read_text().splitlines() if "pip install -e '.[test]'" in line)


def test_the_readme_command_leaves_out_exactly_the_slow_tier():
    command = _readme_test_command()
    assert "pytest" in command and re.search(r"""-m ["']not slow["']""", command), command


def test_ci_runs_the_readme_command_and_then_the_slow_tier():
    ci = (ROOT / ".ci" / "run").read_text()
    assert "grep -m1 -F \"pip install -e '.[test]'\" README.md" in ci and 'eval "$test_command"' in ci
    after = ci[ci.index('eval "$test_command"'):]
    assert re.search(r"^\.venv/bin/python -m pytest .*-m slow\s*$", after, re.M), after


def test_markers_are_strict_and_declared():
    options = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]["ini_options"]
    assert "--strict-markers" in options["addopts"].split()
    assert any(m.startswith("slow:") for m in options["markers"])
