"""A bench does not simulate again, in a small batch, a model it simulated
lately on the same run; what it remembers is what simulating again gives."""
from pathlib import Path

import numpy as np

from sizing.diagnose.bench import Bench
from sizing.diagnose.effects import get
from sizing.io.campaign import campaign_split, load_campaign

ROOT = Path(__file__).resolve().parents[2]


def _bench():
    campaign = load_campaign(ROOT / "studies/campaigns/dc-motor")
    campaign_split(campaign, ["steps_b"])
    return Bench(campaign.kind, campaign.rig, campaign.runs, ["steps_b"])


def test_a_repeated_model_is_not_simulated_again_and_gives_the_same_channels(monkeypatch):
    bench = _bench()
    friction = get("dc_motor", "coulomb_friction").for_rig(bench.rig, bench.model)
    Z = np.array([[0.3], [0.6]])
    first = bench.simulate_channels([friction], Z, bench.train)
    fresh = _bench().simulate_channels([friction], Z[::-1], bench.train)      # other batch, other order
    calls = []
    raw = bench._raw_runs
    monkeypatch.setattr(bench, "_raw_runs", lambda model, runs: calls.extend(r.name for r in runs) or raw(model, runs))
    again = bench.simulate_channels([friction], np.array([[0.6], [0.45], [0.3]]), bench.train)
    assert len(calls) == len(bench.train)                     # 0.45 only, once a run
    for a, b, c in zip(first, again, fresh):
        assert np.array_equal(a[0], b[2]) and np.array_equal(a[1], b[0]) and np.array_equal(a, c[::-1])


def test_another_nominal_model_is_simulated_anew():
    bench = _bench()
    before = bench.nominal_channels()
    other = bench.with_model(bench.model.replace(c1=bench.model.c1 * 1.1))
    after = other.nominal_channels()
    assert not np.array_equal(before[0], after[0])
    assert np.array_equal(bench.with_model(bench.model).nominal_channels()[0], before[0])
