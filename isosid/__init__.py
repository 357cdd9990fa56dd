"""isosid from Python: run scenes through the library's pipeline and read their results as
arrays and tables.

    import isosid
    r = isosid.run("models/sphere_hertz.scene.toml", set={"flexible_body.0.velocity": [0, -0.2, 0]})
    r.contacts["impact"].peak_force_n      # summary.json's figures as attributes
    r.contacts["impact"].force             # results.h5's series as numpy arrays (N, world frame)
    r.to_dataframe()                       # every sampled series against time (pandas)
    s = isosid.load_scene("models/sphere_hertz.scene.toml")   # a scene as a dict
    s["flexible_body"][0]["velocity"] = [0, -0.2, 0]
    r = isosid.run(s, base_dir="models")   # its SIDs and models found from models/

Errors raise InputError (bad input: the command line's exit 2) or ComputationError (a failed
computation: exit 1, its results so far kept) with the command line's message.
"""
import os as _os

_here = _os.path.dirname(_os.path.abspath(__file__))
_root = _os.path.dirname(_here)
# in a source checkout the compiled module is in build/python/isosid (scripts/build makes it);
# installed, it sits beside this file
_build = _os.environ.get("ISOSID_BUILD_DIR", _os.path.join(_root, "build"))
_built = _os.path.join(_build, "python", "isosid")
if _os.path.isdir(_built):
    __path__.append(_built)  # noqa: F821 (the package's own search path)

# isosid-prep, which the runtime calls for SIDs that are missing or out of date: the build
# tree's, else the installation's, else PATH
for _prep in (_os.path.join(_build, "preprocess", "isosid-prep"),
              _os.path.join(_root, "..", "..", "..", "bin", "isosid-prep")):
    if _os.path.isfile(_prep) and "ISOSID_PREP" not in _os.environ:
        _os.environ["ISOSID_PREP"] = _os.path.normpath(_prep)

from ._isosid import ComputationError, InputError  # noqa: E402
from ._isosid import version as _version  # noqa: E402
from .models import modes, prepare  # noqa: E402
from .results import Result, read_results  # noqa: E402
from .runs import load_scene, run, scene_text, toml_value  # noqa: E402
from .studies import Study, read_study  # noqa: E402

__version__ = _version().split()[1]
__all__ = ["run", "load_scene", "scene_text", "prepare", "modes", "read_results", "read_study", "Result", "Study", "InputError", "ComputationError", "toml_value"]
