#!/usr/bin/python3
"""How the runtime's cost grows with the work: scene A's sphere reduced to nq = 36,
100, 148 and 300 (Craig-Bampton, 6 to 270 normal modes and the same 31 interface DOFs; the
interface coordinates quasistatic, the normal modes integrated), and the nq = 36 sphere hit
at 0.03 to 1 m/s so that more and more contact points carry load. For each run: steps, CPU
time per step, computed right-hand sides (RHS) per step, µs per RHS with the static solve's share,
mean loaded points, and the ratio to the bound of bench/cost_model.py. Writes the 'scaling'
section of bench/RESULTS.md.

usage: bench/scaling.py"""
import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
import re  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_common import BUILD, ROOT, machine, run_json, update_section  # noqa: E402
from cost_model import dense_rate, per_rhs  # noqa: E402

PREP = os.path.join(BUILD, "preprocess", "isosid-prep")
RUN = os.path.join(BUILD, "runtime", "isosid-run")


def sphere_sid(work, normal_modes):
    text = open(os.path.join(ROOT, "models", "sphere_axisym.model.toml")).read()
    text = text.replace("normal_modes = 6", f"normal_modes = {normal_modes}")
    model = os.path.join(work, f"sphere{normal_modes}.model.toml")
    with open(model, "w") as f:
        f.write(text)
    sid = os.path.join(work, f"sphere{normal_modes}.sid.h5")
    subprocess.run([PREP, "-q", model, "-o", sid], check=True, capture_output=True)
    return sid


def scene(work, sid, speed, name):
    text = open(os.path.join(ROOT, "models", "sphere_hertz.scene.toml")).read()
    text = re.sub(r'sid = ".*?"', f'sid = "{sid}"', text, count=1)
    text = re.sub(r'model = ".*?"\n', "", text, count=1)  # the SID as given: no rebuild for another contact radius
    text = text.replace("velocity = [0.0, -0.1, 0.0]", f"velocity = [0.0, {-speed}, 0.0]")
    text = re.sub(r"\[reference\].*", "", text, flags=re.S)
    # a slower impact lasts longer (Hertz: t ~ v^-1/5): end after the rebound at any speed
    text = text.replace("end_time = 95e-6", f"end_time = {95e-6 * max(1.0, (0.1 / speed) ** 0.2) * 1.05:.3e}")
    path = os.path.join(work, name + ".scene.toml")
    with open(path, "w") as f:
        f.write(text)
    return run_json([RUN, "-q", "--json", path, "-o", os.path.join(work, name)]), path


def row(label, run, rate):
    s, scene_file = run
    n, per, total, bound = per_rhs(s, scene_file, rate)
    b = s["bodies"][0]
    return (f"| {label} | {b['nq']} ({b['quasistatic_modes']}) | {s['steps']} | {1e6 * s['cpu_time_s'] / s['steps']:.0f} | "
            f"{n / s['steps']:.1f} | {s['rhs_cost']['mean_active_points']:.1f} | {total:.1f} | {per['static_solve']:.1f} | "
            f"{bound:.2f} | {total / bound:.0f} |")


def main():
    rate = dense_rate()
    info = machine()
    header = ["| case | nq (quasistatic) | steps | µs per step (CPU) | RHS per step | mean loaded points | µs per RHS | "
              "of it static solve | bound [µs] | ratio |", "|---|---|---|---|---|---|---|---|---|---|"]
    lines = ["## Runtime: scaling with nq and with loaded contact points",
             f"{info['date']}, {info['machine']}, commit {info['commit']}; `bench/scaling.py`. Scene A's sphere "
             f"(`sphere_axisym`, contact elements a/8 for 0.1 m/s) against its symmetry plane, dopri5 with quasistatic "
             f"interface coordinates; bound as in the cost model ({rate / 1e9:.1f} G multiply-adds/s).", "",
             "Against nq (0.1 m/s):", ""] + header
    with tempfile.TemporaryDirectory(prefix="isosid-scaling-") as work:
        sids = {}
        for normal in (6, 70, 118, 270):
            sids[normal] = sphere_sid(work, normal)
            lines.append(row(f"{normal} normal modes", scene(work, sids[normal], 0.1, f"nq{normal}"), rate))
            print(lines[-1], file=sys.stderr, flush=True)
        lines += ["", "Against loaded points (nq = 36; a faster impact spreads the contact over more points):", ""] + header
        for speed in (0.03, 0.1, 0.3, 1.0):
            lines.append(row(f"{speed} m/s", scene(work, sids[6], speed, f"v{speed}"), rate))
            print(lines[-1], file=sys.stderr, flush=True)
    update_section("scaling", "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
