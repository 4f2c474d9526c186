"""The thresholds that change outcomes are declared once (sizing/settings.py),
each with its rationale in docs/settings.md, each applied by importing it;
and the constants a docstring or comment names exist."""
from __future__ import annotations

import ast
import functools
import re
from fractions import Fraction
from pathlib import Path

import pytest

from sizing import settings

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "sizing"
DOC = (ROOT / "docs" / "settings.md").read_text()
DECLARED = {name: value for name, value in vars(settings).items() if name.isupper()}


@functools.cache
def _sources() -> dict[Path, str]:
    return {path: path.read_text() for path in sorted(PACKAGE.rglob("*.py"))}


def test_there_are_settings():
    assert {"DESIGN_MARGIN", "TRAVEL_FACTOR", "KNIFE_EDGE"} <= DECLARED.keys()


@pytest.mark.parametrize("name", sorted(DECLARED))
def test_each_setting_has_its_row_with_its_value(name):
    row = next((line for line in DOC.splitlines() if line.startswith(f"| `{name}` |")), None)
    assert row is not None, f"docs/settings.md has no row for {name}"
    cells = [c.strip() for c in row.strip("|").split("|")]
    assert float(Fraction(cells[1])) == DECLARED[name], (name, cells[1], DECLARED[name])
    assert all(cells[2:]), f"{name}: every column of its row is filled"


@pytest.mark.parametrize("name", sorted(DECLARED))
def test_each_setting_is_applied_and_declared_nowhere_else(name):
    users, redeclared = [], []
    for path, text in _sources().items():
        if path.name == "settings.py" and path.parent == PACKAGE:
            continue
        if re.search(rf"^\s*{name}\s*=", text, re.M):
            redeclared.append(path.relative_to(ROOT))
        if re.search(rf"\bsettings\.{name}\b|import [^\n]*\b{name}\b", text):
            users.append(path)
    assert users, f"{name} is declared but nothing applies it"
    assert not redeclared, f"{name} is declared again in {redeclared}"


@functools.cache
def _defined_names() -> set[str]:
    names = set()
    for text in _sources().values():
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
                names.add(node.name)
            elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
                names.add(node.id)
            elif isinstance(node, ast.alias):
                names.add(node.asname or node.name)
    return names


# Upper-case words with an underscore that are not constants of the package:
# environment variables, catalog part numbers and symbols of the physics.
NOT_CONSTANTS = re.compile(r"^(OPENBLAS_|MKL_|OMP_|NUMBA_|SIZING_)|^[A-Z]+\d|^[A-Z]{1,3}_\d|^[A-Z]_[A-Z0-9]{1,2}$")


@pytest.mark.parametrize("part", ["api", "diagnose", "engine", "fit", "io", "physics", "report", "sim", "studies", "technologies", ""])
def test_docstrings_and_comments_name_constants_that_exist(part):
    """Constant-style names in prose (``TRAVEL_FACTOR``) are defined
    somewhere in the package. ``""``: the modules at the package's top."""
    sources = _sources()
    defined = _defined_names()
    folder = PACKAGE / part if part else PACKAGE
    missing = []
    for path, text in sources.items():
        if (path.parent != PACKAGE) if not part else (folder not in path.parents):
            continue
        prose = [ast.get_docstring(n) or "" for n in ast.walk(ast.parse(text))
                 if isinstance(n, (ast.Module, ast.FunctionDef, ast.ClassDef, ast.AsyncFunctionDef))]
        prose += re.findall(r"#([^\n]*)", text)
        for words in prose:
            for name in re.findall(r"\b([A-Z][A-Z0-9]*_[A-Z0-9_]*[A-Z0-9])\b", words):
                if name not in defined and not NOT_CONSTANTS.search(name):
                    missing.append(f"{path.relative_to(ROOT)}: {name}")
    assert not missing, missing
