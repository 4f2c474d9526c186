"""A campaign made ready to simulate: treated inputs, measured outputs, the
nominal model, and batch simulation of effect-augmented models.

Input treatment (stated in every report): a measured piezo voltage is
smoothed and made monotone between significant reversals (inputs.py)
before it drives the model, because the Bouc-Wen state reacts to every
reversal of its input and raw sensor noise would ratchet it. A DC motor reference is the
controller's own digital command and is used as logged.

Channels: position always; a dc_motor campaign whose every run logs
``current_A`` is also judged on the current (the simulator's controller
output). The combined measure of a run is
    C = sqrt(mean_c (f_pos / f_c)^2 NRMSE_c^2)
where f_c is the white-noise floor of channel c (robust rms of its second
differences over its span, from the data): each channel is normalised by its
own noise floor and the result is scaled back to position NRMSE units, so a
position-only campaign keeps C = NRMSE of the position.

The current is a command held over each control period and it jumps at a
reference step; the logged reference (sampled at the log rate) cannot say
on which side of a log sample the controller saw the step, so two faithful
simulators of one servo put such a jump one sample apart (a 10 A jump one
sample late is 90 % of a null campaign's current residual). The current's
residual is therefore measured to the band the simulated current spans over
the sample and its two neighbours (``timing_band``): zero for a jump one
sample early or late, the plain difference wherever the current varies
little from sample to sample (levels, where friction and saturation show).
"""
from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass

import numpy as np

from ..sim import dc_motor as dc_sim
from ..sim import piezohydraulic as ph_sim
from ..sim.rigs import dc_model, piezo_model
from .inputs import describe as describe_treatment
from .inputs import hold_rate, noise_sigma, treat_voltage

CHANNEL_UNITS = {"position_m": "m", "current_A": "A"}
MEMO_BATCH = 8      # distinct models in a batch that Bench._remembered serves (a screen's are not kept)
MEMO_KEPT = 128     # simulated runs it keeps (at most ~25 MB on a 12 000-sample campaign)

def timing_band(measured: np.ndarray, simulated: np.ndarray) -> np.ndarray:
    """measured - the nearest value in [min, max] of ``simulated`` over each
    sample and its two neighbours (last axis): a one-sample timing tolerance."""
    before = np.concatenate([simulated[..., :1], simulated[..., :-1]], axis=-1)
    after = np.concatenate([simulated[..., 1:], simulated[..., -1:]], axis=-1)
    low = np.minimum(np.minimum(before, simulated), after)
    high = np.maximum(np.maximum(before, simulated), after)
    return measured - np.clip(measured, low, high)


@dataclass
class PreparedRun:
    name: str
    t: np.ndarray        # (n,) s
    u_raw: np.ndarray    # (n,) V or m, as logged
    u: np.ndarray        # (n,) treated input that drives the model
    y: np.ndarray        # (n,) m, measured position from rest
    holdout: bool
    current: np.ndarray | None = None   # (n,) A, logged controller current (dc_motor)

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

    # (re-calibration effect, stated z, re-calibrated z) when the diagnosis
    # re-calibrates the nominal (diagnosis.diagnose_runs); None otherwise
    nuisance = None

    def __init__(self, kind: str, rig, runs, holdout: list[str], model=None):
        self.kind = kind
        self.rig = rig
        self.model = model if model is not None else (piezo_model(rig) if kind == "piezohydraulic" else dc_model(rig))
        self.runs: list[PreparedRun] = []
        self.input_treatment = ""
        for run in runs:
            u_raw = run["voltage_V"] if kind == "piezohydraulic" else run["reference_m"]
            u, self.input_treatment = treat_input(kind, run.time, u_raw)
            current = run.columns.get("current_A") if kind == "dc_motor" else None
            self.runs.append(PreparedRun(run.name, np.asarray(run.time, float), np.asarray(u_raw, float), u,
                                         np.asarray(run["position_m"], float), run.name in holdout,
                                         None if current is None else np.asarray(current, float)))
        if kind == "piezohydraulic" and model is None and self.runs:
            # a hold is a hold: the sign of dV/dt has a deadband set from the logged voltage noise
            self.model = self.model.replace(hold_rate=hold_rate([r.u_raw for r in self.runs]))
        has_current = bool(self.runs) and all(r.current is not None for r in self.runs)
        self.channels = ("position_m", "current_A") if has_current else ("position_m",)
        self._nominal = None
        self._weights = None
        self._model_key = None               # the nominal model's parameters, as bytes (_remembered)
        self._memo = OrderedDict()           # shared with the benches of other models (with_model)
        self._drives = ph_sim.DriveMemory()  # the piezo kernel's drives of these runs (simulate_runs), shared too
        self._named = {}                     # the arrays _drive_key named

    def measured(self, i: int) -> np.ndarray:
        """(n_ch, n) measured channels of run i."""
        r = self.runs[i]
        return np.vstack([r.y] + ([r.current] if len(self.channels) > 1 else []))

    def gap(self, i: int, S: np.ndarray) -> np.ndarray:
        """Measured - simulated channels of run i; S: (n_ch, n) or
        (n_cand, n_ch, n), n_ch may be 1 (position only). The current's gap
        has a one-sample timing tolerance (module docstring)."""
        S = np.asarray(S, float)
        M = self.measured(i)[:S.shape[-2]]
        G = M - S
        if S.shape[-2] > 1:
            G[..., 1, :] = timing_band(M[1], S[..., 1, :])
        return G

    def spans(self, i: int) -> np.ndarray:
        """(n_ch,) max - min of each measured channel of run i (1 if flat)."""
        return np.array([float(np.ptp(c)) or 1.0 for c in self.measured(i)])

    def channel_floor(self, i: int) -> np.ndarray:
        """(n_ch,) white-noise NRMSE floor of each channel of run i (data only)."""
        return np.maximum([noise_sigma(c) for c in self.measured(i)], 1e-12) / self.spans(i)

    def weights(self, i: int) -> np.ndarray:
        """(n_ch,) weights of the combined measure (module docstring)."""
        if self._weights is None:
            self._weights = {}
        if i not in self._weights:
            f = self.channel_floor(i)
            self._weights[i] = (f[0] / f) ** 2 / len(f)
        return self._weights[i]

    def channel_nrmse(self, Yc, runs) -> np.ndarray:
        """(n_cand, n_runs, n_ch) NRMSE of each channel; Yc from simulate_channels."""
        out = np.empty((Yc[0].shape[0], len(runs), len(self.channels)))
        for j, (i, Y) in enumerate(zip(runs, Yc)):
            out[:, j, :] = np.sqrt(np.mean(self.gap(i, Y) ** 2, axis=2)) / self.spans(i)[None, :]
        return out

    def combined_nrmse(self, Yc, runs) -> np.ndarray:
        """(n_cand, n_runs) combined measure of each run (module docstring)."""
        E = self.channel_nrmse(Yc, runs)
        W = np.array([self.weights(i) for i in runs])
        return np.sqrt(np.sum(W[None] * E ** 2, axis=2))

    def residuals(self, Yc, runs) -> np.ndarray:
        """(n_cand, m) weighted residuals whose sum of squares over a run is
        its combined measure squared."""
        parts = []
        for i, Y in zip(runs, Yc):
            scale = (np.sqrt(self.weights(i)) / self.spans(i))[None, :, None] / np.sqrt(Y.shape[-1])
            parts.append((self.gap(i, Y) * scale).reshape(Y.shape[0], -1))
        return np.concatenate(parts, axis=1)

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
        other._nominal = other._model_key = None
        return other

    def _raw(self, model, run: PreparedRun) -> np.ndarray:
        """(n_cand, n_ch, n) simulated channels."""
        return self._raw_runs(model, [run])[0]

    def _drive_key(self, run: PreparedRun) -> tuple:
        """The name of a run's times and input in the kernel's memory of
        drives (``simulate_runs``): the arrays' identities, a run's input
        replaced (synth, tests) is another; the bench holds every array it
        named, so no other array takes its identity."""
        key = (id(run.t), id(run.u))
        self._named[key] = (run.t, run.u)
        return key

    def _raw_runs(self, model, runs: list) -> list[np.ndarray]:
        """``_raw`` of each of ``runs``; a piezo model's runs in one kernel
        call, whose lanes advance them together (``ph_sim.simulate_runs``)."""
        if self.kind == "piezohydraulic":
            outs = ph_sim.simulate_runs(model, [(run.t, run.u, run.t) for run in runs], drives=self._drives,
                                        keys=[self._drive_key(run) for run in runs])
        else:
            outs = [dc_sim.simulate(model, run.t, run.u, run.t) for run in runs]
        return [np.stack([out[c] for c in self.channels], axis=1) for out in outs]

    def _simulate_unique(self, changes: dict, runs: list, n_cand: int) -> list[np.ndarray]:
        """(n_cand, n_ch, n) of each of ``runs`` for the model ``changes``,
        simulating each distinct set of model values once (a measurement
        effect's candidates share theirs: only the re-calibrated parameters
        change the model), and in a small batch (a fit's point or Jacobian)
        only those not simulated lately (``_remembered``)."""
        keys = list(changes)
        M = np.column_stack([np.broadcast_to(np.asarray(changes[k], float), (n_cand,)) for k in keys])
        uniq, inverse = np.unique(M, axis=0, return_inverse=True)
        inverse = np.asarray(inverse).ravel()
        if len(uniq) <= MEMO_BATCH:
            return [Y[inverse].copy() for Y in self._remembered(runs, keys, uniq)]
        out = []
        for run in runs:
            if len(uniq) < n_cand:
                Y = self._raw(self.model.replace(**{k: uniq[:, j].copy() for j, k in enumerate(keys)}), run)
                if Y.shape[0] != len(uniq):
                    Y = np.broadcast_to(Y, (len(uniq),) + Y.shape[1:])
                out.append(Y[inverse].copy())
                continue
            Y = self._raw(self.model.replace(**changes), run)
            if Y.shape[0] != n_cand:
                Y = np.broadcast_to(Y, (n_cand,) + Y.shape[1:]).copy()
            out.append(Y)
        return out

    def _remembered(self, runs: list, keys: list, rows: np.ndarray) -> list[np.ndarray]:
        """(n_rows, n_ch, n) of each of ``runs`` for the model with ``keys``
        set to each row of ``rows``; the rows simulated lately on a run (the
        last MEMO_KEPT) are not simulated again, the others are simulated
        on all the runs that miss them in one call (``_raw_runs``). The
        kernel simulates each candidate on its own, so a remembered row is
        what simulating it again gives, to the bit. A fit's Jacobian repeats
        its point's simulation where a measurement effect's parameter moves
        (the model stays), a re-calibration's model is the nominal's after
        it."""
        if self._model_key is None:
            self._model_key = self.model.matrix().tobytes()
        names = tuple(keys)
        found = [[self._memo.get((id(run), self._model_key, names, row.tobytes())) for row in rows] for run in runs]
        missing = {}                     # rows missing -> the runs that miss them
        for i, got in enumerate(found):
            lost = tuple(k for k, y in enumerate(got) if y is None)
            if lost:
                missing.setdefault(lost, []).append(i)
        for lost, which in missing.items():
            model = self.model.replace(**{k: rows[list(lost), j].copy() for j, k in enumerate(keys)})
            for i, Y in zip(which, self._raw_runs(model, [runs[i] for i in which])):
                for k, y in zip(lost, np.broadcast_to(Y, (len(lost),) + Y.shape[1:])):
                    found[i][k] = y
                    self._memo[(id(runs[i]), self._model_key, names, rows[k].tobytes())] = y
                    if len(self._memo) > MEMO_KEPT:
                        self._memo.popitem(last=False)
        return [np.stack(got) for got in found]

    def nominal_channels(self, runs=None) -> list:
        """(n_ch, n) simulated channels of every run with the nominal model;
        with ``runs``, of those runs only (the others' entries None until
        asked for: a re-calibration's trial models need the training runs)."""
        if self._nominal is None:
            self._nominal = [None] * len(self.runs)
        wanted = [i for i in (range(len(self.runs)) if runs is None else runs) if self._nominal[i] is None]
        for i, Y in zip(wanted, self._remembered([self.runs[i] for i in wanted], [], np.zeros((1, 0)))):
            self._nominal[i] = Y[0]
        return self._nominal

    def nominal(self) -> list[np.ndarray]:
        """Simulated position (n,) of every run with the nominal model."""
        return [y[0] for y in self.nominal_channels()]

    def simulate(self, effects, Z, runs=None) -> list[np.ndarray]:
        """Position (n_cand, n) of each run (see simulate_channels)."""
        return [Y[:, 0, :] for Y in self.simulate_channels(effects, Z, runs)]

    def simulate_channels(self, effects, Z, runs=None) -> list[np.ndarray]:
        """Channels (n_cand, n_ch, n) of each run in ``runs`` (default all) for the
        model augmented with ``effects`` at the unit coordinates Z (n_cand,
        sum of n_par); effects act in order; measurement effects act on the
        position only."""
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
        runs = list(runs)
        simulated = self._simulate_unique(changes, [self.runs[i] for i in runs], n_cand) if changes else None
        out = []
        for k, i in enumerate(runs):
            run = self.runs[i]
            if changes:
                Y = simulated[k]
            else:
                Y = np.repeat(self.nominal_channels()[i][None], n_cand, axis=0)
            for effect, v in zip(effects, values):
                if effect.post:
                    for c in range(n_cand):
                        Y[c, 0] = effect.measure(run.t, Y[c, 0], {k: a[c] for k, a in v.items()})
            if getattr(self, "fit_linear", True):
                # terms linear in per-run coefficients (an additive sinusoid's
                # amplitude and phase) are solved on each run's measurement last
                for effect, v in zip(effects, values):
                    if hasattr(effect, "fit_run"):
                        for c in range(n_cand):
                            Y[c, 0] = effect.fit_run(run.t, Y[c, 0], run.y, {k: a[c] for k, a in v.items()})
            out.append(Y)
        return out
