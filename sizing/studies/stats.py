"""Statistics of a Monte Carlo: a binomial interval and sensitivity indices.

- ``wilson``: the Wilson score interval of a proportion (Wilson 1927; e.g.
  Brown, Cai & DasGupta 2001, Stat. Sci. 16, eq. 4), 95 % by default.
- ``sensitivity``: first-order variance-based indices by RBD-FAST (SALib's
  ``rbd_fast.analyze``, Plischke 2010 / Tarantola et al. 2006), computed on
  the very Monte Carlo samples (a "given data" estimator: no extra runs),
  of the worst normalised margin of each sample.
"""
from __future__ import annotations

import math

import numpy as np

Z95 = 1.959963984540054


def wilson(successes: int, n: int, z: float = Z95) -> tuple[float, float]:
    """Wilson score interval for successes / n."""
    if n <= 0:
        return (0.0, 1.0)
    p = successes / n
    denom = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return (max(0.0, centre - half), min(1.0, centre + half))


def sensitivity(names: list[str], x: np.ndarray, y: np.ndarray, seed: int = 0) -> dict[str, float]:
    """First-order indices S1 of y over the columns of x (RBD-FAST). Inputs
    that did not vary, or a y that did not, get 0."""
    from SALib.analyze import rbd_fast

    y = np.asarray(y, dtype=float)
    out = {name: 0.0 for name in names}
    varying = [j for j in range(x.shape[1]) if np.ptp(x[:, j]) > 0]
    if not varying or np.ptp(y) == 0 or len(y) < 20:
        return out
    problem = {"num_vars": len(varying), "names": [names[j] for j in varying],
               "bounds": [[float(x[:, j].min()), float(x[:, j].max())] for j in varying]}
    m = max(2, min(10, len(y) // 50))        # harmonics kept: fewer for small samples
    res = rbd_fast.analyze(problem, x[:, varying], y, M=m, num_resamples=2, seed=seed)   # S1 only: no bootstrap CI
    for name, s1 in zip(problem["names"], res["S1"]):
        out[name] = float(np.clip(s1, 0.0, 1.0)) if np.isfinite(s1) else 0.0
    return out
