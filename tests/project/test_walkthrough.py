"""Following the README leaves the checkout as it found it: every command of
its ``sh`` blocks runs, in order, in a scratch clone of the repository, and
afterwards ``git status`` is what it was before and everything written lies
in a folder the README names as an output (``*-out/``, git-ignored).

Long commands run in cheap variants (fewer samples, fewer grid points,
solves with ``--fast``, fits from one start);
commands whose inputs are the reader's own (``my-catalogs/``, a vendor
sheet, the makers' tables) and ``diagnose --check`` (minutes, prints only)
are left out, each with its reason below. Slow: a few minutes of solves and
fits."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from ..conftest import FAST_REQUIREMENTS

ROOT = Path(__file__).resolve().parents[2]

# a line holding one of these is not run: its inputs are the reader's own, or it is the test suite itself
NOT_RUN = {"my-catalogs/": "the reader's own catalog folder", "old-catalogs/": "the reader's old catalog",
           "new-stacks.csv": "the reader's vendor sheet", "TABLES/": "the makers' tables, downloaded by the reader",
           "pytest": "the test suite", "--check": "minutes of injected-effect diagnoses; prints only"}
# (pattern, replacement): the same command, cheaper
CHEAPER = [(r"--samples \d+ --designs \d+", "--samples 2 --designs 1 --workers 0"),
           (r"(--vary \S+):\d+", r"\1:2 --workers 0"),
           (r"^python3 -m venv .*&& \.venv/bin/(sizing .*)$", r"\1"),
           # the checkout's cleanliness does not depend on the flips or the
           # probability of compliance (tests/engine/test_solve.py checks them)
           (r"\bsizing solve ", "sizing solve --fast "),
           (r"\bsizing fit (\S+) ", r"sizing fit \1 --starts 1 ")]


def _blocks(readme: str) -> list[str]:
    return re.findall(r"```sh\n(.*?)```", readme, flags=re.S)


def _script(block: str, my_requirements: Path, have_history: bool) -> str:
    """A block as a bash script: the lines that run, made cheap."""
    lines = []
    for line in block.replace("\\\n", " ").splitlines():
        if any(word in line for word in NOT_RUN) or not line.strip():
            continue
        if "HEAD~3" in line and not have_history:
            continue                          # a shallow clone has no revision three back
        for pattern, replacement in CHEAPER:
            line = re.sub(pattern, replacement, line)
        lines.append(line.replace("my-requirements.toml", str(my_requirements)))
    return "set -e\n" + "\n".join(lines) + "\n"


def _git(*args, cwd) -> str:
    return subprocess.run(["git", *args], cwd=cwd, check=True, capture_output=True, text=True).stdout


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("git") is None or not (ROOT / ".git").exists(), reason="needs git and a checkout")
def test_every_readme_command_leaves_the_checkout_clean(tmp_path):
    repo = tmp_path / "repo"
    _git("clone", "--quiet", "--shared", str(ROOT), str(repo), cwd=tmp_path)
    # the working tree as it is (edits not yet committed included)
    files = _git("ls-files", "-co", "--exclude-standard", "-z", cwd=ROOT).split("\0")
    for name in filter(None, files):
        if (ROOT / name).is_file():
            (repo / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / name, repo / name)
    before = _git("status", "--porcelain", cwd=repo)
    have_history = subprocess.run(["git", "rev-parse", "--verify", "-q", "HEAD~3"], cwd=repo,
                                  capture_output=True).returncode == 0
    mine = tmp_path / "my-requirements.toml"          # the reader's own file lives outside the checkout
    mine.write_text(FAST_REQUIREMENTS)
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
               OPENBLAS_NUM_THREADS="1")
    ran = 0
    for block in _blocks((repo / "README.md").read_text()):
        script = _script(block, mine, have_history)
        if script.strip() == "set -e":
            continue
        done = subprocess.run(["bash", "-c", script], cwd=repo, env=env, capture_output=True, text=True, timeout=900)
        assert done.returncode == 0, (script, done.stderr[-2000:])
        ran += script.count("\n") - 1
    assert ran >= 15, ran
    assert _git("status", "--porcelain", cwd=repo) == before
    ignored = [line[3:] for line in _git("status", "--porcelain", "--ignored", cwd=repo).splitlines()
               if line.startswith("!! ")]
    stray = [p for p in ignored if not p.split("/")[0].endswith("-out") and "__pycache__" not in p]
    assert not stray, f"written outside the README's output folders: {stray}"
    for folder in ("sizing-out", "my-next-out", "fit-out", "dc-diagnose-out", "diagnose-out", "robust-out", "sweep-out"):
        assert (repo / folder).is_dir(), folder
