"""The BLAS library's threads: one each, set by the entry points (the
command line, the benchmarks) before numpy is loaded.

The package's linear algebra is on small or thin matrices (a few
parameters by thousands of samples); its parallel work is the numba
simulators' candidates. OpenBLAS threads on top of those only contend for
the cores: on a loaded 2-core machine a 12 000-sample correlation took
0.03 s single-threaded and up to 6.5 s with OpenBLAS's threads spinning.
A user's own setting of these variables is kept.
"""
from __future__ import annotations

import os

BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def single_threaded_blas() -> None:
    """One BLAS thread unless the environment says otherwise (takes effect
    only before numpy is first imported)."""
    for name in BLAS_THREAD_VARIABLES:
        os.environ.setdefault(name, "1")
