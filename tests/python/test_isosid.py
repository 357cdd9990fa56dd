"""The Python package against the command line on the same scene (identical numbers), its
errors against the command line's exit classes and messages, and its results as arrays and a
table. Run by ctest (tests/python/CMakeLists.txt) with ISOSID_RUN naming isosid-run."""
import ctypes
import json
import os
import shutil
import signal
import subprocess
import threading
import time

import h5py
import numpy as np
import pytest

import isosid

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODELS = os.path.join(ROOT, "models")
RUN = os.environ.get("ISOSID_RUN", os.path.join(ROOT, "build", "runtime", "isosid-run"))
SWEEP = os.environ.get("ISOSID_SWEEP", os.path.join(ROOT, "build", "sweep", "isosid-sweep"))
FASTER = [0.0, -0.2, 0.0]


@pytest.fixture
def scene_a(tmp_path):
    """Scene A (sphere on a plane, Hertz 51.70 N) and its model in a scratch folder."""
    for name in ("sphere_hertz.scene.toml", "sphere_axisym.model.toml"):
        shutil.copy(os.path.join(MODELS, name), tmp_path)
    return tmp_path / "sphere_hertz.scene.toml"


def cli(scene, out, *settings):
    args = [RUN, "-q", str(scene), "-o", str(out)]
    for s in settings:
        args += ["--set", s]
    return subprocess.run(args, capture_output=True, text=True)


def summary_of(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def test_scene_a_equals_the_command_line(scene_a, tmp_path):
    r = isosid.run(scene_a, output=tmp_path / "py", progress=False)
    assert cli(scene_a, tmp_path / "cli").returncode == 0
    s = summary_of(tmp_path / "cli")
    impact = r.contacts["impact"]
    for key in ("peak_force_n", "duration_s", "start_s", "end_s", "impulse_ns"):
        assert getattr(impact, key) == s["contacts"][0][key], key  # the same code on the same input: to the last digit
    assert r.status == "completed" and r.warnings == []
    # and the physics: Hertz's 51.70 N within 1 % (measured +0.83 %: the finite sphere is
    # stiffer than Hertz's half-spaces; docs/validation.md)
    assert abs(impact.peak_force_n / 51.70 - 1) < 1e-2
    with h5py.File(tmp_path / "cli" / "results.h5", "r") as f:
        np.testing.assert_array_equal(impact.force, f["contacts/impact/force"][()])
        np.testing.assert_array_equal(r.time, f["time"][()])
    assert impact.units["force"] == "N"


def test_values_set_over_the_scene_equal_the_command_lines(scene_a, tmp_path):
    r = isosid.run(scene_a, output=tmp_path / "py", set={"flexible_body.0.velocity": FASTER}, progress=False)
    assert cli(scene_a, tmp_path / "cli", "flexible_body.0.velocity=[0.0, -0.2, 0.0]").returncode == 0
    s = summary_of(tmp_path / "cli")
    assert r.contacts["impact"].peak_force_n == s["contacts"][0]["peak_force_n"]
    assert r.summary["provenance"]["scene_overrides"] == ["flexible_body.0.velocity = [0.0, -0.2, 0.0]"]
    # twice as fast: Hertz's peak grows as v^1.2 (2.297 times); the penalty layer and the
    # mesh's resolution of the larger contact keep it within 2 %
    base = isosid.run(scene_a, output=tmp_path / "base", progress=False)
    ratio = r.contacts["impact"].peak_force_n / base.contacts["impact"].peak_force_n
    assert abs(ratio / 2 ** 1.2 - 1) < 0.02


def test_a_scene_as_a_dict_equals_its_file(scene_a, tmp_path):
    scene = isosid.load_scene(scene_a)
    scene["flexible_body"][0]["velocity"] = FASTER
    r = isosid.run(scene, output=tmp_path / "dict", base_dir=scene_a.parent, progress=False)
    f = isosid.run(scene_a, output=tmp_path / "file", set={"flexible_body.0.velocity": FASTER}, progress=False)
    for key in ("peak_force_n", "duration_s", "impulse_ns"):
        assert getattr(r.contacts["impact"], key) == getattr(f.contacts["impact"], key), key  # the same scene: to the last digit
    # the provenance names the dict under its base folder and records its text's hash
    scene_input = next(i for i in r.summary["provenance"]["inputs"] if i["role"] == "scene")
    assert scene_input["path"] == os.path.join(str(scene_a.parent), "<scene dict>")
    assert len(scene_input["sha256"]) == 64
    # and its values set over it as a file's
    s = isosid.run(scene, output=tmp_path / "set", base_dir=scene_a.parent, set={"flexible_body.0.velocity": [0.0, -0.1, 0.0]},
                   progress=False)
    b = isosid.run(scene_a, output=tmp_path / "base", progress=False)
    assert s.contacts["impact"].peak_force_n == b.contacts["impact"].peak_force_n


def test_a_bad_scene_dict_raises_input_error_naming_it_and_the_field(scene_a, tmp_path):
    scene = isosid.load_scene(scene_a)
    scene["simulation"]["end_time"] = -1.0
    with pytest.raises(isosid.InputError, match=r"<scene dict>: simulation.end_time: must be positive"):
        isosid.run(scene, output=tmp_path / "py", base_dir=scene_a.parent, progress=False)
    # relative paths are the base folder's: elsewhere the SID is not found
    scene = isosid.load_scene(scene_a)
    with pytest.raises(isosid.InputError, match="flexible_body"):
        isosid.run(scene, output=tmp_path / "py", base_dir=tmp_path / "elsewhere", progress=False)
    with pytest.raises(TypeError):
        isosid.run(["not", "a", "scene"], output=tmp_path / "py", progress=False)
    assert not (tmp_path / "py").exists()


PREP = os.environ.get("ISOSID_PREP_PROGRAM", os.path.join(ROOT, "build", "preprocess", "isosid-prep"))


def loaded_openblas_core():
    """The kernel set of the OpenBLAS this interpreter has loaded (numpy's, and the preparation's),
    or None when the BLAS is not OpenBLAS."""
    try:
        core = ctypes.CDLL("libblas.so.3").openblas_get_corename
    except (OSError, AttributeError):
        return None
    core.restype = ctypes.c_char_p
    return core().decode()


def test_prepare_and_modes_equal_isosid_prep(tmp_path):
    model = tmp_path / "sphere_axisym.model.toml"
    shutil.copy(os.path.join(MODELS, "sphere_axisym.model.toml"), model)
    report = isosid.prepare(model, progress=False)
    assert report["output"] == str(tmp_path / "sphere_axisym.sid.h5") and os.path.isfile(report["output"])
    # isosid-prep picks the CPU's own BLAS kernels where OpenBLAS fell back to old ones; this
    # interpreter keeps those it loaded: the same kernels give the same numbers to the last bit
    core = loaded_openblas_core()
    env = dict(os.environ, OPENBLAS_CORETYPE=core) if core else None
    cli_run = subprocess.run([PREP, "-q", "--json", str(model), "-o", str(tmp_path / "cli.sid.h5")], capture_output=True, text=True,
                             env=env)
    assert cli_run.returncode == 0, cli_run.stderr
    cli_report = json.loads(cli_run.stdout)
    for key in ("dofs", "nq", "reduction", "frequencies_hz", "contact_points"):
        assert report[key] == cli_report[key], key  # the same code on the same model
    with h5py.File(report["output"], "r") as a, h5py.File(tmp_path / "cli.sid.h5", "r") as b:
        np.testing.assert_array_equal(a["refmod/frequencies_hz"][()], b["refmod/frequencies_hz"][()])
    m = isosid.modes(model, 8, progress=False)
    cli_modes = json.loads(subprocess.run([PREP, "-q", "--json", "--modes", "8", str(model)], capture_output=True, text=True,
                                          env=env).stdout)
    assert m["frequencies_hz"] == cli_modes["frequencies_hz"] and len(m["frequencies_hz"]) == 8


def test_prepare_refuses_bad_models_with_input_error(tmp_path):
    with pytest.raises(isosid.InputError, match="missing.model.toml: file not found"):
        isosid.prepare(tmp_path / "missing.model.toml", progress=False)
    model = tmp_path / "bad.model.toml"
    text = open(os.path.join(MODELS, "sphere_axisym.model.toml")).read().replace("poisson_ratio = 0.33", "poisson_ratio = 0.7")
    model.write_text(text)
    with pytest.raises(isosid.InputError, match="bad.model.toml: material.poisson_ratio"):
        isosid.prepare(model, progress=False)
    with pytest.raises(isosid.InputError, match="output: is the model file itself"):
        isosid.prepare(model, output=model, progress=False)
    with pytest.raises(isosid.InputError, match="count: must be at least 1"):
        isosid.modes(os.path.join(MODELS, "sphere_axisym.model.toml"), 0, progress=False)
    assert not (tmp_path / "bad.sid.h5").exists()


def cli_message(result):
    """The command line's one line, without its program and class prefix."""
    line = result.stderr.strip().splitlines()[-1]
    for prefix in ("isosid-run: error: ", "isosid-run: failed: "):
        if line.startswith(prefix):
            return line[len(prefix):]
    return line


@pytest.mark.parametrize("settings, problem", [
    ({"flexible_body.3.velocity": FASTER}, "'flexible_body' has 1 entries"),
    ({"simulation.end_time": -1.0}, "simulation.end_time: must be positive"),
    ({"simulation.rtol": 10}, "simulation.rtol"),
    ({"nope.x": 1}, "no 'nope' in the file to override"),
])
def test_bad_input_raises_input_error_with_the_command_lines_message(scene_a, tmp_path, settings, problem):
    with pytest.raises(isosid.InputError) as caught:
        isosid.run(scene_a, output=tmp_path / "py", set=settings, progress=False)
    (key, value), = settings.items()
    c = cli(scene_a, tmp_path / "cli", f"{key}={isosid.toml_value(value)}")
    assert c.returncode == 2
    assert str(caught.value) == cli_message(c)
    assert problem in str(caught.value)
    assert isinstance(caught.value, ValueError)
    assert not (tmp_path / "py").exists()  # refused before any output


def test_a_missing_scene_raises_input_error(tmp_path):
    with pytest.raises(isosid.InputError, match="missing.scene.toml: file not found"):
        isosid.run(tmp_path / "missing.scene.toml", output=tmp_path / "py", progress=False)


def test_a_failed_computation_raises_computation_error_with_its_results(scene_a, tmp_path):
    settings = {"simulation.max_steps": 200}
    with pytest.raises(isosid.ComputationError) as caught:
        isosid.run(scene_a, output=tmp_path / "py", set=settings, progress=False)
    c = cli(scene_a, tmp_path / "cli", "simulation.max_steps=200")
    assert c.returncode == 1
    assert str(caught.value) == cli_message(c).replace(str(tmp_path / "cli"), str(tmp_path / "py"))
    assert caught.value.result.status == "failed"
    assert summary_of(tmp_path / "py")["status"] == "failed"  # the results so far are kept


def test_ctrl_c_stops_the_run_at_a_step_and_keeps_its_results(scene_a, tmp_path):
    assert cli(scene_a, tmp_path / "sid").returncode == 0  # the SID built beforehand
    # a run of several seconds (steps of at most 10 ns); Ctrl-C once it is under way (its
    # summary.json says "running"), not while it still reads its inputs
    settings = {"simulation.max_step": 1e-8, "simulation.end_time": 2e-3}
    out = tmp_path / "py"

    def interrupt_once_running():
        for _ in range(3000):
            if (out / "summary.json").exists():
                time.sleep(0.2)
                os.kill(os.getpid(), signal.SIGINT)
                return
            time.sleep(0.01)

    watcher = threading.Thread(target=interrupt_once_running)
    watcher.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            isosid.run(scene_a, output=out, set=settings, progress=False)
    finally:
        watcher.join()
    r = isosid.read_results(out)
    assert r.status == "interrupted"
    assert 0 < r.time[-1] < 2e-3


def test_results_as_a_table(scene_a, tmp_path):
    r = isosid.run(scene_a, output=tmp_path / "py", progress=False)
    df = r.to_dataframe()
    np.testing.assert_array_equal(df.index.to_numpy(), r.time)
    np.testing.assert_array_equal(df["contacts/impact/force_y"].to_numpy(), r.contacts["impact"].force[:, 1])
    np.testing.assert_array_equal(df["energy/total"].to_numpy(), r.energy.total)
    assert df.attrs["units"]["contacts/impact/force_y"] == "N"
    assert df.attrs["units"]["bodies/sphere/q_0"] == "[q]"
    again = isosid.read_results(tmp_path / "py")
    assert again.contacts["impact"].peak_force_n == r.contacts["impact"].peak_force_n
    with pytest.raises(AttributeError, match="no figure or series 'nope'"):
        r.contacts["impact"].nope


def test_a_studys_table_and_cases(scene_a, tmp_path):
    (tmp_path / "s.study.toml").write_text(
        'scene = "sphere_hertz.scene.toml"\ncollect = ["contacts.impact.peak_force_n"]\n'
        '[[parameter]]\nkey = "flexible_body.0.velocity.1"\nvalues = [-0.1, -0.2, "x"]\n')
    done = subprocess.run([SWEEP, "-q", str(tmp_path / "s.study.toml"), "-o", str(tmp_path / "study")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    study = isosid.read_study(tmp_path / "study")
    assert [r["status"] for r in study.rows] == ["completed", "completed", "bad input"]
    assert study.rows[2]["exit_class"] == 2
    df = study.to_dataframe()
    assert df.loc[1, "flexible_body.0.velocity.1"] == "-0.2"  # text: the column also holds "x"
    assert df.loc[1, "contacts.impact.peak_force_n"] == study.case(1).contacts["impact"].peak_force_n
    assert np.isnan(df.loc[2, "contacts.impact.peak_force_n"])  # a refused case collected nothing


def test_python_values_written_as_toml():
    assert isosid.toml_value([0, -0.2, 0.0]) == "[0, -0.2, 0.0]"
    assert isosid.toml_value(np.array([1.5, 2.0])) == "[1.5, 2.0]"
    assert isosid.toml_value(True) == "true"
    assert isosid.toml_value('say "hi"') == '"say \\"hi\\""'
    assert isosid.toml_value({"a": 1}) == '{"a" = 1}'
    assert isosid.toml_value(float("inf")) == "inf"
    with pytest.raises(TypeError):
        isosid.toml_value(object())
