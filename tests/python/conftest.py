"""Makes the build tree's module importable when PYTHONPATH does not already
(the README's line is PYTHONPATH=build/python; OCCLUSION_BUILD_DIR as in the
scripts)."""

import os
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("OCCLUSION_BUILD_DIR", ROOT / "build"))
if str(BUILD / "python") not in sys.path:
    sys.path.insert(0, str(BUILD / "python"))
