"""The thresholds of the diagnosis, declared in one place.

Every rule of the verdict (judge.py), of the parsimony test and of the
floors (floor.py) reads its threshold from one ``Settings`` object; the
rationale of each value is in docs/diagnosis-settings.md, and the cross-form
benchmark reports how its verdicts move when each is varied
(``benchmarks/diagnose_benchmark.py --set NAME``, its sensitivity table), so that
no single threshold decides the benchmark. ``DEFAULT`` is what
``sizing diagnose`` uses.
"""
from __future__ import annotations

from dataclasses import dataclass, fields, replace


@dataclass(frozen=True)
class Settings:
    """Thresholds of the diagnosis (dimensionless unless stated)."""

    gap_factor: float = 1.5        # a gap is a baseline above this x the floor
    explained: float = 0.75        # share of the gap energy above the floor an explaining effect removes
    partial: float = 0.3           # ... a partly explaining effect removes
    residual_factor: float = 2.5   # an explaining effect leaves at most this x the floor
    alpha: float = 0.05            # level of the block-bootstrap tests (two-sided between ranked candidates)
    noise_match: float = 1.2       # within the band, a candidate leaving <= this x the noise is judged on it
    pair_gain: float = 0.25        # a pair removes this share of what its single leaves above the floor...
    line_gain: float = 0.5         # ... or this share of a spectral line its single leaves
    line_share: float = 0.05       # within the band, lines decide when they carry this share of what the best removes
    form_spread: float = 4.0       # a nominal's form error on the held-out run at most this x the training runs' (judge.no_gap_on_training)
    form_floor_prior: float = 0.002  # model-form floor (of the span) when the campaign cannot estimate one
    form_margin: float = 1.0       # a partner removes more than (1 + this) x what the other partners of its single take (judge.beyond_form)
    rest_samples: int = 200        # second differences at rest needed for the at-rest noise estimate
    rest_step: float = 1e-5        # at rest: the nominal moves less than this share of the span per sample
    rest_sigmas: float = 3.0       # the whole run's noise estimate is inflated beyond this x the sampling error
    hold_time_s: float = 0.1       # a voltage moving by less than its noise in this time is held (Bouc-Wen sign deadband), s
    block_s: float = 0.1           # block length of the bootstrap, s
    n_boot: int = 1000             # bootstrap resamples
    # screening and fitting the candidates (attribution.py, fitting.py)
    n_screen: int = 10             # screened parameter sets per effect parameter...
    min_screen: int = 30           # ... and at least this many
    top_fit: int = 4               # families fitted at least (the best-screened form of each)
    fit_below: float = 0.9         # ... and any form that screens below this x the training baseline
    top_pairs: int = 3             # fitted families combined into pairs
    step_pairs: int = 2            # families screened as the second effect given the best single
    discrepancy_taus: tuple = (0.001, 0.003, 0.01, 0.03, 0.1)   # s: low-passes of the rate in a single's model discrepancy (discrepancy.py)
    fd_step: float = 0.01          # forward-difference step of the Jacobian, unit coordinates
    start_spacing: float = 0.15    # the starts of an effect fitted from several: this far apart (unit coordinates, max norm)
    event_grid: int = 10           # an effect judged on its events (events.py): screened at this many values per parameter
    # the campaign and its floors
    min_periods: float = 1.0       # a run lasts at least this x the longest effect time constant
    rest_half_width: int = 10      # samples either side that must be at rest too (the at-rest noise)
    # the logged voltage's treatment (inputs.py, piecewise.py)
    noise_clip: float = 4.0       # a voltage difference beyond this x its robust sigma is a step or a corner, not noise
    smooth_samples: float = 4.0    # sigma of the zero-phase Gaussian low-pass that guides the reversals, samples
    reversal_sigmas: float = 6.0   # a reversal moves by more than this x the voltage noise
    jump_sigmas: float = 8.0       # a jump: a change this x the noise away from the local slope
    kink_scales: tuple = (2, 5, 12, 30)   # samples: scales of the kink detector
    kink_sigmas: float = 5.0       # a kink: the detector's response above this x its own noise
    knot_penalty: float = 4.0      # a knot is kept when it lowers the squared error by this x log(n) sigma^2
    piecewise_accept: float = 1.15  # a piecewise-linear fit is kept when its residual rms is within this x the noise
    piecewise_screen: float = 3.0  # ... and, on knots held to samples, within this x that (else not tried further)
    merge_samples: int = 2         # kink candidates this close are one kink

    def varied(self, name: str, factor: float) -> "Settings":
        """A copy with ``name`` multiplied by ``factor`` (the sensitivity table)."""
        value = getattr(self, name) * factor
        return replace(self, **{name: type(getattr(self, name))(value)})


DEFAULT = Settings()

# thresholds of the verdict varied by the benchmark's sensitivity table
# (form_floor_prior: the combined measure's floor; each channel's floors
# in the verdict's inputs stay as measured)
VERDICT_THRESHOLDS = ("gap_factor", "explained", "partial", "residual_factor", "alpha", "noise_match",
                      "pair_gain", "line_gain", "line_share", "form_spread", "form_margin", "form_floor_prior")


def names() -> list[str]:
    return [f.name for f in fields(Settings)]
