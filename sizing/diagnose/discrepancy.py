"""A flexible account of what a fitted effect leaves: the model discrepancy.

A single effect whose form differs from the hardware's leaves a structured
residual, and a second effect fitted beside it takes up part of that
residual whatever its physics. The discrepancy is the bar such a partner
must clear (judge.beyond_discrepancy): a linear, time-invariant filter of
the single's own simulated channels, in the spirit of Kennedy and
O'Hagan's model discrepancy (J. R. Stat. Soc. B 63, 2001), fitted on the
training runs beside the single (its fit held) and scored on the held-out
runs, one filter per logged channel.

The filter's basis, per channel, of the single's simulated signal s(t):
an offset, s itself (a gain error), its rate ds/dt and the rate passed
through first-order low-passes of time constants ``taus`` (a geometric
ladder over the millisecond to the tenth of a second, the time scales of
a sensor's or a driver's dynamics and of a mis-stated lag of the rig). A
measured response that another simulator's form of the same effect
produces (a delay of another form, a damping of another law) is a
linear filter of the same motion to first order, so this account takes
it up on every run, held-out ones included; an effect the library names
as a partner must do better there than it does.
"""
from __future__ import annotations

import numpy as np
from scipy.signal import lfilter

def low_pass(t: np.ndarray, x: np.ndarray, tau: float) -> np.ndarray:
    """First-order low-pass of x (time constant tau, s), starting at rest at x[0]."""
    dt = float(np.median(np.diff(t)))
    a = float(np.exp(-dt / tau))
    return lfilter([1.0 - a], [1.0, -a], x - x[0]) + x[0]


def basis(t: np.ndarray, s: np.ndarray, taus) -> np.ndarray:
    """(n, 3 + len(taus)) columns of the discrepancy of one simulated signal s."""
    rate = np.gradient(s, t)
    return np.column_stack([np.ones_like(s), s, rate] + [low_pass(t, rate, tau) for tau in taus])


def account(bench, sims: list, taus) -> list:
    """The single plus its discrepancy on the held-out runs: their
    simulated channels (n_ch, n) with each channel's filter added, in
    bench.holdout order. ``sims``: the single's simulated channels
    (n_ch, n) of every run of ``bench``; ``taus``: the low-passes' time
    constants, s (``Settings.discrepancy_taus``). Each channel's filter is fitted by
    least squares on the training runs' residuals (measured - simulated,
    over the channel's span and sqrt(n), as a run's NRMSE weighs them)."""
    n_ch = len(bench.channels)
    design, target = {}, {}
    for i, r in enumerate(bench.runs):
        S = np.asarray(sims[i], float)[:n_ch]
        G = bench.gap(i, S)
        scale = bench.spans(i) * np.sqrt(S.shape[-1])
        design[i] = [basis(r.t, S[k], taus) / scale[k] for k in range(n_ch)]
        target[i] = [G[k] / scale[k] for k in range(n_ch)]
    coef = []
    for k in range(n_ch):
        A = np.vstack([design[i][k] for i in bench.train])
        b = np.concatenate([target[i][k] for i in bench.train])
        norms = np.linalg.norm(A, axis=0)
        norms[norms == 0] = 1.0
        c, *_ = np.linalg.lstsq(A / norms, b, rcond=None)
        coef.append(c / norms)
    out = []
    for i in bench.holdout:
        S = np.array(sims[i], float)[:n_ch]
        scale = bench.spans(i) * np.sqrt(S.shape[-1])
        out.append(np.vstack([S[k] + scale[k] * (design[i][k] @ coef[k]) for k in range(n_ch)]))
    return out
