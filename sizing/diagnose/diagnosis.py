"""The whole diagnosis of a campaign: baseline, where, which effect, how far.

``diagnose_runs`` works on runs in memory (used by the command, the
withheld-effect check and the benchmark); ``Diagnosis.to_json`` gives
diagnosis.json exactly as CONTRACTS.md fixes it, plus extra keys.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from ..sim.signals import nrmse
from . import attribution, where
from .bench import Bench
from .recalibrate import recalibrate as recalibrate_model


@dataclass
class Diagnosis:
    kind: str
    bench: Bench
    baseline_sim: list
    baseline_nrmse: dict
    baseline_holdout: float
    noise_floor: dict
    noise_floor_holdout: float
    where: list
    residual_tests: dict
    fits: list
    verdict: dict
    best_sim: list | None
    recalibration: dict | None = None
    seconds: float = 0.0
    extra: dict = field(default_factory=dict)

    def to_json(self) -> dict:
        candidates = []
        for f in self.fits:
            shrink = 1.0 - f.nrmse_holdout / self.baseline_holdout if self.baseline_holdout > 0 else 0.0
            candidates.append({"effect": f.name, "params": f.params, "nrmse_train": f.nrmse_train,
                               "nrmse_holdout": f.nrmse_holdout, "shrink_holdout": float(shrink),
                               "params_ci95": f.ci, "nrmse_holdout_runs": f.nrmse_runs,
                               "fitted": f.message != "screened only"})
        baseline = {"nrmse": self.baseline_nrmse, "nrmse_holdout": self.baseline_holdout,
                    "noise_floor_nrmse": self.noise_floor, "noise_floor_holdout": self.noise_floor_holdout,
                    "input_treatment": self.bench.input_treatment}
        if self.recalibration:
            baseline["recalibration"] = self.recalibration
        return {"baseline": baseline, "where": self.where, "candidates": candidates, "verdict": self.verdict,
                "residual_tests": self.residual_tests,
                "kind": self.kind, "holdout": [r.name for r in self.bench.runs if r.holdout],
                "seconds": self.seconds}


def diagnose_runs(kind: str, rig, runs, holdout: list[str], recalibrate: list[str] | None = None,
                  seed: int = 0, pairs: bool = True) -> Diagnosis:
    start = time.perf_counter()
    bench = Bench(kind, rig, runs, holdout)
    recal = None
    if recalibrate:
        recal_info, model = recalibrate_model(bench, recalibrate)
        recal = recal_info
        bench = bench.with_model(model)
    sims = bench.nominal()
    base = {r.name: float(nrmse(r.y, s)) for r, s in zip(bench.runs, sims)}
    base_ho = float(np.mean([base[bench.runs[i].name] for i in bench.holdout]))
    floor = attribution.noise_floor(bench)
    floor_ho = float(np.mean(floor[bench.holdout]))
    fits = attribution.attribute(bench, base_ho, floor_ho, seed=seed, pairs=pairs)
    verdict = attribution.verdict(base_ho, floor_ho, fits)
    best_sim = [y[0] for y in bench.simulate(fits[0].effects, fits[0].z[None, :])] if fits else None
    return Diagnosis(kind=kind, bench=bench, baseline_sim=sims, baseline_nrmse=base, baseline_holdout=base_ho,
                     noise_floor={r.name: float(v) for r, v in zip(bench.runs, floor)},
                     noise_floor_holdout=floor_ho, where=where.gap_map(bench, sims),
                     residual_tests=where.residual_tests(bench, sims), fits=fits, verdict=verdict,
                     best_sim=best_sim, recalibration=recal, seconds=time.perf_counter() - start)
