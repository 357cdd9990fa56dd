#!/usr/bin/python3
"""IGA against isoparametric bodies at equal contact resolution ([R1] Tables 1-2 in
docs/references.md): scenes A and B with the spline bodies of models/ and with gmsh's quadratic
quadrilaterals of the same contact element size ([mesh] models), plus coarser variants of each
kind. For every body: free DOFs, nq, preprocessing wall time (isosid-prep alone, two runs, the
faster), the scene's CPU time and its errors against the scene's references. Writes the
'iga-vs-isoparametric' section of bench/RESULTS.md.

usage: bench/iga_vs_isoparametric.py"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import BUILD, ROOT, machine, update_section  # noqa: E402

PREP = os.path.join(BUILD, "preprocess", "isosid-prep")
RUN = os.path.join(BUILD, "runtime", "isosid-run")
MODELS = os.path.join(ROOT, "models")

# (scene, label, model, replacements in the model text)
CASES = [
    ("sphere_hertz", "IGA, graded knots (a/8 = 21 um)", "sphere_axisym.model.toml", []),
    ("sphere_hertz_thb", "IGA, THB (25 um)", "sphere_axisym_thb.model.toml", []),
    ("sphere_hertz_gmsh", "isoparametric Q2, gmsh (21 um)", "sphere_axisym_gmsh.model.toml", []),
    ("sphere_hertz_gmsh", "isoparametric Q2, gmsh (42 um = a/4)", "sphere_axisym_gmsh.model.toml",
     [("contact_element_size = 21e-6", "contact_element_size = 42e-6"), ("interface_points = 31", "interface_points = 16")]),
    ("rod_impact", "IGA, 100 spans p = 5 along, 35 um at the pole", "rod_axisym.model.toml", []),
    ("rod_impact_gmsh", "isoparametric Q2, gmsh, 2 mm along, 35 um", "rod_axisym_gmsh.model.toml", []),
    ("rod_impact_gmsh", "isoparametric Q2, gmsh, 5 mm along, 35 um", "rod_axisym_gmsh.model.toml",
     [("element_size = 2e-3", "element_size = 5e-3")]),
]


def prepare(model_text, work, name):
    model = os.path.join(work, name + ".model.toml")
    with open(model, "w") as f:
        f.write(model_text)
    sid = os.path.join(work, name + ".sid.h5")
    best = None
    for _ in range(2):
        t0 = time.perf_counter()
        subprocess.run([PREP, "-q", model, "-o", sid], check=True, capture_output=True)
        best = min(best or 1e9, time.perf_counter() - t0)
    info = json.loads(subprocess.run([os.path.join(BUILD, "format", "isosid-info"), sid, "--json"], check=True,
                                     capture_output=True, text=True).stdout)
    return model, sid, best, info


def main():
    rows = []
    with tempfile.TemporaryDirectory(prefix="isosid-iga-iso-") as work:
        for k, (scene, label, model_file, edits) in enumerate(CASES):
            text = open(os.path.join(MODELS, model_file)).read()
            for a, b in edits:
                assert a in text, a
                text = text.replace(a, b)
            model, sid, prep_s, info = prepare(text, work, f"body{k}")
            scene_text = open(os.path.join(MODELS, scene + ".scene.toml")).read()
            scene_text = re.sub(r'sid = ".*?"', f'sid = "{sid}"', scene_text, count=1)
            scene_text = re.sub(r'model = ".*?"', f'model = "{model}"', scene_text, count=1)
            scene_path = os.path.join(work, f"scene{k}.scene.toml")
            with open(scene_path, "w") as f:
                f.write(scene_text)
            out = os.path.join(work, f"out{k}")
            subprocess.run([RUN, "-q", scene_path, "-o", out], check=True, capture_output=True)
            s = json.load(open(os.path.join(out, "summary.json")))
            errors = {key: v["rel_error"] for key, v in s["reference"].items()}
            rows.append((scene, label, info["mesh"]["free_dofs"], info["nq"], prep_s, s["cpu_time_s"], s["steps"], errors))
            print(f"{scene:18s} {label:48s} dofs {info['mesh']['free_dofs']:6d} prep {prep_s:6.2f} s run {s['cpu_time_s']:6.2f} s "
                  + " ".join(f"{key} {100 * v:+.2f} %" for key, v in errors.items()), flush=True)
    m = machine()
    lines = [f"## IGA against isoparametric bodies at equal contact resolution",
             f"{m['date']}, {m['machine']}, commit {m['commit']}; `python3 bench/iga_vs_isoparametric.py`. Preprocessing: "
             "isosid-prep's wall time, the faster of two runs (the gmsh meshing included); run: the scene's CPU time. "
             "Errors are signed, against each scene's references (A: Hertz 51.70 N, 83.1 us; B: l/c 195.7 us, the Hertz "
             "rod's contact end 544.4 us, rebound 0.3 m/s).", "",
             "| scene | body | free DOFs | nq | preprocessing | run (CPU) | steps | errors |", "|---|---|---|---|---|---|---|---|"]
    for scene, label, dofs, nq, prep_s, cpu, steps, errors in rows:
        text = ", ".join(f"{key} {100 * v:+.2f} %" for key, v in errors.items())
        lines.append(f"| {scene} | {label} | {dofs} | {nq} | {prep_s:.2f} s | {cpu:.2f} s | {steps} | {text} |")
    update_section("iga-vs-isoparametric", "\n".join(lines))


if __name__ == "__main__":
    main()
