"""The screen's ranking: the entries a full screen gives, in its order and
to the bit, from fewer candidate runs."""
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from sizing.diagnose import fitting, synth
from sizing.diagnose.bench import Bench
from sizing.diagnose.effects import get
from sizing.diagnose.ranking import Ranking
from sizing.io.campaign import campaign_split, load_campaign
from sizing.io.rig import load_rig

ROOT = Path(__file__).resolve().parents[2]


class _Runs:
    """Three runs of 1, 3 and 2 s; candidate z's measure on run j is
    |z - target_j| (a candidate's cost: their mean square); counts each
    candidate run simulated."""
    targets = (0.3, 0.33, 0.31)

    def __init__(self):
        self.runs = [SimpleNamespace(t=np.linspace(0.0, s, 5)) for s in (1.0, 3.0, 2.0)]
        self.simulated = [0, 0, 0]

    def simulate_channels(self, effects, Z, runs):
        for i in runs:
            self.simulated[i] += len(Z)
        return [np.abs(np.asarray(Z)[:, :1] - self.targets[i]) for i in runs]

    def combined_nrmse(self, Yc, runs):
        return np.column_stack([y[:, 0] for y in Yc])


def _full(bench, Z, runs):
    """What the screen did before: every candidate on every run, a stable sort."""
    cost = fitting.cost(bench, [], Z, runs)
    return sorted([(float(c), k) for k, c in enumerate(cost)], key=lambda r: r[0])


def test_the_ranking_is_the_full_sort_from_fewer_runs():
    bench = _Runs()
    Z = np.r_[np.linspace(0.0, 1.0, 41), 0.325, 0.325][:, None]      # two ties with a grid point
    expected = _full(_Runs(), Z, [0, 1, 2])
    ranking = Ranking(bench, [], Z, [0, 1, 2], [(k,) for k in range(len(Z))])
    assert ranking[0] == expected[0]
    # the shortest run for every candidate, the others only for a few
    assert bench.simulated[0] == len(Z) and max(bench.simulated[1:]) <= 5
    assert list(ranking) == expected                 # read to the end: the full sort, ties in order
    assert ranking[3] == expected[3]


def test_a_reader_walking_on_gets_what_could_come_next():
    bench = _Runs()
    Z = np.linspace(0.0, 1.0, 41)[:, None]
    expected = _full(_Runs(), Z, [0, 1, 2])
    ranking = Ranking(bench, [], Z, [0, 1, 2], [(k,) for k in range(len(Z))], wanted=1)
    # the first entry whose point lies beyond 0.6: further down than ``wanted``
    first_far = next(r for r in ranking if Z[r[1], 0] > 0.5)
    assert first_far == next(r for r in expected if Z[r[1], 0] > 0.5)
    assert sum(bench.simulated) < 3 * len(Z)


@pytest.mark.parametrize("case", ["dc", "piezo"])
def test_on_the_simulators_the_costs_are_a_full_screen_s_to_the_bit(case):
    """Position and current (DC, with the current's timing band) or
    position alone (piezo): each cost read equals the one every candidate
    simulated on every training run gives, exactly, and so does the order."""
    if case == "dc":
        campaign = load_campaign(ROOT / "studies/campaigns/dc-motor")
        campaign_split(campaign, ["steps_b"])
        bench = Bench(campaign.kind, campaign.rig, campaign.runs, ["steps_b"])
        effect = get("dc_motor", "coulomb_friction").for_rig(bench.rig, bench.model)
    else:
        rig = load_rig(ROOT / "studies/campaigns/piezo-prototype/rig.toml")
        inputs = synth.piezo_excitations(150.0, duration=1.0)
        inputs["ramp"] = tuple(a[:600] for a in inputs["ramp"])          # runs of other lengths
        leak = get("piezohydraulic", "leakage")
        runs = synth.synthesize("piezohydraulic", rig, inputs, [leak], [leak.sizes[0]],
                                noise=synth.Noise(seed=1))
        bench = Bench("piezohydraulic", rig, runs, ["steps_b"])
        effect = leak.for_rig(bench.rig, bench.model)
    Z = np.random.default_rng(0).random((24, len(effect.params)))
    cost = fitting.cost(bench, [effect], Z, bench.train)
    expected = sorted([(float(c), k) for k, c in enumerate(cost)], key=lambda r: r[0])
    ranking = Ranking(bench, [effect], Z, bench.train, [(k,) for k in range(len(Z))])
    assert ranking[0] == expected[0]
    assert list(ranking) == expected
