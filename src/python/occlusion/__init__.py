"""Occlusion of indoor 3D scans, numpy in and out.

Import from a build tree with ``PYTHONPATH=build/python``; ``cmake --install``
puts the package into the interpreter's site-packages. Everything here is the
C++ library's (the extension ``occlusion._occlusion``); this file only
re-exports it.
"""

from . import _occlusion
from ._occlusion import *  # noqa: F401,F403

__all__ = [name for name in dir(_occlusion) if not name.startswith("_")]
