#!/usr/bin/env python3
"""Preprocessing time of every validation model by stage, from model file to SID (target: each
model of [R1] in docs/references.md under 20 s on this 2-core machine; [R1]'s MATLAB tool took
minutes per model).
Writes the 'prep-sid' section of bench/RESULTS.md. Usage: bench/prep_sid.py [--quick]"""
import os
import statistics
import sys
import tempfile

from bench_common import BUILD, ROOT, machine, run_json, update_section

PREP = os.path.join(BUILD, "preprocess", "isosid-prep")
MODELS = ["sphere_axisym", "sphere_axisym_full", "rod_axisym", "disk_plane_strain", "ball_3d", "beam_free_free"]
STAGES = ["refine", "assembly", "mass", "reduction", "sid_terms", "write"]


def main():
    quick = "--quick" in sys.argv
    repeats = 1 if quick else 3
    info = machine()
    lines = ["## Preprocessor: model file to SID, by stage",
             f"{info['date']}, {info['machine']}, commit {info['commit']}; median of {repeats} run(s); `bench/prep_sid.py`.",
             "", "| model | reduction | DOFs | nq (low + high) | " + " | ".join(f"{s} [s]" for s in STAGES) + " | total [s] |",
             "|---|---|---|---|" + "---|" * len(STAGES) + "---|"]
    with tempfile.TemporaryDirectory() as scratch:
        for name in MODELS:
            out = os.path.join(scratch, name + ".sid.h5")
            runs = [run_json([PREP, "-q", "--json", os.path.join(ROOT, "models", name + ".model.toml"), "-o", out])
                    for _ in range(repeats)]
            r = runs[0]
            t = {s: statistics.median(run["timings_s"][s] for run in runs) for s in STAGES}
            lines.append(f"| {name} | {r['reduction']} | {r['dofs']} | {r['nq']} ({r['n_low']} + {r['n_high']}) | " +
                         " | ".join(f"{t[s]:.3f}" for s in STAGES) + f" | {sum(t.values()):.2f} |")
    update_section("prep-sid", "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
