"""How far a candidate explains the gap, and the verdict.

The candidates come from attribution.py (every effect screened and fitted,
pairs); this module picks the one the verdict judges (``pick``: a pair
only when it earns its second effect), finds the runner-up, tests
separation (``evidence``) and states the verdict (verdict.Verdict): each
rule below is a named predicate on that evidence, applied in the declared
order of ``RULES`` (the first that applies decides), then the channel rule.

Verdict (all measures are the combined measure of bench.py, holdout runs):
- "no_significant_gap": baseline <= ``gap_factor`` x the noise floor
  (decided first, before the line rule), unless the holdout gap has a
  spectral line that the best candidate removes (``narrowband_gap``):
  then the line rule below judges it;
- "undetectable" (named nothing) when the baseline is above that but within
  ``gap_factor`` x the floor (noise and model form together; "unexplained"
  when the gap has a line no candidate removes), unless the
  holdout gap has a spectral line (gap_lines, a narrow band the
  broadband model-form floor does not cover): then the best candidate is
  judged on the share of the lines' energy it removes (line rule) when
  the lines carry ``line_share`` of what it removes (``lines_carry``);
- "undetectable" too when the training runs the candidates were fitted
  to show no gap (``no_gap_on_training``: the nominal leaves within
  ``gap_factor`` x their floor there): a fit to them is a fit to form error;
- "explained": the best removes >= ``explained`` of the gap energy above the
  floor (and, unless judged on lines, at least the floor's own energy:
  base^2 - best^2 >= floor^2, so that it is not fitting model-form
  error), leaves <= ``residual_factor`` x floor, is significantly better
  than the baseline and separated from the runner-up (the best
  candidate that is a different explanation: neither a subset nor a
  superset of its effects);
- "partial": the best removes >= ``partial`` of the gap energy above the
  floor and is significantly better than the baseline, but one of the
  other conditions fails; ``remaining`` says where its residual is;
  it must remove most of the gap (>= ``explained``) or be separated from
  the runner-up: an effect that removes less than most of the gap and
  that another explanation matches names nothing (``tied``);
  an effect whose fitted time constant (a ``*time_s`` parameter) is
  longer than the shortest training run does not settle within a run,
  so it cannot be told from a slow drift: it is at most "partial";
- "unexplained" otherwise. Both null verdicts name no effect.
Channel rule (``channel_verdict``): on a campaign that logs more than the
position (a DC servo's current), a verdict short of "explained" on the
combined measure is judged again on each channel by the same rules,
against that channel's own floors; an effect that explains one channel
(or, when the combined measure names nothing, part of it) and worsens
none is named from it, and the verdict says which channel decided.
Parsimony (``pick``, ``beyond_form``): a pair is taken over its single
only when its partner removes more than the other partners of the same
single take of the single's own form error and, when the pair still
leaves a gap, does better on the holdout than the single with a model
discrepancy (``beyond_discrepancy``, discrepancy.py).
The thresholds are declared in settings.py (rationale: docs/diagnosis-settings.md).
Significance (separation test): a bootstrap of fixed, non-overlapping
blocks (Carlstein's non-overlapping block bootstrap, not a moving-block
one): the holdout runs are cut into consecutive ``settings.block_s``
blocks, each block's energy is one observation, and the blocks are drawn
with replacement. The statistic is the difference of the weighted squared
residual energy of two candidates, paired block by block; B =
``settings.n_boot`` resamples (seeded); "significant" when fewer than ``alpha`` of the
resampled differences favour the other candidate. Against the baseline the
test is one-sided (an effect is asked to lower the gap); between two
candidates ranked on the same holdout runs it is two-sided
(``separation_p``), because the ranking already chose which looks better.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from .. import spectrum
from .floor import total_floor
from .settings import DEFAULT, Settings
from .verdict import Verdict


def gap_lines(bench, nominal: list, candidate: list | None) -> dict | None:
    """The lines of the holdout gap and how much of them a candidate removes
    (``line_removal`` of the baseline residuals, measured - nominal).
    ``nominal`` and ``candidate``: simulated positions (n,) of the holdout
    runs (bench.holdout order)."""
    runs = [bench.runs[i] for i in bench.holdout]
    base = [(r.t, r.y - y) for r, y in zip(runs, nominal)]
    after = None if candidate is None else [(r.t, r.y - y) for r, y in zip(runs, candidate)]
    return spectrum.line_removal(base, nominal, after)


def block_energy(bench, sims, runs, channel: int | None = None, settings: Settings = DEFAULT) -> np.ndarray:
    """Weighted squared residual energy of each ``block_s`` block of the runs
    (sims: (n_ch, n) per run), one array over all runs; ``channel``: of
    that channel alone (unweighted)."""
    out = []
    for i, S in zip(runs, sims):
        r = bench.runs[i]
        g2 = (bench.gap(i, S) / bench.spans(i)[:, None]) ** 2
        e2 = g2[channel] if channel is not None else np.sum(bench.weights(i)[:, None] * g2, axis=0)
        dt = float(np.median(np.diff(r.t)))
        size = max(int(round(settings.block_s / dt)), 1)
        n_blocks = max(len(e2) // size, 1)
        out.append(np.array([e2[k * size:(k + 1) * size].sum() for k in range(n_blocks)]) / len(e2))
    return np.concatenate(out)


def bootstrap_p(better: np.ndarray, worse: np.ndarray, seed: int = 0, n_boot: int = DEFAULT.n_boot) -> float:
    """One-sided bootstrap p-value that ``better`` (block energies) is not
    smaller than ``worse``: share of block resamples in which it is not."""
    d = np.asarray(worse) - np.asarray(better)
    if d.size == 0:
        return 1.0
    rng = np.random.default_rng(seed)
    idx = rng.integers(0, d.size, size=(n_boot, d.size))
    return float(np.mean(d[idx].sum(axis=1) <= 0.0))


def separation_p(better: np.ndarray, worse: np.ndarray, seed: int = 0, n_boot: int = DEFAULT.n_boot) -> float:
    """Two-sided bootstrap p-value of the difference between two candidates
    that were ranked on these same holdout runs: which one is ``better`` was
    read from the data the test is run on, so the one-sided p (bootstrap_p)
    is doubled. Of two candidates that are equally good, the one ranked
    first looks better by construction, and a one-sided test would call
    them separated twice as often as its level says."""
    return min(1.0, 2.0 * bootstrap_p(better, worse, seed, n_boot))


def explained(base: float, after: float, floor: float) -> float:
    """Fraction of the gap energy above the noise floor that an effect removes."""
    excess = base ** 2 - floor ** 2
    if excess <= 0:
        return 0.0
    return float(1.0 - max(after ** 2 - floor ** 2, 0.0) / excess)


def pick(fits, seed: int = 0, floor: float = 0.0, settings: Settings = DEFAULT, noise: float | None = None,
         channels: dict | None = None):
    """The candidate the verdict judges: the best fitted candidate, except
    that a pair is taken only when it is significantly better on the
    holdout (block bootstrap) than the best single of its two effects,
    removes at least ``pair_gain`` of the gap energy that single leaves above
    the floor when the single leaves a gap (``leaves_a_gap``: on the
    combined measure or on one of the logged ``channels``), or most of
    a spectral line it leaves (``removes_what_is_left``), fits the training runs at least as well as it and names a
    partner no other family replaces (``partner_identified``) and that
    removes more than the other partners of that single take of its form
    error (``beyond_form``), and, where the pair still leaves a gap, that
    does better than the single with a model discrepancy
    (``beyond_discrepancy``); otherwise that single is (parsimony). The pair holds
    the single (its partner at no size), so a pair that fits the training
    runs worse is a fit stuck short of its optimum, and its better holdout
    is chance or form error taken up elsewhere. A candidate only screened,
    not fitted (not promising on the training runs), is never taken,
    whatever its holdout: its holdout rank is chance. A pair that leaves
    no more than ``noise_match`` x the ``noise`` floor on the holdout runs
    is judged against the noise floor alone (``noise_matched``: the
    campaign then shows no model-form error to allow for)."""
    fitted = [f for f in fits if f.message != "screened only"]
    if not fitted:
        return None
    best = fitted[0]
    if len(best.named) < 2:
        return best
    names = {e.name for e in best.named}
    singles = [f for f in fitted if len(f.named) == 1 and f.named[0].name in names]
    if singles:
        single = singles[0]
        if noise is not None and best.nrmse_holdout <= settings.noise_match * noise:
            floor = noise
        gain = explained(single.nrmse_holdout, best.nrmse_holdout, floor)
        earned = ((gain >= settings.pair_gain and leaves_a_gap(single, floor, settings, channels))
                  or removes_what_is_left(single, best, settings))
        if (separation_p(best.residual_blocks, single.residual_blocks, seed) >= settings.alpha or not earned
                or best.nrmse_train > single.nrmse_train
                or not partner_identified(fits, best, single, seed, settings)
                or not beyond_form(fits, best, single, settings)
                or not beyond_discrepancy(best, single, floor, seed, settings)):
            return single
    return best


def beyond_discrepancy(pair, single, floor: float, seed: int = 0, settings: Settings = DEFAULT) -> bool:
    """Whether the pair is significantly better on the holdout runs (the
    two-sided block bootstrap of ``separation_p``) than its single with a
    model discrepancy (``single.discrepancy``: discrepancy.account, a
    linear filter of the single's own simulated channels fitted on the
    training runs beside it; {"nrmse_holdout", "blocks"}), when the pair
    itself still leaves a gap (more than ``gap_factor`` x the floor). A
    partner that only takes up part of its single's form error, as any
    flexible term would, leaves a structured residual and does no better
    than the flexible term (a delay of another form than the library's: a
    viscous partner took 35-50 % of what the pure delay left and the pair
    still left 1.8-3.4 x the floor, where the discrepancy left less). A
    pair within the floor is an account of the gap by two effects of the
    library and is not asked: the discrepancy has more free coefficients
    than any partner, and a partner whose response is itself a linear
    filter of the motion (a real delay behind a real damping) is matched
    by it. True when the single carries no discrepancy."""
    account = getattr(single, "discrepancy", None)
    if account is None or not leaves_a_gap(pair, floor, settings):
        return True
    return (pair.nrmse_holdout < account["nrmse_holdout"]
            and separation_p(pair.residual_blocks, account["blocks"], seed, settings.n_boot) < settings.alpha)


def leaves_a_gap(single, floor: float, settings: Settings = DEFAULT, channels: dict | None = None) -> bool:
    """Whether the single leaves a gap on the holdout runs: more than
    ``gap_factor`` x the floor (noise and model form), the rule by which
    the baseline is a gap at all, on the combined measure or on one logged
    channel against that channel's floors (``channels``: {channel: {"noise",
    "form"}}; a sensor mount behind a friction rings in the position, which
    the current, already at its floor, dilutes in the combined measure: the
    friction left 1.4 x the combined floor and 1.9 x the position's). What
    a single leaves within that band is
    what a nominal of another form leaves, and a partner fitted to it takes
    up the single's form error (a leak behind a slew limit that already
    left 1.3 x the floor); only a spectral line the single leaves
    (``removes_what_is_left``), which the broadband floor does not cover,
    can still earn a partner there."""
    if single.nrmse_holdout > settings.gap_factor * floor:
        return True
    return any(single.nrmse_channels.get(c, 0.0) > settings.gap_factor * float(np.hypot(ch["noise"], ch["form"]))
               for c, ch in (channels or {}).items())


def removes_what_is_left(single, pair, settings: Settings = DEFAULT) -> bool:
    """Whether the single leaves a spectral line on the holdout runs
    (spectrum.line_removal of its residuals) of which the pair removes at
    least ``line_gain`` of the energy. A second effect whose energy is a
    narrow band (a sensor mount ringing behind a backlash or a current
    limit) can take a small share of the broadband gap the single leaves
    (``pair_gain``, measured against the whole floor) and still be plain in
    the spectrum. ``line_gain`` asks more than ``pair_gain``, because a line is a
    narrow band; less than ``explained``, because the library's form of the
    second effect is not the hardware's (a fitted mount settles at another
    damping than the hardware's and removes part of the line only)."""
    if not single.holdout_residual or not pair.holdout_residual:
        return False
    left = spectrum.line_removal(single.holdout_residual, single.holdout_position, pair.holdout_residual)
    return left is not None and left["removed"] >= settings.line_gain


def partner_identified(fits, pair, single, seed: int = 0, settings: Settings = DEFAULT) -> bool:
    """Whether ``pair`` is significantly better on the holdout than the
    best other pair built on the same ``single`` with another family: when a
    different partner does as well, the data say "this single and
    something", not which."""
    lead = single.named[0].name
    partner = {e.name for e in pair.named} - {lead}
    rivals = [f for f in fits if len(f.named) == 2 and lead in {e.name for e in f.named}
              and not partner & {e.name for e in f.named}]
    return not rivals or separation_p(pair.residual_blocks, rivals[0].residual_blocks, seed) < settings.alpha


def runner_up(fits, best):
    """The best candidate that is a different explanation from ``best``."""
    if best is None:
        return None
    chosen = {e.name for e in best.named}
    for f in fits:
        names = {e.name for e in f.named}
        if f is not best and not (names <= chosen or chosen <= names):
            return f
    return None


def unsettled(fit, run_length: float | None) -> dict:
    """The fitted time constants (parameters named ``*time_s``) of ``fit``
    longer than ``run_length`` (s): an effect that does not settle within a
    run is indistinguishable from a slow drift over it."""
    if fit is None or run_length is None:
        return {}
    return {k: v for k, v in fit.params.items()
            if k.endswith("time_s") and not k.startswith("recalibration.") and v > run_length}


def noise_matched(best, noise_floor: float, p_second: float, settings: Settings = DEFAULT) -> bool:
    """Within the model-form floor, a candidate that leaves no more than
    ``noise_match`` x the noise floor on the holdout runs, separated from the
    runner-up, is judged against the noise floor alone: nominal and effect
    then leave nothing but measurement noise on runs they were not fitted
    to, so this campaign shows no model-form error to allow for. (Above
    the band the ordinary rules ask less: an effect may leave up to
    ``residual_factor`` x the floor.) ``noise_match`` is a little above 1, the
    sampling spread of a noise estimate from a few thousand samples; a
    nominal of another form leaves more than that on runs it was not
    fitted to."""
    return best.nrmse_holdout <= settings.noise_match * noise_floor and p_second < settings.alpha


def tied(share: float, separated: bool, settings: Settings = DEFAULT) -> bool:
    """Whether a candidate is too weak on two counts to be named even as
    partial: it removes less than most (``explained``) of the gap energy above
    the floor and is not separated from the runner-up, another
    explanation. Either alone still names it "partial"; both together
    mean the data neither pin the gap on it nor prefer it to another
    family: what a candidate removes then is as likely model-form error
    that any flexible family takes up."""
    return share < settings.explained and not separated


def narrowband_gap(line: dict | None, best, baseline_blocks, seed: int = 0, settings: Settings = DEFAULT) -> bool:
    """Whether a holdout gap within ``gap_factor`` x the noise floor is still a
    gap: a spectral line of it (gap_lines: in every holdout run,
    >= LINE_FACTOR x the local level, not a line of the nominal itself)
    that the best candidate removes for the most part (>= ``explained`` of the
    lines' energy) while being significantly better than the baseline on
    the holdout (block bootstrap). A lightly damped sensor mount rings for
    a few cycles after each step: its broadband energy can be at the noise
    while its line stands far above the spectrum's local level, and a
    fitted mount at the line's frequency removes it. The input
    treatment's own error (not white) can show a line too, which an effect
    halves but does not remove: ``explained`` of the line's energy is asked."""
    if line is None or best is None or baseline_blocks is None:
        return False
    return (line.get("removed", 0.0) >= settings.explained
            and bootstrap_p(best.residual_blocks, baseline_blocks, seed) < settings.alpha)


@dataclass(frozen=True)
class Evidence:
    """What the rules judge, computed once from the candidates: the gap
    (baseline), the noise floor and the floor with model form (``floor``,
    the one the share is measured against), the candidate ``pick`` chose
    (``best``, None when nothing was fitted) and its runner-up, the
    share of the gap energy above the floor it removes (or of the lines'
    energy: ``basis`` "lines"; against the noise floor alone: "noise"),
    the separation p-values and the fitted time constants that do not
    settle within a run (``slow``)."""

    baseline: float
    noise: float
    floor: float
    settings: Settings
    total: float = 0.0
    best: object = None
    second: object = None
    narrowband: bool = False
    basis: str = "gap"
    shrink: float = 0.0
    share: float = 0.0
    p_base: float = 1.0
    p_second: float = 1.0
    slow: dict = field(default_factory=dict)
    run_length: float | None = None
    details: dict = field(default_factory=dict)
    training: dict | None = None

    @property
    def in_band(self) -> bool:
        """Above the noise, within ``gap_factor`` x the floor with model form."""
        return self.baseline <= self.settings.gap_factor * self.floor

    @property
    def removed(self) -> float:
        return self.baseline ** 2 - self.best.nrmse_holdout ** 2

    @property
    def substantial(self) -> bool:
        """It removes at least the floor's own energy (not asked of the line
        rule, whose lines the broadband floor does not cover)."""
        return self.removed >= self.floor ** 2 or self.basis == "lines"

    @property
    def significant(self) -> bool:
        return self.shrink > 0 and self.p_base < self.settings.alpha and self.substantial

    @property
    def separated(self) -> bool:
        return self.p_second < self.settings.alpha

    @property
    def leaves(self) -> bool:
        return self.best.nrmse_holdout <= self.settings.residual_factor * self.floor

    @property
    def runner_up_name(self) -> str:
        return self.second.name if self.second else "every other effect"

    def null(self, rule: str, *reasons: str) -> Verdict:
        return Verdict("unexplained", reasons=reasons, rule=rule, separation=self.details.get("separation"),
                       details={k: v for k, v in self.details.items() if k != "separation"})

    def named(self, status: str, rule: str, *reasons: str) -> Verdict:
        return self.null(rule, *reasons).replace(status=status, effect=self.best.name, form=self.best.form,
                                                 shrink=self.shrink)


def evidence(baseline: float, noise: float, fits, baseline_blocks=None, seed: int = 0,
             run_length: float | None = None, line: dict | None = None, form_floor: float | None = None,
             settings: Settings = DEFAULT, channels: dict | None = None, training: dict | None = None) -> Evidence:
    """The evidence of the rules (Evidence) from the verdict's inputs."""
    floor = total_floor(noise, form_floor, settings)
    best = pick(fits, seed, floor, settings, noise=noise, channels=channels)
    ev = Evidence(baseline, noise, floor, settings, total=floor, best=best, run_length=run_length,
                  narrowband=narrowband_gap(line, best, baseline_blocks, seed, settings), training=training)
    if best is None:
        return ev
    second = runner_up(fits, best)
    p_base = bootstrap_p(best.residual_blocks, baseline_blocks, seed, settings.n_boot) if baseline_blocks is not None else 0.0
    p_second = separation_p(best.residual_blocks, second.residual_blocks, seed, settings.n_boot) if second is not None else 0.0
    share = explained(baseline, best.nrmse_holdout, floor)
    details = {"explained_gap_energy": share, "floor_holdout": floor,
               "runner_up": None if second is None else {
                   "effect": second.name, "form": second.form,
                   "shrink_holdout": float(1.0 - second.nrmse_holdout / baseline),
                   "explained_gap_energy": explained(baseline, second.nrmse_holdout, floor)},
               "separation": {"test": f"block bootstrap over holdout segments ({settings.block_s:g} s blocks, "
                                      f"{settings.n_boot} resamples; one-sided against the baseline, two-sided "
                                      f"between candidates ranked on the holdout)",
                              "p_vs_baseline": p_base, "p_vs_runner_up": p_second, "alpha": settings.alpha}}
    if line is not None:
        details["line"] = dict(line, judged_on=False)
    ev = dataclasses.replace(ev, second=second, p_base=p_base, p_second=p_second, share=share,
                             shrink=float(1.0 - best.nrmse_holdout / baseline), slow=unsettled(best, run_length),
                             details=details)
    return judged_basis(ev, line, channels)


def judged_basis(ev: Evidence, line: dict | None, channels: dict | None = None) -> Evidence:
    """Within the model-form floor (``in_band``), what a candidate is judged
    on: the share of the gap lines' energy it removes when it removes at
    least ``partial`` of it and the lines carry what it removes
    (``lines_carry``; the model-form floor is broadband, smooth-model
    error; a spectral line of the holdout gap is not covered by it), else
    the noise floor alone when it leaves no more than ``noise_match`` x the
    noise (``noise_matched``); otherwise the gap energy above the floor."""
    if not ev.in_band:
        return ev
    if line is not None and line.get("removed", 0.0) >= ev.settings.partial and lines_carry(ev, line, channels):
        share = float(line["removed"])
        details = dict(ev.details, explained_gap_energy=share, line=dict(ev.details["line"], judged_on=True))
        return dataclasses.replace(ev, basis="lines", share=share, details=details)
    if noise_matched(ev.best, ev.noise, ev.p_second, ev.settings):
        share = explained(ev.baseline, ev.best.nrmse_holdout, ev.noise)
        details = dict(ev.details, explained_gap_energy=share, floor_holdout=ev.noise, judged_on_noise_floor=True)
        return dataclasses.replace(ev, basis="noise", floor=ev.noise, share=share, details=details)
    return ev


def lines_carry(ev: Evidence, line: dict, channels: dict | None = None) -> bool:
    """Whether the gap's spectral lines (gap_lines, of the position) carry
    at least ``line_share`` of the energy the best candidate removes from
    the position's holdout gap: the lines' energy it removes, a share
    ``line["share"] x line["removed"]`` of the baseline residual's power,
    against 1 - (candidate / baseline)^2 of the position's NRMSE. A mount
    that rings after each step removes its line and little else; a
    broadband candidate fitted to the nominal's form error (a softer oil
    taking up a stiffer response) removes the broadband gap and, with it,
    whatever line the excitation leaves in that error, a few per cent of
    what it removes (4 % on a null of the second generator's two-stack
    rig; viscous damping that damps a rig's 89 Hz ring: 9 %). The
    broadband part is what the model-form floor covers, so such a line
    does not decide."""
    position = next(iter(channels), None) if channels else None
    base, after = ev.baseline, ev.best.nrmse_holdout
    if position is not None and channels[position].get("baseline"):
        base = channels[position]["baseline"]
        after = ev.best.nrmse_channels.get(position, after) if getattr(ev.best, "nrmse_channels", None) else after
    removed = 1.0 - min((after / base) ** 2, 1.0) if base > 0 else 0.0
    return float(line.get("share", 0.0)) * float(line["removed"]) >= ev.settings.line_share * removed


# The rules, each a named predicate on the evidence that returns the
# verdict when it applies (None otherwise), applied in the order of RULES.

def no_significant_gap(ev: Evidence) -> Verdict | None:
    """The baseline is within ``gap_factor`` x the noise floor, and the gap has
    no spectral line that the best candidate removes (narrowband_gap).
    Decided before the line rule: the voltage treatment's error carried
    through the model is not white and can show a line that an effect
    halves."""
    if ev.baseline > ev.settings.gap_factor * ev.noise or ev.narrowband:
        return None
    return Verdict("no_significant_gap", rule="no_significant_gap", details={"floor_holdout": ev.total}, reasons=(
        f"baseline holdout NRMSE {ev.baseline:.4f} is within {ev.settings.gap_factor:g} x "
        f"the noise floor {ev.noise:.4f}",))


def nothing_fitted(ev: Evidence) -> Verdict | None:
    """No effect applies, or none fits the training runs well enough to be fitted."""
    if ev.best is not None:
        return None
    return Verdict("unexplained", rule="nothing_fitted",
                   reasons=("no effect applies or fits the training runs well enough to be fitted",))


def within_form_floor(ev: Evidence) -> Verdict | None:
    """Above the noise but within ``gap_factor`` x the floor with model form,
    and judged neither on lines nor on the noise alone: no effect is blamed
    for what a nominal of another form leaves. The status is
    "undetectable": the data show a gap beyond the noise, of a size that
    the difference between two faithful simulators of the rig also
    leaves, so no effect of that size can be told on this campaign (an
    effect there may be real: a larger one, or a campaign whose best
    account leaves the noise, ``noise_matched``, would tell it). A gap with
    a spectral line that no candidate removes stays "unexplained": the
    broadband model-form floor does not cover a line."""
    if not ev.in_band or ev.basis != "gap":
        return None
    lined = "line" in ev.details
    verdict = ev.null("within_form_floor",
                      f"the gap ({ev.baseline:.4f}) is above the noise floor but within {ev.settings.gap_factor:g} x "
                      f"the model-form floor {ev.floor:.4f}: no effect is blamed for what a nominal of "
                      f"another form leaves" + ("" if lined else "; an effect of this size cannot be told on "
                                                                  "this campaign"))
    return verdict if lined else verdict.replace(status="undetectable")


def no_gap_on_training(ev: Evidence) -> Verdict | None:
    """The held-out gap is judged, but the training runs the candidates
    were fitted to show no gap: the nominal's NRMSE there is within
    ``gap_factor`` x their floor, by the rule that makes the held-out
    baseline a gap. Their floor is their noise with the held-out run's
    model-form floor, or their noise alone where the candidate is judged
    on the noise or takes the training runs to it (leaves at most
    ``noise_match`` x their noise: those runs then show no model-form
    error to allow for, as ``noise_matched`` reads the held-out runs). Not
    asked of a verdict on the gap's spectral lines, which the broadband
    floor does not cover. An effect of the library that is there shows on
    the runs it is fitted to, or is fitted there down to the noise; a
    candidate that leaves a structured residual on training runs without
    a gap was fitted to the nominal's form error, and what it removes of
    the held-out gap is that form error where it is larger (a nominal of
    another form errs more on some runs than on others, but not
    ``form_spread`` x more: a held-out gap beyond that is not the
    nominal's form error, whatever the training runs show). The status is
    "undetectable": the training runs cannot tell an effect of that size
    (runs that show it would). Asked only of a verdict that would name an
    effect (``names_an_effect``): one that names nothing keeps its own
    status and reason (an outside effect stays "unexplained")."""
    if ev.training is None or ev.best is None or ev.basis == "lines" or not names_an_effect(ev):
        return None
    base, noise = float(ev.training["baseline"]), float(ev.training["noise"])
    if ev.baseline > ev.settings.form_spread * base:
        return None      # many times the training runs' error: more than a form error's spread between runs
    to_noise = ev.basis == "noise" or ev.best.nrmse_train <= ev.settings.noise_match * noise
    form = 0.0 if to_noise else float(np.sqrt(max(ev.total ** 2 - ev.noise ** 2, 0.0)))
    floor = float(np.hypot(noise, form))      # the held-out run's model-form floor, the training runs' noise
    if base > ev.settings.gap_factor * floor:
        return None
    return ev.null("no_gap_on_training",
                   f"the training runs show no gap: the nominal leaves {base:.4f} there, within "
                   f"{ev.settings.gap_factor:g} x their floor {floor:.4f}, and {ev.best.name}, fitted to them, "
                   f"leaves {ev.best.nrmse_train:.4f} (their noise {noise:.4f}): it takes up the nominal's form "
                   f"error, which is larger on the held-out run ({ev.baseline:.4f}); an effect of this size cannot "
                   f"be told on this campaign").replace(status="undetectable")


def names_an_effect(ev: Evidence) -> bool:
    """Whether the rules after ``no_gap_on_training`` would name an effect."""
    later = RULES[RULES.index(no_gap_on_training) + 1:]
    return next(v for v in (rule(ev) for rule in later) if v is not None).effect is not None


def explains(ev: Evidence) -> Verdict | None:
    """Significantly better than the baseline, removes at least ``explained``
    of the gap energy above the floor (and the floor's own energy), leaves
    at most ``residual_factor`` x the floor, separated from the runner-up and
    settled within a run."""
    s = ev.settings
    if not (ev.significant and ev.share >= s.explained and ev.separated and ev.leaves and not ev.slow):
        return None
    what = ("of the energy of the gap's spectral lines" if ev.basis == "lines"
            else "of the holdout gap energy above the floor")
    return ev.named("explained", "explains",
                    f"{ev.best.name} removes {100 * ev.share:.0f} % {what}, "
                    f"separated from {ev.runner_up_name} (p = {ev.p_second:.3f})")


def tied_with_runner_up(ev: Evidence) -> Verdict | None:
    """Significant and above ``partial``, but ``tied``: less than most of the
    gap and not separated from another explanation, which names nothing."""
    s = ev.settings
    if not (ev.significant and ev.share >= s.partial and tied(ev.share, ev.separated, s)):
        return None
    return ev.null("tied_with_runner_up",
                   f"{ev.best.name} removes {100 * ev.share:.0f} % < {100 * s.explained:.0f} % of the holdout gap "
                   f"energy above the floor and is not separated from {ev.second.name} (p = {ev.p_second:.3f}): "
                   f"the data do not say which")


def explains_part(ev: Evidence) -> Verdict | None:
    """Significant and removes at least ``partial`` of the gap energy above the
    floor, but one condition of ``explains`` fails (each is a reason)."""
    s = ev.settings
    if not (ev.significant and ev.share >= s.partial):
        return None
    why = []
    if ev.share < s.explained:
        why.append(f"it removes {100 * ev.share:.0f} % < {100 * s.explained:.0f} % of the gap energy above the floor")
    if not ev.separated:
        why.append(f"not separated from {ev.second.name} (p = {ev.p_second:.3f})")
    if not ev.leaves:
        why.append(f"it leaves {ev.best.nrmse_holdout:.4f} > {s.residual_factor:g} x the floor {ev.floor:.4f}")
    for k, v in ev.slow.items():
        why.append(f"its fitted {k} = {v:.3g} s is longer than the shortest training run ({ev.run_length:.3g} s): "
                   f"it does not settle within a run and cannot be told from a slow drift")
    why[0] = f"{ev.best.name} explains part of the gap: {why[0]}"
    return ev.named("partial", "explains_part", *why)


def explains_too_little(ev: Evidence) -> Verdict:
    """Otherwise: no effect removes a significant part of the gap."""
    small = "" if ev.substantial else (f"; it removes {ev.removed:.3g} of gap energy, less than the model-form "
                                       f"floor's own {ev.floor ** 2:.3g}")
    return ev.null("explains_too_little",
                   f"no effect of the library removes a significant part ({100 * ev.settings.partial:.0f} %) of the "
                   f"holdout gap energy above the floor (best: {ev.best.name}, {100 * ev.share:.0f} %, p vs baseline "
                   f"{ev.p_base:.3f}{small})")


RULES = (no_significant_gap, nothing_fitted, within_form_floor, no_gap_on_training, explains, tied_with_runner_up,
         explains_part, explains_too_little)


# Verdicts another measure of the same runs may revisit (``revisit``): the
# holdout shows a gap, and no candidate removes it point by point.
REVISITED = ("unexplained", "undetectable")


def revisit(out: Verdict, measures) -> tuple[Verdict, object]:
    """The verdict of the first of ``measures`` that names an effect, when
    ``out`` names nothing and its status is REVISITED; else ``out``. Each
    measure is called without arguments, only when reached (it simulates),
    and gives (Verdict, payload) or None: events.event_verdict judges a
    train of slips on the position's increments. Returns (verdict, the
    deciding measure's payload or None); a revisited verdict keeps the
    point-by-point reason and details beside its own."""
    if out.effect is not None or out.status not in REVISITED:
        return out, None
    for measure in measures:
        found = measure()
        if found is not None:
            named, payload = found
            return named.replace(reasons=named.reasons + (f"on the point-by-point measure: {out.reason}",),
                                 details={**out.details, **named.details}), payload
    return out, None


def verdict(baseline_holdout: float, floor_holdout: float, fits, baseline_blocks=None, seed: int = 0,
            run_length: float | None = None, line: dict | None = None, form_floor: float | None = None,
            channels: dict | None = None, settings: Settings = DEFAULT, training: dict | None = None) -> Verdict:
    """The first verdict of RULES on the combined measure; then, on a
    campaign that logs more than the position, the channel rule
    (``channel_verdict``) when it names more: "explained" from a channel
    over anything short of it on the combined measure, "partial" from a
    channel over a combined verdict that names nothing. ``floor_holdout``:
    the noise floor; ``run_length``: the shortest training run (s), for
    the settling rule; ``line``: the spectral lines of the holdout gap
    (gap_lines); ``form_floor``: the model-form floor of the
    combined measure (None: the prior); ``channels``: {channel:
    {"baseline", "noise", "form", "blocks"}}; ``training``: {"baseline",
    "noise"} of the training runs (the nominal's combined NRMSE and the
    noise floor, root mean square over those runs), for
    ``no_gap_on_training`` (None: not judged)."""
    ev = evidence(baseline_holdout, floor_holdout, fits, baseline_blocks, seed, run_length, line, form_floor,
                  settings, channels, training)
    out = next(v for v in (rule(ev) for rule in RULES) if v is not None)
    if not channels or len(channels) < 2 or out.status == "explained":
        return out
    named = channel_verdict(fits, channels, seed, settings, run_length=run_length)
    if named is None or (named.status == "partial" and out.status == "partial"):
        return out
    prior = "" if form_floor is not None else (
        f" (its position model-form floor is the prior {settings.form_floor_prior:g} of the span, "
        f"settings.form_floor_prior)")
    return named.replace(reasons=named.reasons + (f"on the combined measure: {out.reason}{prior}",),
                         details={**out.details, **named.details})


class ChannelView:
    """A candidate as one logged channel shows it: its holdout NRMSE and
    residual block energies are that channel's; everything else is the
    candidate's."""

    def __init__(self, fit, channel: str):
        self.fit, self.channel = fit, channel
        self.nrmse_holdout = fit.nrmse_channels[channel]
        self.residual_blocks = fit.channel_blocks[channel]
        account = getattr(fit, "discrepancy", None)
        self.discrepancy = None if account is None else account["channels"][channel]

    def __getattr__(self, name):
        return getattr(self.fit, name)


def channel_evidence(fits, c: str, channels: dict, seed: int = 0, settings: Settings = DEFAULT,
                     run_length: float | None = None) -> Evidence | None:
    """The evidence of channel ``c`` alone: its baseline, its noise floor,
    its floor with model form sqrt(noise^2 + form^2), the candidates ranked
    by their NRMSE on c (``pick`` and ``runner_up`` on that ranking) and
    the block bootstraps of c's residual energy. None when no candidate
    was judged on c."""
    ch = channels[c]
    ranked = sorted((ChannelView(f, c) for f in fits if c in getattr(f, "channel_blocks", {})
                     and c in getattr(f, "nrmse_channels", {})), key=lambda f: f.nrmse_holdout)
    total = float(np.hypot(ch["noise"], ch["form"]))
    best = pick(ranked, seed, total, settings, noise=ch["noise"], channels=channels)
    if best is None or ch["baseline"] <= 0:
        return None
    second = runner_up(ranked, best)
    base = ch["baseline"]
    p_base = bootstrap_p(best.residual_blocks, ch["blocks"], seed, settings.n_boot)
    p_second = separation_p(best.residual_blocks, second.residual_blocks, seed, settings.n_boot) if second else 0.0
    return Evidence(base, ch["noise"], total, settings, total=total, best=best, second=second,
                    shrink=float(1.0 - best.nrmse_holdout / base), share=explained(base, best.nrmse_holdout, total),
                    p_base=p_base, p_second=p_second, slow=unsettled(best, run_length), run_length=run_length,
                    details={"explained_gap_energy": explained(base, best.nrmse_holdout, total),
                             "floor_holdout": total})


CHANNEL_RULES = (explains, tied_with_runner_up, explains_part)   # the rules that can name an effect


def channel_verdict(fits, channels: dict, seed: int = 0, settings: Settings = DEFAULT,
                    run_length: float | None = None) -> Verdict | None:
    """The verdict of the channel that names the most: each logged channel
    c is judged alone (``channel_evidence``) by the rules of the combined
    measure that can name an effect (CHANNEL_RULES: "explained", the tie,
    "partial"), when c's baseline is above ``gap_factor`` x c's floor (its
    noise and its model-form floor, floor.form_floor) and the candidate
    leaves no other channel worse than its baseline beyond that channel's
    floor. "explained" on a channel wins over "partial", then the larger
    share of c's gap energy removed. A friction in a stiff position loop
    shows in the current the controller adds to overcome it and hardly
    in the position: the combined measure, normalised by each channel's
    noise, can be ruled by a position gap within its model-form floor
    while the current's gap is many times its own. The verdict says which
    channel decided (``judged_on_channel``). None when no channel names
    an effect."""
    found = []
    for c in channels:
        ev = channel_evidence(fits, c, channels, seed, settings, run_length)
        if ev is None or ev.in_band or not others_kept(ev.best.fit, c, channels):
            continue
        v = next((v for v in (rule(ev) for rule in CHANNEL_RULES) if v is not None), None)
        if v is not None and v.status in ("explained", "partial"):
            found.append((v.status == "explained", ev.share, c, ev, v))
    if not found:
        return None
    _, share, c, ev, v = max(found, key=lambda x: x[:2])
    return v.replace(rule=f"{v.rule}_on_channel", reasons=(f"judged on {c}: {v.reasons[0]}",) + v.reasons[1:],
                     details={**v.details, "judged_on_channel": c, "explained_gap_energy": share,
                              "separation_on_channel": {"p_vs_baseline": ev.p_base, "p_vs_runner_up": ev.p_second}})


def others_kept(fit, c: str, channels: dict) -> bool:
    """Whether ``fit`` leaves every channel but ``c`` no worse than its
    baseline beyond that channel's floor."""
    return all(fit.nrmse_channels.get(d, 0.0) ** 2 <= o["baseline"] ** 2 + o["noise"] ** 2 + o["form"] ** 2
               for d, o in channels.items() if d != c)


def beyond_form(fits, pair, single, settings: Settings = DEFAULT) -> bool:
    """Whether the pair's partner removes a share of the gap that the
    single's own form error cannot explain: the holdout gap energy the
    pair removes beyond the single, single^2 - pair^2, must exceed
    (1 + ``form_margin``) x the median that the other fitted partners of the
    same single remove (pairs of that single with another family). What
    any partner takes from the single's residual is the difference between
    the single's form and the hardware's, which a flexible second effect
    absorbs whatever its physics; a partner that is really there removes
    what the others cannot. Estimated from the campaign's own fits; true
    (no judgement) when the single has no other fitted partner."""
    lead = single.named[0].name
    partner = {e.name for e in pair.named} - {lead}
    rivals = [f for f in fits if len(f.named) == 2 and lead in {e.name for e in f.named}
              and not partner & {e.name for e in f.named} and f.message != "screened only"]
    if not rivals:
        return True
    typical = float(np.median([max(energy(single) - energy(f), 0.0) for f in rivals]))
    return energy(single) - energy(pair) > (1.0 + settings.form_margin) * typical


def energy(fit) -> float:
    """Holdout residual energy of a candidate: the sum of its block
    energies (block_energy: the sum over holdout runs of the combined
    measure squared), or its holdout measure squared without blocks."""
    blocks = getattr(fit, "residual_blocks", None)
    return float(np.sum(blocks)) if blocks is not None and len(blocks) else float(fit.nrmse_holdout ** 2)
