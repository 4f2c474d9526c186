"""The withheld-effect check (``sizing diagnose CAMPAIGN --check``).

Takes the campaign's own excitations (the treated inputs) and rig,
simulates "measured" runs with each library effect injected at each of its
two realistic sizes (and null runs with no effect), with the noise level
estimated from the campaign, diagnoses each without being told which, and tabulates the
confusion matrix: true effect (rows) against the verdict (columns; "none"
for a null verdict), and which effects the campaign can tell at all
(``can_tell``: the sizes named right, and the verdicts of the others,
"undetectable" when an injected effect stayed within the floors). It
tells whether a test campaign can tell the effects apart before anyone
trusts a verdict on real data.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..io.runs import Run
from .bench import Bench
from .diagnosis import diagnose_runs
from .effects import library
from .inputs import drive_noise_sigma, noise_sigma
from .synth import Noise, synthesize

NONE = "none"


@dataclass
class Case:
    truth: str
    size: int
    predicted: str
    shrink: float
    seconds: float
    status: str = ""


@dataclass
class CheckResult:
    kind: str
    labels: list
    cases: list

    def matrix(self) -> np.ndarray:
        idx = {name: i for i, name in enumerate(self.labels)}
        M = np.zeros((len(self.labels), len(self.labels)), dtype=int)
        for c in self.cases:
            M[idx[c.truth], idx.get(c.predicted, idx[NONE])] += 1
        return M

    @property
    def accuracy(self) -> float:
        named = [c for c in self.cases if c.truth != NONE]
        return float(np.mean([c.predicted == c.truth for c in named])) if named else float("nan")

    @property
    def null_false_positive(self) -> float:
        null = [c for c in self.cases if c.truth == NONE]
        return float(np.mean([c.predicted != NONE for c in null])) if null else float("nan")

    def can_tell(self) -> dict:
        """{effect: (sizes named right, sizes tried, statuses of the others)}:
        which effects this campaign's excitations, noise and holdout can
        tell. An effect named at neither size is one the campaign cannot
        tell at those sizes: "undetectable" when its gap stayed within the
        floors, a wrong name or "unexplained" otherwise."""
        out = {}
        for c in self.cases:
            if c.truth == NONE:
                continue
            right, tried, other = out.get(c.truth, (0, 0, ()))
            ok = c.predicted == c.truth
            out[c.truth] = (right + ok, tried + 1, other if ok else other + (c.status or c.predicted,))
        return out

    @property
    def median_shrink(self) -> float:
        good = [c.shrink for c in self.cases if c.truth != NONE and c.predicted == c.truth]
        return float(np.median(good)) if good else float("nan")

    def table(self) -> str:
        """The confusion matrix as a markdown table (rows: true effect)."""
        M = self.matrix()
        short = [name for name in self.labels]
        lines = ["| true \\ diagnosed | " + " | ".join(short) + " |",
                 "|---|" + "---|" * len(short)]
        for name, row in zip(self.labels, M):
            lines.append(f"| {name} | " + " | ".join(str(v) if v else "." for v in row) + " |")
        told = self.can_tell()
        lines += ["", "| effect | sizes told | the others |", "|---|---|---|"]
        for name, (right, tried, other) in told.items():
            lines.append(f"| {name} | {right}/{tried} | {', '.join(other) or '-'} |")
        return "\n".join(lines)

    def to_json(self) -> dict:
        return {"kind": self.kind, "labels": self.labels, "matrix": self.matrix().tolist(),
                "accuracy": self.accuracy, "null_false_positive_rate": self.null_false_positive,
                "median_shrink_correct": self.median_shrink,
                "can_tell": {k: {"sizes_told": r, "sizes_tried": n, "others": list(o)}
                             for k, (r, n, o) in self.can_tell().items()},
                "cases": [c.__dict__ for c in self.cases]}


def clean_inputs(bench: Bench) -> dict:
    return {r.name: (r.t, r.u.copy()) for r in bench.runs}


def campaign_noise(bench: Bench, seed: int) -> Noise:
    floor = []
    for i, r in enumerate(bench.runs):
        floor.append(noise_sigma(r.y - bench.nominal()[i]) / r.span)
    volts = [drive_noise_sigma(r.u_raw) for r in bench.runs] if bench.kind == "piezohydraulic" else [0.0]
    return Noise(position=float(np.median(floor)), voltage_V=float(np.median(volts)), seed=seed)


def _jobs(kind: str, rig, inputs: dict):
    """(the rig's model, its applicable effects, the labels, the check's
    cases as (effect or None, size index); the nulls last)."""
    model = Bench(kind, rig, [Run(n, None, t, {("voltage_V" if kind == "piezohydraulic" else "reference_m"): u,
                                                "position_m": np.zeros(len(t))}) for n, (t, u) in inputs.items()],
                  []).model
    effects = [e.for_rig(rig, model) for e in library(kind) if e.applicable(rig, model)]
    labels = list(dict.fromkeys(e.name for e in effects)) + [NONE]   # a family once, whatever its forms
    jobs = [(e, k) for e in effects for k in range(len(e.sizes_for(rig, model)) if e.params else 1)]
    return model, labels, jobs


def check_case(kind: str, rig, inputs: dict, holdout: list[str], noise: Noise, n_null: int, seed: int,
               j: int) -> Case:
    """Case ``j`` of the check: its runs synthesised (noise seeded by the
    case number) and diagnosed without the truth."""
    model, _, jobs = _jobs(kind, rig, inputs)
    jobs += [(None, k) for k in range(n_null)]
    effect, k = jobs[j]
    case_noise = Noise(noise.position, noise.voltage_V, seed=seed * 1000 + j)
    if effect is None:
        runs = synthesize(kind, rig, inputs, noise=case_noise)
    else:
        runs = synthesize(kind, rig, inputs, [effect], [effect.sizes_for(rig, model)[k]], noise=case_noise)
    d = diagnose_runs(kind, rig, runs, holdout, seed=seed)
    return Case(effect.name if effect else NONE, k, d.verdict["effect"] or NONE, float(d.verdict["shrink_holdout"]),
                d.seconds, d.verdict["status"])


def _one_thread_worker() -> None:
    """A worker process of the check: one simulator thread, one BLAS thread
    (the cores are shared out between the processes)."""
    import numba
    from threadpoolctl import threadpool_limits

    numba.set_num_threads(1)
    threadpool_limits(1)


def check_runs(kind: str, rig, inputs: dict, holdout: list[str], noise: Noise, n_null: int = 2,
               seed: int = 0, progress=None, workers: int = 1, only: list[int] | None = None) -> CheckResult:
    """Diagnose synthetic runs of every effect at both sizes, plus nulls.
    ``workers`` > 1 diagnoses that many cases at once in separate processes
    (each case is seeded by its number, so the verdicts do not depend on
    it); ``only``: the case numbers to run (default all)."""
    _, labels, jobs = _jobs(kind, rig, inputs)
    numbers = list(range(len(jobs) + n_null)) if only is None else list(only)
    args = (kind, rig, inputs, holdout, noise, n_null, seed)
    cases = []
    if workers > 1 and len(numbers) > 1:
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor

        # spawned, not forked: a fork of a process whose OpenMP threads ran can hang
        with ProcessPoolExecutor(min(workers, len(numbers)), mp_context=multiprocessing.get_context("spawn"),
                                 initializer=_one_thread_worker) as pool:
            for case in pool.map(check_case, *zip(*[args + (j,) for j in numbers])):
                cases.append(case)
                if progress:
                    progress(case)
        return CheckResult(kind, labels, cases)
    for j in numbers:
        cases.append(check_case(*args, j))
        if progress:
            progress(cases[-1])
    return CheckResult(kind, labels, cases)
