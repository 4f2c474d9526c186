"""Threads: the BLAS library's, one each, for the command line, the
benchmarks and every call into ``sizing.api`` from Python; and whether a
worker thread of the solve would find a core of its own (``core_to_spare``).

The package's linear algebra is on small or thin matrices (a few
parameters by thousands of samples); its parallel work is the numba
simulators' candidates. OpenBLAS threads on top of those only contend for
the cores: on a loaded 2-core machine a 12 000-sample correlation took
0.03 s single-threaded and up to 6.5 s with OpenBLAS's threads spinning.

Two mechanisms, because environment variables act only before numpy is
first imported: the command line sets them first thing
(``single_threaded_blas``), and each ``sizing.api`` call runs under
threadpoolctl's limit (``one_blas_thread``), which acts on the loaded
library at any time and is undone when the call returns, so a Python user's
own numpy work keeps its threads. A user's own setting of these variables
(made before ``sizing`` is imported) is kept by both.
"""
from __future__ import annotations

import functools
import os

BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")
# what the user asked for before sizing was imported (None: nothing)
USER_SETTING = {name: os.environ.get(name) for name in BLAS_THREAD_VARIABLES}


def single_threaded_blas() -> None:
    """One BLAS thread unless the environment says otherwise (takes effect
    only before numpy is first imported)."""
    for name in BLAS_THREAD_VARIABLES:
        os.environ.setdefault(name, "1")


def user_chose_threads() -> bool:
    return any(value is not None for value in USER_SETTING.values())


def one_blas_thread(func):
    """Run ``func`` with the BLAS libraries limited to one thread (restored
    afterwards), unless the user set a thread count in the environment."""
    @functools.wraps(func)
    def limited(*args, **kwargs):
        if user_chose_threads():
            return func(*args, **kwargs)
        from threadpoolctl import threadpool_limits

        with threadpool_limits(limits=1, user_api="blas"):
            return func(*args, **kwargs)
    return limited


def core_to_spare() -> bool:
    """Whether a second thread of this process would find a core of its own
    now: the tasks running or ready to run besides this one (Linux:
    /proc/loadavg's count; elsewhere the last minute's load average) leave
    a core this process may use free. On a busy machine a worker thread
    only contends for the same cores: the seed's --fast solve with its
    stages side by side took 6 % more CPU and 5-10 % more wall time than one
    stage after another at a load average of 6 on two cores
    (benchmarks/fast_solve_parts.py).

    Only the timing depends on the load: each stage reads only its inputs,
    so a solve's results are the same to the bit whether its stages run
    side by side or one after another (tests/engine/test_stages_alongside.py)."""
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    if cores < 2:
        return False
    try:
        with open("/proc/loadavg") as handle:
            others = int(handle.read().split()[3].partition("/")[0]) - 1
    except (OSError, ValueError, IndexError):
        try:
            others = os.getloadavg()[0]
        except (AttributeError, OSError):
            return True
    return others <= cores - 2
