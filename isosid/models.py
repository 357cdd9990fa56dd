"""isosid.prepare and isosid.modes: isosid-prep's work on a model file, in-process."""
import importlib
import json
import os

from . import _hdf5


def _prep():
    """The compiled preparation, loaded on first use (its libraries would slow every import)."""
    return importlib.import_module("._isosid_prep", __package__)


def prepare(model, output=None, contact_radius=None, progress=True):
    """Builds the SID of the model file `model` (refinement, assembly, reduction) and writes it
    to `output` (default: the model's name with .sid.h5 for .model.toml). `contact_radius` (m)
    sizes a model with [contact_resolution] for that contact radius, as isosid-prep
    --contact-radius. Returns isosid-prep's report (its --json) as a dict: the body's size,
    mass and levels, the reduction, nq, the frequencies, contact points, nodes and stage times.

    Raises InputError for a bad model (or one too large for the memory, before the stage that
    would not fit) and ComputationError for a failed computation. `progress` shows the stages
    on stderr."""
    with _hdf5.turn:
        raw = _prep().prepare(os.fspath(model), os.fspath(output) if output is not None else "",
                              float(contact_radius) if contact_radius is not None else 0.0, bool(progress))
    return json.loads(raw)


def modes(model, count, progress=True):
    """The `count` lowest modes of the model file `model` (rigid-body modes included), as
    isosid-prep --modes --json reports them: `frequencies_hz`, `rigid_body_modes`, the body's
    size, mass and stage times. Writes nothing."""
    return json.loads(_prep().modes(os.fspath(model), int(count), bool(progress)))
