"""Where the tasks of ``sizing robust`` and ``sizing sweep`` run: in this
process, on a local Dask cluster of processes, or on a running scheduler.
The only module that imports dask.

Every task carries its own seed (``task_seed``: numpy SeedSequence keyed on
the task's index), so its result does not depend on the worker, the order
or the number of workers; results come back in task order.
"""
from __future__ import annotations

import logging
from typing import Callable, Sequence

import numpy as np

from ..errors import InputError

CONNECT_TIMEOUT_S = 3


def task_seed(seed: int, *index: int) -> np.random.Generator:
    """The random generator of task ``index`` (a tuple of ints) under ``seed``."""
    return np.random.default_rng(np.random.SeedSequence(int(seed), spawn_key=tuple(int(i) for i in index)))


class Executor:
    """``Executor(workers=0)``: run in this process. ``Executor(workers=N)``:
    a local cluster of N worker processes (the dashboard on a free port).
    ``Executor(scheduler=ADDRESS)``: an existing cluster; an address that does
    not answer within CONNECT_TIMEOUT_S is an InputError naming --scheduler.
    ``cluster=``: an existing dask cluster object (tests). Use as a context
    manager; ``map`` keeps the order of the tasks."""

    def __init__(self, workers: int = 0, scheduler: str | None = None, cluster=None, processes: bool = True):
        self.client = None
        self._cluster = None
        if scheduler is None and cluster is None and workers <= 0:
            return
        from dask.distributed import Client, LocalCluster
        if scheduler is not None:
            try:
                self.client = Client(scheduler, timeout=f"{CONNECT_TIMEOUT_S}s")
            except Exception as exc:       # noqa: BLE001 -- OSError, TimeoutError, ValueError from bad addresses
                # the exception's type says little (dask reports a refused or
                # malformed address as TimeoutError, OSError, even MemoryError)
                raise InputError(None, "--scheduler", f"cannot reach a Dask scheduler at {scheduler!r} within "
                                 f"{CONNECT_TIMEOUT_S} s; check the address and that the scheduler is running") from None
        else:
            if cluster is None:
                cluster = self._cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=processes,
                                                       dashboard_address=":0", silence_logs=logging.ERROR)
            self.client = Client(cluster)

    @property
    def where(self) -> str:
        if self.client is None:
            return "serial (this process)"
        n = len(self.client.scheduler_info().get("workers", {}))
        return f"dask {self.client.scheduler.address} ({n} workers)"

    @property
    def dashboard(self) -> str | None:
        return None if self.client is None else self.client.dashboard_link

    def map(self, fn: Callable, tasks: Sequence, progress: Callable[[int, int], None] | None = None) -> list:
        """[fn(t) for t in tasks]; ``progress(done, total)`` after each task."""
        total = len(tasks)
        if self.client is None:
            out = []
            for i, t in enumerate(tasks):
                out.append(fn(t))
                if progress:
                    progress(i + 1, total)
            return out
        from dask.distributed import as_completed
        futures = self.client.map(fn, list(tasks), pure=False)
        index = {f.key: i for i, f in enumerate(futures)}
        out = [None] * total
        for done, fut in enumerate(as_completed(futures), start=1):
            out[index[fut.key]] = fut.result()
            if progress:
                progress(done, total)
        return out

    def close(self) -> None:
        if self.client is not None:
            self.client.close()
        if self._cluster is not None:
            self._cluster.close()

    def __enter__(self) -> "Executor":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
