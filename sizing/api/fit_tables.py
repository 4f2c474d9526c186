"""The tables a fit command reports (docs/formats.md, "Fit output"): which
model wins on the holdout, the [fit] table with intervals, prior and initial
states, and the rig-ready [stack] / [motor] tables. Pure: fitted estimators
and NRMSE figures in, dicts out."""
from __future__ import annotations

import numpy as np

# the fits' modules (numba) are imported where a table is built: the
# command checks its options against MODELS before they load

MODELS = ("bouc-wen", "prandtl-ishlinskii")
FROM_PRIOR_SHARE = 0.5      # posterior/prior variance above which a value "comes from the prior"


def mean(values):
    values = list(values)
    return float(np.mean(values)) if values else None


def nrmse_summary(per_role: dict) -> dict:
    """{"nrmse_train", "nrmse_holdout", "nrmse_runs"} of {role: {run: NRMSE}}."""
    return {"nrmse_train": mean(per_role["train"].values()), "nrmse_holdout": mean(per_role["holdout"].values()),
            "nrmse_runs": {**per_role["train"], **per_role["holdout"]}}


def choose(summary: dict) -> dict:
    """Which model wins: lower mean holdout NRMSE (training NRMSE when
    nothing is held out), and by how much."""
    key = "nrmse_holdout" if summary["bouc-wen"]["nrmse_holdout"] is not None else "nrmse_train"
    scores = {m: summary[m][key] for m in MODELS}
    winner = min(MODELS, key=lambda m: scores[m])
    loser = MODELS[1 - MODELS.index(winner)]
    return {"winner": winner, "criterion": f"mean {key.removeprefix('nrmse_')} NRMSE" +
            ("" if key == "nrmse_holdout" else " (nothing held out)"),
            "bouc_wen": scores["bouc-wen"], "prandtl_ishlinskii": scores["prandtl-ishlinskii"],
            "margin": scores[loser] - scores[winner],
            "margin_relative": (scores[loser] - scores[winner]) / scores[loser] if scores[loser] else 0.0}


def stack_tables(bw) -> dict:
    """[stack] d33 and [stack.bouc_wen] of the regularised Bouc-Wen fit."""
    from ..fit.bouc_wen import PARAM_NAMES
    th = bw.regularised_.params.as_array()
    return {"stack": {"d33": th[0]}, "stack.bouc_wen": dict(zip(PARAM_NAMES[1:], th[1:]))}


def _filter_note(cutoffs: list) -> str:
    if not any(cutoffs):
        return "voltage used unfiltered (--cutoff-hz 0)"
    return ("voltage low-passed before it drives the models: 4th-order Butterworth, zero phase "
            f"(forwards and backwards), cut-off {', '.join(f'{c:g}' for c in cutoffs)} Hz, chosen per run "
            "from its sample rate and excitation (20 x the dominant frequency, 3 x the band holding 99 % of "
            "the excitation's energy, at least 5 Hz, at most a quarter of the Nyquist frequency), so sensor "
            "noise cannot ratchet the hysteresis state")


def _prior_table(reg, prior_text: str, prior_sigma: float) -> dict:
    from ..fit.bouc_wen import PARAM_NAMES
    return {"source": prior_text, "sigma_relative": prior_sigma,
            "weight": (f"Gaussian prior on each dimensionless group, 1-sigma {prior_sigma:g} x its prior value "
                       "(at least 0.1), against the data's white-noise chi^2 at the plain fit's residual "
                       "level; intervals and prior shares count the data with the interval inflation"),
            "values": dict(zip(PARAM_NAMES, reg.prior.tolist())),
            "prior_share": dict(zip(PARAM_NAMES, reg.prior_share.tolist())),
            "from_prior": [n for n, s in zip(PARAM_NAMES, reg.prior_share) if s > FROM_PRIOR_SHARE]}


def _initial_states(states: dict, pi) -> dict:
    return {"h0_m": states["h0_m"], "offset_m": states["offset_m"],
            "prandtl_ishlinskii_u_V": {k: "steady-state guess" if u is None else float(u)
                                       for k, u in pi.memory_.items()},
            "prandtl_ishlinskii_offset_m": dict(pi.offset_)}


def hysteresis_fit_table(carried, requested, choice, summary, bw, pi, runs, states, prior_text,
                         prior_sigma, fit_offset) -> dict:
    """The [fit] table of ``sizing fit hysteresis``; ``runs``: (training, holdout) records."""
    from ..fit.bouc_wen import PARAM_NAMES
    from ..fit.common import Z95
    from ..fit.prior import combinations
    reg = bw.regularised_
    cutoffs = sorted(set(round(c, 3) for c in bw.cutoff_hz_.values()))
    half = Z95 * np.sqrt(np.clip(np.diag(reg.cov), 0, None))
    th = reg.params.as_array()
    other = MODELS[1 - MODELS.index(carried)]
    table = {
        "model": carried,
        "model_requested": requested,
        "nrmse_train": summary[carried]["nrmse_train"],
        "nrmse_holdout": summary[carried]["nrmse_holdout"],
        "train_runs": [r.name for r in runs[0]],
        "holdout_runs": [r.name for r in runs[1]],
        "sensor_offset": ("fitted per run (default; --no-offset holds it at 0)" if fit_offset
                          else "held at 0 (--no-offset)"),
        "initial_state_note": ("fitted per run: Bouc-Wen h0, Prandtl-Ishlinskii the last turning point u of the "
                               "input before the record; holdout runs get theirs with the model held"),
        "input_filter": _filter_note(cutoffs),
        "cutoff_Hz": cutoffs[0] if len(cutoffs) == 1 else cutoffs,
        "warnings": plain_warnings(bw.warnings_),
        "nrmse_runs": summary[carried]["nrmse_runs"],
        "model_choice": choice,
        "ci95": {n: [float(th[i] - half[i]), float(th[i] + half[i])] for i, n in enumerate(PARAM_NAMES)},
        "residual_lag1_correlation": bw.residual_correlation_,
        "interval_inflation": bw.interval_inflation_,
        "combinations": combinations(bw.params_.as_array(), bw.cov_),
        "prior": _prior_table(reg, prior_text, prior_sigma),
        "unregularised": {"nrmse_train": summary["bouc-wen-plain"]["nrmse_train"],
                          "nrmse_holdout": summary["bouc-wen-plain"]["nrmse_holdout"],
                          "values": dict(zip(PARAM_NAMES, bw.params_.as_array().tolist())),
                          "ci95": {n: list(bw.ci95_[n]) for n in PARAM_NAMES}},
        "initial_state": _initial_states(states, pi),
    }
    table[other.replace("-", "_")] = {k: summary[other][k] for k in ("nrmse_train", "nrmse_holdout", "nrmse_runs")}
    return table


def hysteresis_tables(carried: str, bw, pi, fit_table: dict) -> dict:
    """The TOML's tables: [prandtl_ishlinskii] first when it is the carried
    model, then [stack], [stack.bouc_wen] and [fit]."""
    tables = stack_tables(bw)
    if carried == "prandtl-ishlinskii":
        tables = {"prandtl_ishlinskii": {"thresholds_V": [float(x) for x in pi.thresholds_],
                                         "weights_m_V": [float(x) for x in pi.weights_]}, **tables}
    tables["fit"] = fit_table
    return tables


HYSTERESIS_COMMENTS = {
    "stack": ("sizing fit hysteresis: seed eq. 1-2, SI (paste into rig.toml); values the data leave "
              "free come from the prior, see [fit.prior]"),
    "prandtl_ishlinskii": ("the model this fit carries (see [fit.model_choice]); [stack] below is the Bouc-Wen "
                           "form a rig.toml takes"),
    "fit": "not part of a rig: fit figures (NRMSE per docs/formats.md)"}
DC_COMMENTS = {"motor": "sizing fit dc-motor: seed eq. 13-14, SI (paste into rig.toml)",
               "fit": "not part of a rig: fit figures (NRMSE per docs/formats.md)"}


def dc_fit_table(est, runs, per_role: dict) -> dict:
    """The [fit] table of ``sizing fit dc-motor``; ``runs``: (training, holdout) records."""
    return {"model": "dc-motor", "nrmse_train": mean(per_role["train"].values()),
            "nrmse_holdout": mean(per_role["holdout"].values()),
            "train_runs": [r.name for r in runs[0]], "holdout_runs": [r.name for r in runs[1]],
            "warnings": list(est.warnings_),
            "nrmse_runs": {**per_role["train"], **per_role["holdout"]},
            "ci95": {n: list(v) for n, v in est.ci95_.items()},
            "stderr": {n: float(s) for n, s in zip(est.names_, est.stderr_)}}


def dc_tables(est, fit_table: dict) -> dict:
    """[motor] c1, c2, [controller] the fitted gains (if any) and [fit]."""
    tables = {"motor": {"c1": est.params_["c1"], "c2": est.params_["c2"]}}
    gains = {k: v for k, v in est.params_.items() if k in ("kp", "ki", "kd")}
    if gains:
        tables["controller"] = gains
    tables["fit"] = fit_table
    return tables


PLAIN = "plain least-squares fit (before the prior): "


def plain_warnings(messages) -> list[str]:
    """The plain fit's warnings, saying so: its values (beta = 1.7) are not
    the [stack] values the TOML carries (beta = 7.3, with the prior)."""
    return [m if m.startswith(PLAIN) else PLAIN + m for m in messages]

