"""isosid.run: a scene file run in-process, with values set over it by dotted key."""
import json
import math
import numbers
import os

from . import _isosid
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


def default_output(scene):
    """out/<scene name>, as isosid-run's default."""
    return os.path.join("out", os.path.basename(os.fspath(scene)).split(".")[0])


def run(scene, output=None, set=None, progress=True):  # noqa: A002 (the keyword users write)
    """Runs the scene file `scene` into the results folder `output` (default out/<scene name>)
    with the values of `set` ({dotted key: value}, as isosid-run --set) over the file's, and
    returns its Result.

    Raises InputError for bad input (nothing run), ComputationError for a failed computation
    (its `result` holds the results so far), and KeyboardInterrupt on Ctrl-C, which stops the
    run at its next step with the results so far written to `output`. `progress` shows the
    progress line on stderr."""
    output = os.fspath(output) if output is not None else default_output(scene)
    settings = [(str(key), toml_value(value)) for key, value in (set or {}).items()]
    raw = _isosid.run_scene(os.fspath(scene), output, settings, bool(progress))
    result = Result(output, json.loads(raw["summary"]))
    if raw["status"] == "failed":
        error = _isosid.ComputationError(f"{raw['failure']}; results so far are in {output}")
        error.result = result
        raise error
    return result
