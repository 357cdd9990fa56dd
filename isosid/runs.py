"""isosid.run: a scene, from its file or a dict, run in-process, with values set over it by
dotted key."""
import json
import math
import numbers
import os
import tomllib
from collections.abc import Mapping

from . import _hdf5, _isosid
from .results import Result


def toml_value(value):
    """A Python value written as a TOML value: numbers, booleans, strings, sequences (lists,
    tuples, numpy arrays) and dicts (inline tables)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        x = float(value)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string: the same escapes
    if isinstance(value, dict):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {toml_value(v)}" for k, v in value.items()) + "}"
    if hasattr(value, "tolist"):  # numpy arrays and scalars
        return toml_value(value.tolist())
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    raise TypeError(f"isosid: cannot write {type(value).__name__} as a TOML value")


def scene_text(scene):
    """A scene dict (as load_scene() returns: tables as dicts, arrays of tables as lists of
    dicts) written as TOML text, every table inline."""
    if not isinstance(scene, Mapping):
        raise TypeError(f"isosid: a scene is a file name or a dict, not {type(scene).__name__}")
    return "".join(f"{json.dumps(str(key))} = {toml_value(value)}\n" for key, value in scene.items())


def load_scene(path):
    """The scene file `path` as a dict, to change and run with run(scene, base_dir=...)."""
    with open(path, "rb") as f:
        return tomllib.load(f)


def default_output(scene):
    """out/<scene name>, as isosid-run's default."""
    return os.path.join("out", os.path.basename(os.fspath(scene)).split(".")[0])


def run(scene, output=None, set=None, progress=True, base_dir=None):  # noqa: A002 (the keyword users write)
    """Runs `scene` into the results folder `output` with the values of `set` ({dotted key:
    value}, as isosid-run --set) over the scene's, and returns its Result.

    `scene` is a scene file's name, or a scene as a dict (see load_scene()). A dict's relative
    paths (its bodies' SID and model files, the adaptive cache) are taken from `base_dir`
    (default: the working folder), and errors name it as `<base_dir>/<scene dict>`. The
    default `output` is out/<scene file's name>, or out/scene for a dict.

    Raises InputError for bad input (nothing run), ComputationError for a failed computation
    (its `result` holds the results so far), and KeyboardInterrupt on Ctrl-C, which stops the
    run at its next step with the results so far written to `output`. `progress` shows the
    progress line on stderr."""
    settings = [(str(key), toml_value(value)) for key, value in (set or {}).items()]
    if isinstance(scene, Mapping):
        output = os.fspath(output) if output is not None else os.path.join("out", "scene")
        name = os.path.join(os.path.abspath(base_dir if base_dir is not None else os.getcwd()), "<scene dict>")
        with _hdf5.turn:
            raw = _isosid.run_scene_text(scene_text(scene), name, output, settings, bool(progress))
    else:
        if base_dir is not None:
            raise TypeError("isosid.run: base_dir is for a scene given as a dict (a file's paths are relative to the file)")
        output = os.fspath(output) if output is not None else default_output(scene)
        with _hdf5.turn:
            raw = _isosid.run_scene(os.fspath(scene), output, settings, bool(progress))
    result = Result(output, json.loads(raw["summary"]))
    if raw["status"] == "failed":
        error = _isosid.ComputationError(f"{raw['failure']}; results so far are in {output}")
        error.result = result
        raise error
    return result
