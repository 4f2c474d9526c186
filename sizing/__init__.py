"""sizing: size smart-material actuators for glide-body control surfaces.

Data flows one way: files -> SI objects (``sizing.io``) -> physics
(``sizing.physics``, ``sizing.sim``) -> engine -> results -> report.
"""
from importlib.metadata import PackageNotFoundError, version

from . import kernel_cache

kernel_cache.configure()       # before any kernel is compiled or loaded (kernel_cache.py says why)

try:
    __version__ = version("sizing")
except PackageNotFoundError:  # running from a source tree without install
    __version__ = "0.1.0"
