"""``sizing diagnose``: where a campaign's runs and the model disagree, which
unmodelled effect explains it and how far the gap shrinks; ``--check``: the
withheld-effect check on the campaign's own excitations and rig."""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, ClassVar

from . import output
from .output import PLOTLY_FILE, plotly_js

if TYPE_CHECKING:                   # the types alone: not imported when the module loads
    from ..diagnose.diagnosis import Diagnosis

DIAGNOSE_OUTPUTS = ("diagnosis.json", "diagnosis.html", PLOTLY_FILE)


@dataclass(frozen=True)
class DiagnoseResult:
    """The diagnosis (``sizing.diagnose``) of a campaign and the title of its
    page. Its attributes (``verdict``, ``fits``, ...) read through to it."""

    diagnosis: Diagnosis
    title: str
    inputs: tuple = ()
    layout: ClassVar[str] = "folder"

    def __getattr__(self, name):
        if name.startswith("__") or name == "diagnosis":
            raise AttributeError(name)
        return getattr(self.diagnosis, name)

    @property
    def verdict_dict(self) -> dict:
        """The verdict as a dict, whatever type the diagnosis gives it."""
        verdict = self.diagnosis.verdict
        return verdict.to_dict() if hasattr(verdict, "to_dict") else dict(verdict)

    def to_json(self) -> dict:
        """diagnosis.json."""
        return self.diagnosis.to_json()

    def files(self) -> dict:
        from ..report.diagnose_html import render
        return {"diagnosis.json": json.dumps(self.to_json(), indent=2),
                "diagnosis.html": render(self.diagnosis, self.title), PLOTLY_FILE: plotly_js}


def diagnose(campaign_dir: str | Path, holdout: list[str], out_dir: str | Path | None = None,
             recalibrate: list[str] | None = None, seed: int = 0) -> DiagnoseResult:
    """Diagnose the sim-to-real gap of a campaign (docs/formats.md). Writes
    diagnosis.json and diagnosis.html into ``out_dir`` when given."""
    return output.produce(DIAGNOSE_OUTPUTS, out_dir, (campaign_dir,),
                          lambda: run_diagnose(campaign_dir, holdout, recalibrate, seed))


def run_diagnose(campaign_dir, holdout, recalibrate=None, seed: int = 0) -> DiagnoseResult:
    """The diagnosis without writing anything (``diagnose``'s arguments)."""
    from ..io.campaign import campaign_split, load_campaign

    campaign = load_campaign(campaign_dir)
    campaign_split(campaign, holdout)
    from ..diagnose.diagnosis import diagnose_runs     # numba and scipy load once the campaign reads well
    found = diagnose_runs(campaign.kind, campaign.rig, campaign.runs, list(holdout), recalibrate=recalibrate,
                          seed=seed)
    return DiagnoseResult(found, f"Sim-to-real gap: {Path(campaign_dir).name}", (campaign_dir,))


def diagnose_check(campaign_dir: str | Path, holdout: list[str] | None = None, seed: int = 0, progress=None,
                   workers: int = 1):
    """The withheld-effect check on a campaign's own excitations and rig
    (``diagnose.check``: its result has ``table()``, ``matrix()``,
    ``accuracy``); ``workers`` cases at once, each in its own process;
    writes no file."""
    from ..io.campaign import campaign_split, load_campaign

    campaign = load_campaign(campaign_dir)
    holdout = list(holdout) if holdout else [campaign.runs[-1].name]
    campaign_split(campaign, holdout)
    from ..diagnose.bench import Bench
    from ..diagnose.check import campaign_noise, check_runs, clean_inputs
    bench = Bench(campaign.kind, campaign.rig, campaign.runs, holdout)
    return check_runs(campaign.kind, campaign.rig, clean_inputs(bench), holdout, campaign_noise(bench, seed),
                      seed=seed, progress=progress, workers=workers)
