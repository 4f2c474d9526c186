"""The whole diagnosis of a campaign: baseline, where, which effect, how far.

``diagnose_runs`` works on runs in memory (used by the command, the
withheld-effect check and the benchmark); ``Diagnosis.to_json`` gives
diagnosis.json exactly as docs/formats.md fixes it, plus extra keys.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from . import attribution, events, judge, where
from .floor import campaign_form_floor, form_floor, noise_floor, total_floor
from .bench import Bench
from .effects import library
from .recalibrate import DEFAULT, nuisance, recalibrate as recalibrate_model
from .settings import DEFAULT as DEFAULT_SETTINGS, Settings
from .verdict import Verdict



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
    verdict: Verdict
    best_sim: list | None
    recalibration: dict | None = None
    seconds: float = 0.0
    extra: dict = field(default_factory=dict)
    baseline_channels: dict = field(default_factory=dict)

    def to_json(self) -> dict:
        candidates = []
        for f in self.fits:
            shrink = 1.0 - f.nrmse_holdout / self.baseline_holdout if self.baseline_holdout > 0 else 0.0
            by_channel = {c: float(1.0 - v / self.baseline_channels[c]) if self.baseline_channels.get(c) else 0.0
                          for c, v in f.nrmse_channels.items()}
            candidates.append({"effect": f.name, "form": f.form, "params": f.params, "nrmse_train": f.nrmse_train,
                               "nrmse_holdout": f.nrmse_holdout, "shrink_holdout": float(shrink),
                               "nrmse_holdout_channels": f.nrmse_channels,
                               "shrink_holdout_channels": by_channel,
                               "params_ci95": f.ci, "nrmse_holdout_runs": f.nrmse_runs,
                               "fitted": f.message != "screened only"})
        baseline = {"nrmse": self.baseline_nrmse, "nrmse_holdout": self.baseline_holdout,
                    "noise_floor_nrmse": self.noise_floor, "noise_floor_holdout": self.noise_floor_holdout,
                    "input_treatment": self.bench.input_treatment,
                    "channels": list(self.bench.channels), "nrmse_holdout_channels": self.baseline_channels,
                    "combined_measure": "sqrt(mean over channels of (f_pos / f_c)^2 NRMSE_c^2), f_c the "
                                        "white-noise floor of channel c (README, diagnose)"}
        if self.recalibration:
            baseline["recalibration"] = self.recalibration
        return {"baseline": baseline, "where": self.where, "candidates": candidates, "verdict": self.verdict.to_dict(),
                "residual_tests": self.residual_tests,
                "kind": self.kind, "holdout": [r.name for r in self.bench.runs if r.holdout],
                "seconds": self.seconds}


def check_runs(kind: str, bench: Bench, runs) -> None:
    """Bad input the diagnosis cannot judge: exit 2 with one line."""
    for run in runs:
        name = str(run.path) if getattr(run, "path", None) else run.name
        logged = set(run.columns)
        if getattr(run, "path", None) is not None:      # the reader keeps only its technology's columns
            with open(run.path, encoding="utf-8") as handle:
                logged |= {c.strip() for c in handle.readline().split(",")}
        if "current_A" in logged:
            if kind != "dc_motor":
                raise InputError(name, "current_A", f"a current channel on a {kind} rig; "
                                 "only dc_motor runs log the controller current")
            bad = ~np.isfinite(np.asarray(run.columns.get("current_A", []), float))
            if bad.any():
                raise InputError(name, f"current_A, sample {int(np.argmax(bad)) + 1}",
                                 "expected a finite current, got NaN or inf")
    longest, which = 0.0, ""
    for effect in library(kind):
        tau = effect.time_constant(bench.rig, bench.model)
        if tau > longest:
            longest, which = tau, effect.name
    for run, r in zip(runs, bench.runs):
        duration = float(r.t[-1] - r.t[0])
        if duration < DEFAULT_SETTINGS.min_periods * longest:
            name = str(run.path) if getattr(run, "path", None) else run.name
            raise InputError(name, "time_s", f"the run lasts {duration:.3g} s, shorter than the longest effect "
                             f"time constant {longest:.3g} s ({which}); record longer runs")


def floors_by_channel(bench, nominal, noise_position: float, forms, settings: Settings = DEFAULT_SETTINGS) -> dict:
    """{channel: {"baseline", "noise", "form", "blocks"}} of the holdout runs:
    the nominal's NRMSE, the noise floor (the position's from
    floor.noise_floor, another channel's from its second differences), the
    model-form floor and the baseline's residual block energies of the
    channel. The model-form floor of the position is the prior
    (settings.form_floor_prior: what independent simulators' null cases
    leave, which the campaign cannot measure); that of another channel is
    estimated from the campaign (floor.form_floor), because the prior is a
    share of the position's span and says nothing of a current's."""
    E = bench.channel_nrmse([nominal[i][None] for i in bench.holdout], bench.holdout)[0]
    noise = np.mean([bench.channel_floor(i) for i in bench.holdout], axis=0)
    out = {}
    for k, c in enumerate(bench.channels):
        out[c] = {"baseline": float(np.mean(E[:, k])), "noise": noise_position if k == 0 else float(noise[k]),
                  "form": float(forms[k]) if forms is not None and k > 0 else settings.form_floor_prior,
                  "blocks": judge.block_energy(bench, [nominal[i] for i in bench.holdout], bench.holdout, channel=k,
                                               settings=settings)}
    return out


def training_gap(combined: np.ndarray, floor: np.ndarray, train: list[int]) -> dict | None:
    """{"baseline", "noise"}: the nominal's combined NRMSE and the noise
    floor over the training runs (root mean square over them, as a
    candidate's training NRMSE is), for judge.no_gap_on_training; None
    without training runs."""
    if not train:
        return None
    return {"baseline": float(np.sqrt(np.mean(np.asarray(combined, float)[train] ** 2))),
            "noise": float(np.sqrt(np.mean(np.asarray(floor, float)[train] ** 2)))}


def stated_form_floor(verdict: Verdict, campaign: float | None, settings: Settings = DEFAULT_SETTINGS) -> Verdict:
    """The verdict with the position's model-form floor stated: the prior
    it was judged against and the campaign's own reading
    (floor.campaign_form_floor), in ``form_floor_position``; an
    "undetectable" verdict says both in its reason."""
    stated = {"prior": settings.form_floor_prior, "campaign": campaign,
              "campaign_from": "the best fitted candidate's training NRMSE beyond the training runs' noise floor"}
    verdict = verdict.with_details(form_floor_position=stated)
    if verdict.status != "undetectable" or campaign is None:
        return verdict
    return verdict.replace(reasons=verdict.reasons + (
        f"the model-form floor of the position is the prior {settings.form_floor_prior:g} of the span "
        f"(settings.form_floor_prior); on this campaign the library's best account leaves {campaign:.4f} on the "
        f"training runs beyond their noise",))


def diagnose_runs(kind: str, rig, runs, holdout: list[str], recalibrate: list[str] | None = None,
                  seed: int = 0, pairs: bool = True, settings: Settings = DEFAULT_SETTINGS) -> Diagnosis:
    """``recalibrate``: None re-fits the default parameters (recalibrate.DEFAULT)
    on the training runs first; [] turns re-calibration off. ``settings``:
    the thresholds (settings.py)."""
    start = time.perf_counter()
    bench = Bench(kind, rig, runs, holdout)
    check_runs(kind, bench, runs)
    recal = None
    names = DEFAULT[kind] if recalibrate is None else list(recalibrate)
    if names:
        recal_info, model = recalibrate_model(bench, names)
        recal = recal_info
        effect = nuisance(kind, bench.model, names)
        bench = bench.with_model(model)
        # effects are screened and fitted with the re-calibrated parameters
        # free, starting from their stated values (an effect the stated
        # nominal lacks is not hidden by a re-calibration that absorbed it);
        # a second screening start: the re-calibrated values (an effect the
        # stated values would make the screen over-size, e.g. friction that
        # offsets a mis-stated d33, is screened where the nominal fits best)
        bench.nuisance = (effect, effect.unit({n: recal_info["nominal"][n] for n in names}),
                          effect.unit(recal_info["recalibrated"]))
    sims = bench.nominal()
    nominal = bench.nominal_channels()
    all_runs = list(range(len(bench.runs)))
    combined = bench.combined_nrmse([y[None] for y in nominal], all_runs)[0]
    base = {r.name: float(v) for r, v in zip(bench.runs, combined)}
    base_ho = float(np.mean([base[bench.runs[i].name] for i in bench.holdout]))
    E = bench.channel_nrmse([nominal[i][None] for i in bench.holdout], bench.holdout)[0]
    base_channels = {c: float(np.mean(E[:, k])) for k, c in enumerate(bench.channels)}
    floor = noise_floor(bench)
    floor_ho = float(np.mean(floor[bench.holdout]))
    channels = floors_by_channel(bench, nominal, floor_ho, form_floor(bench), settings)
    form_ho = None      # the combined measure keeps the prior model-form floor (docs/diagnosis-settings.md)
    fits = attribution.attribute(bench, base_ho, floor_ho, seed=seed, pairs=pairs, form_floor=form_ho, settings=settings)
    base_blocks = judge.block_energy(bench, [nominal[i] for i in bench.holdout], bench.holdout, settings=settings)
    shortest = min((float(bench.runs[i].t[-1] - bench.runs[i].t[0]) for i in bench.train), default=None)
    chosen = judge.pick(fits, seed, total_floor(floor_ho, form_ho, settings), settings, noise=floor_ho,
                        channels=channels)
    best_sim = [y[0] for y in bench.simulate_channels(chosen.effects, chosen.z[None, :])] if chosen else None
    line = judge.gap_lines(bench, [nominal[i][0] for i in bench.holdout],
                              None if best_sim is None else [best_sim[i][0] for i in bench.holdout])
    inputs = dict(baseline_holdout=base_ho, floor_holdout=floor_ho, fits=fits, baseline_blocks=base_blocks,
                  seed=seed, run_length=shortest, line=line, form_floor=form_ho, channels=channels,
                  training=training_gap(combined, floor, bench.train))
    verdict = judge.verdict(**inputs, settings=settings)
    # a gap no candidate removes point by point: an effect whose response
    # is a train of events (a seal's slips) is judged on them
    verdict, evented = judge.revisit(verdict, (lambda: events.event_verdict(bench, base_ho, settings, seed),))
    if evented is not None:
        effect, z = evented
        best_sim = [y[0] for y in bench.simulate_channels([effect], z[None, :])]
    verdict = stated_form_floor(verdict, campaign_form_floor(fits, floor, bench.train), settings)
    floors = {c: {k: v for k, v in ch.items() if k != "blocks"} for c, ch in channels.items()}
    named = verdict.status in ("explained", "partial") and best_sim is not None
    left = (where.gap_map(bench, best_sim if named else nominal, max_entries=5)
            if named or verdict.status in ("unexplained", "undetectable") else None)
    verdict = verdict.with_details(floors=floors, **({} if left is None else {"remaining": [
        {k: e[k] for k in ("run", "label", "share", "t_start_s", "t_end_s", "channel")} for e in left]}))
    return Diagnosis(kind=kind, bench=bench, baseline_sim=sims, baseline_nrmse=base, baseline_holdout=base_ho,
                     noise_floor={r.name: float(v) for r, v in zip(bench.runs, floor)},
                     noise_floor_holdout=floor_ho, where=where.gap_map(bench, nominal),
                     residual_tests=where.residual_tests(bench, sims), fits=fits, verdict=verdict,
                     best_sim=[y[0] for y in best_sim] if best_sim is not None else None,
                     recalibration=recal, seconds=time.perf_counter() - start,
                     extra={"best_channels": best_sim, "verdict_inputs": inputs}, baseline_channels=base_channels)
