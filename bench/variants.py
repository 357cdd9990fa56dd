"""Model and scene variants for the benchmark: copies of the files of models/ with chosen keys
replaced (every occurrence of `key = value` at the start of a line, so both graded requests of
a model change together), run through isosid-prep and isosid-run in a scratch folder."""
import os
import re
import shutil
import subprocess
import time

from bench_common import BUILD, ROOT

PREP = os.path.join(BUILD, "preprocess", "isosid-prep")
RUN = os.path.join(BUILD, "runtime", "isosid-run")
MODELS = os.path.join(ROOT, "models")


def with_keys(text, values, insert_after=None):
    """Replaces `key = ...` lines by the given values (Python values written as TOML); keys
    that are missing are inserted after the line `insert_after` (e.g. '[simulation]')."""
    for key, value in values.items():
        literal = f'"{value}"' if isinstance(value, str) else repr(value)
        pattern = re.compile(rf"^{re.escape(key)}\s*=.*$", re.M)
        if pattern.search(text):
            text = pattern.sub(f"{key} = {literal}", text)
        elif insert_after:
            text = text.replace(insert_after + "\n", f"{insert_after}\n{key} = {literal}\n", 1)
        else:
            raise KeyError(f"{key} not in the file and no place to insert it")
    return without_unused_contact_resolution(text)


def without_unused_contact_resolution(text):
    """A model whose element sizes were all given in metres no longer derives them from its
    [contact_resolution] (which isosid-prep refuses unused): the table is dropped."""
    if 'smallest = "contact"' in text or "[contact_resolution]" not in text:
        return text
    return re.sub(r"^\[contact_resolution\]\n(?:[^\[\n][^\n]*\n|\n)*", "", text, flags=re.M)


def write_variant(folder, label, scene, model, scene_keys=None, model_keys=None, sid_name=None):
    """Writes <label>.scene.toml and, if model_keys are given, <label>.model.toml into folder,
    pointing the scene at them; returns the scene path."""
    os.makedirs(folder, exist_ok=True)
    scene_text = open(os.path.join(MODELS, scene)).read()
    model_file = model
    if model_keys is not None:
        model_file = f"{label}.model.toml"
        with open(os.path.join(folder, model_file), "w") as f:
            f.write(with_keys(open(os.path.join(MODELS, model)).read(), model_keys))
    else:
        shutil.copy(os.path.join(MODELS, model), os.path.join(folder, model))
    sid = sid_name or model_file.replace(".model.toml", ".sid.h5")
    scene_text = scene_text.replace(model.replace(".model.toml", ".sid.h5"), sid).replace(model, model_file)
    scene_text = with_keys(scene_text, scene_keys or {}, insert_after="[simulation]")
    path = os.path.join(folder, f"{label}.scene.toml")
    with open(path, "w") as f:
        f.write(scene_text)
    return path


def prepare(scene_path):
    """Builds the SIDs of a variant scene (timed separately from the run); returns seconds."""
    import tomllib
    folder = os.path.dirname(scene_path)
    with open(scene_path, "rb") as f:
        scene = tomllib.load(f)
    seconds = 0.0
    for body in scene.get("flexible_body", []):
        model, sid = os.path.join(folder, body["model"]), os.path.join(folder, body["sid"])
        if not os.path.exists(sid) or os.path.getmtime(sid) < os.path.getmtime(model):
            start = time.perf_counter()
            subprocess.run([PREP, "-q", model, "-o", sid], check=True)
            seconds += time.perf_counter() - start
    return seconds


def run(scene_path, out_dir, timeout=None):
    """Runs isosid-run; returns (summary or None, exit status, stderr's last line, wall seconds)."""
    import json
    env = dict(os.environ, ISOSID_PREP=PREP)
    start = time.perf_counter()
    try:
        p = subprocess.run([RUN, "-q", "--json", scene_path, "-o", out_dir], capture_output=True, text=True, env=env,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timeout", f"no result after {timeout} s", time.perf_counter() - start
    last = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""
    summary = json.loads(p.stdout) if p.stdout.strip() else None
    return summary, p.returncode, last, time.perf_counter() - start
