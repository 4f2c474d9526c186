"""The one output writer (sizing/io/atomic.py) and the hostile paths:
--out naming a file, a folder holding a file named like an output
subfolder, an input; SIGINT/SIGTERM during a command; never a mix of old
and new outputs, nothing left behind."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest

from sizing.errors import InputError
from sizing.io import atomic
from sizing.io.atomic import check_folder, write_files, write_folder

from ..conftest import FAST_REQUIREMENTS as FAST_REQ, STUDIES, run_cli

def leftovers(folder):
    """Temporary files or folders the writer would leave (names start with '.')."""
    return [p.name for p in folder.iterdir() if p.name.startswith(".")]


def one_line_exit_2(code, err, *words):
    assert code == 2, err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    for word in words:
        assert word in err, err


@pytest.fixture
def req(tmp_path):
    path = tmp_path / "req.toml"
    path.write_text(FAST_REQ)
    return path


def test_out_naming_an_existing_file(tmp_path, req):
    target = tmp_path / "results"
    target.write_text("mine")
    one_line_exit_2(*run_cli("solve", req, "--out", target, "--quiet")[::2], "--out", "expected a folder, got a file")
    assert target.read_text() == "mine"


def test_out_below_a_file(tmp_path, req):
    (tmp_path / "f").write_text("x")
    one_line_exit_2(*run_cli("solve", req, "--out", tmp_path / "f" / "sub", "--quiet")[::2], "--out", "a file")


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write anywhere")
def test_out_in_an_unwritable_folder(tmp_path, req):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        one_line_exit_2(*run_cli("solve", req, "--out", locked / "o", "--quiet")[::2], "not writable")
    finally:
        locked.chmod(0o700)


def test_out_on_a_read_only_file_system(tmp_path):
    # /proc refuses new entries even to root: the write fails, one line, exit 2
    with pytest.raises(InputError, match="cannot write|not writable"):
        write_folder("/proc/sizing-out", {"a.txt": "x"})


def test_out_folder_holding_a_file_named_like_an_output_subfolder(tmp_path, req):
    out = tmp_path / "o"
    out.mkdir()
    (out / "catalog").write_text("not a folder")
    start = time.monotonic()
    one_line_exit_2(*run_cli("solve", req, "--out", out, "--quiet")[::2], "catalog", "expected a folder")
    assert time.monotonic() - start < 20          # refused before the solve, not after
    assert (out / "catalog").read_text() == "not a folder" and leftovers(tmp_path) == []


def test_fit_out_naming_a_folder(tmp_path):
    runs = sorted((STUDIES / "campaigns" / "piezo-prototype" / "runs").glob("*.csv"))
    one_line_exit_2(*run_cli("fit", "hysteresis", *runs, "--out", tmp_path)[::2], "--out", "got a folder")


def test_fit_out_naming_one_of_its_inputs_is_refused(tmp_path):
    victim = tmp_path / "victim.csv"
    victim.write_bytes((STUDIES / "campaigns" / "piezo-prototype" / "runs" / "ramp.csv").read_bytes())
    before = victim.read_bytes()
    one_line_exit_2(*run_cli("fit", "hysteresis", victim, "--out", victim)[::2], "victim.csv", "inputs")
    assert victim.read_bytes() == before
    # the same file reached through another path is still the input
    one_line_exit_2(*run_cli("fit", "hysteresis", victim, "--out", tmp_path / "." / "victim.csv")[::2], "inputs")
    # and --report cannot name it either
    one_line_exit_2(*run_cli("fit", "hysteresis", victim, "--out", tmp_path / "f.toml", "--report", victim)[::2], "inputs")
    assert victim.read_bytes() == before


def test_out_folder_holding_the_input_is_refused(tmp_path, req):
    one_line_exit_2(*run_cli("solve", req, "--out", tmp_path, "--quiet")[::2], "holds the input")


def test_swap_replaces_every_output_and_keeps_other_files(tmp_path):
    out = tmp_path / "o"
    write_folder(out, {"results.json": "old", "report.html": "old", "catalog/a.toml": "old"})
    (out / "notes.txt").write_text("mine")
    write_folder(out, {"results.json": "new", "report.html": "new", "catalog/b.toml": "new"})
    assert (out / "results.json").read_text() == "new" and (out / "report.html").read_text() == "new"
    assert sorted(p.name for p in (out / "catalog").iterdir()) == ["b.toml"]   # the old subfolder is gone whole
    assert (out / "notes.txt").read_text() == "mine"
    assert leftovers(tmp_path) == []


def test_failure_while_writing_leaves_the_old_set(tmp_path):
    out = tmp_path / "o"
    write_folder(out, {"a.txt": "old", "b.txt": "old"})

    def boom():
        raise RuntimeError("renderer failed")
    with pytest.raises(RuntimeError):
        write_folder(out, {"a.txt": "new", "b.txt": boom})
    assert (out / "a.txt").read_text() == "old" and (out / "b.txt").read_text() == "old"
    assert leftovers(tmp_path) == []


def test_loose_files_roll_back_when_a_rename_fails(tmp_path, monkeypatch):
    a, b = tmp_path / "a.toml", tmp_path / "a.html"
    write_files({a: "old", b: "old"})
    real, calls = os.replace, []

    def flaky(src, dst):
        calls.append(dst)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")
        return real(src, dst)
    monkeypatch.setattr(atomic.os, "replace", flaky)
    with pytest.raises(InputError, match="No space left"):
        write_files({a: "new", b: "new"})
    monkeypatch.setattr(atomic.os, "replace", real)
    assert a.read_text() == "old" and b.read_text() == "old"
    assert leftovers(tmp_path) == []


def test_sigint_while_writing_exits_130_and_keeps_the_old_outputs(tmp_path, req, monkeypatch):
    out = tmp_path / "o"
    assert run_cli("solve", req, "--out", out, "--quiet")[0] == 0
    before = {p.relative_to(out): p.read_bytes() for p in out.rglob("*") if p.is_file()}
    real, written = atomic._write, []

    def interrupted_write(path, content):
        real(path, content)
        written.append(path)
        if len(written) == 2:             # between two files of the new set
            os.kill(os.getpid(), signal.SIGINT)
    monkeypatch.setattr(atomic, "_write", interrupted_write)
    code, _, err = run_cli("solve", req, "--out", out, "--quiet")
    assert code == 130 and len(err.strip().splitlines()) == 1 and "SIGINT" in err, err
    after = {p.relative_to(out): p.read_bytes() for p in out.rglob("*") if p.is_file()}
    assert after == before                                   # no mix of old and new
    assert leftovers(tmp_path) == []


def test_check_folder_refuses_the_current_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(InputError, match="current one"):
        check_folder(".", ["results.json"])


def _wait_until_sigterm_is_caught(pid: int, timeout: float = 60.0) -> None:
    """Linux: poll the process's caught-signal mask (SigCgt) until SIGTERM is in it."""
    status = f"/proc/{pid}/status"
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        with open(status) as handle:
            caught = next(int(line.split()[1], 16) for line in handle if line.startswith("SigCgt:"))
        if caught & (1 << (signal.SIGTERM - 1)):
            return
        time.sleep(0.05)
    raise AssertionError("the command never installed its SIGTERM handler")


@pytest.mark.skipif(not os.path.exists("/proc/self/status"), reason="needs Linux /proc to know when start-up is over")
def test_sigterm_during_solve_exits_143_with_nothing_written(tmp_path):
    req = tmp_path / "req.toml"
    req.write_text((STUDIES / "seed-requirements.toml").read_text())     # the full solve: many seconds
    out = tmp_path / "o"
    proc = subprocess.Popen([sys.executable, "-m", "sizing.cli", "solve", str(req), "--out", str(out), "--quiet"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _wait_until_sigterm_is_caught(proc.pid)     # start-up can take seconds on a loaded machine
    time.sleep(1.0)                             # well inside the solve (it takes many seconds)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 143, err
    assert len(err.strip().splitlines()) == 1 and "SIGTERM" in err, err
    assert not out.exists() and leftovers(tmp_path) == []


def test_a_swallowed_signal_still_stops_the_write(tmp_path):
    # cvxpy's solver import catches every exception, so the Interrupted the
    # SIGTERM handler raised there was lost and the solve ran on and wrote its
    # outputs with exit 0 (seen on a fresh install). The handler also records
    # the signal, and the writer asks before it swaps anything in.
    from sizing.errors import RECEIVED_SIGNALS, Interrupted
    from sizing.io.atomic import write_folder
    RECEIVED_SIGNALS.append(15)
    try:
        with pytest.raises(Interrupted):
            write_folder(tmp_path / "out", {"results.json": "{}"})
    finally:
        RECEIVED_SIGNALS.clear()
    assert not (tmp_path / "out").exists() and not list(tmp_path.iterdir())


def _record_durability(monkeypatch):
    """Log every fsync (by what it flushed) and every rename, in order."""
    import sizing.io.atomic as atomic
    events = []
    real_fsync, real_replace = os.fsync, os.replace

    def fsync(fd):
        events.append(("fsync", os.readlink(f"/proc/self/fd/{fd}")))
        return real_fsync(fd)

    def replace(src, dst):
        events.append(("replace", str(src), str(dst)))
        return real_replace(src, dst)
    monkeypatch.setattr(atomic.os, "fsync", fsync)
    monkeypatch.setattr(atomic.os, "replace", replace)
    return events


def test_a_folder_is_fsynced_before_and_after_its_swap(tmp_path, monkeypatch):
    from sizing.io.atomic import write_folder
    dest = tmp_path / "out"
    write_folder(dest, {"a.txt": "old"})
    events = _record_durability(monkeypatch)
    write_folder(dest, {"a.txt": "new", "sub/b.txt": "b"})
    swap = next(i for i, e in enumerate(events) if e[0] == "replace" and e[2] == str(dest))
    flushed_before = {e[1] for e in events[:swap] if e[0] == "fsync"}
    new = events[swap][1]
    assert {f"{new}/a.txt", f"{new}/sub/b.txt", new, f"{new}/sub"} <= flushed_before   # files, then their folders
    assert ("fsync", str(tmp_path)) in events[swap:]                                   # the renames themselves
    assert (dest / "a.txt").read_text() == "new"


def test_loose_files_are_fsynced_before_and_after_their_rename(tmp_path, monkeypatch):
    from sizing.io.atomic import write_files
    target = tmp_path / "fit.toml"
    target.write_text("old")
    events = _record_durability(monkeypatch)
    write_files({target: "new"})
    rename = next(i for i, e in enumerate(events) if e[0] == "replace" and e[2] == str(target))
    assert any(e[0] == "fsync" and e[1] == events[rename][1] for e in events[:rename])
    assert ("fsync", str(tmp_path)) in events[rename:]
    assert target.read_text() == "new" and [p.name for p in tmp_path.iterdir()] == ["fit.toml"]   # no backup left


def test_no_temporary_name_is_taken_without_creating_it():
    """``tempfile.mktemp`` hands out a name another process can take first."""
    import inspect

    import sizing.io.atomic as atomic
    assert "mktemp(" not in inspect.getsource(atomic).replace("mkstemp(", "").replace("mkdtemp(", "")
