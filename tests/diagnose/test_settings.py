"""Every setting of the diagnosis is declared in settings.py and has a row
with its rationale in docs/diagnosis-settings.md; no docstring names a
threshold by a constant that does not exist."""
import re
from pathlib import Path

from sizing.diagnose import settings

ROOT = Path(__file__).resolve().parents[2]


def test_every_setting_has_a_rationale_row():
    table = (ROOT / "docs" / "diagnosis-settings.md").read_text(encoding="utf-8")
    rows = set(re.findall(r"^\| `(\w+)` \|", table, flags=re.M))
    assert set(settings.names()) <= rows, set(settings.names()) - rows


def test_no_source_names_a_setting_as_an_absent_constant():
    """A threshold is named as the setting it is (``gap_factor``), never as
    an upper-case module constant that is not defined (GAP_FACTOR)."""
    upper = {n.upper() for n in settings.names()}
    for path in (ROOT / "sizing").rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        defined = set(re.findall(r"^([A-Z_][A-Z_0-9]*)\s*=", text, flags=re.M))
        named = set(re.findall(r"\b[A-Z_][A-Z_0-9]+\b", text)) & upper
        assert named <= defined, (path, named - defined)
