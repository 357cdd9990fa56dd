#!/usr/bin/env python3
"""Runtime speed against error: runs validation scenes with isosid-run and records wall time,
steps, rejected steps, right-hand-side evaluations, Newton iterations and the error of every
reference value; CPU and wall time are the medians of three runs (a single run of the 0.1 s
scene varies by 10 %). Writes the 'scenes' section of bench/RESULTS.md.
Usage: bench/scenes.py [SCENE.toml ...] (default: every validation scene of models/)"""
import os
import statistics
import sys
import tempfile

from bench_common import BUILD, ROOT, machine, run_json, update_section

RUN = os.path.join(BUILD, "runtime", "isosid-run")
REPEATS = 3


def main():
    default = ["sphere_hertz", "sphere_hertz_full", "sphere_pair", "rod_impact", "cylinder_friction"]
    scenes = [a for a in sys.argv[1:] if not a.startswith("--")] or [os.path.join(ROOT, "models", f"{n}.scene.toml") for n in default]
    info = machine()
    lines = ["## Runtime: scenes", f"{info['date']}, {info['machine']}, commit {info['commit']}; `bench/scenes.py`; "
             f"times: median of {REPEATS} runs.", "",
             "| scene | CPU [s] | wall [s] | steps | rejected | RHS evaluations | Newton iterations | energy error | reference errors |",
             "|---|---|---|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as scratch:
        for scene in scenes:
            runs = [run_json([RUN, "-q", "--json", scene, "-o", scratch]) for _ in range(REPEATS)]
            s = runs[-1]  # the runs are deterministic but for their times
            s["cpu_time_s"] = statistics.median(r["cpu_time_s"] for r in runs)
            s["wall_time_s"] = statistics.median(r["wall_time_s"] for r in runs)
            errors = ", ".join(f"{k} {v['value']:.4g} ({100 * v['rel_error']:.2f} %)" for k, v in s["reference"].items()
                               if v.get("rel_error") is not None)
            lines.append(f"| {os.path.basename(scene)} | {s['cpu_time_s']:.3f} | {s['wall_time_s']:.3f} | {s['steps']} | {s['rejected_steps']} |"
                         f" {s['rhs_evaluations']} | {s['newton_iterations']} | {s['energy']['max_rel_error']:.2e} | {errors} |")
    update_section("scenes", "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
