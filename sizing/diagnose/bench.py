"""A campaign made ready to simulate: treated inputs, measured outputs, the
nominal model, and batch simulation of effect-augmented models.

Input treatment (stated in every report): a measured piezo voltage is
smoothed and made monotone between significant reversals (inputs.py)
before it drives the model, because the Bouc-Wen state reacts to every
reversal of its input and raw sensor noise would ratchet it. A DC motor reference is the
controller's own digital command and is used as logged.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..sim import dc_motor as dc_sim
from ..sim import piezohydraulic as ph_sim
from ..sim.rigs import dc_model, piezo_model
from .inputs import describe as describe_treatment
from .inputs import treat_voltage

@dataclass
class PreparedRun:
    name: str
    t: np.ndarray        # (n,) s
    u_raw: np.ndarray    # (n,) V or m, as logged
    u: np.ndarray        # (n,) treated input that drives the model
    y: np.ndarray        # (n,) m, measured position from rest
    holdout: bool

    @property
    def span(self) -> float:
        return float(np.ptp(self.y)) or 1.0


def treat_input(kind: str, t: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, str]:
    """(treated input, one line saying what was done)."""
    if kind == "piezohydraulic":
        return treat_voltage(u), describe_treatment()
    return np.asarray(u, float).copy(), "reference: the controller's digital command, used as logged"


class Bench:
    """Nominal model + prepared runs; simulates many parameter sets at once."""

    def __init__(self, kind: str, rig, runs, holdout: list[str], model=None):
        self.kind = kind
        self.rig = rig
        self.model = model if model is not None else (piezo_model(rig) if kind == "piezohydraulic" else dc_model(rig))
        self.runs: list[PreparedRun] = []
        self.input_treatment = ""
        for run in runs:
            u_raw = run["voltage_V"] if kind == "piezohydraulic" else run["reference_m"]
            u, self.input_treatment = treat_input(kind, run.time, u_raw)
            self.runs.append(PreparedRun(run.name, np.asarray(run.time, float), np.asarray(u_raw, float), u,
                                         np.asarray(run["position_m"], float), run.name in holdout))
        self._nominal = None

    @property
    def train(self) -> list[int]:
        return [i for i, r in enumerate(self.runs) if not r.holdout]

    @property
    def holdout(self) -> list[int]:
        return [i for i, r in enumerate(self.runs) if r.holdout]

    def with_model(self, model) -> "Bench":
        other = object.__new__(Bench)
        other.__dict__.update(self.__dict__)
        other.model = model
        other._nominal = None
        return other

    def _raw(self, model, run: PreparedRun) -> np.ndarray:
        if self.kind == "piezohydraulic":
            return ph_sim.simulate(model, run.t, run.u, run.t)["position_m"]
        return dc_sim.simulate(model, run.t, run.u, run.t)["position_m"]

    def nominal(self) -> list[np.ndarray]:
        """Simulated position (n,) of every run with the nominal model."""
        if self._nominal is None:
            self._nominal = [self._raw(self.model, r)[0] for r in self.runs]
        return self._nominal

    def simulate(self, effects, Z, runs=None) -> list[np.ndarray]:
        """Position (n_cand, n) of each run in ``runs`` (default all) for the
        model augmented with ``effects`` at the unit coordinates Z (n_cand,
        sum of n_par); effects act in order."""
        Z = np.atleast_2d(np.asarray(Z, float))
        n_cand = Z.shape[0]
        runs = range(len(self.runs)) if runs is None else runs
        changes, values, col = {}, [], 0
        for effect in effects:
            v = effect.values(Z[:, col:col + len(effect.params)]) if effect.params else {}
            if not effect.params:
                v = {"_": np.zeros(n_cand)}
            col += len(effect.params)
            values.append(v)
            changes.update(effect.model_changes(self.model, v))
        out = []
        for i in runs:
            run = self.runs[i]
            if changes:
                Y = self._raw(self.model.replace(**changes), run)
                if Y.shape[0] != n_cand:
                    Y = np.broadcast_to(Y, (n_cand, len(run.t))).copy()
            else:
                Y = np.repeat(self.nominal()[i][None, :], n_cand, axis=0)
            for effect, v in zip(effects, values):
                if effect.post:
                    for c in range(n_cand):
                        Y[c] = effect.measure(run.t, Y[c], {k: a[c] for k, a in v.items()})
            out.append(Y)
        return out
