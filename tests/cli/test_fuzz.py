"""Fuzz every command: random mutations of valid example files.

Each example copies small, valid inputs of one command into a fresh folder,
mutates them one to three times (a value replaced by a hostile one, a line deleted,
duplicated or cut, a byte-order mark, CRLF, a separator swapped, the file
emptied or turned into a symlink loop) and runs the command in-process.
Every outcome must be exit 0, or exit 2 with one error line and no
traceback, and on exit 2 nothing may be left behind (no output, no
temporary file). Examples are few and derandomised (a fixed seed), so the
whole file stays well under a minute.
"""
from __future__ import annotations

import os
import re
import shutil
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from sizing.physics.bouc_wen import BoucWen, free_displacement
from sizing.sim.dc_motor import DCMotorModel, simulate

from ..conftest import CATALOGS, FAST_REQUIREMENTS, SEED_BOUC_WEN, STUDIES, run_cli
from ..io.test_catalog_tracking import _SHEET as SHEET

HOSTILE_VALUES = [
    '"1/0 mm"', '"1 mm/0"', '"40 (mm"', '"50 delta_degC"', '"50 %"', '"1e30 mm"', "1e300", "nan", "inf", "-1", "0",
    "[]", "3", '"3"', '""', "true", '"1 ' + "(" * 200 + 'm"', '"1 m**2**2**2**2"', "{}", "[1, [2]]",
    '"' + "x" * 1000 + '"', "-0.0", "1e-300", '"1e9 Hz"', '"1e9 s"', '"40 kg"', '"2026-13-45"',
]
HOSTILE_CELLS = ["1e300", "nan", "", '"1"', "abc", "1;2", "-1e9", "1e-300", ",,,", "0x10", "inf", '"', "1\t2"]


def _csv(path: Path, header, columns) -> Path:
    rows = [",".join(f"{v:.7g}" for v in row) for row in zip(*columns)]
    path.write_text(",".join(header) + "\n" + "\n".join(rows) + "\n")
    return path


@pytest.fixture(scope="module")
def base(tmp_path_factory) -> Path:
    """Small valid inputs of every command, built once."""
    root = tmp_path_factory.mktemp("fuzz-base")
    (root / "req.toml").write_text(FAST_REQUIREMENTS)
    (root / "dc.toml").write_text((STUDIES / "seed-dc-step.toml").read_text())
    t = np.arange(0.0, 0.4, 1e-3)
    v = 75.0 * (1 - np.cos(2 * np.pi * 5 * t))
    _csv(root / "p.csv", ["time_s", "voltage_V", "position_m"], [t, v, free_displacement(t, v, BoucWen(**SEED_BOUC_WEN))])
    camp = root / "camp"
    (camp / "runs").mkdir(parents=True)
    shutil.copy(STUDIES / "campaigns" / "dc-motor" / "rig.toml", camp / "rig.toml")
    model = DCMotorModel(c1=-25.5552, c2=2987.02, lead=0.002, kp=4000.0, ki=8000.0, kd=90.0,
                         derivative_on_measurement=1.0, current_limit=10.0, torque_constant=0.05)
    t = np.arange(0.0, 0.3, 1e-3)
    for name, step in (("a", 0.004), ("b", 0.002)):
        ref = np.where(t >= 0.02, step, 0.0)
        _csv(camp / "runs" / f"{name}.csv", ["time_s", "reference_m", "position_m"],
             [t, ref, simulate(model, t, ref)["position_m"][0]])
    shutil.copytree(CATALOGS, root / "cat")
    (root / "sheet.csv").write_text(SHEET)
    return root


# command: (arguments with {d} for the example's folder, files that may be mutated, output that must not linger)
COMMANDS = {
    "solve": (["solve", "{d}/req.toml", "--out", "{d}/out", "--quiet"], ["req.toml"], "out"),
    "evaluate": (["evaluate", "{d}/dc.toml", "--json"], ["dc.toml"], None),
    "fit-hysteresis": (["fit", "hysteresis", "{d}/p.csv", "--starts", "1", "--operators", "4", "--out", "{d}/fit.toml"],
                       ["p.csv"], "fit.toml"),
    "fit-dc-motor": (["fit", "dc-motor", "{d}/camp/runs/a.csv", "--rig", "{d}/camp/rig.toml", "--starts", "1",
                      "--out", "{d}/motor.toml"], ["camp/runs/a.csv", "camp/rig.toml"], "motor.toml"),
    "diagnose": (["diagnose", "{d}/camp", "--holdout", "b", "--out", "{d}/out"],
                 ["camp/rig.toml", "camp/runs/a.csv", "camp/runs/b.csv"], "out"),
    "catalog-validate": (["catalog", "validate", "{d}/cat"],
                         ["cat/stacks.toml", "cat/seals.toml", "cat/dc_actuators.toml"], None),
    "catalog-add": (["catalog", "add", "stack", "{d}/sheet.csv", "--catalog", "{d}/cat"], ["sheet.csv"], None),
    "robust": (["robust", "{d}/req.toml", "--samples", "4", "--designs", "1", "--workers", "0", "--out", "{d}/out",
                "--quiet"], ["req.toml"], "out"),
    "sweep": (["sweep", "{d}/req.toml", "--vary", "stroke=38mm..40mm:2", "--workers", "0", "--out", "{d}/out",
               "--quiet"], ["req.toml"], "out"),
}
# examples per command: the cheap ones get more (a valid diagnose takes seconds)
EXAMPLES = {"diagnose": 4, "solve": 12, "evaluate": 30, "catalog-validate": 20, "fit-hysteresis": 15,
            "fit-dc-motor": 12, "catalog-add": 15, "robust": 6, "sweep": 5}


def _lines(text: str) -> list[str]:
    return text.splitlines(keepends=True)


def mutate(path: Path, draw) -> None:
    """Apply one drawn mutation to ``path`` in place."""
    text = path.read_bytes().decode("utf-8", errors="replace")    # an earlier mutation may have added bytes
    lines = _lines(text)
    kind = draw(st.sampled_from(["value"] * 8 + ["delete", "duplicate", "cut", "bom", "crlf",
                                                 "separator", "empty", "loop", "bytes"]))
    i = draw(st.integers(0, max(len(lines) - 1, 0)))
    if kind == "value" and path.suffix == ".toml":
        keyed = [k for k, line in enumerate(lines) if re.match(r"\s*[\w.\"-]+\s*=", line)]
        if keyed:
            k = keyed[i % len(keyed)]
            lines[k] = lines[k].split("=", 1)[0] + "= " + draw(st.sampled_from(HOSTILE_VALUES)) + "\n"
    elif kind == "value" and lines:
        cells = lines[i].rstrip("\r\n").split(",")
        cells[draw(st.integers(0, len(cells) - 1))] = draw(st.sampled_from(HOSTILE_CELLS))
        lines[i] = ",".join(cells) + "\n"
    elif kind == "delete" and lines:
        del lines[i]
    elif kind == "duplicate" and lines:
        lines.insert(i, lines[i])
    elif kind == "cut":
        text = text[:draw(st.integers(0, len(text)))]
        lines = _lines(text)
    elif kind == "bom":
        lines = ["\ufeff"] + lines
    elif kind == "crlf":
        lines = [line.replace("\n", "\r\n") for line in lines]
    elif kind == "separator" and lines:
        lines[i] = lines[i].replace(",", draw(st.sampled_from([";", "\t", ", "])))
    elif kind == "empty":
        lines = []
    elif kind == "loop":
        path.unlink()
        os.symlink(path, path)
        return
    elif kind == "bytes":
        pos = draw(st.integers(0, len(text)))
        path.write_bytes(text[:pos].encode() + draw(st.binary(min_size=1, max_size=8)) + text[pos:].encode())
        return
    path.write_text("".join(lines), encoding="utf-8", newline="")


def check_outcome(code: int, err: str, folder: Path, output: str | None) -> None:
    assert code in (0, 2), f"exit {code}: {err[-2000:]}"
    assert "Traceback" not in err, err[-2000:]
    if code == 2:
        errors = [line for line in err.splitlines() if line.strip() and not line.startswith("warning:")]
        assert len(errors) == 1 and errors[0].startswith("error: "), err[-2000:]
        if output is not None:
            assert not (folder / output).exists(), f"{output} left behind on exit 2: {errors[0]}"
        assert not [p for p in folder.iterdir() if p.name.startswith(".")], "temporary files left behind"


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_fuzz_command(command, base):
    args, targets, output = COMMANDS[command]

    scale = float(os.environ.get("SIZING_FUZZ_SCALE", "1"))     # e.g. 10 for a longer hunt, by hand
    @settings(max_examples=max(1, int(EXAMPLES[command] * scale)), deadline=None,
              derandomize=os.environ.get("SIZING_FUZZ_SEED") is None, database=None,
              suppress_health_check=list(HealthCheck))
    @given(data=st.data())
    def run(data):
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp)
            for entry in base.iterdir():
                (shutil.copytree if entry.is_dir() else shutil.copy)(entry, folder / entry.name)
            for _ in range(data.draw(st.integers(1, 3))):
                target = folder / data.draw(st.sampled_from(targets))
                if target.is_symlink():
                    break
                mutate(target, data.draw)
            code, _, err = run_cli(*[a.format(d=folder) for a in args])
            check_outcome(code, err, folder, output)

    run()
