"""Which effect explains the gap, and how far it shrinks.

The candidates of the verdict (judge.py), judged against the floor of
floor.py:

1. Screen: every effect of the library at its two realistic sizes and a
   seeded Latin-hypercube of parameter sets (``n_screen`` per parameter, at
   least ``min_screen``), one simulator batch per effect, scored on the
   training runs.
2. Fit the promising effects (least squares on the training runs, from the
   best screened point; an effect whose cost is rugged, the Karnopp seal,
   screened densely and fitted from several distinct screened points, the
   best on the training runs kept): the best-screened form of each of the ``top_fit`` best
   families, and any form that screens at < ``fit_below`` x the baseline; judge every
   effect on the holdout runs only.
3. Pairs: unless the best single explains the gap and leaves at most
   ``residual_factor`` x the noise floor on the holdout, the best pairs of the
   top fitted singles (``top_pairs`` families; a single only screened, not
   promising on the training runs, is not paired) are fitted together,
   and the best single with the next family; a pair ranks first only when it is
   significantly better than the best of its two singles (same bootstrap)
   and removes >= ``pair_gain`` of the gap energy that single leaves above the floor.
"""
from __future__ import annotations

import itertools

import numpy as np

from .. import spectrum
from . import discrepancy, fitting
from .effects import library
from .floor import total_floor
from .judge import block_energy, explained
from .ranking import Ranking
from .settings import DEFAULT, Settings



def _lhs(n: int, d: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    Z = (np.argsort(rng.random((d, n)), axis=1).T + rng.random((n, d))) / n
    return Z


def screen(bench, effect, seed: int = 0, head=(), z_heads=(np.zeros(0),)) -> tuple[np.ndarray, float, np.ndarray]:
    """(best unit point, its training score, the head start it was found
    with) over sizes + a Latin hypercube; ``head`` effects (the
    re-calibrated parameters) held at each of ``z_heads`` in turn."""
    c, z, zh, _ = screen_ranked(bench, effect, seed, head, z_heads, dense=False)[0]
    return z, float(np.sqrt(c)), zh


def screen_ranked(bench, effect, seed: int = 0, head=(), z_heads=(np.zeros(0),), dense: bool = True) -> Ranking:
    """Every screened point as (mean squared training score, unit point,
    head start, regular), best first (a ``ranking.Ranking``: read from its
    start, computed as read). ``regular``: one of the sizes and
    the Latin hypercube every effect is screened with, from which its
    screening score comes (the families are ranked on equal draws); a
    rugged effect (``extra["screen_factor"]``) adds ``screen_factor`` - 1
    times as many further points, used only as starts of its fit (not
    with ``dense`` False)."""
    train = bench.train
    d = len(effect.params)
    if d == 0:
        scores = [fitting.cost(bench, list(head) + [effect], zh[None, :], train)[0] for zh in z_heads]
        return sorted([(float(c), np.zeros(0), zh, True) for c, zh in zip(scores, z_heads)], key=lambda r: r[0])
    sizes = [effect.unit(s) for s in effect.sizes_for(bench.rig, bench.model) if s]
    sizes += list(effect.starts(bench, head, z_heads[0]))   # from the data (e.g. residual spectrum lines)
    n = max(DEFAULT.n_screen * d, DEFAULT.min_screen) * (4 if effect.post else 1)
    Z = np.vstack(sizes + [_lhs(n, d, seed)]) if sizes else _lhs(n, d, seed)
    n_regular = len(Z)
    extra = (int(effect.extra.get("screen_factor", 1)) - 1) * n if dense else 0   # a rugged cost: more starts
    if extra > 0:
        Z = np.vstack([Z, _lhs(extra, d, seed + 1)])
    Z = np.clip(Z, 0.0, 1.0)
    # stable: among equal scores the earlier head start and point;
    # computed as read, the candidates that cannot rank first not simulated
    # on every run (ranking.py)
    points = [(z, zh, k < n_regular) for zh in z_heads for k, z in enumerate(Z)]
    heads = np.vstack([np.hstack([np.tile(zh, (len(Z), 1)), Z]) for zh in z_heads])
    return Ranking(bench, list(head) + [effect], heads, train, points,
                   wanted=int(effect.extra.get("fit_starts", 1)) if dense else 1)


def fit_starts(ranked, n: int, spacing: float) -> list:
    """The starts (unit point, head start) of the local fits of an effect
    whose training cost is rugged: the best screened point of ``ranked``
    (``screen_ranked``) and the next best ones at least ``spacing`` (unit
    coordinates, max norm) from every start already taken, ``n`` in all,
    best first. A stick-slip's cost jumps where a slip instant moves by a
    sample between two nearby parameter sets, and a local least squares
    from one start stops on the first such step."""
    out = []
    for _, z, zh, *_ in ranked:
        if len(out) == n:
            break
        if all(not np.array_equal(zh, ho) or np.max(np.abs(z - zo), initial=0.0) >= spacing for zo, ho in out):
            out.append((z, zh))
    return out


def holdout_score(bench, fit: fitting.EffectFit) -> None:
    runs = bench.holdout
    Y = bench.simulate_channels(fit.effects, fit.z[None, :], runs)
    per_run = fitting.run_nrmse(bench, Y, runs)[0]
    fit.nrmse_runs = {bench.runs[i].name: float(v) for i, v in zip(runs, per_run)}
    fit.nrmse_holdout = float(np.mean(per_run))
    E = bench.channel_nrmse(Y, runs)[0]               # (n_runs, n_ch)
    fit.nrmse_channels = {c: float(np.mean(E[:, k])) for k, c in enumerate(bench.channels)}
    fit.residual_blocks = block_energy(bench, [y[0] for y in Y], runs)
    if len(bench.channels) > 1:
        fit.channel_blocks = {c: block_energy(bench, [y[0] for y in Y], runs, channel=k)
                              for k, c in enumerate(bench.channels)}
    fit.holdout_position = [y[0][0] for y in Y]
    fit.holdout_residual = [(bench.runs[i].t, bench.runs[i].y - y[0][0]) for i, y in zip(runs, Y)]


def attribute(bench, baseline_holdout: float, floor_holdout: float, seed: int = 0, pairs: bool = True,
              form_floor: float | None = None, settings: Settings = DEFAULT):
    """Screen, fit and rank every effect. Returns (fits sorted best first,
    verdict dict)."""
    effects = [e.for_rig(bench.rig, bench.model) for e in library(bench.kind) if e.applicable(bench.rig, bench.model)]
    base_train = float(np.sqrt(np.mean(fitting.run_nrmse(
        bench, [y[None] for y in (bench.nominal_channels()[i] for i in bench.train)], bench.train) ** 2)))
    # the re-calibrated parameters: re-fitted with every effect, screened
    # from their stated and their re-calibrated values
    joint = bench.nuisance
    head, z_head = ((joint[0],), joint[1]) if joint else ((), np.zeros(0))
    effects = [e for e in effects if e.observable(bench, head, z_head)]
    z_heads = (z_head, joint[2]) if joint else (z_head,)
    ranked = {id(e): screen_ranked(bench, e, seed, head, z_heads) for e in effects}
    regular = {k: next(x for x in r if x[3]) for k, r in ranked.items()}     # the best of the regular points
    screened = [(e, regular[id(e)][1], float(np.sqrt(regular[id(e)][0])), regular[id(e)][2]) for e in effects]
    screened.sort(key=lambda s: s[2])
    fits = []

    def fit_with(effects, z, start=z_head):
        return fitting.fit(bench, head + tuple(effects), np.concatenate([start, z]), bench.train)

    # ``top_fit`` counts families: the best-screened form of each of the top
    # ``top_fit`` families is fitted (so a family with several forms does not
    # push another family out), and any form that screens well on its own
    family_rank = {}
    for effect, *_ in screened:
        family_rank.setdefault(effect.name, (len(family_rank), effect))
    for effect, z0, score, start in screened:
        rank, first_form = family_rank[effect.name]
        promising = (rank < DEFAULT.top_fit and effect is first_form) or score < DEFAULT.fit_below * base_train
        if promising:
            f = fit_best_of_starts(effect, ranked[id(effect)], fit_with, settings)
        else:
            f = fitting.EffectFit((effect,), z0, score, message="screened only")
        holdout_score(bench, f)
        fits.append(f)
    fits.sort(key=lambda f: f.nrmse_holdout)
    best = fits[0]
    # pairs are tried unless the best single explains the gap and leaves at
    # most ``residual_factor`` x the *noise* floor: a single that explains most
    # of the gap above the model-form floor too may still leave a second
    # effect's gap well above the noise (a 12 ms delay over a 0.2 mm
    # backlash left 4.9 x the noise; the piezo singles that explain their
    # gap leave 0.8-2.5 x, model-form error that a second effect would absorb);
    # and a single that leaves next to nothing of the broadband gap energy
    # may still leave a spectral line (a mount ringing under a current
    # limit or a backlash whose broadband gap is far larger): pairs are
    # tried then too
    enough = (explained(baseline_holdout, best.nrmse_holdout, total_floor(floor_holdout, form_floor, settings))
              >= settings.explained and best.nrmse_holdout <= settings.residual_factor * floor_holdout
              and not spectrum.lines(best.holdout_residual, best.holdout_position))
    if pairs and not enough:
        tops = []                                         # the best fitted form of each of the top families
        for f in fits:
            if f.message == "screened only":
                continue                                  # not promising on the training runs: not paired
            if len(tops) < DEFAULT.top_pairs + 1 and f.name not in {t.name for t in tops}:
                tops.append(f)
        # every pair of the top ``top_pairs`` families, and the best single with the next family
        combos = list(itertools.combinations(tops[:DEFAULT.top_pairs], 2)) + [(tops[0], t) for t in tops[DEFAULT.top_pairs:]]
        for a, b in combos:
            ea, eb = a.named, b.named
            if {e.name for e in ea} & {e.name for e in eb}:
                continue                                  # two forms of one family are alternatives, not a pair
            ea, eb, za, zb = _model_first(ea, eb, _named_z(a), _named_z(b))
            f = fit_with(ea + eb, np.concatenate([za, zb]))
            holdout_score(bench, f)
            fits.append(f)
        # a best that was only screened carries no re-calibrated parameters
        start = best.z[:len(z_head)] if len(best.effects) > len(best.named) else z_head
        for ea, eb, za, zb in stepwise_pairs(bench, best, effects, seed, fits):
            fits.append(fit_with(ea + eb, np.concatenate([za, zb]), start))
            holdout_score(bench, fits[-1])
        fits.sort(key=lambda f: f.nrmse_holdout)
        refit_singles(bench, fits, head, len(z_head))
        account_discrepancy(bench, fits, settings)
    return fits


def account_discrepancy(bench, fits, settings: Settings = DEFAULT) -> None:
    """Each fitted single of a family that some fitted pair holds gets
    ``discrepancy``: the single plus a model discrepancy on the holdout
    runs (discrepancy.account), the bar its partner must clear
    (judge.beyond_discrepancy)."""
    paired = {e.name for f in fits if len(f.named) == 2 for e in f.named}
    for f in fits:
        if len(f.named) == 1 and f.message != "screened only" and f.name in paired:
            sims = [Y[0] for Y in bench.simulate_channels(f.effects, f.z[None, :])]
            S = discrepancy.account(bench, sims, settings.discrepancy_taus)
            runs, one = bench.holdout, [s[None] for s in S]
            E = bench.channel_nrmse(one, runs)[0]
            f.discrepancy = {"nrmse_holdout": float(np.mean(bench.combined_nrmse(one, runs)[0])),
                             "blocks": block_energy(bench, S, runs),
                             "channels": {c: {"nrmse_holdout": float(np.mean(E[:, k])),
                                              "blocks": block_energy(bench, S, runs, channel=k)}
                                          for k, c in enumerate(bench.channels)}}


def fit_best_of_starts(effect, ranked, fit_with, settings: Settings = DEFAULT) -> fitting.EffectFit:
    """The local fit of one effect from its best screened point or, for an
    effect that declares a rugged cost (``extra["fit_starts"]``: the seal
    stick-slip), from that many distinct screened points (``fit_starts``),
    keeping the fit that leaves the least on the training runs (the
    verdict still reads the holdout runs only)."""
    starts = fit_starts(ranked, int(effect.extra.get("fit_starts", 1)), settings.start_spacing)
    fits = [fit_with([effect], z, zh) for z, zh in starts]
    return min(fits, key=lambda f: f.nrmse_train)        # the first (best screened) on a tie


def _named_z(fit) -> np.ndarray:
    """The unit coordinates of a fit's named effects (without the re-calibrated parameters before them)."""
    return fit.z[len(fit.z) - sum(len(e.params) for e in fit.named):]


def _model_first(ea, eb, za, zb):
    """A pair's two effect tuples and coordinates, model effects first and
    measurement effects after."""
    if ea[0].post and not eb[0].post:
        return eb, ea, zb, za
    return ea, eb, za, zb


def stepwise_pairs(bench, best, effects, seed: int, fits):
    """Forward selection's second step: every other family screened with the
    best single held at its fit, and the best-screened form of each of the
    best ``step_pairs`` families (forms not yet paired with it) returned as
    (effects a, effects b, z a, z b) pair starts, model effects first. A
    dominant effect masks a second one in the screen against the nominal
    (a 12 ms delay over a seal, or over a leak: the second family ranked
    below the top ``top_pairs`` and was never paired); given the dominant one,
    the second is screened on what it leaves."""
    lead = tuple(best.effects)                            # with the re-calibrated parameters it was fitted with
    # a pair of forms already fitted is not fitted again; another form of
    # the same family may be (the top families' pairs take each family's
    # best form against the nominal: a sinusoid, where given friction the
    # residual rings like a mount)
    paired = [{(e.name, e.form) for e in f.named} for f in fits if len(f.named) == 2]
    ranked = []
    for effect in effects:
        if effect.name == best.name or {(best.name, best.form), (effect.name, effect.form)} in paired:
            continue
        z0, score, _ = screen(bench, effect, seed, lead, (best.z,))
        ranked.append((score, effect.name, effect, z0))
    out, families = [], set()
    for score, name, effect, z0 in sorted(ranked, key=lambda r: r[0]):
        if name in families:
            continue                                      # the best-screened form of each family
        families.add(name)
        out.append(_model_first(best.named, (effect,), _named_z(best), z0))
        if len(out) == DEFAULT.step_pairs:
            break
    return out


def refit_singles(bench, fits, head, n_head: int) -> None:
    """A pair's fit continues from its singles' optima and can reach one
    effect's parameters better than that single's own local least squares
    did (the other effect then fitted at no size): the singles of the
    leading pair are re-fitted from the pair's coordinates and the better
    fit of each is kept (so the pair test compares a pair with its singles
    at their best)."""
    lead = fits[0]
    if len(lead.named) != 2:
        return
    col = n_head
    for effect in lead.named:
        z = np.concatenate([lead.z[:n_head], lead.z[col:col + len(effect.params)]])
        col += len(effect.params)
        old = next((k for k, f in enumerate(fits) if len(f.named) == 1 and f.named[0] is effect), None)
        new = fitting.fit(bench, tuple(head) + (effect,), z, bench.train)
        if old is not None and new.nrmse_train < fits[old].nrmse_train:
            holdout_score(bench, new)
            fits[old] = new
    fits.sort(key=lambda f: f.nrmse_holdout)
