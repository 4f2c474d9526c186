"""A test campaign folder: rig.toml and runs/*.csv (docs/formats.md)."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from .rig import Rig, load_rig
from ..limits import check_steps, dc_steps, piezo_steps
from .runs import Run, read_runs, split_holdout


@dataclass
class Campaign:
    folder: Path
    rig: Rig
    runs: list[Run]

    @property
    def kind(self) -> str:
        return self.rig.kind


def load_campaign(folder: str | Path) -> Campaign:
    folder = Path(folder)
    if not folder.is_dir():
        raise InputError(str(folder), None, "expected a campaign folder with rig.toml and runs/*.csv")
    rig_path = folder / "rig.toml"
    if not rig_path.exists():
        raise InputError(str(rig_path), None, "missing: a campaign needs rig.toml (the nominal model)")
    rig = load_rig(rig_path)
    paths = sorted((folder / "runs").glob("*.csv"))
    if not paths:
        raise InputError(str(folder / "runs"), None, "no runs: expected runs/NAME.csv files")
    runs = read_runs(paths, rig.kind)
    duration = sum(float(r.time[-1] - r.time[0]) for r in runs)
    if rig.kind == "dc_motor":   # refuse a rig rate that would never finish ("1e9 Hz")
        check_steps(dc_steps(duration, rig.controller.rate), str(rig_path), "[controller].rate",
                    "controller steps per simulation of the runs")
    else:                        # the oil's 50 us sub-steps over every run's time span
        check_steps(piezo_steps(duration), str(folder / "runs"), "time_s",
                    "simulation steps per simulation of the runs (their time spans x 20 kHz)")
    return Campaign(folder=folder, rig=rig, runs=runs)


def campaign_split(campaign: Campaign, holdout: list[str] | None):
    return split_holdout(campaign.runs, holdout, str(campaign.folder))
