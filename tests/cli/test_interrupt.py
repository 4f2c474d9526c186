"""Ctrl-C at any moment of ``sizing solve``: one line on stderr, exit 130,
nothing written. Half a second in, the interrupt arrives while the command
line is still importing its libraries (it printed a 46-line traceback
then); three seconds in, it arrives inside the solve."""
from __future__ import annotations

import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from ..conftest import STUDIES


def _command() -> list[str]:
    """The installed console script when there is one (what people run)."""
    script = Path(sys.executable).with_name("sizing")
    return [str(script)] if script.exists() else [sys.executable, "-m", "sizing.cli"]


@pytest.mark.parametrize("after_s", [0.5, 3.0])
def test_ctrl_c_gives_one_line_exit_130_and_writes_nothing(tmp_path, after_s):
    out = tmp_path / "out"
    proc = subprocess.Popen([*_command(), "solve", str(STUDIES / "seed-requirements.toml"), "--out", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=tmp_path)
    time.sleep(after_s)
    proc.send_signal(signal.SIGINT)
    stdout, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "interrupted by SIGINT" in lines[0], err
    assert stdout == ""
    assert sorted(p.name for p in tmp_path.iterdir()) == [], "something was written"


def test_ctrl_c_while_the_outputs_are_swapped_in_exits_130_with_them_complete(tmp_path, monkeypatch):
    """Signals are held back for the renames; the one that arrives then is
    delivered right after, so the run still ends interrupted (it exited 0),
    and the outputs are the new ones, whole."""
    import os

    from sizing.io import atomic

    from ..conftest import FAST_REQUIREMENTS, run_cli
    req = tmp_path / "req.toml"
    req.write_text(FAST_REQUIREMENTS)
    out = tmp_path / "out"
    real = os.replace

    def replace_under_a_signal(src, dst):
        if Path(dst) == out:                  # the swap of the new folder into place
            os.kill(os.getpid(), signal.SIGINT)
        return real(src, dst)
    monkeypatch.setattr(atomic.os, "replace", replace_under_a_signal)
    code, _, err = run_cli("solve", req, "--out", out, "--quiet")
    assert code == 130 and len(err.strip().splitlines()) == 1 and "SIGINT" in err, err
    assert {p.name for p in out.iterdir()} >= {"results.json", "report.html", "candidates.csv"}
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []
