"""The floor a gap is judged against: the noise measured in the data and
the model-form floor (what a well-fitted nominal of another form leaves).

Noise floor of each run, from the data: the white part of the position
measurement (second differences, robust) plus, on a piezo rig, the
spread of the simulated output when the logged voltage is logged again
with its own noise and treated the same way (``noise_floor``).
Model-form floor: FORM_FLOOR, of the span; a stated assumption, see the
README: 0.3-0.5 % on other simulators' null cases, 0.1-0.7 % between the
two piezo generators of this project on their noise-free null runs. The
floor an effect is judged against is
floor = sqrt(noise^2 + FORM_FLOOR^2) (``total_floor``).
"""
from __future__ import annotations

import numpy as np

from .inputs import noise_sigma

FORM_FLOOR = 0.002     # NRMSE a well-fitted nominal of another form leaves (assumed, see README)


def noise_floor(bench, replicas: int = 3, seed: int = 0) -> np.ndarray:
    """(n_runs,) NRMSE expected from measurement noise alone: the position
    noise (robust, from second differences of the baseline residual) and, for a piezo rig, the
    spread of the simulated output when the logged voltage is logged again
    with the same noise and treated the same way (one simulator batch)."""
    from ..sim import piezohydraulic as ph_sim
    from .inputs import treat_voltage

    rng = np.random.default_rng(seed)
    out = []
    for i, r in enumerate(bench.runs):
        sy = noise_sigma(r.y - bench.nominal()[i])     # high-frequency residual
        su = 0.0
        if bench.kind == "piezohydraulic":
            sigma_v = noise_sigma(r.u_raw)
            if sigma_v > 0:
                V = np.vstack([treat_voltage(r.u_raw + rng.normal(0.0, sigma_v, len(r.t))) for _ in range(replicas)])
                Y = ph_sim.simulate(bench.model.replace(h0=np.zeros(replicas)), r.t, V, r.t)["position_m"]
                su = float(np.sqrt(np.mean((Y - bench.nominal()[i][None, :]) ** 2)))
        out.append(float(np.hypot(sy, su)) / r.span)
    return np.array(out)


def total_floor(noise: float) -> float:
    """Noise floor and model-form floor together."""
    return float(np.hypot(noise, FORM_FLOOR))
