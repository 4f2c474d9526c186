"""Where numba keeps the compiled kernels: one folder per version of their
sources.

numba marks a cached kernel stale when the file that defines it changes,
not when a function it inlines from another file does (numba's developer
documentation, "Notes on Caching", limitations: cache invalidation "fails
to recognize changes in symbols defined in another file"; numba pull
requests 8396 and 9563, which would extend it, are not merged). Two of the
simulators' kernels inline the Bouc-Wen step of physics/bouc_wen.py: after
an edit there, or a pull that changes only that file, numba's own cache
would go on running the previous loop. The kernels are
therefore cached in a folder named by a digest of every file that holds
one and of its neighbours (``KERNEL_FILES``, kept complete by
tests/project/test_kernel_cache.py),
in the project's cache folder; a NUMBA_CACHE_DIR the user set is left as
it is. A new version of the sources compiles once, in about a minute.
"""
from __future__ import annotations

import hashlib
import os
import sys
from pathlib import Path

from . import disk_cache

PACKAGE = Path(__file__).resolve().parent
# the files whose kernels numba compiles, and every file beside them (a
# kernel may inline a function of a neighbour)
KERNEL_FILES = ("physics/*.py", "sim/*.py", "diagnose/piecewise.py", "diagnose/effects/*.py")


def kernel_modules(package: Path = PACKAGE) -> list[Path]:
    """The files of KERNEL_FILES, in a stable order."""
    return sorted({path for pattern in KERNEL_FILES for path in package.glob(pattern)})


def sources_digest(package: Path = PACKAGE) -> str:
    """A digest of the kernel files' names and bytes."""
    digest = hashlib.sha256()
    for path in kernel_modules(package):
        digest.update(path.relative_to(package).as_posix().encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()[:16]


def cache_folder(package: Path = PACKAGE) -> Path:
    """The folder of this version's compiled kernels, in the project's cache
    folder (``disk_cache.root``)."""
    return disk_cache.root() / "numba" / sources_digest(package)


def configure() -> None:
    """Point numba's cache at ``cache_folder()`` unless the user chose one.
    numba makes the folder; where it cannot, it caches beside the sources
    as it would have."""
    if os.environ.get("NUMBA_CACHE_DIR"):
        return
    folder = str(cache_folder())
    os.environ["NUMBA_CACHE_DIR"] = folder          # read by numba when it is imported, here and in workers
    if "numba" in sys.modules:                      # imported already: its configuration is read
        sys.modules["numba"].config.CACHE_DIR = folder
