#!/usr/bin/env python3
"""Preprocessor speed: assembly throughput (DOFs/s) and eigen-solve time for 2D and 3D
validation models, and the convergence of the first twelve elastic frequencies of the beam of
case F ([R3] in docs/references.md).
Writes the 'prep-modal' section of bench/RESULTS.md. Usage: bench/prep_modal.py [--quick]"""
import os
import re
import statistics
import sys
import tempfile

from bench_common import BUILD, ROOT, machine, run_json, update_section

PREP = os.path.join(BUILD, "preprocess", "isosid-prep")
MODELS = os.path.join(ROOT, "models")


def timed(model, modes, repeats):
    runs = [run_json([PREP, "-q", "--json", "--modes", str(modes), model]) for _ in range(repeats)]
    result = runs[0]
    result["timings_s"] = {k: statistics.median(r["timings_s"][k] for r in runs) for k in runs[0]["timings_s"]}
    return result


def with_subdivisions(model, subdivisions):
    text = open(model).read()
    text = re.sub(r"subdivisions = \[[^\]]*\]", "subdivisions = [" + ", ".join(map(str, subdivisions)) + "]", text)
    f = tempfile.NamedTemporaryFile("w", suffix=".model.toml", delete=False)
    f.write(text)
    f.close()
    return f.name


def main():
    quick = "--quick" in sys.argv
    repeats = 1 if quick else 3
    info = machine()
    lines = [f"## Preprocessor: assembly and modal analysis",
             f"{info['date']}, {info['machine']}, commit {info['commit']}; median of {repeats} run(s);"
             " `bench/prep_modal.py`.", "",
             "| model | analysis | degrees | elements | DOFs | assembly [s] | DOFs/s | mass [s] | eigen (12 modes) [s] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name in ["sphere_axisym", "rod_axisym", "disk_plane_strain", "beam_free_free"]:
        r = timed(os.path.join(MODELS, name + ".model.toml"), 12, repeats)
        t = r["timings_s"]
        lines.append(f"| {name} | {r['analysis']} | {r['degrees']} | {r['elements']} | {r['dofs']} | {t['assembly']:.3f} |"
                     f" {r['dofs'] / t['assembly']:.0f} | {t['mass']:.3f} | {t['eigen']:.3f} |")

    beam = os.path.join(MODELS, "beam_free_free.model.toml")
    levels = [(12, 1, 1), (24, 2, 2), (36, 3, 3)] + ([] if quick else [(48, 4, 4)])
    spectra = []
    for sub in levels:
        path = with_subdivisions(beam, sub)
        r = run_json([PREP, "-q", "--json", "--modes", "18", path])
        os.unlink(path)
        spectra.append((sub, r["dofs"], r["frequencies_hz"][6:18], sum(r["timings_s"].values())))
    finest = spectra[-1][2]
    lines += ["", "### [R3]'s beam (210 x 15 x 10 mm, free-free, cubic): first twelve elastic frequencies [Hz]",
              "", "| elements | DOFs | time [s] | " + " | ".join(f"f{k + 1}" for k in range(12)) + " | max change vs finest |",
              "|---|---|---|" + "---|" * 12 + "---|"]
    for sub, dofs, f, seconds in spectra:
        change = max(abs(a - b) / b for a, b in zip(f, finest))
        lines.append(f"| {sub[0]}x{sub[1]}x{sub[2]} | {dofs} | {seconds:.2f} | " + " | ".join(f"{x:.1f}" for x in f) +
                     f" | {100 * change:.3f} % |")
    lines += ["", "The model file uses 24x2x2 (marked converged: further refinement changes no frequency by 0.1 %)."]
    update_section("prep-modal", "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
