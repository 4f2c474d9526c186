"""Where numba keeps the compiled kernels: one folder per version of their
sources.

numba marks a cached kernel stale when the file that defines it changes,
not when a function it inlines from another file does (numba's
documentation, "Notes on caching": "changes in other files are not
detected"). The piezohydraulic and pump kernels inline the Bouc-Wen step of
physics/bouc_wen.py: after an edit there, or a pull that changes only that
file, they went on running the old loop from the cache. The kernels are
therefore cached in a folder named by a digest of every file that holds
one (``KERNEL_MODULES``, kept complete by tests/project/test_kernel_cache.py),
in the project's cache folder; a NUMBA_CACHE_DIR the user set is left as
it is. A new version of the sources compiles once, in about a minute.
"""
from __future__ import annotations

import hashlib
import os
import sys
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent
KERNEL_MODULES = (
    "physics/bouc_wen.py",
    "physics/prandtl_ishlinskii.py",
    "sim/piezohydraulic.py",
    "sim/pump.py",
    "sim/dc_motor.py",
    "diagnose/effects/backlash.py",
    "diagnose/piecewise.py",
)


def sources_digest(package: Path = PACKAGE) -> str:
    """A digest of the kernel modules' bytes, in KERNEL_MODULES' order."""
    digest = hashlib.sha256()
    for module in KERNEL_MODULES:
        digest.update(module.encode() + b"\0" + (package / module).read_bytes())
    return digest.hexdigest()[:16]


def cache_folder(package: Path = PACKAGE) -> Path:
    """The folder of this version's compiled kernels, in the project's cache
    folder (SIZING_CACHE_DIR, else ~/.cache/sizing, as ``disk_cache``)."""
    root = os.environ.get("SIZING_CACHE_DIR") or Path.home() / ".cache" / "sizing"
    return Path(root) / "numba" / sources_digest(package)


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
