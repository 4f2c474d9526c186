"""Batch simulators: many candidates at once, compiled with numba.

The compiled kernels spread their candidates over numba's OpenMP threads.
OpenMP's default wait policy keeps an idle thread spinning after each
parallel region; the diagnosis calls a kernel thousands of times with one to
six candidates, and on a loaded 2-core machine the spinning threads took the
core the caller needed: a one-candidate call of the stack-and-oil kernel
cost 14 ms of CPU (22 ms wall) against 1.5 ms with passive waiting, and a
32-candidate call 1.8 ms a candidate against 1.5 ms
(benchmarks/diagnose_speed.py). Idle threads therefore sleep
unless the user set a policy; libgomp reads it when numba first loads it,
at the first parallel call, after this package is imported.

The solve runs some technologies' stages in worker threads beside the
others (``Technology.alongside``); numba's workqueue threading layer (where
neither OpenMP nor TBB is installed) aborts when two threads launch
parallel kernels at once, and two teams would only share the same cores,
so the parallel kernels are launched one at a time (``PARALLEL_LAUNCH``).
"""
import os
import threading

os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

PARALLEL_LAUNCH = threading.Lock()
