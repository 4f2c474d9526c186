"""The user documentation keeps up with the command line: every command and
subcommand has help text and a row in the README's command table, help
texts and the documentation use no project-history wording, and nothing
points outside the repository for the file formats. Fast: no command runs."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import typer.main

from sizing.cli import app

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
DOCS = sorted((ROOT / "docs").glob("*.md"))
# history belongs in CHANGELOG.md and git, not in what a user reads
HISTORY = re.compile(r"\b(sessions?|rounds?|blind|seen|helpers?|reserved)\b|\bissues?\s*#?\d+", re.IGNORECASE)
OUTSIDE = re.compile(r"\.\./shared|CONTRACTS\.md")


def _is_group(cmd) -> bool:
    """A command group (typer ships its own click, so no isinstance check)."""
    return hasattr(cmd, "commands")


def _commands(group, prefix: str = "sizing"):
    """(path, command) for every leaf command, and every group, of the CLI."""
    for name, cmd in sorted(group.commands.items()):
        path = f"{prefix} {name}"
        yield path, cmd
        if _is_group(cmd):
            yield from _commands(cmd, path)


ROOT_COMMAND = typer.main.get_command(app)
COMMANDS = list(_commands(ROOT_COMMAND))
LEAVES = [(path, cmd) for path, cmd in COMMANDS if not _is_group(cmd)]


def _command_table() -> str:
    """The README's command table: the table rows of its "## Commands" section."""
    text = README.read_text()
    section = text.split("\n## Commands", 1)[1].split("\n## ", 1)[0]
    return "\n".join(line for line in section.splitlines() if line.startswith("|"))


def test_the_cli_has_the_expected_commands():
    paths = {path for path, _ in LEAVES}
    for expected in ("sizing solve", "sizing evaluate", "sizing robust", "sizing sweep", "sizing diagnose",
                     "sizing fit hysteresis", "sizing fit dc-motor", "sizing catalog list", "sizing catalog show",
                     "sizing catalog validate", "sizing catalog diff", "sizing catalog add"):
        assert expected in paths


@pytest.mark.parametrize("path,cmd", COMMANDS, ids=[p for p, _ in COMMANDS])
def test_every_command_has_help(path, cmd):
    assert (cmd.help or cmd.short_help or "").strip(), f"{path} has no help text"
    for param in cmd.params:
        if param.name == "help":
            continue
        assert (getattr(param, "help", None) or "").strip(), f"{path}: {param.name} has no help text"


@pytest.mark.parametrize("path", [p for p, _ in LEAVES])
def test_every_command_is_in_the_readme_table(path):
    assert f"`{path}" in _command_table(), f"{path} is missing from the README's command table"


def _help_texts():
    yield "sizing", ROOT_COMMAND.help or ""
    for path, cmd in COMMANDS:
        yield path, " ".join(filter(None, [cmd.help, cmd.short_help]))
        for param in cmd.params:
            yield f"{path} {param.name}", getattr(param, "help", None) or ""


@pytest.mark.parametrize("where,text", [(str(p.relative_to(ROOT)), p.read_text()) for p in [README, *DOCS]]
                         + [("mkdocs.yml", (ROOT / "mkdocs.yml").read_text())],
                         ids=lambda value: value if len(value) < 40 else "")
def test_documentation_states_evidence_not_history(where, text):
    found = [(n + 1, m.group(0)) for n, line in enumerate(text.splitlines()) for m in HISTORY.finditer(line)]
    assert not found, f"{where}: history wording (line, word): {found[:10]}"
    outside = [n + 1 for n, line in enumerate(text.splitlines()) if OUTSIDE.search(line)]
    assert not outside, f"{where}: points outside the repository for formats on lines {outside}"


def test_help_texts_state_rules_not_history():
    for where, text in _help_texts():
        assert not HISTORY.search(text), f"{where}: history wording in help text: {text!r}"
        assert not OUTSIDE.search(text), f"{where}: help points outside the repository: {text!r}"


def test_docs_site_lists_every_page():
    nav = (ROOT / "mkdocs.yml").read_text()
    for page in DOCS:
        assert page.name in nav, f"docs/{page.name} is not in mkdocs.yml's nav"


def test_readme_links_resolve():
    for target in re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", README.read_text()):
        if "://" not in target:
            assert (ROOT / target).exists(), f"README links to a missing file: {target}"


def test_docs_build_strict(tmp_path):
    """``mkdocs build --strict``: every page in the nav, every link and
    anchor resolved (a broken one fails the build)."""
    import shutil
    import subprocess
    import sys
    mkdocs = shutil.which("mkdocs", path=str(Path(sys.executable).parent)) or shutil.which("mkdocs")
    if mkdocs is None:
        pytest.skip("mkdocs is not installed (it comes with the test extras)")
    done = subprocess.run([mkdocs, "build", "--strict", "--site-dir", str(tmp_path / "site")], cwd=ROOT,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr[-2000:]
    assert (tmp_path / "site" / "index.html").exists()


# in code, "round" is also geometry (a round port) and a catalog value
# (section = "round"); the project's history is the other words
HISTORY_IN_CODE = re.compile(r"\b(sessions?|blind|seen|reserved)\b|\bissues?\s*#?\d+|\b(first|second|third)\s+round\b",
                             re.IGNORECASE)


@pytest.mark.parametrize("path", sorted((ROOT / "sizing").rglob("*.py")), ids=lambda p: str(p.relative_to(ROOT)))
def test_code_states_rules_not_history(path):
    found = [(n + 1, m.group(0)) for n, line in enumerate(path.read_text().splitlines())
             for m in HISTORY_IN_CODE.finditer(line)]
    assert not found, f"{path.relative_to(ROOT)}: history wording (line, word): {found[:10]}"
