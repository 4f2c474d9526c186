"""The model discrepancy a partner must beat (discrepancy.account,
judge.beyond_discrepancy): a second effect is named beside a single only
when it does better on the held-out runs than a flexible account of what
the single leaves, wherever the pair still leaves a gap."""
from __future__ import annotations

import numpy as np
import pytest

from sizing.diagnose import discrepancy, judge
from sizing.diagnose.effects import get
from sizing.diagnose.fitting import EffectFit
from sizing.diagnose.floor import total_floor
from sizing.diagnose.settings import DEFAULT


class _Run:
    def __init__(self, t, y, holdout):
        self.t, self.y, self.holdout = t, y, holdout


class _Bench:
    """The part of diagnose.bench.Bench that discrepancy.account reads: one
    position channel, measured ``ys`` against simulated ``sims``."""

    channels = ("position_m",)

    def __init__(self, t, ys, holdout):
        self.runs = [_Run(t, y, k in holdout) for k, y in enumerate(ys)]

    def gap(self, i, S):
        return self.runs[i].y[None, :] - S

    def spans(self, i):
        return np.array([float(np.ptp(self.runs[i].y))])

    def weights(self, i):
        return np.ones(1)

    @property
    def train(self):
        return [i for i, r in enumerate(self.runs) if not r.holdout]

    @property
    def holdout(self):
        return [i for i, r in enumerate(self.runs) if r.holdout]


def _excitations(t):
    """A ramp-and-hold, a trapezoid and a staircase (the held-out run), 1 mm,
    as a rig's output follows them (through a 15 ms lag: no jumps)."""
    ramp = np.clip(t / 0.3, 0, 1)
    trapezoid = np.clip(np.minimum(t / 0.2, (1.6 - t) / 0.2), 0, 1)
    stairs = np.floor(np.clip(t, 0, 1.99) / 0.4) / 4.0
    return [1e-3 * _lag(t, s, 0.015) for s in (ramp, trapezoid, stairs)]


def _nrmse(measured, simulated):
    return float(np.sqrt(np.mean((measured - simulated) ** 2)) / np.ptp(measured))


def _lag(t, y, tau):
    return discrepancy.low_pass(t, y, tau)


def test_a_filter_of_the_motion_is_taken_up_on_the_held_out_run():
    """The measured position is the simulated one through a 4 ms
    first-order lag plus 1 um of noise: the lag is a linear filter of the
    motion, so the account fitted on the ramp and the trapezoid leaves
    the noise on the held-out staircase (1 um over a 1 mm span), where
    the single alone leaves more than 5 x that."""
    t = np.arange(0.0, 2.0, 5e-4)
    sims = _excitations(t)
    rng = np.random.default_rng(3)
    ys = [_lag(t, s, 0.004) + rng.normal(0.0, 1e-6, t.size) for s in sims]
    bench = _Bench(t, ys, holdout={2})
    held = discrepancy.account(bench, [s[None, :] for s in sims], DEFAULT.discrepancy_taus)
    noise = 1e-6 / np.ptp(ys[2])
    alone = _nrmse(ys[2], sims[2])
    assert len(held) == 1 and held[0].shape == (1, t.size)
    assert alone > 5 * noise
    assert _nrmse(ys[2], held[0][0]) < 1.2 * noise


def test_what_is_not_a_filter_of_the_motion_is_left():
    """A slip of 20 um at a fixed instant of each run (an event, not a
    response to the motion): the account cannot take it up on the held-out
    run, it leaves most of it."""
    t = np.arange(0.0, 2.0, 5e-4)
    sims = _excitations(t)
    slip = 2e-5 * (t > 1.1)
    ys = [s + slip for s in sims]
    bench = _Bench(t, ys, holdout={2})
    held = discrepancy.account(bench, [s[None, :] for s in sims], DEFAULT.discrepancy_taus)
    assert _nrmse(ys[2], held[0][0]) > 0.5 * _nrmse(ys[2], sims[2])


def _delay_and_partner(pair_holdout: float, account: float | None):
    """A delay alone (holdout 0.0075, its account with a discrepancy
    ``account``) and with viscous damping (``pair_holdout``, lower on the
    training runs)."""
    delay, viscous = get("piezohydraulic", "sensor_delay"), get("piezohydraulic", "viscous_damping")
    z_delay, z_visc = delay.unit({"delay_s": 0.011}), viscous.unit({"viscous_damping_N_s_m": 150.0})

    rng = np.random.default_rng(7)

    def blocks(level):
        """40 holdout blocks whose energies sum to about level^2, spread
        by a quarter from block to block (a residual's energy is not even)."""
        return level ** 2 / 40 * rng.gamma(16.0, 1 / 16.0, 40)

    def fit(effects, z, holdout, train):
        return EffectFit(tuple(effects), z, train, nrmse_holdout=holdout, residual_blocks=blocks(holdout))

    single = fit((delay,), z_delay, 0.0075, 0.0045)
    single.discrepancy = None if account is None else {"nrmse_holdout": account, "blocks": blocks(account)}
    pair = fit((viscous, delay), np.concatenate([z_visc, z_delay]), pair_holdout, 0.0040)
    return single, pair


@pytest.mark.parametrize("pair_holdout, account, chosen", [
    (0.0056, 0.0050, "sensor_delay"),                     # a gap left, the discrepancy does better: the single
    (0.0056, 0.0060, "viscous_damping+sensor_delay"),     # a gap left, the partner does better: the pair
    (0.0056, 0.0057, "sensor_delay"),                     # ... but not significantly: the single
    (0.0025, 0.0020, "viscous_damping+sensor_delay"),     # the pair within the floor: not asked
    (0.0056, None, "viscous_damping+sensor_delay"),       # no discrepancy measured: not asked
])
def test_a_partner_must_beat_the_single_with_a_discrepancy_where_the_pair_leaves_a_gap(pair_holdout, account, chosen):
    """The floor: 0.0009 of noise with the 0.2 % model-form prior, 0.0022;
    a gap is more than 1.5 x that (0.0033). A delay of another form than
    the library's (the cross-form generator's pz-h12-pade): the pure delay
    leaves 0.0075, a viscous partner takes it to 0.0056 and the single
    with a discrepancy to 0.0050, so the single is named. The pair must be
    better on the holdout blocks at the level ``alpha`` (two-sided): 0.0056
    against 0.0057 on 40 blocks spread by a quarter is not."""
    single, pair = _delay_and_partner(pair_holdout, account)
    floor = total_floor(0.0009)
    assert judge.beyond_discrepancy(pair, single, floor) is (chosen != "sensor_delay")
    assert judge.pick([pair, single], floor=floor).name == chosen


@pytest.mark.slow
@pytest.mark.parametrize("name, named", [
    ("pz-h12-pade", {"sensor_delay"}),                        # a delay of another form: named alone
    ("pz-h10-viscous+pade", {"viscous_damping", "sensor_delay"}),   # a real pair keeps its partner
])
def test_a_delay_of_another_form_is_named_alone_and_a_real_pair_kept(tmp_path, name, named):
    """Campaigns of the cross-form generator (benchmarks/crossform), which
    delays the position through a first-order Pade all-pass where the
    library shifts it. On pz-h12-pade (10.9 ms) the pure delay leaves
    0.0075, a viscous partner 0.0056 (2.6 x the floor) and the delay with a
    discrepancy 0.0050: the delay is named alone (it was named with the
    viscous partner). Behind a real damping (pz-h10-viscous+pade) the pair
    leaves the floor and keeps its partner."""
    from benchmarks.crossform import cases
    from benchmarks.crossform.common import write_campaign
    from sizing import api

    rig, runs, holdout = cases.generate(cases.find(name))
    folder = write_campaign(tmp_path / "c", rig, runs)
    d = api.diagnose(folder, [holdout])
    assert set(d.verdict["effect"].split("+")) == named, d.verdict["reason"]
    assert d.verdict["status"] in ("explained", "partial")
